// SPDX-License-Identifier: Apache-2.0
// A simulated CiA 402 drive on the CAN bus, for tests and the bench: NMT (boot-up, start,
// pre-operational), an SDO server over a small object dictionary, PDOs as the master maps them
// (RPDO contents applied, TPDOs sent by their event timer), the CiA 402 state machine with profile
// velocity and profile position (new set-point handshake, change set immediately), a heartbeat
// producer (0x1017), a heartbeat consumer (0x1016) acting by 0x6007 on communication loss, and an
// AxisDynamics for the motion. It records every frame it receives, with the time.
// Faults on demand: drive fault, heartbeat loss, SDO aborts, silence. All methods thread-safe.
#pragma once
#include <array>
#include <cstdint>
#include <mutex>
#include <vector>

#include "drivers/axis_dynamics.hpp"
#include "drivers/can/canopen/cia402.hpp"
#include "drivers/can/sim/sim_bus_host.hpp"

namespace rays::canopen {

struct Cia402SimConfig {
    int node = 1;
    double counts_per_rad = 131072 / 6.283185307179586;
    ptu::AxisDynamicsConfig dynamics{3.0, 20.0, 0.0};
    std::size_t record_capacity = 1 << 16;
};

struct ReceivedFrame {
    TimePoint time{};
    can_frame frame{};
};

class Cia402SimDrive final : public can::SimNode {
public:
    explicit Cia402SimDrive(const Cia402SimConfig& config);

    void on_frame(const can_frame& frame, TimePoint now, can::FrameSink& bus) override;
    void tick(TimePoint now, can::FrameSink& bus) override;

    double position_rad() const;
    double velocity_rad_s() const;
    DriveState state() const;
    std::uint8_t nmt_state() const;
    std::uint32_t object(std::uint16_t index, std::uint8_t sub) const;  // 0 when absent
    std::vector<ReceivedFrame> received() const;
    int communication_losses() const;

    void inject_fault(std::uint16_t emcy_code);  // into Fault; a fault reset works only after clear_fault
    void clear_fault();
    void stop_heartbeat(bool stopped);
    void abort_sdo(std::uint16_t index, std::uint32_t code);  // every SDO access to index aborts; 0: none
    void mute(bool muted);  // sends nothing at all

private:
    struct Entry {
        std::uint16_t index;
        std::uint8_t sub;
        std::uint8_t size;
        bool writable;
        std::uint32_t value;
    };

    Entry* find(std::uint16_t index, std::uint8_t sub);
    const Entry* find(std::uint16_t index, std::uint8_t sub) const;
    std::uint32_t get(std::uint16_t index, std::uint8_t sub) const;
    void set(std::uint16_t index, std::uint8_t sub, std::uint32_t value);
    void on_sdo(const can_frame& frame, can::FrameSink& bus);
    void on_rpdo(int pdo, const can_frame& frame, TimePoint now);
    void on_controlword(std::uint16_t controlword, TimePoint now);
    void apply_motion(TimePoint now);
    void enter(DriveState state, TimePoint now);
    std::uint16_t statusword() const;
    void send_tpdo(int pdo, can::FrameSink& bus);
    void emergency(std::uint16_t code, can::FrameSink& bus);

    mutable std::mutex mutex_;
    const Cia402SimConfig config_;
    ptu::AxisDynamics axis_;
    std::vector<Entry> dictionary_;
    std::vector<ReceivedFrame> received_;
    DriveState state_ = DriveState::SwitchOnDisabled;
    std::uint8_t nmt_ = 0x00;  // boot-up pending
    bool booted_ = false;
    std::uint16_t last_controlword_ = 0;
    bool acknowledged_ = false;
    bool fault_condition_ = false;
    std::uint16_t pending_emcy_ = 0;
    bool heartbeat_stopped_ = false, muted_ = false;
    std::uint16_t abort_index_ = 0;
    std::uint32_t abort_code_ = 0;
    TimePoint next_heartbeat_{}, last_master_heartbeat_{};
    std::array<TimePoint, 2> next_tpdo_{};
    bool consumer_active_ = false;
    int communication_losses_ = 0;
};

}  // namespace rays::canopen
