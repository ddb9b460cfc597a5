// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_INTERNAL_LPFB_SOLVER_H
#define CGAL_QD_INTERNAL_LPFB_SOLVER_H

// Angle-space solver of the length-preserved free boundary (Wang, "Computing
// Length-Preserved Free Boundary for Quasi-Developable Mesh Segmentation",
// Sections 3.1-3.3). It works on one closed loop of "corners" (the border of the
// patch after virtual cutting), knows nothing about meshes, and is tested on
// its own.
//
// Unknowns: the planar inner angle theta_i at every corner i. Edge i runs from
// corner i to corner i+1 with fixed length l_i; its direction is
// phi_i = sum_{b<=i} (pi - theta_b), so every edge keeps its length by
// construction.
//
// Objective: 1/2 sum (theta_i - a_i)^2.
//
// Constraints, in a full-rank form equivalent to the paper's Eq. (10):
//  * linear "group" constraints with disjoint supports: sum_{i in g} theta_i = t_g.
//    One group per original border loop (total turning +2pi for the outer loop,
//    -2pi for a hole, i.e. t = (n_l -+ 2) pi with n_l counting the loop's original
//    vertices) and one group per interior vertex of the cut graph (its copies
//    fill a full turn, t = 2 pi).
//  * two closure rows per original loop l: sum_{k in E_l} l_k (cos, sin) phi_k = 0.
// Given the group constraints, the two copies of every cut edge are
// antiparallel, so closing each loop makes every pair of copies coincide; the
// paper's pair equations, whose Gram matrix is rank-deficient as soon as a cut
// path has an edge, are never formed.
//
// Step (sequential linearly constrained programming, identity Hessian): the
// minimum-norm correction delta = r - L^+(L r + c), r = a - theta. The group rows
// are handled exactly by the projector P that removes group means; only the 2K
// closure rows need a (rank-revealing) solve with S = N P N^T, K the number of
// loops. Steps are globalised by an l1 merit function with backtracking and a
// second-order correction at every step length tried; full steps are kept
// whenever they decrease the merit.

#include <CGAL_QD/internal/compensated_sum.h>
#include <CGAL_QD/internal/constants.h>
#include <CGAL_QD/internal/lpfb_hessian.h>
#include <CGAL_QD/internal/lpfb_problem.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numeric>
#include <vector>

namespace CGAL_QD {
namespace internal {

class Lpfb_solver
{
public:
  explicit Lpfb_solver(const Lpfb_problem& p) : pb_(p)
  {
    n_ = pb_.target_angle.size();
    K_ = pb_.number_of_loops;
    G_ = pb_.group_sum.size();
    loop_length_.assign(K_, 0.);
    for(std::size_t k = 0; k < n_; ++k)
      if(pb_.edge_loop[k] >= 0)
        loop_length_[pb_.edge_loop[k]] += pb_.edge_length[k];
    group_size_.assign(G_, 0.);
    for(std::size_t i = 0; i < n_; ++i)
      group_size_[pb_.corner_group[i]] += 1.;
    cos_.assign(n_, 0.);
    sin_.assign(n_, 0.);
    N_.resize(2 * K_, n_);
    NP_.resize(2 * K_, n_);
  }

