// A two-bar linkage drawing a straight line through external setpoint generation (seed 000 §2.6,
// use case "coordinate transformations"), as an ncsdk PLC program.
//
// Two joint axes (degrees) carry links of 400 mm and 300 mm. The PLC program moves the joints to
// the start pose with MC_MoveAbsolute (a point-to-point move: the tool path between is a curve),
// then plans the straight line from (550, -150) mm to (150, 450) mm as a jerk-limited path
// parameter s(t) (nc::plan_position: V 300 mm/s, A 1000 mm/s², J 10000 mm/s³ along the path),
// turns every point of it into joint angles, velocities and accelerations with the inverse
// kinematics (kinematics.hpp, Eigen) and feeds both joints each PLC cycle through
// MC_ExtSetPointGenFeed — enabled absolute with the goal angles as the target-window positions,
// direction ±1 from one cycle before to one cycle after the line (seed 000 §2.6), then disabled.
// Joint 2 reverses on the way (the elbow opens to 117° where the line passes closest to the
// base, then closes to 96°): its packet direction follows the sign of its velocity.
//
// TwoBarLinkageSample runs it on two simulated axes (1 ms NC cycle, the PLC task with it, a
// scope every cycle that also records the tool point computed from the set and from the actual
// joint angles). Header-only, so that tests/samples/test_two_bar_linkage_sample.cpp runs exactly
// what the sample program runs.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Dense>

#include "fb/mc_ext_set_point_gen_disable.hpp"
#include "fb/mc_ext_set_point_gen_enable.hpp"
#include "fb/mc_ext_set_point_gen_feed.hpp"
#include "fb/mc_move_absolute.hpp"
#include "fb/mc_power.hpp"
#include "fb/types.hpp"
#include "kinematics.hpp"
#include "nc_core/axis_config.hpp"
#include "nc_core/cycle_driver.hpp"
#include "nc_core/kernel.hpp"
#include "nc_core/profile.hpp"
#include "nc_core/scope.hpp"
#include "nc_core/svg_plot.hpp"
#include "plc_interface/axis_ref.hpp"
#include "sample_output.hpp"

namespace two_bar_linkage {

inline const Eigen::Vector2d kLineStart{550.0, -150.0};  // mm
inline const Eigen::Vector2d kLineGoal{150.0, 450.0};    // mm
// Path dynamics along the line (mm/s, mm/s², mm/s³).
inline constexpr nc::Limits kPathLimits{300.0, 1000.0, 1000.0, 10000.0};
inline constexpr double kPtpVelocity = 90.0;  // °/s, the move to the start pose

enum class LinkState {
  STATE_INIT,           // wait for both MC_Power
  STATE_MOVE_TO_START,  // MC_MoveAbsolute of both joints to the start pose
  STATE_ENABLE,         // MC_ExtSetPointGenEnable on both joints
  STATE_PRE_LINE,       // one packet at the start pose, directions already ±1
  STATE_LINE,           // the line's packets
  STATE_POST_LINE,      // one more packet at the goal, directions still ±1
  STATE_WAIT_TARGET,    // directions 0; wait for InTargetPosition on both joints
  STATE_DISABLE,        // MC_ExtSetPointGenDisable on both joints
  STATE_FINISHED,
  STATE_ERROR,
};

inline const char* state_name(LinkState state) noexcept {
  switch (state) {
    case LinkState::STATE_INIT:
      return "STATE_INIT";
    case LinkState::STATE_MOVE_TO_START:
      return "STATE_MOVE_TO_START";
    case LinkState::STATE_ENABLE:
      return "STATE_ENABLE";
    case LinkState::STATE_PRE_LINE:
      return "STATE_PRE_LINE";
    case LinkState::STATE_LINE:
      return "STATE_LINE";
    case LinkState::STATE_POST_LINE:
      return "STATE_POST_LINE";
    case LinkState::STATE_WAIT_TARGET:
      return "STATE_WAIT_TARGET";
    case LinkState::STATE_DISABLE:
      return "STATE_DISABLE";
    case LinkState::STATE_FINISHED:
      return "STATE_FINISHED";
    case LinkState::STATE_ERROR:
      return "STATE_ERROR";
  }
  return "?";
}

// The joint blocks of one axis.
struct Joint {
  fb::MC_Power Power;
  fb::MC_MoveAbsolute Move;
  fb::MC_ExtSetPointGenEnable Enable;
  fb::MC_ExtSetPointGenDisable Disable;
  int direction = 1;  // packet direction, kept through standstill of the joint
  double FedPos = 0.0, FedVelo = 0.0, FedAcc = 0.0, FedDirection = 0.0;
};

// PROGRAM MAIN, one call per PLC cycle (the PLC task runs with the NC cycle). A cycle function:
// the path profile is planned into a member (no allocation).
struct Main {
  double cycle_time = 0.001;  // s
  Linkage linkage;
  JointState start_pose, goal_pose;
  nc::Profile path;  // s(t) along the line, 0 … |goal - start|
  std::array<Joint, 2> joints;
  LinkState state = LinkState::STATE_INIT;
  uint64_t line_cycles = 0;
  uint32_t error_id = 0;
  double PathS = 0.0;  // mm along the line, of this cycle's packet

