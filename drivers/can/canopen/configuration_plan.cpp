// SPDX-License-Identifier: Apache-2.0
#include "drivers/can/canopen/configuration_plan.hpp"
#include "common/angles.hpp"

#include <cmath>
#include <cstdint>

#include "drivers/can/canopen/canopen_ids.hpp"
#include "drivers/can/canopen/cia402.hpp"

namespace rays::canopen {
namespace {

class PlanBuilder {
public:
    explicit PlanBuilder(ConfigurationPlan& plan) : plan_(plan) {}
    void write(std::uint16_t index, std::uint8_t sub, std::uint8_t size, std::uint32_t value) {
        plan_.steps[plan_.count++] = SdoRequest{index, sub, size, value, false};
    }
    void read(std::uint16_t index, std::uint8_t sub) { plan_.steps[plan_.count++] = SdoRequest{index, sub, 4, 0, true}; }

    // CiA 301 §7.4.8 mapping procedure for one PDO.
    void pdo(std::uint16_t comm, std::uint16_t map, std::uint32_t cob_id, std::initializer_list<std::uint32_t> entries,
             std::uint16_t event_timer_ms) {
        write(comm, 1, 4, kPdoInvalid | cob_id);
        write(map, 0, 1, 0);
        std::uint8_t sub = 0;
        for (std::uint32_t entry : entries) write(map, ++sub, 4, entry);
        write(map, 0, 1, sub);
        write(comm, 2, 1, kTransmissionEventDriven);
        if (event_timer_ms > 0) write(comm, 5, 2, event_timer_ms);
        write(comm, 1, 4, cob_id);
    }

private:
    ConfigurationPlan& plan_;
};

std::uint32_t per_second(double deg_per_s, double counts_per_rad) {
    return static_cast<std::uint32_t>(std::lround(deg_per_s * kRadPerDeg * counts_per_rad));
}

}  // namespace

std::int16_t abort_connection_code(const std::string& action) {
    if (action == "fault") return kAbortFault;
    if (action == "disable_voltage") return kAbortDisableVoltage;
    return kAbortQuickStop;
}

ConfigurationPlan configuration_plan(const CanopenSettings& s, int node, double counts_per_rad) {
    ConfigurationPlan plan;
    PlanBuilder b(plan);
    b.write(od::kControlword, 0, 2, cw::kQuickStop);  // stop whatever the drive was doing
    b.write(od::kProducerHeartbeat, 0, 2, static_cast<std::uint32_t>(s.drive_heartbeat_ms));
    b.write(od::kConsumerHeartbeat, 1, 4,
            (static_cast<std::uint32_t>(s.master_id) << 16) | static_cast<std::uint32_t>(s.drive_consumer_timeout_ms));
    b.write(od::kAbortConnection, 0, 2, static_cast<std::uint16_t>(abort_connection_code(s.comm_loss_action)));
    b.write(od::kModesOfOperation, 0, 1, static_cast<std::uint32_t>(kProfileVelocity));
    b.write(od::kMaxProfileVelocity, 0, 4, per_second(s.max_velocity_deg_s, counts_per_rad));
    b.write(od::kProfileVelocity, 0, 4, per_second(s.max_velocity_deg_s, counts_per_rad));
    b.write(od::kProfileAcceleration, 0, 4, per_second(s.accel_deg_s2, counts_per_rad));
    b.write(od::kProfileDeceleration, 0, 4, per_second(s.accel_deg_s2, counts_per_rad));
    b.write(od::kQuickStopDeceleration, 0, 4, per_second(s.quick_stop_decel_deg_s2, counts_per_rad));
    b.pdo(od::kRpdoComm, od::kRpdoMap, rpdo_id(1, node),
          {mapping(od::kControlword, 0, 16), mapping(od::kModesOfOperation, 0, 8), mapping(od::kTargetVelocity, 0, 32)}, 0);
    b.pdo(od::kRpdoComm + 1, od::kRpdoMap + 1, rpdo_id(2, node),
          {mapping(od::kControlword, 0, 16), mapping(od::kModesOfOperation, 0, 8), mapping(od::kTargetPosition, 0, 32)}, 0);
    const auto timer = static_cast<std::uint16_t>(s.tpdo_period_ms);
    b.pdo(od::kTpdoComm, od::kTpdoMap, tpdo_id(1, node),
          {mapping(od::kStatusword, 0, 16), mapping(od::kPositionActual, 0, 32)}, timer);
    b.pdo(od::kTpdoComm + 1, od::kTpdoMap + 1, tpdo_id(2, node),
          {mapping(od::kVelocityActual, 0, 32), mapping(od::kModesDisplay, 0, 8)}, timer);
    b.read(od::kStatusword, 0);
    return plan;
}

}  // namespace rays::canopen
