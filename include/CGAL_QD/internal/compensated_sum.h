// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_INTERNAL_COMPENSATED_SUM_H
#define CGAL_QD_INTERNAL_COMPENSATED_SUM_H

// A sum with the rounding error of each addition carried along (Neumaier's
// variant of Kahan summation). The LPFB's angle sum of a border of n corners
// is about n pi; summed plainly, its rounding error grows with n and reaches
// the constraint tolerance on long borders: a solution found from another
// first corner (Lpfb_solver::solve()) could fail the check made in the order
// of corner 0 (1.4e-11 against 1e-11 on a merging trial of 1,763 corners).

#include <cmath>

namespace CGAL_QD {
namespace internal {

struct Compensated_sum
{
  double sum = 0, error = 0;
  void add(double x)
  {
    const double t = sum + x;
    error += std::abs(sum) >= std::abs(x) ? (sum - t) + x : (x - t) + sum;
    sum = t;
  }
  double value() const { return sum + error; }
};

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_INTERNAL_COMPENSATED_SUM_H