  Main() {
    inverse(linkage, kLineStart, Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero(), start_pose);
    inverse(linkage, kLineGoal, Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero(), goal_pose);
  }

  void operator()(plc::AXIS_REF& axis1, plc::AXIS_REF& axis2) noexcept {
    plc::AXIS_REF* axes[2] = {&axis1, &axis2};
    for (std::size_t i = 0; i < 2; ++i) {
      Joint& j = joints[i];
      j.Power.Enable = j.Power.Enable_Positive = j.Power.Enable_Negative = true;
      j.Power(*axes[i]);
      j.Enable.Execute = false;
      j.Disable.Execute = false;
    }

    bool feeding = false;  // this cycle's packets carry a direction
    JointState point{goal_pose.q, Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero()};
    switch (state) {
      case LinkState::STATE_INIT:
        if (joints[0].Power.Status && joints[1].Power.Status) {
          state = LinkState::STATE_MOVE_TO_START;
        }
        point.q = {axis1.NcToPlc.SetPos, axis2.NcToPlc.SetPos};
        break;
      case LinkState::STATE_MOVE_TO_START:
        for (std::size_t i = 0; i < 2; ++i) {
          joints[i].Move.Execute = true;
          joints[i].Move.Position = start_pose.q[static_cast<Eigen::Index>(i)];
          joints[i].Move.Velocity = kPtpVelocity;
        }
        point.q = {axis1.NcToPlc.SetPos, axis2.NcToPlc.SetPos};
        if (joints[0].Move.Done && joints[1].Move.Done) state = LinkState::STATE_ENABLE;
        break;
      case LinkState::STATE_ENABLE:
        for (std::size_t i = 0; i < 2; ++i) {
          joints[i].Move.Execute = false;
          joints[i].Enable.Execute = true;
          joints[i].Enable.Position = goal_pose.q[static_cast<Eigen::Index>(i)];
          joints[i].Enable.PositionType = fb::POSITIONTYPE_ABSOLUTE;
        }
        point = start_pose;
        break;
      case LinkState::STATE_PRE_LINE:
        path = nc::plan_position({}, (kLineGoal - kLineStart).norm(), kPathLimits);
        if (!path.ok()) {
          error_id = plc::to_id(path.error());
          state = LinkState::STATE_ERROR;
          break;
        }
        line_cycles = 0;
        point = start_pose;
        feeding = true;
        state = LinkState::STATE_LINE;
        break;
      case LinkState::STATE_LINE: {
        ++line_cycles;
        const double t = static_cast<double>(line_cycles) * cycle_time;
        const nc::KinematicState s = path.at(t);
        const Eigen::Vector2d u = (kLineGoal - kLineStart).normalized();
        PathS = s.p;
        if (!inverse(linkage, kLineStart + s.p * u, s.v * u, s.a * u, point)) {
          error_id = plc::to_id(plc::ErrorCode::kTargetPositionNotAllowed);
          state = LinkState::STATE_ERROR;
          break;
        }
        feeding = true;
        if (t >= path.duration()) state = LinkState::STATE_POST_LINE;
        break;
      }
      case LinkState::STATE_POST_LINE:
        feeding = true;
        state = LinkState::STATE_WAIT_TARGET;
        break;
      case LinkState::STATE_WAIT_TARGET:
        if (plc::test_bit(axis1.NcToPlc.StateDWord, plc::kStateInTargetPosition) &&
            plc::test_bit(axis2.NcToPlc.StateDWord, plc::kStateInTargetPosition)) {
          state = LinkState::STATE_DISABLE;
        }
        break;
      case LinkState::STATE_DISABLE:
        for (Joint& j : joints)
          j.Disable.Execute = true;
        break;
      case LinkState::STATE_FINISHED:
      case LinkState::STATE_ERROR:
        break;
    }

    bool moved = true, enabled = true, disabled = true;
    for (std::size_t i = 0; i < 2; ++i) {
      Joint& j = joints[i];
      plc::AXIS_REF& axis = *axes[i];
      j.Move(axis);
      j.Enable(axis);
      j.Disable(axis);
      moved = moved && j.Move.Done;
      enabled = enabled && j.Enable.Done;
      disabled = disabled && j.Disable.Done;
      const auto e = static_cast<Eigen::Index>(i);
      // The set direction follows the joint's velocity; through its standstill it keeps the
      // last one, so it stays ±1 for the whole line (seed 000 §2.6).
      if (point.qd[e] > 0.0) j.direction = 1;
      if (point.qd[e] < 0.0) j.direction = -1;
      const int direction = feeding ? j.direction : 0;
      const uint32_t feed =
          fb::MC_ExtSetPointGenFeed(point.q[e], point.qd[e], point.qdd[e], direction, axis);
      j.FedPos = point.q[e];
      j.FedVelo = point.qd[e];
      j.FedAcc = point.qdd[e];
      j.FedDirection = direction;
      const uint32_t code = feed != 0         ? feed
                            : j.Power.Error   ? j.Power.ErrorID
                            : j.Move.Error    ? j.Move.ErrorID
                            : j.Enable.Error  ? j.Enable.ErrorID
                            : j.Disable.Error ? j.Disable.ErrorID
                                              : 0U;
      if (code != 0) {
        error_id = code;
        state = LinkState::STATE_ERROR;
      }
    }
    if (state == LinkState::STATE_ENABLE && enabled) state = LinkState::STATE_PRE_LINE;
    if (state == LinkState::STATE_DISABLE && disabled) state = LinkState::STATE_FINISHED;
    (void)moved;
  }
};

// What the run showed, for the summary and the test.
struct Report {
  bool finished = false;
  uint32_t error_id = 0;
  double line_start_time = -1.0;   // s, first packet with a direction
  double line_end_time = -1.0;     // s, last packet with a direction
  double line_duration = 0.0;      // s, the path profile's duration
  double max_set_deviation = 0.0;  // mm, max distance of the set tool point from the line
  double max_act_deviation = 0.0;  // mm, the same for the actual tool point
  double max_set_minus_fed = 0.0;  // °, max |SetPos - FedPos| over the taken packets
  double max_tool_speed = 0.0;     // mm/s, of the set tool point along the line
  double joint2_max = -1e9;        // °, the elbow's largest set angle during the line
  double max_following_error[2] = {0.0, 0.0};                // °
  Eigen::Vector2d final_set_tool = Eigen::Vector2d::Zero();  // mm
  Eigen::Vector2d final_act_tool = Eigen::Vector2d::Zero();  // mm
  bool final_in_target = false;  // both joints InTargetPosition at the end
  bool final_enabled = true;     // either joint still ExtSetPointGenEnabled
  uint32_t axis_error = 0;
  double end_time = 0.0;

