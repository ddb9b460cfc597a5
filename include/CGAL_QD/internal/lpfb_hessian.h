// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_INTERNAL_LPFB_HESSIAN_H
#define CGAL_QD_INTERNAL_LPFB_HESSIAN_H

// The Hessian of the Lagrangian of the LPFB problem (internal/lpfb_solver.h),
// shifted by tau: H = (1 + tau) I + U D U^T, with U_im = [i <= m] (every edge
// direction depends on a prefix of the angles) and D diagonal. With
// B = U^{-1} (1 on the diagonal, -1 above it), H = U T U^T where
// T = (1 + tau) B B^T + D is tridiagonal, so H^{-1} v = B^T T^{-1} B v costs
// O(n), and T, congruent to H, has H's number of negative eigenvalues.

#include <Eigen/Dense>

#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL_QD {
namespace internal {

class Nested_rank_one_hessian
{
public:
  // LDL^T of T (B B^T has diagonal 2, ..., 2, 1 and off-diagonal -1), counting
  // its negative pivots; false if a pivot is nearly zero
  bool factor(const std::vector<double>& diagonal, double tau, std::size_t& negative_pivots)
  {
    diagonal_ = diagonal;
    tau_ = tau;
    const std::size_t n = diagonal_.size();
    negative_pivots = 0;
    pivot_.assign(n, 0.);
    multiplier_.assign(n, 0.);
    const double s = 1. + tau_;
    for(std::size_t i = 0; i < n; ++i) {
      const double diag = s * (i + 1 < n ? 2. : 1.) + diagonal_[i];
      const double off = -s;  // T(i, i-1)
      const double p = (i == 0) ? diag : diag - multiplier_[i] * multiplier_[i] * pivot_[i - 1];
      if(!(std::abs(p) > 1e-12 * s)) return false;
      if(p < 0) ++negative_pivots;
      pivot_[i] = p;
      if(i + 1 < n) multiplier_[i + 1] = off / p;
    }
    return true;
  }

  // H^{-1} v, after a successful factor()
  Eigen::VectorXd solve(const Eigen::VectorXd& v) const
  {
    const std::size_t n = pivot_.size();
    Eigen::VectorXd y(n);
    for(std::size_t i = 0; i < n; ++i) y[i] = v[i] - (i + 1 < n ? v[i + 1] : 0.);  // B v
    for(std::size_t i = 1; i < n; ++i) y[i] -= multiplier_[i] * y[i - 1];        // L^{-1}
    for(std::size_t i = 0; i < n; ++i) y[i] /= pivot_[i];                        // D^{-1}
    for(std::size_t i = n - 1; i-- > 0;) y[i] -= multiplier_[i + 1] * y[i + 1];  // L^{-T}
    Eigen::VectorXd x(n);
    for(std::size_t i = 0; i < n; ++i) x[i] = y[i] - (i > 0 ? y[i - 1] : 0.);    // B^T y
    return x;
  }

  // d^T H d for the diagonal and tau of the last factor()
  double dot(const std::vector<double>& d) const
  {
    double h = 0, prefix = 0;
    for(std::size_t m = 0; m < diagonal_.size(); ++m) {
      prefix += d[m];
      h += (1. + tau_) * d[m] * d[m] + diagonal_[m] * prefix * prefix;
    }
    return h;
  }

private:
  std::vector<double> diagonal_, pivot_, multiplier_;
  double tau_ = 0;
};

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_INTERNAL_LPFB_HESSIAN_H
