// SPDX-License-Identifier: Apache-2.0
#include "drivers/can/can_transport.hpp"

#include <linux/can/error.h>

namespace rays::can {

CanBusEvent classify_error_frame(const can_frame& frame) {
    if ((frame.can_id & CAN_ERR_FLAG) == 0) return CanBusEvent::None;
    if ((frame.can_id & CAN_ERR_BUSOFF) != 0) return CanBusEvent::BusOff;
    if ((frame.can_id & CAN_ERR_RESTARTED) != 0) return CanBusEvent::Restarted;
    if ((frame.can_id & CAN_ERR_CRTL) != 0) return CanBusEvent::ControllerProblem;
    return CanBusEvent::Other;
}

}  // namespace rays::can
