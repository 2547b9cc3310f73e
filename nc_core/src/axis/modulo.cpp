// The modulo start (SPEC B1, seed 000 §2.1 "Units and reference systems"; MC_MoveModulo).
//
// Position P and the axis's modulo factor F give the end position X, which is always congruent
// to P modulo F (so NcToPlc.ModuloSetPos ends at P mod F, in [0, F)):
// - below the factor (|P| < F): the nearest such X in the direction — MC_Positive_Direction (1)
//   the first one ahead, MC_Negative_Direction (3) the first one behind, MC_Shortest_Way (2) the
//   nearer of the two (a tie goes positive), MC_Current_Direction (4) the first one in the
//   direction the axis moves (refused with kDirectionInvalid at standstill). "Nearest" is
//   counted from where the axis would come to rest (its set position at standstill), so that a
//   moving axis reaches it without reversing; an end within one encoder increment behind that
//   point counts as reached (no full turn for a rounding).
// - at or above the factor: floor(|P| / F) extra whole turns after that, in the same direction
//   (from 0, P = 540 with F = 360 travels 540 and ends at modulo 180). With MC_Shortest_Way the
//   turns take the direction of the sign of P, as the seed's modulo start does.
// The seed takes the direction from the sign of P; with the explicit Direction the sign only
// matters through the congruence: -1e-6 with MC_Negative_Direction ends 1e-6 past 0 going
// negative (ModuloSetPos 360 - 1e-6), 0.0 with MC_Positive_Direction ends on 0 going positive.
// Refused: P not finite (kPositionNotFinite), more than kMaxModuloTurns extra turns
// (kModuloTargetInvalid), Direction not 1 … 4 (kDirectionInvalid); the rest as MoveAbsolute.
#include <algorithm>
#include <cmath>

#include "axis/axis_commands.hpp"

namespace nc::detail {

namespace {

// More extra turns than this are not a meaningful modulo target (and would cost the end
// position its resolution).
constexpr double kMaxModuloTurns = 1'000'000.0;

}  // namespace

ErrorCode AxisCommands::start_modulo(const plc::Command& command) noexcept {
  Limits limits;
  if (const ErrorCode code = check_start(command, true, limits); code != ErrorCode::kNone) {
    return code;
  }
  // Where the axis comes to rest on the shortest stop: from there on, no reversal is needed.
  double from = s_.set_.p;
  if (s_.set_.v != 0.0 || s_.set_.a != 0.0) {
    s_.scratch_ = plan_stop(s_.set_, limits.deceleration, limits.jerk);
    if (!s_.scratch_.ok()) return s_.scratch_.error();
    from = s_.scratch_.final_state().p;
  }
  double end = 0.0;
  if (const ErrorCode code = modulo_end(command, from, s_.current_direction(), end);
      code != ErrorCode::kNone) {
    return code;
  }
  return start_to_target(command.number, end, limits);
}

ErrorCode AxisCommands::modulo_end(const plc::Command& command, double from, double moving,
                                   double& end) const noexcept {
  const double position = command.position;
  double direction = 0.0;
  switch (command.direction) {
    case plc::MC_Positive_Direction:
      direction = 1.0;
      break;
    case plc::MC_Negative_Direction:
      direction = -1.0;
      break;
    case plc::MC_Current_Direction:
      direction = moving;
      if (direction == 0.0) return ErrorCode::kDirectionInvalid;
      break;
    case plc::MC_Shortest_Way:  // decided below
      break;
    default:
      return ErrorCode::kDirectionInvalid;
  }
  const double factor = s_.config_.modulo_factor;
  const double turns = std::floor(std::abs(position) / factor);
  if (!(turns <= kMaxModuloTurns)) return ErrorCode::kModuloTargetInvalid;

  const double tolerance = std::max(s_.config_.encoder_increment, 1e-9 * factor);
  // The nearest ends congruent to P ahead of and behind `from` (P + F·m, m whole).
  const double ahead = position + factor * std::ceil((from - tolerance - position) / factor);
  const double behind = position + factor * std::floor((from + tolerance - position) / factor);
  if (direction == 0.0) {
    direction =
        turns > 0.0 ? (position < 0.0 ? -1.0 : 1.0) : (ahead - from <= from - behind ? 1.0 : -1.0);
  }
  end = (direction > 0.0 ? ahead : behind) + direction * turns * factor;
  return ErrorCode::kNone;
}

}  // namespace nc::detail
