// Kinematics of a planar two-bar linkage (seed 000 §2.6: "coordinate transformations … e.g.
// geometries like a 'two-bar linkage'"), written with Eigen.
//
// Joint 1 turns the first link (length l1) about the base, joint 2 the second link (l2) about
// the end of the first; joint angles in degrees (the joint axes' unit), the tool point in mm.
// The inverse solution takes the branch with a positive elbow angle (0 < q2 < 180°), which is
// regular and unique as long as the tool stays strictly between the inner (|l1 - l2|) and the
// outer (l1 + l2) reach — the restriction the seed puts on such transformations.
// Fixed-size Eigen types only: every function is a cycle function (noexcept, no allocation).
#pragma once

#include <cmath>
#include <numbers>

#include <Eigen/Dense>

namespace two_bar_linkage {

inline constexpr double kDegPerRad = 180.0 / std::numbers::pi;

struct Linkage {
  double l1 = 400.0;  // mm, base → elbow
  double l2 = 300.0;  // mm, elbow → tool
};

// Joint angles, their velocities and accelerations (°, °/s, °/s²).
struct JointState {
  Eigen::Vector2d q = Eigen::Vector2d::Zero();
  Eigen::Vector2d qd = Eigen::Vector2d::Zero();
  Eigen::Vector2d qdd = Eigen::Vector2d::Zero();
};

// Tool point of the joint angles `q` (°).
inline Eigen::Vector2d forward(const Linkage& k, const Eigen::Vector2d& q) noexcept {
  const double a1 = q.x() / kDegPerRad;
  const double a12 = (q.x() + q.y()) / kDegPerRad;
  return {k.l1 * std::cos(a1) + k.l2 * std::cos(a12), k.l1 * std::sin(a1) + k.l2 * std::sin(a12)};
}

// d(tool) / d(q) in mm per radian.
inline Eigen::Matrix2d jacobian(const Linkage& k, const Eigen::Vector2d& q) noexcept {
  const double a1 = q.x() / kDegPerRad;
  const double a12 = (q.x() + q.y()) / kDegPerRad;
  Eigen::Matrix2d j;
  j << -k.l1 * std::sin(a1) - k.l2 * std::sin(a12), -k.l2 * std::sin(a12),
      k.l1 * std::cos(a1) + k.l2 * std::cos(a12), k.l2 * std::cos(a12);
  return j;
}

// Joint angles, velocities and accelerations that put the tool at `x` with velocity `xd` and
// acceleration `xdd` (mm, mm/s, mm/s²). False (and `out` untouched) when `x` is not strictly
// inside the reachable ring, where the linkage would be singular.
inline bool inverse(const Linkage& k, const Eigen::Vector2d& x, const Eigen::Vector2d& xd,
                    const Eigen::Vector2d& xdd, JointState& out) noexcept {
  const double c2 = (x.squaredNorm() - k.l1 * k.l1 - k.l2 * k.l2) / (2.0 * k.l1 * k.l2);
  if (!(std::fabs(c2) < 1.0)) return false;
  const double a2 = std::acos(c2);  // the positive elbow branch
  const double a1 = std::atan2(x.y(), x.x()) - std::atan2(k.l2 * std::sin(a2), k.l1 + k.l2 * c2);
  const Eigen::Vector2d q{a1 * kDegPerRad, a2 * kDegPerRad};
  // Velocities: J q̇ = ẋ. Accelerations: J q̈ = ẍ - J̇ q̇, J̇ q̇ being the centripetal terms.
  const Eigen::Matrix2d j = jacobian(k, q);
  const Eigen::Vector2d qd = j.partialPivLu().solve(xd);  // rad/s
  const double w1 = qd.x();
  const double w12 = qd.x() + qd.y();
  const Eigen::Vector2d centripetal{
      -k.l1 * std::cos(a1) * w1 * w1 - k.l2 * std::cos(a1 + a2) * w12 * w12,
      -k.l1 * std::sin(a1) * w1 * w1 - k.l2 * std::sin(a1 + a2) * w12 * w12};
  const Eigen::Vector2d qdd = j.partialPivLu().solve(xdd - centripetal);  // rad/s²
  out.q = q;
  out.qd = qd * kDegPerRad;
  out.qdd = qdd * kDegPerRad;
  return true;
}

}  // namespace two_bar_linkage
