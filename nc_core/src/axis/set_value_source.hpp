// Where the basic set value of an axis comes from: exactly one source at a time, a closed set.
// The axis decides the source once per cycle (AxisCore::source()) and switches over it without
// a default, so a new source (slave link, homing job, two-speed sequencer) is a compile error in
// every place that must handle it. Superpositions come on top (superposition_stack.hpp).
//
// The sources' state lives with them: the PTP job in MasterJob (master_job.hpp), the absolute
// external generator in ExternalSetpoint (external_setpoint.hpp), the coupling in SlaveLink
// (slave_link.hpp); a hold has none.
// Real-time contract: the choice and the sampling are cycle functions (noexcept, no allocation).
#pragma once

#include <cstdint>

namespace nc::detail {

enum class SetValueSource : uint8_t {
  kHold,              // the axis holds its set position (superpositions may still move it)
  kPtpJob,            // MasterJob: positioning, velocity, halt, stop or the error ramp, with the
                      // online functions (override, new end position, new velocity)
  kExternalAbsolute,  // ExternalSetpoint of type absolute: the PLC's set values (seed 000 §2.6)
  kSlaveLink,         // SlaveLink: factor × the master's set values + offset (SPEC C1)
  kHomingJob,         // HomingJob: MC_Home's default homing sequence (homing/homing_job.hpp)
  // Next: kTwoSpeedSequencer (two-speed axis).
};

}  // namespace nc::detail
