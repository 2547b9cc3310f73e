// Issue 10 item 4: when losing the controller enable is the vendor's axis error 0x4260 ("the
// axis or a coupled slave axis has lost its controller enable signal while executing a command";
// docs/behaviour.md "Axis state and enables").
#include "axis/group_errors.hpp"

namespace nc::detail {

bool GroupErrors::enable_loss_is_error(bool lost) const noexcept {
  // A master: its own job (not the error ramp, which already belongs to an error) or a homing.
  if ((s_.job_.active() && s_.job_.kind() != JobKind::kEmergencyStop) || s_.homing_.active()) {
    return true;
  }
  // A coupled slave executes its coupling command (MC_GearIn / MC_GearInDyn stays Busy): the
  // edge of the enable is the error; the group reaction (SPEC C7) then reaches its master.
  // (SPEC C8 case 2, a head master pushed by hand, is no error: check_enables() asks
  // update_by_hand() first and does not get here then.)
  return lost && s_.slave_link_.coupled;
}

}  // namespace nc::detail
