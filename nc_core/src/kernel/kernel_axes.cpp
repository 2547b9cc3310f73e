#include "nc_core/detail/kernel_axes.hpp"

#include <string>

#include "axis/servo_axis.hpp"
#include "homing/axis_homing.hpp"
#include "kernel/hli_phase.hpp"
#include "nc_core/config.hpp"
#include "nc_core/profile.hpp"

namespace nc::detail {

KernelAxes::KernelAxes() : scratch_(std::make_unique<Profile>()) {}

bool KernelAxes::reference_cam(std::string_view name) const {
  return AxisHoming(find(name).core()).reference_cam();
}

ServoAxis& KernelAxes::find(std::string_view name) const {
  for (const auto& a : axes_) {
    if (a->config().name == name) return *a;
  }
  throw ConfigError("/axes", "has no axis with this name", std::string(name));
}

plc::AXIS_REF& KernelAxes::axis(std::string_view name) {
  return find(name).ref();
}
const plc::AXIS_REF& KernelAxes::axis(std::string_view name) const {
  return find(name).ref();
}
plc::AXIS_REF& KernelAxes::axis(std::size_t index) noexcept {
  return axes_[index]->ref();
}
const AxisConfig& KernelAxes::config(std::string_view name) const {
  return find(name).config();
}
const plc::NCTOIO_DRIVE_TWO_SPEED& KernelAxes::two_speed_output(std::string_view name) const {
  const AxisCore& axis = find(name).core();
  const plc::NCTOIO_DRIVE_TWO_SPEED* image = axis.two_speed_ ? &axis.two_speed_->output() : nullptr;
  if (image == nullptr) {
    throw ConfigError("/axes", "has this axis, but not of kind two_speed", std::string(name));
  }
  return *image;
}

std::span<plc::hli::HLI_AX* const> KernelAxes::gpAx() const noexcept {
  return hli_->gpAx();
}
double KernelAxes::command_position_request(int ax_nr) const noexcept {
  return hli_->command_position_request(ax_nr, axes_);
}
const AxisSnapshot& KernelAxes::snapshot(std::size_t index) const noexcept {
  axes_[index]->fill_snapshot(snapshots_[index]);
  return snapshots_[index];
}
bool KernelAxes::published_image_consistent(std::size_t index) const noexcept {
  return image_consistent(axes_[index]->core());
}

}  // namespace nc::detail