  // The sample's success rule: the set tool point on the line (1e-6 mm), the actual one within
  // 0.05 mm of it, the tool at the goal, both joints in the target window, generation disabled.
  static constexpr double kSetTolerance = 1e-6;  // mm
  static constexpr double kActTolerance = 0.05;  // mm
  bool ok() const noexcept {
    return finished && error_id == 0 && axis_error == 0 && max_set_deviation <= kSetTolerance &&
           max_act_deviation <= kActTolerance && max_set_minus_fed == 0.0 &&
           (final_set_tool - kLineGoal).norm() <= kSetTolerance && final_in_target &&
           !final_enabled;
  }
};

struct Options {
  double nc_cycle = 0.001;   // s
  double timeout = 10.0;     // s of simulated time
  double settle_time = 0.2;  // s recorded after STATE_FINISHED
};

// A joint axis in degrees: a lagging drive like the other samples', with a stiffer position
// loop (Kv 20 /s) as a robot joint would have, and windows scaled to degrees.
inline nc::AxisConfig joint_axis_config(const char* name) {
  nc::AxisConfig config;
  config.name = name;
  config.max_velocity = 360.0;  // °/s
  config.ref_velocity = 360.0;
  config.acceleration = 720.0;  // °/s²
  config.deceleration = 720.0;
  config.jerk = 7200.0;  // °/s³
  sample_common::use_lagging_drive(config, 20.0);
  config.encoder_increment = 1e-6;     // °
  config.following_error_limit = 1.0;  // °
  config.target_window = 0.01;         // °
  config.position_range_window = 0.1;  // °
  return config;
}

// Signed distance of `p` from the line through kLineStart and kLineGoal (mm).
inline double line_deviation(const Eigen::Vector2d& p) noexcept {
  const Eigen::Vector2d u = (kLineGoal - kLineStart).normalized();
  const Eigen::Vector2d d = p - kLineStart;
  return u.x() * d.y() - u.y() * d.x();
}

// One line of an x–y plot.
struct XySeries {
  std::string label;
  std::string colour;
  std::span<const double> x, y;
  double width = 1.5;
  bool dashed = false;
};

// After-run: an x–y plot (equal scales, mm) with a grid every `grid` mm and a legend; the
// linkage is drawn in the poses `poses` (grey links, joint circles).
inline std::string xy_svg(const std::string& title, const std::vector<XySeries>& series,
                          const Linkage& linkage, const std::vector<Eigen::Vector2d>& poses,
                          double grid = 100.0) {
  double x0 = 0.0, x1 = 0.0, y0 = 0.0, y1 = 0.0;  // the base is always shown
  for (const XySeries& s : series) {
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) continue;
      x0 = std::min(x0, s.x[i]), x1 = std::max(x1, s.x[i]);
      y0 = std::min(y0, s.y[i]), y1 = std::max(y1, s.y[i]);
    }
  }
  x0 = std::floor(x0 / grid) * grid - grid, x1 = std::ceil(x1 / grid) * grid + grid;
  y0 = std::floor(y0 / grid) * grid - grid, y1 = std::ceil(y1 / grid) * grid + grid;
  const double scale = 700.0 / std::max(x1 - x0, y1 - y0);  // px per mm
  const double left = 70.0, top = 50.0;
  const double width = (x1 - x0) * scale, height = (y1 - y0) * scale;
  const auto px = [&](double x) { return left + (x - x0) * scale; };
  const auto py = [&](double y) { return top + (y1 - y) * scale; };
  char buf[512];
  std::string out;
  std::snprintf(buf, sizeof buf,
                "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" "
                "viewBox=\"0 0 %.0f %.0f\" font-family=\"sans-serif\" font-size=\"12\">\n"
                "<rect x=\"0\" y=\"0\" width=\"%.0f\" height=\"%.0f\" fill=\"white\"/>\n",
                left + width + 230.0, top + height + 50.0, left + width + 230.0,
                top + height + 50.0, left + width + 230.0, top + height + 50.0);
  out += buf;
  std::snprintf(buf, sizeof buf, "<text x=\"%.1f\" y=\"25\" font-size=\"14\">", left);
  out += buf;
  for (char c : title) {
    if (c == '<')
      out += "&lt;";
    else if (c == '>')
      out += "&gt;";
    else if (c == '&')
      out += "&amp;";
    else
      out += c;
  }
  out += "</text>\n<g id=\"grid\" stroke=\"#dddddd\" stroke-width=\"1\">\n";
  for (double x = x0; x <= x1 + 1e-9; x += grid) {
    std::snprintf(buf, sizeof buf,
                  "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\"/>"
                  "<text x=\"%.2f\" y=\"%.2f\" fill=\"#333333\" stroke=\"none\" "
                  "text-anchor=\"middle\">%.0f</text>\n",
                  px(x), top, px(x), top + height, px(x), top + height + 16.0, x);
    out += buf;
  }
  for (double y = y0; y <= y1 + 1e-9; y += grid) {
    std::snprintf(buf, sizeof buf,
                  "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\"/>"
                  "<text x=\"%.2f\" y=\"%.2f\" fill=\"#333333\" stroke=\"none\" "
                  "text-anchor=\"end\">%.0f</text>\n",
                  left, py(y), left + width, py(y), left - 6.0, py(y) + 4.0, y);
    out += buf;
  }
  std::snprintf(buf, sizeof buf,
                "</g>\n<text x=\"%.2f\" y=\"%.2f\" text-anchor=\"middle\">x [mm]</text>\n"
                "<text x=\"18\" y=\"%.2f\" transform=\"rotate(-90 18 %.2f)\" "
                "text-anchor=\"middle\">y [mm]</text>\n",
                left + width / 2.0, top + height + 36.0, top + height / 2.0, top + height / 2.0);
  out += buf;
  out +=
      "<g id=\"linkage\" stroke=\"#999999\" stroke-width=\"6\" stroke-linecap=\"round\" "
      "fill=\"white\">\n";
  for (const Eigen::Vector2d& q : poses) {
    const Eigen::Vector2d elbow{linkage.l1 * std::cos(q.x() / kDegPerRad),
                                linkage.l1 * std::sin(q.x() / kDegPerRad)};
    const Eigen::Vector2d tool = forward(linkage, q);
    std::snprintf(buf, sizeof buf,
                  "<polyline points=\"%.2f,%.2f %.2f,%.2f %.2f,%.2f\" fill=\"none\" "
                  "opacity=\"0.6\"/><circle cx=\"%.2f\" cy=\"%.2f\" r=\"5\" stroke-width=\"2\"/>"
                  "<circle cx=\"%.2f\" cy=\"%.2f\" r=\"5\" stroke-width=\"2\"/>\n",
                  px(0.0), py(0.0), px(elbow.x()), py(elbow.y()), px(tool.x()), py(tool.y()),
                  px(0.0), py(0.0), px(elbow.x()), py(elbow.y()));
    out += buf;
  }
  out += "</g>\n";
  for (std::size_t k = 0; k < series.size(); ++k) {
    const XySeries& s = series[k];
    std::snprintf(buf, sizeof buf,
                  "<polyline id=\"series-%zu\" fill=\"none\" stroke=\"%s\" stroke-width=\"%.1f\"%s "
                  "points=\"",
                  k, s.colour.c_str(), s.width, s.dashed ? " stroke-dasharray=\"8 5\"" : "");
    out += buf;
    // Points closer than 0.3 px to the last one drawn add nothing but bytes (the last is kept).
    double last_x = -1e9, last_y = -1e9;
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) continue;
      const double x = px(s.x[i]), y = py(s.y[i]);
      if (std::hypot(x - last_x, y - last_y) < 0.3 && i + 1 != s.x.size()) continue;
      std::snprintf(buf, sizeof buf, "%.2f,%.2f ", x, y);
      out += buf;
      last_x = x, last_y = y;
    }
    out += "\"/>\n";
    const double ly = top + 20.0 + 22.0 * static_cast<double>(k);
    std::snprintf(buf, sizeof buf,
                  "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\" stroke=\"%s\" "
                  "stroke-width=\"3\"%s/><text x=\"%.2f\" y=\"%.2f\">",
                  left + width + 20.0, ly, left + width + 50.0, ly, s.colour.c_str(),
                  s.dashed ? " stroke-dasharray=\"8 5\"" : "", left + width + 58.0, ly + 4.0);
    out += buf;
    out += s.label;
    out += "</text>\n";
  }
  out += "</svg>\n";
  return out;
}

