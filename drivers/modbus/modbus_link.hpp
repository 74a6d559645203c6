// SPDX-License-Identifier: Apache-2.0
// One Modbus connection (TCP or RTU) over libmodbus, with per-request timeout and retries; errors
// come back as text naming the request (and the exception code when the drive answered with one).
// Blocking: used only on the driver's I/O thread (and in configure/deactivate). Not thread-safe.
#pragma once
#include <cstdint>
#include <string>

#include "drivers/modbus/modbus_settings.hpp"

typedef struct _modbus modbus_t;

namespace rays::ptu {

class ModbusLink {
public:
    explicit ModbusLink(const ModbusSettings& settings);
    ~ModbusLink();
    ModbusLink(const ModbusLink&) = delete;
    ModbusLink& operator=(const ModbusLink&) = delete;

    bool open(std::string& error);  // connects (closing any previous connection)
    void close();
    bool is_open() const { return open_; }

    // FC 0x06 for one register, FC 0x10 for more (Modbus application protocol spec 6.6, 6.12).
    bool write(int slave, int address, int count, const std::uint16_t* values, std::string& error);
    // FC 0x03 read holding registers (spec 6.3).
    bool read(int slave, int address, int count, std::uint16_t* values, std::string& error);

private:
    bool attempt(int slave, std::string& error, const char* what, int address, int (*call)(modbus_t*, void*),
                 void* argument);

    ModbusSettings settings_;
    modbus_t* context_ = nullptr;
    bool open_ = false;
};

}  // namespace rays::ptu
