// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_INTERNAL_LPFB_PROBLEM_H
#define CGAL_QD_INTERNAL_LPFB_PROBLEM_H

// What the angle-space solver of the length-preserved free boundary
// (internal/lpfb_solver.h) is given and gives back: the loop of corners with
// their target angles, edge lengths and constraint groups, the options of the
// iteration, and the solution.

#include <CGAL_QD/internal/constants.h>

#include <array>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL_QD {
namespace internal {

struct Lpfb_problem
{
  std::vector<double> target_angle;  // a_i, one per corner
  std::vector<double> edge_length;   // l_i, edge i from corner i to corner i+1
  std::vector<int> edge_loop;        // original loop of edge i, -1 for a cut edge
  std::vector<int> corner_group;     // group of corner i
  std::vector<double> group_sum;     // t_g
  int number_of_loops = 1;
};

struct Lpfb_options
{
  std::size_t max_iterations = 200;
  double constraint_tolerance = 1e-11;  // on closure rows divided by loop length
  double angle_tolerance = 1e-9;        // radians
  bool line_search = true;
  // identity-Hessian steps converge linearly, slowly where the multipliers are
  // large (strongly curved borders); from this iteration on the steps use the
  // Hessian of the Lagrangian (Newton SQP; with line search only)
  std::size_t newton_after = 20;
  // Far from a solution (a loop whose 3D shape turns much less than the plane
  // needs, such as a tube's rim) the linearised closure can ask for steps of
  // hundreds of radians, after which the iteration wanders among windings of
  // the border. An iteration that reaches the limit is therefore run again
  // from the start with no angle changing by more than `retry_max_step` (in
  // radians) in one step, twice: with the merit's penalty weight set for the
  // whole step, then for the shortened one. Bounding the steps from the start
  // would fail where the angle-sum constraints themselves need large changes.
  double max_step = std::numeric_limits<double>::infinity();
  double retry_max_step = pi / 2;
  // an iteration that still does not converge is started again from another
  // first corner (see Lpfb_solver::solve(); with line search only)
  bool restart_from_other_corners = true;
};

// The same problem with corner `first` as corner 0
inline Lpfb_problem rotate_corner_order(const Lpfb_problem& pb, std::size_t first)
{
  const std::size_t n = pb.target_angle.size();
  Lpfb_problem rotated = pb;
  for(std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + first) % n;
    rotated.target_angle[i] = pb.target_angle[j];
    rotated.edge_length[i] = pb.edge_length[j];
    rotated.edge_loop[i] = pb.edge_loop[j];
    rotated.corner_group[i] = pb.corner_group[j];
  }
  return rotated;
}

enum class Lpfb_status { CONVERGED, NOT_CONVERGED, FAILED };

struct Lpfb_solution
{
  Lpfb_status status = Lpfb_status::FAILED;
  std::vector<double> theta;
  std::vector<std::array<double, 2>> position;  // per corner, corner 0 at the origin
  std::size_t iterations = 0;
  std::size_t backtracking_steps = 0;
  double constraint_residual = 0;  // max |c|, closure rows relative to loop length
  double objective = 0;            // 1/2 sum (theta - a)^2
};

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_INTERNAL_LPFB_PROBLEM_H