class TwoBarLinkageSample {
 public:
  // Set-up: kernel, the two joint axes, tasks and scope (throws on a bad option).
  explicit TwoBarLinkageSample(const Options& options = {})
      : kernel_(nc::KernelConfig{options.nc_cycle}),
        joint1_(kernel_.add_axis(joint_axis_config("Joint1"))),
        joint2_(kernel_.add_axis(joint_axis_config("Joint2"))),
        driver_(kernel_),
        scope_(sample_common::scope_capacity(options)),
        options_(options) {
    main_.cycle_time = options.nc_cycle;
    for (const auto& [axis, name] :
         {std::pair{&joint1_, "Joint1"}, std::pair{&joint2_, "Joint2"}}) {
      scope_.add_signal(*axis, name, nc::Signal::kSetPos);
      scope_.add_signal(*axis, name, nc::Signal::kActPos);
      scope_.add_signal(*axis, name, nc::Signal::kSetVelo);
      scope_.add_signal(*axis, name, nc::Signal::kActVelo);
      scope_.add_signal(*axis, name, nc::Signal::kPosDiff);
    }
    scope_.add_variable(&tool_set_.x(), "Tool.SetX", "mm");
    scope_.add_variable(&tool_set_.y(), "Tool.SetY", "mm");
    scope_.add_variable(&tool_act_.x(), "Tool.ActX", "mm");
    scope_.add_variable(&tool_act_.y(), "Tool.ActY", "mm");
    scope_.add_variable(&deviation_set_, "Tool.SetDeviation", "mm");
    scope_.add_variable(&deviation_act_, "Tool.ActDeviation", "mm");
    scope_.add_variable(&on_line_, "MAIN.OnLine", "");
    scope_.add_variable(&main_.PathS, "MAIN.PathS", "mm");
    driver_.add_task("Scope", options.nc_cycle, [this] { sample(); });
    driver_.add_task("PlcTask", options.nc_cycle, [this] { plc_cycle(); });
  }

