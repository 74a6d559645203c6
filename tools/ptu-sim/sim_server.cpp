// SPDX-License-Identifier: Apache-2.0
#include "sim_server.hpp"

#include <modbus/modbus.h>
#include <poll.h>
#include <termios.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <thread>

namespace rays::ptusim {
namespace {

// Modbus over serial line spec V1.02, 6.2.2: CRC-16, polynomial 0xA001 (reflected), init 0xFFFF.
std::uint16_t crc16(const std::uint8_t* data, int length) {
    std::uint16_t crc = 0xFFFF;
    for (int i = 0; i < length; ++i) {
        crc ^= data[i];
        for (int bit = 0; bit < 8; ++bit) crc = (crc & 1) ? static_cast<std::uint16_t>((crc >> 1) ^ 0xA001) : crc >> 1;
    }
    return crc;
}

// libmodbus's RTU receive answers one slave id, and after a frame for another id it takes the next
// frame for that slave's reply and drops it. The map may put two slaves on one line, so RTU frames
// are read here: length from the function code (spec 6.3, 6.6, 6.12), CRC low byte first
// (serial line spec 6.2.2); libmodbus then builds the reply. Returns the length, 0 for no frame.
bool read_exactly(int fd, std::uint8_t* buffer, int count) {
    for (int got = 0; got < count;) {
        pollfd p{fd, POLLIN, 0};
        if (poll(&p, 1, 50) <= 0) return false;  // the rest of the frame did not come
        const ssize_t n = ::read(fd, buffer + got, static_cast<std::size_t>(count - got));
        if (n <= 0) return false;
        got += static_cast<int>(n);
    }
    return true;
}

int read_rtu_frame(int fd, std::uint8_t* frame) {
    if (!read_exactly(fd, frame, 2)) return 0;
    int length = 0;
    if (frame[1] == 0x03 || frame[1] == 0x06) {
        length = 8;
        if (!read_exactly(fd, frame + 2, 6)) return 0;
    } else if (frame[1] == 0x10) {
        if (!read_exactly(fd, frame + 2, 5)) return 0;
        length = 9 + frame[6];
        if (length > MODBUS_RTU_MAX_ADU_LENGTH || !read_exactly(fd, frame + 7, length - 7)) return 0;
    } else {
        tcflush(fd, TCIFLUSH);  // a function this unit does not serve: resynchronise on silence
        return 0;
    }
    if (crc16(frame, length - 2) != (frame[length - 2] | (frame[length - 1] << 8))) return 0;
    return length;
}

class Handler {
public:
    Handler(modbus_t* context, SimUnit& unit, Faults& faults) : context_(context), unit_(unit), faults_(faults) {}

    void handle(std::uint8_t* request, int length) {
        const int header = modbus_get_header_length(context_);
        const int slave = request[header - 1];
        const int function = request[header];
        const TimePoint now = MonoClock::now();
        if (faults_.drop || faults_.disconnect) return;  // as if the request never arrived
        if (const int slow = faults_.slow_ms; slow > 0) std::this_thread::sleep_for(std::chrono::milliseconds(slow));
        if (!unit_.serves(slave)) {
            modbus_reply_exception(context_, request, MODBUS_EXCEPTION_GATEWAY_TARGET);
            return;
        }
        if (const int code = faults_.exception; code > 0) {  // refused: not a valid request for the watchdog
            modbus_reply_exception(context_, request, static_cast<unsigned>(code));
            return;
        }
        unit_.request_received(now);
        unit_.before_reply(slave, MonoClock::now());
        modbus_set_slave(context_, slave);
        if (modbus_reply(context_, request, length, unit_.mapping(slave)) == -1) return;
        const int address = (request[header + 1] << 8) | request[header + 2];
        if (function == 0x06) unit_.after_write(slave, address, 1, now);
        if (function == 0x10) unit_.after_write(slave, address, (request[header + 3] << 8) | request[header + 4], now);
    }

private:
    modbus_t* context_;
    SimUnit& unit_;
    Faults& faults_;
};

bool wait_readable(int fd, int timeout_ms) {
    pollfd p{fd, POLLIN, 0};
    return poll(&p, 1, timeout_ms) > 0;
}

bool serve_tcp(int port, SimUnit& unit, Faults& faults, const std::atomic<bool>& stop, std::atomic<bool>& ready,
               std::string& error) {
    modbus_t* context = modbus_new_tcp("127.0.0.1", port);
    int listener = context == nullptr ? -1 : modbus_tcp_listen(context, 1);
    if (listener < 0) {
        error = std::string("cannot listen on 127.0.0.1:") + std::to_string(port) + ": " + modbus_strerror(errno);
        if (context != nullptr) modbus_free(context);
        return false;
    }
    Handler handler(context, unit, faults);
    std::uint8_t request[MODBUS_TCP_MAX_ADU_LENGTH];
    int client = -1;
    ready = true;
    while (!stop) {
        unit.check_watchdog(MonoClock::now());
        if (faults.disconnect && client >= 0) {
            close(client);
            client = -1;
        }
        pollfd fds[2] = {{listener, POLLIN, 0}, {client, POLLIN, 0}};
        if (poll(fds, client >= 0 ? 2 : 1, 5) <= 0) continue;
        if (fds[0].revents & POLLIN) {
            const int accepted = accept(listener, nullptr, nullptr);
            if (accepted >= 0 && (faults.disconnect || client >= 0)) {
                close(accepted);  // one client at a time, none while disconnected
            } else if (accepted >= 0) {
                client = accepted;
            }
        }
        if (client >= 0 && (fds[1].revents & (POLLIN | POLLHUP | POLLERR))) {
            modbus_set_socket(context, client);
            const int length = modbus_receive(context, request);
            if (length == -1) {
                close(client);
                client = -1;
            } else if (length > 0) {
                handler.handle(request, length);
            }
        }
    }
    if (client >= 0) close(client);
    close(listener);
    modbus_free(context);
    return true;
}

bool serve_rtu(const std::string& device, SimUnit& unit, Faults& faults, const std::atomic<bool>& stop,
               std::atomic<bool>& ready, std::string& error) {
    modbus_t* context = modbus_new_rtu(device.c_str(), 115200, 'N', 8, 1);
    if (context == nullptr || modbus_connect(context) == -1) {
        error = "cannot open " + device + ": " + modbus_strerror(errno);
        if (context != nullptr) modbus_free(context);
        return false;
    }
    Handler handler(context, unit, faults);
    std::uint8_t request[MODBUS_RTU_MAX_ADU_LENGTH];
    ready = true;
    while (!stop) {
        unit.check_watchdog(MonoClock::now());
        if (!wait_readable(modbus_get_socket(context), 5)) continue;
        const int length = read_rtu_frame(modbus_get_socket(context), request);
        if (length > 0 && unit.serves(request[0])) handler.handle(request, length);
    }
    modbus_close(context);
    modbus_free(context);
    return true;
}

}  // namespace

bool serve(const ServerOptions& options, SimUnit& unit, Faults& faults, const std::atomic<bool>& stop,
           std::atomic<bool>& ready, std::string& error) {
    if (options.tcp_port > 0) return serve_tcp(options.tcp_port, unit, faults, stop, ready, error);
    return serve_rtu(options.rtu_device, unit, faults, stop, ready, error);
}

}  // namespace rays::ptusim
