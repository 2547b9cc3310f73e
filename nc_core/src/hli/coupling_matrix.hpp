// The HLI stage's coupling matrix (SPEC D3): d = K·q + c over all axes, Eigen, dense, row-major.
// Only the targets' rows are stored, packed at the top, so one cycle costs (number of targets) ×
// (number of axes); an axis without a row has the unit row (d = q + c, not stored). The matrix is
// kept square at a capacity that grows by doubling, zero beyond the stored rows and the axes in
// use, so a row is written without touching the other axes' columns.
// Set-up (reserve, add_axis) may allocate; everything else is noexcept and allocates nothing.
#pragma once

#include <cstddef>
#include <vector>

#include <Eigen/Core>

namespace nc::hli {

class CouplingMatrix {
 public:
  static constexpr std::size_t kNoRow = static_cast<std::size_t>(-1);

  // Set-up: room for `axes` axes (rows and columns) without reallocating later.
  void reserve(std::size_t axes);
  // Set-up: `axes` axes in all now; the new one has no row and a zero column.
  void add_axis(std::size_t axes);

  // The stored rows applied to the program state of `m` axes: d = K·q + c, dv = K·qv, da = K·qa
  // for every axis with a row; the others are left as they are.
  void apply(Eigen::Index m, const Eigen::VectorXd& q, const Eigen::VectorXd& qv,
             const Eigen::VectorXd& qa, const Eigen::VectorXd& c, Eigen::VectorXd& d,
             Eigen::VectorXd& dv, Eigen::VectorXd& da) noexcept;
  // The target's row over the first `axes` columns, zeroed (over the whole capacity) and stored
  // when it had none; the caller adds its factors.
  auto new_row(std::size_t target, std::size_t axes) noexcept {
    if (row_of_[target] == kNoRow) {
      row_of_[target] = rows_.size();
      rows_.push_back(target);  // within the reserve: one row per axis at most
    }
    const auto r = static_cast<Eigen::Index>(row_of_[target]);
    k_.row(r).setZero();  // the whole capacity: unused columns stay zero
    return k_.row(r).head(static_cast<Eigen::Index>(axes));
  }
  // Removes the axis's row (no-op without one); the last stored row takes its place.
  void drop_row(std::size_t axis) noexcept;
  bool has_row(std::size_t axis) const noexcept { return row_of_[axis] != kNoRow; }
  // K(target, source) of a target with a row.
  double at(std::size_t target, std::size_t source) const noexcept {
    return k_(static_cast<Eigen::Index>(row_of_[target]), static_cast<Eigen::Index>(source));
  }

 private:
  using Matrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  void grow(std::size_t axes);

  Matrix k_;                         // row j: the row of target rows_[j], column = source
  std::vector<std::size_t> rows_;    // targets in row order (reserved in add_axis)
  std::vector<std::size_t> row_of_;  // axis → its row, kNoRow when it has none
  Eigen::VectorXd product_;          // K·x of the stored rows (scratch, sized in add_axis)
};

}  // namespace nc::hli
