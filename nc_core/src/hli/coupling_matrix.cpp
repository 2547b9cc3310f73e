// CouplingMatrix (coupling_matrix.hpp): growing, applying and rewriting the HLI coupling matrix.
#include "hli/coupling_matrix.hpp"

#include <algorithm>

namespace nc::hli {

namespace {

Eigen::Index ix(std::size_t i) noexcept {
  return static_cast<Eigen::Index>(i);
}

}  // namespace

void CouplingMatrix::reserve(std::size_t axes) {
  rows_.reserve(axes);
  row_of_.reserve(axes);
  grow(axes);
}

void CouplingMatrix::add_axis(std::size_t axes) {
  // What the cycle pushes into must hold `axes` rows without reallocating (at least doubling, so
  // that adding axes one by one copies the storage only O(log n) times).
  if (rows_.capacity() < axes) rows_.reserve(std::max(axes, 2 * rows_.capacity()));
  grow(axes);
  row_of_.push_back(kNoRow);
  product_.conservativeResize(ix(axes));
  product_(ix(axes - 1)) = 0.0;
}

// Square at a capacity that grows by doubling (or to a reserve); the part beyond the axes in use
// is zero.
void CouplingMatrix::grow(std::size_t axes) {
  if (axes <= static_cast<std::size_t>(k_.rows())) return;
  const auto capacity = ix(std::max(axes, 2 * static_cast<std::size_t>(k_.rows())));
  k_.conservativeResizeLike(Matrix::Zero(capacity, capacity));
}

void CouplingMatrix::apply(Eigen::Index m, const Eigen::VectorXd& q, const Eigen::VectorXd& qv,
                           const Eigen::VectorXd& qa, const Eigen::VectorXd& c, Eigen::VectorXd& d,
                           Eigen::VectorXd& dv, Eigen::VectorXd& da) noexcept {
  const Eigen::Index rows = ix(rows_.size());
  if (rows == 0) return;
  const auto k = k_.topLeftCorner(rows, m);
  product_.head(rows).noalias() = k * q;
  for (std::size_t j = 0; j < rows_.size(); ++j)
    d(ix(rows_[j])) = product_(ix(j)) + c(ix(rows_[j]));
  product_.head(rows).noalias() = k * qv;
  for (std::size_t j = 0; j < rows_.size(); ++j)
    dv(ix(rows_[j])) = product_(ix(j));
  product_.head(rows).noalias() = k * qa;
  for (std::size_t j = 0; j < rows_.size(); ++j)
    da(ix(rows_[j])) = product_(ix(j));
}

void CouplingMatrix::drop_row(std::size_t axis) noexcept {
  const std::size_t j = row_of_[axis];
  if (j == kNoRow) return;
  const std::size_t last = rows_.size() - 1;
  if (j != last) {
    k_.row(ix(j)) = k_.row(ix(last));
    k_.row(ix(last)).setZero();
    rows_[j] = rows_[last];
    row_of_[rows_[j]] = j;
  }
  rows_.pop_back();
  row_of_[axis] = kNoRow;
}

}  // namespace nc::hli