  TwoBarLinkageSample(const TwoBarLinkageSample&) = delete;
  TwoBarLinkageSample& operator=(const TwoBarLinkageSample&) = delete;

  const Report& run() {
    report_.finished =
        sample_common::run_to_state(driver_, main_.state, LinkState::STATE_FINISHED,
                                    LinkState::STATE_ERROR, options_.timeout, options_.settle_time);
    sample();
    report_.error_id = main_.error_id;
    report_.line_duration = main_.path.duration();
    report_.final_set_tool = tool_set_;
    report_.final_act_tool = tool_act_;
    report_.final_in_target =
        plc::test_bit(joint1_.NcToPlc.StateDWord, plc::kStateInTargetPosition) &&
        plc::test_bit(joint2_.NcToPlc.StateDWord, plc::kStateInTargetPosition);
    report_.final_enabled =
        plc::test_bit(joint1_.NcToPlc.StateDWord, plc::kStateExtSetPointGenEnabled) ||
        plc::test_bit(joint2_.NcToPlc.StateDWord, plc::kStateExtSetPointGenEnabled);
    report_.axis_error =
        joint1_.NcToPlc.ErrorCode != 0 ? joint1_.NcToPlc.ErrorCode : joint2_.NcToPlc.ErrorCode;
    report_.end_time = kernel_.time();
    return report_;
  }

