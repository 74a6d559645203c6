// SPDX-License-Identifier: Apache-2.0
#include "drivers/modbus/modbus_link.hpp"

#include <modbus/modbus.h>

#include <cerrno>
#include <cstdio>

namespace rays::ptu {
namespace {

// The unit did not answer in time: libmodbus says ETIMEDOUT, and on a loaded machine sometimes EAGAIN
// (seen in CI with slow replies over TCP); both mean no reply.
bool no_reply(int code) { return code == ETIMEDOUT || code == EAGAIN; }

struct Transfer {
    int address;
    int count;
    std::uint16_t* values;
};

int do_write(modbus_t* context, void* argument) {
    auto* t = static_cast<Transfer*>(argument);
    if (t->count == 1) return modbus_write_register(context, t->address, t->values[0]);
    return modbus_write_registers(context, t->address, t->count, t->values);
}

int do_read(modbus_t* context, void* argument) {
    auto* t = static_cast<Transfer*>(argument);
    return modbus_read_registers(context, t->address, t->count, t->values);
}

// libmodbus maps exception responses (spec 7) to errno MODBUS_ENOBASE + code.
bool is_exception(int error) { return error > MODBUS_ENOBASE && error <= MODBUS_ENOBASE + MODBUS_EXCEPTION_GATEWAY_TARGET; }

}  // namespace

ModbusLink::ModbusLink(const ModbusSettings& settings) : settings_(settings) {}

ModbusLink::~ModbusLink() {
    close();
    if (context_ != nullptr) modbus_free(context_);
}

bool ModbusLink::open(std::string& error) {
    close();
    if (context_ == nullptr) {
        if (settings_.transport == "rtu") {
            const char parity = settings_.parity == "even" ? 'E' : settings_.parity == "odd" ? 'O' : 'N';
            context_ = modbus_new_rtu(settings_.device.c_str(), settings_.baud, parity, 8, settings_.stop_bits);
        } else {
            context_ = modbus_new_tcp(settings_.host.c_str(), settings_.port);
        }
        if (context_ == nullptr) {
            error = std::string("modbus: cannot create the context: ") + modbus_strerror(errno);
            return false;
        }
        const auto ms = static_cast<std::uint32_t>(settings_.timeout_ms);
        modbus_set_response_timeout(context_, ms / 1000, (ms % 1000) * 1000);
        // After a timeout or a bad frame, wait out and flush what a late reply may still send.
        modbus_set_error_recovery(context_, MODBUS_ERROR_RECOVERY_PROTOCOL);
    }
    if (modbus_connect(context_) == -1) {
        error = settings_.transport == "rtu"
                    ? "modbus: cannot open " + settings_.device + ": " + modbus_strerror(errno)
                    : "modbus: cannot connect to " + settings_.host + ":" + std::to_string(settings_.port) + ": " +
                          modbus_strerror(errno);
        return false;
    }
    open_ = true;
    return true;
}

void ModbusLink::close() {
    if (open_) modbus_close(context_);
    open_ = false;
}

bool ModbusLink::attempt(int slave, std::string& error, const char* what, int address, int (*call)(modbus_t*, void*),
                         void* argument) {
    if (!open_) {
        error = "modbus: not connected";
        return false;
    }
    modbus_set_slave(context_, slave);
    int code = 0;
    for (int attempt = 0; attempt <= settings_.retries; ++attempt) {
        if (call(context_, argument) != -1) return true;
        code = errno;
        if (is_exception(code)) break;  // the drive answered: asking again gets the same answer
    }
    char text[160];
    if (is_exception(code))
        std::snprintf(text, sizeof text, "modbus: slave %d %s 0x%04X: exception %d (%s)", slave, what, address,
                      code - MODBUS_ENOBASE, modbus_strerror(code));
    else
        std::snprintf(text, sizeof text, "modbus: slave %d %s 0x%04X: %s after %d tries", slave, what, address,
                      no_reply(code) ? "no reply" : modbus_strerror(code), settings_.retries + 1);
    error = text;
    return false;
}

bool ModbusLink::write(int slave, int address, int count, const std::uint16_t* values, std::string& error) {
    Transfer transfer{address, count, const_cast<std::uint16_t*>(values)};
    return attempt(slave, error, "write", address, do_write, &transfer);
}

bool ModbusLink::read(int slave, int address, int count, std::uint16_t* values, std::string& error) {
    Transfer transfer{address, count, values};
    return attempt(slave, error, "read", address, do_read, &transfer);
}

}  // namespace rays::ptu
