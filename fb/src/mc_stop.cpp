#include "fb/mc_stop.hpp"

namespace fb {

void MC_Stop::operator()(plc::AXIS_REF& axis) noexcept {
  const detail::ExecuteOutputs out = block_(Execute, axis, [this]() noexcept {
    detail::Start start;
    start.command.type = plc::CommandType::kStop;
    start.command.deceleration = Deceleration;
    start.command.jerk = Jerk;
    return start;
  });
  if (out.done) holding_lock_ = true;
  if (holding_lock_ && !Execute) {
    holding_lock_ = false;
    release_pending_ = true;
  }
  bool releasing = false;
  if (release_pending_) {
    plc::Command release;
    release.type = plc::CommandType::kStopRelease;
    release_pending_ = axis.Mailbox.post(release) == 0;
    // Busy only while the release still waits and no result is on show (exclusivity).
    releasing = release_pending_ && !out.done && !out.error && !out.aborted;
  }
  Done = out.done;
  Busy = out.busy || releasing;
  Active = out.active;
  CommandAborted = out.aborted;
  Error = out.error;
  ErrorID = out.error_id;
}

}  // namespace fb
