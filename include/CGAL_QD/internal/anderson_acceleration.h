// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_INTERNAL_ANDERSON_ACCELERATION_H
#define CGAL_QD_INTERNAL_ANDERSON_ACCELERATION_H

// Anderson acceleration of a fixed-point iteration x <- G(x) (Walker and Ni
// 2011; used for local/global geometry solvers by Peng et al. 2018): from the
// last m + 1 iterates x_j and their images g_j = G(x_j), with residuals
// f_j = g_j - x_j, the next iterate is
//
//   g_k - sum_j theta_j (g_{j+1} - g_j),
//
// theta minimising |f_k - sum_j theta_j (f_{j+1} - f_j)| in the least-squares
// sense. The caller keeps the iteration safe: it takes the accelerated point
// only where it is better than the plain one by its own measure, and resets
// the history otherwise.

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace CGAL_QD {
namespace internal {

class Anderson_acceleration
{
public:
  // `n` unknowns, a history of `m` differences (m >= 1)
  Anderson_acceleration(Eigen::Index n, Eigen::Index m) : m_dg(n, m), m_df(n, m), m_g(n), m_f(n), m_m(m) {}

  // forgets the history: the next call of `compute()` returns g
  void reset() { m_count = 0; }

  // Takes the iterate `x` and its image `g`; writes the next iterate to
  // `out` and returns whether it differs from g (false while the history is
  // empty or its least-squares problem cannot be solved).
  template <class X, class G, class Out>
  bool compute(const X& x, const G& g, Out& out)
  {
    if(m_count > 0) {
      // the differences with the previous pair, in the ring buffer
      const Eigen::Index c = (m_count - 1) % m_m;
      m_dg.col(c) = g - m_g;
      m_df.col(c) = (g - x) - m_f;
    }
    m_g = g;
    m_f = g - x;
    ++m_count;
    const Eigen::Index used = (std::min)(m_count - 1, m_m);
    out = g;
    if(used == 0) return false;
    const auto DF = m_df.leftCols(used);
    Eigen::MatrixXd normal = DF.transpose() * DF;
    const Eigen::VectorXd rhs = DF.transpose() * m_f;
    // a tiny Tikhonov term keeps nearly dependent differences solvable
    const double trace = normal.trace();
    if(!(trace > 0) || !std::isfinite(trace)) return false;
    normal.diagonal().array() += 1e-10 * trace / double(used);
    const Eigen::VectorXd theta = normal.ldlt().solve(rhs);
    if(!theta.allFinite()) return false;
    out.noalias() -= m_dg.leftCols(used) * theta;
    return true;
  }

private:
  Eigen::MatrixXd m_dg, m_df;  // differences of images and of residuals, columns in a ring
  Eigen::VectorXd m_g, m_f;    // the latest image and residual
  Eigen::Index m_m;
  Eigen::Index m_count = 0;  // pairs taken since the last reset
};

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_INTERNAL_ANDERSON_ACCELERATION_H