  // After-run: <dir>/two_bar_linkage.csv, two_bar_linkage_path.svg (the tool path, x–y) and
  // two_bar_linkage_joints.svg (joint angles, velocities and the distance from the line over
  // time). Returns the three paths.
  std::array<std::filesystem::path, 3> write(const std::filesystem::path& dir) const {
    const auto csv = dir / "two_bar_linkage.csv";
    const auto path_svg = dir / "two_bar_linkage_path.svg";
    const auto joints_svg = dir / "two_bar_linkage_joints.svg";
    scope_.write_csv(csv);
    const auto v = [this](const char* name) { return scope_.values(scope_.find(name)); };
    const std::array<double, 2> line_x{kLineStart.x(), kLineGoal.x()};
    const std::array<double, 2> line_y{kLineStart.y(), kLineGoal.y()};
    const std::vector<XySeries> series{
        {"planned line", "#e6c200", line_x, line_y, 5.0, false},
        {"tool from actual angles", std::string(nc::plot_colour::kActualPosition), v("Tool.ActX"),
         v("Tool.ActY"), 2.0, false},
        {"tool from set angles", std::string(nc::plot_colour::kSetPosition), v("Tool.SetX"),
         v("Tool.SetY"), 1.0, true},
    };
    const JointState middle = [this] {
      JointState m;
      inverse(main_.linkage, 0.5 * (kLineStart + kLineGoal), Eigen::Vector2d::Zero(),
              Eigen::Vector2d::Zero(), m);
      return m;
    }();
    nc::write_svg(
        path_svg,
        xy_svg("Two-bar linkage (400 mm + 300 mm), tool path: PTP to the start pose, "
               "then the straight line by external setpoints",
               series, main_.linkage,
               {Eigen::Vector2d::Zero(), main_.start_pose.q, middle.q, main_.goal_pose.q}));
    // The distance from the line only where the line is fed (the PTP approach is far off it).
    const auto on_line = v("MAIN.OnLine");
    const auto line_only = [&](const char* name) {
      std::vector<double> out(on_line.size(), std::nan(""));
      const auto values = v(name);
      for (std::size_t i = 0; i < out.size(); ++i) {
        if (on_line[i] != 0.0) out[i] = values[i];
      }
      return out;
    };
    const std::vector<double> deviation_set = line_only("Tool.SetDeviation");
    const std::vector<double> deviation_act = line_only("Tool.ActDeviation");
    const std::vector<nc::PlotPanel> panels{
        {"panel-joint-angles",
         "Joint angles",
         "\u00b0",
         {{"Joint1.ActPos", std::string(nc::plot_colour::kActualPosition), v("Joint1.ActPos"), 3.0},
          {"Joint1.SetPos", std::string(nc::plot_colour::kSetPosition), v("Joint1.SetPos"), 1.0},
          {"Joint2.ActPos", std::string(nc::plot_colour::kActualAcceleration), v("Joint2.ActPos"),
           3.0},
          {"Joint2.SetPos", std::string(nc::plot_colour::kSetAcceleration), v("Joint2.SetPos"),
           1.0}}},
        {"panel-joint-velocities",
         "Joint velocities",
         "\u00b0/s",
         {{"Joint1.ActVelo", std::string(nc::plot_colour::kActualPosition), v("Joint1.ActVelo"),
           3.0},
          {"Joint1.SetVelo", std::string(nc::plot_colour::kSetPosition), v("Joint1.SetVelo"), 1.0},
          {"Joint2.ActVelo", std::string(nc::plot_colour::kActualAcceleration), v("Joint2.ActVelo"),
           3.0},
          {"Joint2.SetVelo", std::string(nc::plot_colour::kSetAcceleration), v("Joint2.SetVelo"),
           1.0}}},
        {"panel-path",
         "Path parameter along the line",
         "mm",
         {{"MAIN.PathS", std::string(nc::plot_colour::kSetVelocity), v("MAIN.PathS")}}},
        {"panel-line-deviation",
         "Tool distance from the line (while the line is fed)",
         "mm",
         {{"from actual angles", std::string(nc::plot_colour::kActualPosition), deviation_act},
          {"from set angles", std::string(nc::plot_colour::kSetPosition), deviation_set}}},
    };
    nc::write_svg(joints_svg, nc::svg_plot(scope_.time(), panels,
                                           {"Two-bar linkage: joint axes fed by external "
                                            "setpoints (seed 000 \u00a72.6)",
                                            1000, 150}));
    return {csv, path_svg, joints_svg};
  }

