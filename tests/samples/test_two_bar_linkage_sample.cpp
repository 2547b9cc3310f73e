// The two-bar linkage sample (seed 000 §2.6, coordinate transformation): the PLC plans a
// straight line of the tool point, the inverse kinematics turn it into joint setpoints fed
// through external setpoint generation, and the tool stays on the line — to 1e-6 mm computed
// from the set joint angles (the axes take the fed angles exactly), to 0.05 mm from the actual
// ones (the simulated servo loop lags) — and ends at the goal with both joints in their target
// windows.
#include <cmath>
#include <filesystem>
#include <string>

#include <catch2/catch.hpp>

#include "../../samples/two_bar_linkage/two_bar_linkage_program.hpp"
#include "text_file.hpp"
#include "well_formed_xml.hpp"

namespace {

using ncsdk_test::read_text;

using two_bar_linkage::TwoBarLinkageSample;

}  // namespace

TEST_CASE("inverse and forward kinematics agree; velocities and accelerations match the tool's") {
  const two_bar_linkage::Linkage k;
  const Eigen::Vector2d u = (two_bar_linkage::kLineGoal - two_bar_linkage::kLineStart).normalized();
  for (double s = 0.0; s <= 721.0; s += 40.0) {
    CAPTURE(s);
    const Eigen::Vector2d x = two_bar_linkage::kLineStart + s * u;
    const Eigen::Vector2d xd = 250.0 * u;
    const Eigen::Vector2d xdd = -800.0 * u;
    two_bar_linkage::JointState j;
    REQUIRE(two_bar_linkage::inverse(k, x, xd, xdd, j));
    CHECK((two_bar_linkage::forward(k, j.q) - x).norm() < 1e-9);
    CHECK(j.q.y() > 0.0);  // the positive elbow branch
    // Finite differences of the joint trajectory through x(t) = x + xd t + xdd t²/2.
    const double h = 1e-4;
    two_bar_linkage::JointState a, b;
    REQUIRE(two_bar_linkage::inverse(k, x - h * xd + 0.5 * h * h * xdd, xd, xdd, a));
    REQUIRE(two_bar_linkage::inverse(k, x + h * xd + 0.5 * h * h * xdd, xd, xdd, b));
    const Eigen::Vector2d qd = (b.q - a.q) / (2.0 * h);
    const Eigen::Vector2d qdd = (b.q - 2.0 * j.q + a.q) / (h * h);
    CHECK((qd - j.qd).norm() < 1e-5);
    CHECK((qdd - j.qdd).norm() < 1e-2);
  }
  two_bar_linkage::JointState untouched;
  const Eigen::Vector2d zero = Eigen::Vector2d::Zero();
  CHECK_FALSE(two_bar_linkage::inverse(k, {750.0, 0.0}, zero, zero, untouched));  // out of reach
  CHECK_FALSE(two_bar_linkage::inverse(k, {50.0, 0.0}, zero, zero, untouched));   // in the hole
  CHECK(untouched.q.isZero());
}

TEST_CASE("the tool draws the straight line and ends at the goal") {
  TwoBarLinkageSample sample;
  const two_bar_linkage::Report& report = sample.run();
  INFO(sample.summary());
  REQUIRE(report.finished);
  CHECK(report.error_id == 0);
  CHECK(report.axis_error == 0);
  CHECK(report.max_set_deviation <= 1e-6);
  CHECK(report.max_act_deviation <= 0.05);
  CHECK(report.max_act_deviation > 0.0);  // the servo loop lags: actual values differ
  CHECK(report.max_set_minus_fed == 0.0);
  CHECK((report.final_set_tool - two_bar_linkage::kLineGoal).norm() <= 1e-9);
  CHECK((report.final_act_tool - two_bar_linkage::kLineGoal).norm() <= 0.05);
  CHECK(report.final_in_target);
  CHECK_FALSE(report.final_enabled);
  // The path parameter keeps to its limits: the tool never runs faster than 300 mm/s.
  CHECK(report.max_tool_speed <= 300.0 + 1e-6);
  CHECK(report.max_tool_speed >= 299.0);
  CHECK(report.ok());
}

TEST_CASE("the elbow opens past the goal angle and closes again: joint 2 reverses on the line") {
  TwoBarLinkageSample sample;
  const two_bar_linkage::Report& report = sample.run();
  REQUIRE(report.ok());
  // The line passes the base at 374.5 mm: elbow angle acos((374.5² - 400² - 300²) / 240000).
  const double closest = std::fabs(550.0 * 600.0 - 150.0 * 400.0) / std::hypot(400.0, 600.0);
  const double widest =
      std::acos((closest * closest - 400.0 * 400.0 - 300.0 * 300.0) / (2.0 * 400.0 * 300.0)) *
      two_bar_linkage::kDegPerRad;
  CHECK(report.joint2_max == Approx(widest).margin(1e-3));
  CHECK(report.joint2_max > sample.program().goal_pose.q.y() + 20.0);
  const nc::Scope& s = sample.scope();
  const auto velo = s.values(s.find("Joint2.SetVelo"));
  const auto on_line = s.values(s.find("MAIN.OnLine"));
  bool positive = false, negative_after = false;
  for (std::size_t i = 0; i < velo.size(); ++i) {
    if (on_line[i] == 0.0) continue;
    if (velo[i] > 1.0) positive = true;
    if (positive && velo[i] < -1.0) negative_after = true;
  }
  CHECK(positive);
  CHECK(negative_after);
}

TEST_CASE("the sample writes the trace, the x-y tool path and the joint plot, well-formed") {
  const auto dir = std::filesystem::temp_directory_path() / "ncsdk_test_two_bar_linkage";
  std::filesystem::remove_all(dir);
  TwoBarLinkageSample sample;
  REQUIRE(sample.run().ok());
  const auto files = sample.write(dir);
  const std::string csv = read_text(files[0]);
  CHECK(csv.find("Tool.ActX [mm]") != std::string::npos);
  const std::string path = read_text(files[1]);
  CHECK(ncsdk_test::xml_problem(path).empty());
  CHECK(path.find("tool from actual angles") != std::string::npos);
  const std::string joints = read_text(files[2]);
  CHECK(ncsdk_test::xml_problem(joints).empty());
  CHECK(joints.find("id=\"panel-line-deviation\"") != std::string::npos);
  std::filesystem::remove_all(dir);
}