  Lpfb_solution solve(const Lpfb_options& opt)
  {
    Lpfb_solution sol = solve_from_corner_0(opt);
    // The iteration's path depends on which corner comes first: the edge
    // directions are measured from edge 0's, and off the angle-sum constraints
    // the closure rows of two corner orders are different functions. For a few
    // orders (7 of the 5,845 rotations of 43 merging trials and patches
    // collected from the sweep) every run above wanders among windings of the
    // border until the iteration limit; started from the corner halfway round
    // (then a quarter, three quarters round), the same problem converges. The
    // angles are mapped back and laid out from corner 0 as usual.
    const std::size_t starts[] = {n_ / 2, n_ / 4, (3 * n_) / 4};
    for(std::size_t first : starts) {
      if(sol.status != Lpfb_status::NOT_CONVERGED || !opt.line_search || !opt.restart_from_other_corners) break;
      if(first == 0 || first >= n_) continue;
      const Lpfb_problem rotated = rotate_corner_order(pb_, first);
      const Lpfb_solution other = Lpfb_solver(rotated).solve_from_corner_0(opt);
      sol.iterations += other.iterations;
      sol.backtracking_steps += other.backtracking_steps;
      if(other.status != Lpfb_status::CONVERGED) continue;
      std::vector<double> theta(n_);
      for(std::size_t i = 0; i < n_; ++i) theta[(i + first) % n_] = other.theta[i];
      std::vector<double> c_lin(G_);
      Eigen::VectorXd c_N(2 * K_);
      evaluate(theta, c_lin, c_N);
      const double residual = violation_inf(c_lin, c_N);
      if(!(residual <= opt.constraint_tolerance)) continue;
      sol.status = Lpfb_status::CONVERGED;
      sol.constraint_residual = residual;
      sol.objective = objective(theta);
      sol.theta = theta;
      layout(theta, sol.position);
    }
    return sol;
  }

  const std::vector<double>& loop_lengths() const { return loop_length_; }

private:
  Lpfb_solution solve_from_corner_0(const Lpfb_options& opt)
  {
    Lpfb_solution sol = solve_once(opt, opt.max_step, false);
    // the bounded runs: the merit's penalty weight raised for the unbounded
    // step, then for the shortened one (which removes only part of the
    // violation: a larger weight, smaller steps)
    for(int run = 0; run < 2 && sol.status == Lpfb_status::NOT_CONVERGED && opt.line_search &&
                     opt.retry_max_step < opt.max_step;
        ++run) {
      Lpfb_solution bounded = solve_once(opt, opt.retry_max_step, run == 1);
      bounded.iterations += sol.iterations;
      bounded.backtracking_steps += sol.backtracking_steps;
      if(bounded.status != Lpfb_status::FAILED) sol = bounded;
    }
    return sol;
  }