  std::string summary() const {
    char text[1400];
    std::snprintf(
        text, sizeof text,
        "Two-bar linkage (seed 000 2.6, coordinate transformation): %s\n"
        "  links 400 mm + 300 mm; line (%.0f, %.0f) -> (%.0f, %.0f) mm, %.3f mm long\n"
        "  start pose q1 %.4f deg, q2 %.4f deg; goal pose q1 %.4f deg, q2 %.4f deg\n"
        "  line fed %.3f..%.3f s (path profile %.3f s, max tool speed %.3f mm/s); "
        "elbow up to %.3f deg\n"
        "  max distance from the line: set %.3g mm, actual %.4f mm\n"
        "  max |SetPos - FedPos| over taken packets %.3g deg; max following error %.4f / "
        "%.4f deg\n"
        "  end: tool from set angles (%.6f, %.6f) mm, from actual angles (%.4f, %.4f) mm, "
        "InTargetPosition %s, enabled %s\n"
        "  samples recorded %zu (%zu dropped), simulated %.3f s\n",
        report_.ok() ? "the tool drew the straight line" : "FAILED", kLineStart.x(), kLineStart.y(),
        kLineGoal.x(), kLineGoal.y(), (kLineGoal - kLineStart).norm(), main_.start_pose.q.x(),
        main_.start_pose.q.y(), main_.goal_pose.q.x(), main_.goal_pose.q.y(),
        report_.line_start_time, report_.line_end_time, report_.line_duration,
        report_.max_tool_speed, report_.joint2_max, report_.max_set_deviation,
        report_.max_act_deviation, report_.max_set_minus_fed, report_.max_following_error[0],
        report_.max_following_error[1], report_.final_set_tool.x(), report_.final_set_tool.y(),
        report_.final_act_tool.x(), report_.final_act_tool.y(),
        report_.final_in_target ? "yes" : "no", report_.final_enabled ? "yes" : "no", scope_.size(),
        scope_.dropped(), report_.end_time);
    std::string out = text;
    if (report_.error_id != 0 || report_.axis_error != 0) {
      out += sample_common::error_line("program", report_.error_id, report_.axis_error,
                                       state_name(main_.state));
    }
    return out;
  }

