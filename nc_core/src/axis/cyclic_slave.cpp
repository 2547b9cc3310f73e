// The cyclic slave (SPEC C6, seed 000 §3.3; MC_GearInDyn): its coupling command and the smoothing
// of the factor the PLC writes into PlcToNc.GearRatio1 every cycle. The law and why it is stable
// are in docs/behaviour.md "Cyclic slave (MC_GearInDyn)".
#include <algorithm>
#include <cmath>

#include "axis/servo_axis.hpp"
#include "axis/slave_coupling.hpp"

namespace nc::detail {

namespace {

// The factor's rate is kept this much inside AccBound, so that the rounding of
// factor · master a + rate · master v never takes the slave's acceleration above AccBound.
constexpr double kBoundMargin = 1e-12;

}  // namespace

ErrorCode SlaveCoupling::gear_in_dyn(const plc::Command& command, CouplingPort& port) noexcept {
  // A coupled slave never gets here: handle() refuses MC_GearInDyn on it (0x424E).
  if (const ErrorCode code = check_gear_ratio(command.ratio); code != ErrorCode::kNone) {
    return code;
  }
  if (!std::isfinite(command.acceleration)) return ErrorCode::kParameterNotFinite;
  if (command.acceleration <= 0.0) return ErrorCode::kAccelerationNotAllowed;
  if (const ErrorCode code = check_gear_master(command, port); code != ErrorCode::kNone) {
    return code;
  }
  const auto master_index = static_cast<uint32_t>(command.other_axis);
  if (const ErrorCode code = check_new_coupling(master_index, port); code != ErrorCode::kNone) {
    return code;
  }
  const double master_acceleration =
      SlaveCoupling(port.axes[master_index]->core()).max_acceleration(port);
  if (!couple_new(command, master_index, port)) return ErrorCode::kCouplingLoop;
  s_.slave_link_.cyclic = true;
  s_.slave_link_.acc_bound = command.acceleration;
  s_.slave_link_.master_acceleration = master_acceleration;
  // Seed 000 §3.3: stable for AccBound >= max|Cf| × max(A+, A-) of the master. Accepted below
  // it, with a warning (the same check runs for every new factor the PLC commands).
  if (command.acceleration < std::abs(command.ratio) * master_acceleration) {
    s_.channel_.warnings.warn(Warning::kAccBoundBelowStability);
  }
  return ErrorCode::kNone;  // answered kActive; the block shows InGear from NcToPlc.GearRatio
}

double SlaveCoupling::max_acceleration(const CouplingPort& port) const noexcept {
  if (!s_.slave_link_.coupled) return std::max(s_.config_.acceleration, s_.config_.deceleration);
  const double factor =
      std::max(std::abs(s_.slave_link_.factor), std::abs(s_.slave_link_.commanded));
  const double scaled =
      factor * SlaveCoupling(port.axes[s_.slave_link_.master]->core()).max_acceleration(port);
  return s_.slave_link_.cyclic ? std::max(s_.slave_link_.acc_bound, scaled) : scaled;
}

void SlaveCoupling::step_cyclic_factor(const AxisSnapshot& master) noexcept {
  SlaveLink& link = s_.slave_link_;
  const double written = s_.channel_.ref().PlcToNc.GearRatio1;
  if (written != link.commanded) {
    if (check_gear_ratio(written) != ErrorCode::kNone) {
      s_.channel_.warnings.warn(Warning::kGearRatio1NotTaken);  // the factor commanded before stays
    } else {
      link.commanded = written;
      if (link.acc_bound < std::abs(written) * link.master_acceleration) {
        s_.channel_.warnings.warn(Warning::kAccBoundBelowStability);
      }
    }
  }
  const double f = link.factor;
  const double c = link.commanded;
  if (f == c) {
    link.set_factor(c, 0.0);
    return;
  }
  // The slave's acceleration this cycle, with the factor moving at rate r (f' = f + r·T):
  //   a = f'·am + r·vm = f·am + r·(vm + T·am).
  // Every r with |a| <= AccBound is allowed; of those, the one closest to the rate that reaches
  // the commanded factor in this cycle, but never away from it nor past it.
  const double wanted = (c - f) / s_.cycle_time_;
  double rate = wanted;
  const double w = master.followed_velocity() + s_.cycle_time_ * master.followed_acceleration();
  if (w != 0.0) {
    const double bound = link.acc_bound * (1.0 - kBoundMargin);
    const double fa = f * master.followed_acceleration();
    const double lo = std::min((-bound - fa) / w, (bound - fa) / w);
    const double hi = std::max((-bound - fa) / w, (bound - fa) / w);
    rate = std::clamp(std::clamp(wanted, lo, hi), std::min(0.0, wanted), std::max(0.0, wanted));
  }
  // Reaching it: exactly the commanded factor (bit for bit), not f + r·T rounded.
  link.set_factor(rate == wanted ? c : f + rate * s_.cycle_time_, rate);
}

}  // namespace nc::detail