  Lpfb_solution solve_once(const Lpfb_options& opt, double max_step, bool penalise_shortened_steps)
  {
    Lpfb_solution sol;
    std::vector<double> theta = pb_.target_angle;
    std::vector<double> c_lin(G_), trial_lin(G_);
    Eigen::VectorXd c_N(2 * K_), trial_N(2 * K_);
    std::vector<double> r(n_), delta(n_), trial(n_), correction(n_), soc(n_);
    double mu = 1.;  // l1 penalty weight of the merit function
    double step_scale = 1.;  // first trial step length, shortened on oscillation
    std::vector<double> previous_delta;

    evaluate(theta, c_lin, c_N);
    for(;;) {
      if(!all_finite(theta) || !c_N.allFinite()) { sol.status = Lpfb_status::FAILED; break; }
      for(std::size_t i = 0; i < n_; ++i) r[i] = pb_.target_angle[i] - theta[i];
      assemble_jacobian();
      const bool newton = opt.line_search && sol.iterations >= opt.newton_after;
      if(!(newton ? newton_step(theta, c_lin, c_N, delta) : step(r, c_lin, c_N, delta))) {
        sol.status = Lpfb_status::FAILED;
        break;
      }

      const double viol = violation_inf(c_lin, c_N);
      double step_size = inf_norm(delta);
      double fraction = 1.;  // of the step that satisfies the linearised constraints
      if(opt.line_search && step_size > max_step) {
        for(double& d : delta) d *= max_step / step_size;
        if(penalise_shortened_steps) fraction = max_step / step_size;
        step_size = max_step;
      }
#ifdef CGAL_QD_TRACE_LPFB
      std::cerr << "it " << sol.iterations << " viol " << viol << " step " << step_size << " f " << objective(theta) << " bt " << sol.backtracking_steps << "\n";
#endif
      if(viol <= opt.constraint_tolerance && step_size <= opt.angle_tolerance) {
        sol.status = Lpfb_status::CONVERGED;
        // the last step (below the angle tolerance) taken too: it meets the
        // linearised constraints, so the closure gap that the layout leaves
        // in the edge closing each loop falls to the order of its square
        // (manual, section 2.3). Not only where it lowers the violation (near
        // rounding that is noise: a moved copy would end otherwise), and not
        // where an angle would cross 0 or 2 pi (a needle triangle's corner).
        bool same_sides = true;
        for(std::size_t i = 0; i < n_; ++i) {
          trial[i] = theta[i] + delta[i];
          same_sides = same_sides && (trial[i] > 0) == (theta[i] > 0) && (trial[i] < 2 * pi) == (theta[i] < 2 * pi);
        }
        if(same_sides && all_finite(trial)) {
          evaluate(trial, trial_lin, trial_N);
          if(trial_N.allFinite() && violation_inf(trial_lin, trial_N) <= opt.constraint_tolerance) {
            theta.swap(trial);
            c_lin.swap(trial_lin);
            c_N.swap(trial_N);
          }
        }
        break;
      }
      if(sol.iterations >= opt.max_iterations) { sol.status = Lpfb_status::NOT_CONVERGED; break; }
      ++sol.iterations;

      if(!opt.line_search) {
        for(std::size_t i = 0; i < n_; ++i) theta[i] += delta[i];
        evaluate(theta, c_lin, c_N);
        continue;
      }

      // l1 merit m = f + mu |c|_1. Raise mu so that delta is a descent direction
      // (Nocedal & Wright, Numerical Optimization, 2nd ed., Eq. 18.36, H = I).
      const double c1 = violation_1(c_lin, c_N);
      double g_dot_d = 0, d_dot_d = 0;
      for(std::size_t i = 0; i < n_; ++i) { g_dot_d -= r[i] * delta[i]; d_dot_d += delta[i] * delta[i]; }
      const double curvature = newton ? (std::max)(0., hessian_.dot(delta)) : d_dot_d;
      // a shortened step removes only `fraction` of the violation to first order
      if(c1 > 0) mu = std::max(mu, 1.1 * (g_dot_d + 0.5 * curvature) / (0.5 * fraction * c1));
      const double merit0 = objective(theta) + mu * c1;
      const double slope = g_dot_d - mu * fraction * c1;  // directional derivative, < 0

      auto merit_at = [&](const std::vector<double>& th) {
        evaluate(th, trial_lin, trial_N);
        return objective(th) + mu * violation_1(trial_lin, trial_N);
      };
      const double armijo = 1e-4;
      // changes of the merit below its rounding error are not measurable: near a
      // solution of a strongly curved patch the decrease of a full step (about
      // |delta|^2) falls under the rounding error of f and of mu |c|_1 (each
      // closure residual is a sum of n terms of size up to 1)
      const double eps = std::numeric_limits<double>::epsilon();
      const double noise =
          64 * eps * (std::abs(objective(theta)) + mu * std::sqrt(double(n_)) * double(2 * K_ + G_));
      // Oscillation: successive steps pointing back and forth mean that the full
      // step overshoots along some direction (the constraint curvature adds to
      // the identity Hessian); such a flip-flop can leave the merit unchanged to
      // rounding, so it is detected from the steps and the step is shortened.
      if(newton) step_scale = 1.;
      else if(!previous_delta.empty()) {
        double dot = 0, pp = 0;
        for(std::size_t i = 0; i < n_; ++i) { dot += delta[i] * previous_delta[i]; pp += previous_delta[i] * previous_delta[i]; }
        const double cosine = dot / std::sqrt(pp * d_dot_d + 1e-300);
        if(cosine < -0.3) step_scale = (std::max)(step_scale * 0.5, 1. / 64);
        else if(cosine > 0.3) step_scale = (std::min)(step_scale * 2., 1.);
      }
      previous_delta = delta;
      // second-order correction: the trial point (whose constraints
      // `merit_at()` left in trial_lin, trial_N) pulled back onto the
      // linearised constraints with the current Jacobian, kept where its merit
      // is at most `bound` (the Maratos effect). Tried at every step length,
      // not only the full one: a trial point theta + t delta misses the
      // constraints by their curvature, of order t^2 |delta|^2, and where that
      // outweighs the decrease of the objective the merit accepts only a very
      // short step (a refined_elephant border of 1,763 corners: halved seven
      // times in every iteration, 200 iterations without converging; corrected,
      // 43 iterations in all).
      auto corrected = [&](double bound) {
        std::fill(r.begin(), r.end(), 0.);
        if(!step(r, trial_lin, trial_N, correction)) return false;
        for(std::size_t i = 0; i < n_; ++i) soc[i] = trial[i] + correction[i];
        const double ms = merit_at(soc);
        if(!(std::isfinite(ms) && ms <= bound)) return false;
        trial.swap(soc);
        return true;
      };
      // backtracking from `step_scale`; a first step that oscillation shortened
      // is tried without the correction, as before the correction was tried
      // at every step length
      bool accepted = false;
      for(double t = step_scale;; t *= 0.5, ++sol.backtracking_steps) {
        for(std::size_t i = 0; i < n_; ++i) trial[i] = theta[i] + t * delta[i];
        const double m = merit_at(trial), bound = merit0 + armijo * t * slope + noise;
        if(std::isfinite(m) && m <= bound) accepted = true;
        else if(std::isfinite(m) && (t != step_scale || t == 1.)) accepted = corrected(bound);
        if(accepted || !(t > 1e-12)) break;
      }
      if(!accepted) { sol.status = Lpfb_status::NOT_CONVERGED; break; }
      theta.swap(trial);
      evaluate(theta, c_lin, c_N);
    }

    sol.constraint_residual = violation_inf(c_lin, c_N);
    sol.objective = objective(theta);
    sol.theta = theta;
    layout(theta, sol.position);
    if(!all_finite(sol.theta)) sol.status = Lpfb_status::FAILED;
    return sol;
  }