  const nc::Scope& scope() const noexcept { return scope_; }
  const Main& program() const noexcept { return main_; }
  const nc::Kernel& kernel() const noexcept { return kernel_; }
  const plc::AXIS_REF& joint(std::size_t i) const noexcept { return i == 0 ? joint1_ : joint2_; }

 private:
  // Scope task: the tool point of the last NC cycle's set and actual joint angles, beside the
  // packets the PLC fed for that cycle.
  void sample() noexcept {
    const Linkage& k = main_.linkage;
    tool_set_ = forward(k, {joint1_.NcToPlc.SetPos, joint2_.NcToPlc.SetPos});
    tool_act_ = forward(k, {joint1_.NcToPlc.ActPos, joint2_.NcToPlc.ActPos});
    deviation_set_ = line_deviation(tool_set_);
    deviation_act_ = line_deviation(tool_act_);
    on_line_ = fed_on_line_ ? 1.0 : 0.0;
    scope_.record(kernel_.time());
    if (fed_on_line_) {
      report_.max_set_deviation = std::max(report_.max_set_deviation, std::fabs(deviation_set_));
      report_.max_act_deviation = std::max(report_.max_act_deviation, std::fabs(deviation_act_));
      report_.joint2_max = std::max(report_.joint2_max, joint2_.NcToPlc.SetPos);
      const Eigen::Vector2d tool_velo =
          jacobian(k, {joint1_.NcToPlc.SetPos, joint2_.NcToPlc.SetPos}) *
          Eigen::Vector2d{joint1_.NcToPlc.SetVelo, joint2_.NcToPlc.SetVelo} / kDegPerRad;
      report_.max_tool_speed = std::max(report_.max_tool_speed, tool_velo.norm());
      for (std::size_t i = 0; i < 2; ++i) {
        const plc::AXIS_REF& axis = joint(i);
        report_.max_set_minus_fed =
            std::max(report_.max_set_minus_fed, std::fabs(axis.NcToPlc.SetPos - fed_pos_[i]));
      }
    }
    for (std::size_t i = 0; i < 2; ++i) {
      sample_common::track_max(report_.max_following_error[i], joint(i).NcToPlc.PosDiff);
    }
  }

  void plc_cycle() noexcept {
    main_(joint1_, joint2_);
    const double now = kernel_.time();
    fed_on_line_ = main_.joints[0].FedDirection != 0.0;
    if (fed_on_line_) {
      if (report_.line_start_time < 0.0) report_.line_start_time = now;
      report_.line_end_time = now;
    }
    for (std::size_t i = 0; i < 2; ++i)
      fed_pos_[i] = main_.joints[i].FedPos;
  }

  nc::Kernel kernel_;
  plc::AXIS_REF& joint1_;
  plc::AXIS_REF& joint2_;
  nc::CycleDriver driver_;
  nc::Scope scope_;
  Options options_;
  Main main_;
  Report report_;
  Eigen::Vector2d tool_set_ = Eigen::Vector2d::Zero();
  Eigen::Vector2d tool_act_ = Eigen::Vector2d::Zero();
  double deviation_set_ = 0.0, deviation_act_ = 0.0, on_line_ = 0.0;
  bool fed_on_line_ = false;
  std::array<double, 2> fed_pos_{};
};

}  // namespace two_bar_linkage
