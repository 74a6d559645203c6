// SPDX-License-Identifier: Apache-2.0
// The simulated pan/tilt unit behind ptu-sim: holding registers per slave laid out as the register
// map says, two AxisDynamics driven by the writes the map gives meaning to, the drive-side
// communication watchdog, a drive-fault bit, and every received register write reported with its
// receive time (steady clock, the same monotonic clock raysd uses). Thread-safe (one mutex).
#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <string>

#include "core/clock.hpp"
#include "drivers/axis_dynamics.hpp"
#include "drivers/modbus/register_map.hpp"

typedef struct _modbus_mapping_t modbus_mapping_t;

namespace rays::ptusim {

// One register write as received, or an event (slave -1, register = axis, note says what).
struct WriteRecord {
    TimePoint time{};
    int slave = 0;
    int address = 0;
    std::uint16_t value = 0;
    const char* note = "";
};

struct AxisView {
    double position_rad = 0.0;
    double velocity_rad_s = 0.0;
    bool enabled = false;
    bool fault = false;
};

class SimUnit {
public:
    using Recorder = std::function<void(const WriteRecord&)>;

    SimUnit(const ptu::RegisterMap& map, Recorder recorder);
    ~SimUnit();

    bool serves(int slave) const;
    modbus_mapping_t* mapping(int slave);  // the slave's register space (null when not served)

    // Around each request the server answers: a valid request feeds the watchdog; before the reply
    // the readable registers show the model at `now`; after it the written ones take effect.
    void request_received(TimePoint now);
    void before_reply(int slave, TimePoint now);
    void after_write(int slave, int address, int count, TimePoint now);
    // No valid request for the watchdog time: both axes stop (recorded as "watchdog_stop").
    void check_watchdog(TimePoint now);

    void set_drive_fault(std::size_t axis, bool fault, TimePoint now);
    AxisView view(std::size_t axis, TimePoint now);

private:
    struct Axis {
        ptu::AxisDynamics dynamics;
        bool enabled = false;
        bool fault = false;
        ptu::AxisCommand pending{};  // latched until the trigger register is written
    };
    std::uint16_t* registers(int slave);
    void apply(std::size_t axis, const ptu::AxisCommand& command, TimePoint now);
    void event(const char* note, int axis, TimePoint now);

    std::mutex mutex_;
    const ptu::RegisterMap map_;
    Recorder recorder_;
    std::array<modbus_mapping_t*, 2> mappings_{};
    std::array<int, 2> slaves_{};
    std::array<std::unique_ptr<Axis>, ptu::kAxes> axes_;
    double watchdog_ms_ = 0.0;
    TimePoint last_request_{};
    bool watchdog_tripped_ = false;
};

}  // namespace rays::ptusim