  static bool all_finite(const std::vector<double>& v)
  {
    for(double x : v) if(!std::isfinite(x)) return false;
    return true;
  }
  static double inf_norm(const std::vector<double>& v)
  {
    double m = 0;
    for(double x : v) m = std::max(m, std::abs(x));
    return m;
  }
  double violation_inf(const std::vector<double>& c_lin, const Eigen::VectorXd& c_N) const
  {
    double m = c_N.size() ? c_N.cwiseAbs().maxCoeff() : 0.;
    for(double x : c_lin) m = std::max(m, std::abs(x));
    return m;
  }
  double violation_1(const std::vector<double>& c_lin, const Eigen::VectorXd& c_N) const
  {
    double s = c_N.cwiseAbs().sum();
    for(double x : c_lin) s += std::abs(x);
    return s;
  }
  double objective(const std::vector<double>& theta) const
  {
    double f = 0;
    for(std::size_t i = 0; i < n_; ++i) {
      const double d = theta[i] - pb_.target_angle[i];
      f += 0.5 * d * d;
    }
    return f;
  }

  // edge directions and constraint values at theta
  void evaluate(const std::vector<double>& theta, std::vector<double>& c_lin, Eigen::VectorXd& c_N)
  {
    angle_sum_.assign(G_, Compensated_sum());
    c_N.setZero();
    Compensated_sum turning;
    for(std::size_t k = 0; k < n_; ++k) {
      turning.add(pi - theta[k]);
      angle_sum_[pb_.corner_group[k]].add(theta[k]);
      const int l = pb_.edge_loop[k];
      if(l >= 0) {
        cos_[k] = std::cos(turning.value());
        sin_[k] = std::sin(turning.value());
        c_N[2 * l] += pb_.edge_length[k] * cos_[k];
        c_N[2 * l + 1] += pb_.edge_length[k] * sin_[k];
      }
    }
    for(std::size_t g = 0; g < G_; ++g) {
      angle_sum_[g].add(-pb_.group_sum[g]);
      c_lin[g] = angle_sum_[g].value();
    }
    for(int l = 0; l < K_; ++l) {
      c_N[2 * l] /= loop_length_[l];
      c_N[2 * l + 1] /= loop_length_[l];
    }
  }

