// SPDX-License-Identifier: Apache-2.0
// ptu-bench "canopen" and "odrive": the real drivers on the in-memory CAN bus with simulated drives
// (drivers/can/sim). Latency = from PtuDriver::write() to the moment the frame carrying that command
// (RPDO1 with the new target velocity; Set_Input_Vel) goes onto the bus to the simulated drive. Each
// command has a new pan velocity; commands are 2 ms apart, as from a fast frame loop.
#include <atomic>
#include <cmath>
#include <numbers>
#include <thread>

#include "drivers/can/can_frame_codec.hpp"
#include "drivers/can/canopen/canopen_driver.hpp"
#include "drivers/can/canopen/canopen_ids.hpp"
#include "drivers/can/odrive/odrive_driver.hpp"
#include "drivers/can/odrive/odrive_protocol.hpp"
#include "drivers/can/sim/cia402_sim_drive.hpp"
#include "drivers/can/sim/loopback_bus.hpp"
#include "drivers/can/sim/odrive_sim_axis.hpp"
#include "latency_bench.hpp"

namespace rays::bench {
namespace {

using Matcher = std::function<bool(const can_frame&, double value)>;

bool bring_up(ptu::PtuDriver& driver, std::string& error) {
    ptu::DriverStatus status = driver.configure();
    if (status.ok) status = driver.activate();
    if (!status.ok) error = status.what();
    return status.ok;
}

// Writes `commands` pan velocities and times each to its frame on the bus.
std::vector<double> measure(can::LoopbackBus& bus, ptu::PtuDriver& driver, const SteadyClock& clock, int commands,
                            const Matcher& carries, std::string& error) {
    std::atomic<double> wanted{0.0};
    std::atomic<std::int64_t> seen_ns{-1};
    bus.set_observer([&](const can::BusRecord& record) {
        if (seen_ns.load() < 0 && carries(record.frame, wanted.load()))
            seen_ns = std::chrono::duration_cast<std::chrono::nanoseconds>(record.time.time_since_epoch()).count();
    });
    std::vector<double> latencies;
    latencies.reserve(static_cast<std::size_t>(commands));
    for (int i = 0; i < commands; ++i) {
        const double velocity = 0.01 * (1 + i % 50) * (i % 2 == 0 ? 1.0 : -1.0);
        ptu::PtuCommand command;
        command.axes[0] = {ptu::CommandMode::Velocity, velocity};
        wanted = velocity;
        seen_ns = -1;
        const TimePoint written = clock.now();
        driver.write(command, written);
        const TimePoint deadline = written + std::chrono::milliseconds(200);
        while (seen_ns.load() < 0 && clock.now() < deadline) std::this_thread::yield();
        if (seen_ns.load() < 0) {
            error = "command " + std::to_string(i) + " never reached the bus";
            bus.set_observer(nullptr);
            return {};
        }
        const auto written_ns = std::chrono::duration_cast<std::chrono::nanoseconds>(written.time_since_epoch()).count();
        latencies.push_back(static_cast<double>(seen_ns.load() - written_ns) / 1000.0);
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    bus.set_observer(nullptr);
    driver.deactivate();
    return latencies;
}

std::vector<double> run_canopen(int commands, std::string& error) {
    SteadyClock clock;
    can::LoopbackBus bus(clock, 1 << 20);
    canopen::CanopenSettings settings;
    canopen::Cia402SimConfig pan_config, tilt_config;
    pan_config.node = settings.pan_node_id;
    tilt_config.node = settings.tilt_node_id;
    canopen::Cia402SimDrive pan(pan_config), tilt(tilt_config);
    can::SimBusHost host(bus, {&pan, &tilt});
    auto driver = canopen::make_canopen_driver(settings, bus.transport_for(bus.add_endpoint()), clock, error);
    if (!driver || !bring_up(*driver, error)) return {};
    const double counts_per_rad = settings.pan_counts_per_turn / (2.0 * std::numbers::pi);
    const std::uint32_t rpdo = canopen::rpdo_id(1, settings.pan_node_id);
    return measure(bus, *driver, clock, commands, [&](const can_frame& frame, double value) {
        return can::standard_id(frame) == rpdo &&
               static_cast<std::int32_t>(can::get_u32(frame, 3)) == std::lround(value * counts_per_rad);
    }, error);
}

std::vector<double> run_odrive(int commands, std::string& error) {
    SteadyClock clock;
    can::LoopbackBus bus(clock, 1 << 20);
    odrive::OdriveSettings settings;
    odrive::OdriveSimConfig pan_config, tilt_config;
    pan_config.node = settings.pan_node_id;
    tilt_config.node = settings.tilt_node_id;
    odrive::OdriveSimAxis pan(pan_config), tilt(tilt_config);
    can::SimBusHost host(bus, {&pan, &tilt});
    auto driver = odrive::make_odrive_driver(settings, bus.transport_for(bus.add_endpoint()), clock, error);
    if (!driver || !bring_up(*driver, error)) return {};
    const double turns_per_rad = settings.pan_motor_turns_per_axis_turn / (2.0 * std::numbers::pi);
    const auto id = odrive::frame_id(settings.pan_node_id, odrive::Cmd::SetInputVel);
    return measure(bus, *driver, clock, commands, [&](const can_frame& frame, double value) {
        return can::standard_id(frame) == id && can::get_f32(frame, 0) == static_cast<float>(value * turns_per_rad);
    }, error);
}

const bool registered_canopen = register_bench(
    {"canopen", "CiA 402 driver, in-memory CAN bus, 2 simulated drives: write() to the RPDO on the bus", run_canopen});
const bool registered_odrive = register_bench(
    {"odrive", "ODrive CAN simple driver, in-memory CAN bus, 2 simulated axes: write() to Set_Input_Vel on the bus",
     run_odrive});

}  // namespace
}  // namespace rays::bench