  // closure Jacobian by suffix sums (d phi_k / d theta_i = -1 for k >= i), and
  // its projection N P (group means removed from every row); uses the
  // directions of the last evaluate(), which is always at the current theta
  void assemble_jacobian()
  {
    std::vector<double> ssin(K_, 0.), scos(K_, 0.);
    for(std::size_t i = n_; i-- > 0;) {
      const int l = pb_.edge_loop[i];
      if(l >= 0) {
        ssin[l] += pb_.edge_length[i] * sin_[i] / loop_length_[l];
        scos[l] += pb_.edge_length[i] * cos_[i] / loop_length_[l];
      }
      for(int q = 0; q < K_; ++q) {
        N_(2 * q, i) = ssin[q];
        N_(2 * q + 1, i) = -scos[q];
      }
    }
    for(int row = 0; row < 2 * K_; ++row) NP_.row(row) = remove_group_means(N_.row(row).transpose()).transpose();
  }

  // The least-squares solution of minimum norm of S x = b, with the pivots
  // below 1e-12 of the largest taken as zero. The threshold must be set before
  // the decomposition: compute() forms the Householder coefficients of Z for
  // the rank it sees, and a threshold raised afterwards makes solve() use a
  // smaller rank with coefficients that were never formed.
  static Eigen::VectorXd minimum_norm_solve(const Eigen::MatrixXd& S, const Eigen::VectorXd& b)
  {
    Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(S.rows(), S.cols());
    cod.setThreshold(1e-12);
    cod.compute(S);
    return cod.solve(b);
  }

  // P v: v with the mean of every group removed, its projection onto the
  // null space of the group rows
  Eigen::VectorXd remove_group_means(const Eigen::Ref<const Eigen::VectorXd>& v) const
  {
    std::vector<double> mean(G_, 0.);
    for(std::size_t i = 0; i < n_; ++i) mean[pb_.corner_group[i]] += v[i];
    for(std::size_t g = 0; g < G_; ++g) mean[g] /= group_size_[g];
    Eigen::VectorXd p(n_);
    for(std::size_t i = 0; i < n_; ++i) p[i] = v[i] - mean[pb_.corner_group[i]];
    return p;
  }

  // delta = r - L^+ (L r + c) with L = [group rows; N]
  bool step(const std::vector<double>& r, const std::vector<double>& c_lin,
            const Eigen::VectorXd& c_N, std::vector<double>& delta)
  {
    // minimum-norm solution of the group rows, and the projection of r
    const Eigen::VectorXd Pr = remove_group_means(Eigen::Map<const Eigen::VectorXd>(r.data(), Eigen::Index(n_)));
    Eigen::VectorXd dp(n_);
    for(std::size_t i = 0; i < n_; ++i) dp[i] = -c_lin[pb_.corner_group[i]] / group_size_[pb_.corner_group[i]];
    const Eigen::VectorXd rhs = NP_ * Pr + c_N + N_ * dp;
    const Eigen::MatrixXd S = NP_ * NP_.transpose();
    const Eigen::VectorXd lambda = minimum_norm_solve(S, rhs);
    if(!lambda.allFinite()) return false;
    const Eigen::VectorXd d = dp + Pr - NP_.transpose() * lambda;
    delta.assign(d.data(), d.data() + n_);
    return true;
  }

  // Newton SQP step: minimise 1/2 d^T H d + g^T d subject to A d + c = 0, with
  // A = [group rows; N] and H the Hessian of the Lagrangian at the
  // least-squares multipliers. Since d phi_k / d theta_i = -[k >= i], the
  // closure rows contribute rank-one terms on nested index sets:
  // H = I + U D U^T with U_im = [i <= m] and D_m = -(nu_x cos phi_m + nu_y sin phi_m) l_m / L
  // for an edge m of loop l (0 for a cut edge); solves with H cost O(n)
  // (internal/lpfb_hessian.h). Where H is not positive definite on the null
  // space of A, tau I is added (tau = 0, 1e-3, 1e-2, ...).
  bool newton_step(const std::vector<double>& theta, const std::vector<double>& c_lin,
                   const Eigen::VectorXd& c_N, std::vector<double>& delta)
  {
    Eigen::VectorXd g(n_);
    for(std::size_t i = 0; i < n_; ++i) g[i] = theta[i] - pb_.target_angle[i];
    const Eigen::VectorXd Pg = remove_group_means(g);
    const Eigen::VectorXd nu = -minimum_norm_solve(NP_ * NP_.transpose(), NP_ * Pg);
    if(!nu.allFinite()) return false;
    std::vector<double> hessian_diagonal(n_, 0.);
    for(std::size_t m = 0; m < n_; ++m) {
      const int l = pb_.edge_loop[m];
      if(l >= 0)
        hessian_diagonal[m] =
            -(nu[2 * l] * cos_[m] + nu[2 * l + 1] * sin_[m]) * pb_.edge_length[m] / loop_length_[l];
    }
    const std::size_t rows = G_ + 2 * K_;
    Eigen::MatrixXd M(n_, rows), S(rows, rows);  // H^{-1} A^T and A H^{-1} A^T
    Eigen::VectorXd column(n_), Hg(n_), rhs(rows);
    double tau = 0.;
    for(; tau < 1e8; tau = (tau == 0. ? 1e-3 : 10. * tau)) {
      std::size_t negative_pivots = 0;
      if(!hessian_.factor(hessian_diagonal, tau, negative_pivots)) continue;
      for(std::size_t j = 0; j < G_; ++j) {
        for(std::size_t i = 0; i < n_; ++i) column[i] = (pb_.corner_group[i] == int(j)) ? 1. : 0.;
        M.col(j) = hessian_.solve(column);
      }
      for(int q = 0; q < 2 * K_; ++q) M.col(G_ + q) = hessian_.solve(N_.row(q).transpose());
      Hg = hessian_.solve(g);
      S.setZero();
      for(std::size_t i = 0; i < n_; ++i) S.row(pb_.corner_group[i]) += M.row(i);
      for(int q = 0; q < 2 * K_; ++q) S.row(G_ + q) = N_.row(q) * M;
      S = 0.5 * (S + S.transpose()).eval();
      // the step minimises the quadratic model on the linearised constraints
      // only if H is positive definite on their null space: by Sylvester's law
      // of inertia, iff H and S have as many negative eigenvalues (T is
      // congruent to H, so it has H's)
      if(negative_pivots > 0) {
        const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(S, Eigen::EigenvaluesOnly);
        const double scale = es.eigenvalues().cwiseAbs().maxCoeff();
        std::size_t negative = 0;
        for(Eigen::Index k = 0; k < es.eigenvalues().size(); ++k)
          if(es.eigenvalues()[k] < -1e-12 * scale) ++negative;
        if(negative != negative_pivots) continue;
      }
      break;
    }
    if(!(tau < 1e8)) return false;
    for(std::size_t j = 0; j < G_; ++j) rhs[j] = c_lin[j];
    for(std::size_t i = 0; i < n_; ++i) rhs[pb_.corner_group[i]] -= Hg[i];
    for(int q = 0; q < 2 * K_; ++q) rhs[G_ + q] = c_N[q] - N_.row(q).dot(Hg);
    const Eigen::VectorXd lambda = minimum_norm_solve(S, rhs);
    if(!lambda.allFinite()) return false;
    const Eigen::VectorXd d = -Hg - M * lambda;
    if(!d.allFinite()) return false;
    delta.assign(d.data(), d.data() + n_);
    return true;
  }

  void layout(const std::vector<double>& theta, std::vector<std::array<double, 2>>& pos) const
  {
    // corner 0 at the origin, edge 0 along +x
    pos.assign(n_, {0., 0.});
    Compensated_sum turning;
    double x = 0, y = 0;
    for(std::size_t k = 0; k < n_; ++k) {
      if(k > 0) turning.add(pi - theta[k]);
      pos[k] = {x, y};
      x += pb_.edge_length[k] * std::cos(turning.value());
      y += pb_.edge_length[k] * std::sin(turning.value());
    }
  }

  const Lpfb_problem& pb_;
  std::size_t n_ = 0, G_ = 0;
  int K_ = 1;
  std::vector<double> loop_length_, group_size_, cos_, sin_;
  std::vector<Compensated_sum> angle_sum_;  // angle sums of the last evaluate()
  Nested_rank_one_hessian hessian_;  // of the last Newton step
  Eigen::MatrixXd N_, NP_;
};

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_INTERNAL_LPFB_SOLVER_H
