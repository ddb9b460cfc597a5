// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_INTERNAL_ARAP_ITERATION_H
#define CGAL_QD_INTERNAL_ARAP_ITERATION_H

// The iteration of `optimize_flattening()` on a patch given by index arrays:
// local and global steps (internal/arap_optimizer.h) until the energy stops
// decreasing, with steps that would flip a triangle shortened and, on request,
// Anderson acceleration.

#include <CGAL_QD/Optimization_result.h>
#include <CGAL_QD/internal/anderson_acceleration.h>
#include <CGAL_QD/internal/arap_optimizer.h>
#include <CGAL_QD/internal/timing.h>

#include <Eigen/Core>

#include <array>
#include <chrono>
#include <cstddef>
#include <memory>
#include <vector>

namespace CGAL_QD {
namespace internal {

struct Arap_options
{
  std::size_t iterations = 30;
  Arap_border border = Arap_border::LENGTH_PRESERVED;
  double border_length_weight = 10.;
  // stop when an iteration lowers the energy by less than this fraction
  double relative_decrease = 1e-4;
  double area_preservation = 0.;  // see Arap_optimizer
  // the history of the Anderson acceleration (0: plain iteration)
  std::size_t anderson_window = 0;
};

// no callback: the iteration never stops early
struct No_iteration_callback
{
  bool operator()(std::size_t, const std::vector<std::array<double, 2>>&) const { return false; }
};

// Optimises `u` (by vertex index) in place; see `optimize_flattening()`.
// `callback(iterations, u)` is called after every iteration; it stops the
// iteration by returning true.
template <class Solver, class Callback = No_iteration_callback>
Optimization_result optimize_flattening_impl(std::size_t nv, const std::vector<std::array<std::size_t, 3>>& tri,
                                             const std::vector<std::array<double, 3>>& p,
                                             const std::vector<std::array<std::size_t, 2>>& border_edges,
                                             const std::vector<double>& border_length,
                                             std::vector<std::array<double, 2>>& u, const Arap_options& opt,
                                             const Solver& solver, const Callback& callback = Callback())
{
  const auto start = std::chrono::steady_clock::now();
  Optimization_result result;
  Arap_optimizer<Solver> arap(nv, tri, p, border_edges, border_length,
                              opt.border == Arap_border::KEEP_LENGTHS ? opt.border_length_weight : 0., solver,
                              opt.area_preservation);
  std::vector<char> fixed(nv, 0);
  if(opt.border == Arap_border::FIXED) {
    for(const auto& e : border_edges) fixed[e[0]] = fixed[e[1]] = 1;
  } else if(nv > 0) {
    fixed[tri.front()[0]] = 1;  // translation
  }
  if(!arap.factorize(fixed)) {
    result.status = Error_code::SOLVER_FAILED;
    result.time_ms = milliseconds_since(start);
    return result;
  }
  double energy = arap.local_step(u);
  result.energy_before = result.energy_after = energy;
  result.input_flipped = arap.has_flip(u);
  bool flip_free = !result.input_flipped;
  std::vector<std::array<double, 2>> next, trial, accelerated;
  std::unique_ptr<Anderson_acceleration> anderson;
  if(opt.anderson_window > 0 && nv > 0)
    anderson.reset(new Anderson_acceleration(Eigen::Index(2 * nv), Eigen::Index(opt.anderson_window)));
  const auto as_vector = [nv](std::vector<std::array<double, 2>>& x) {
    return Eigen::Map<Eigen::VectorXd>(x.front().data(), Eigen::Index(2 * nv));
  };
  for(std::size_t it = 0; it < opt.iterations; ++it) {
    if(!arap.global_step(u, next)) {
      result.status = Error_code::SOLVER_FAILED;
      break;
    }
    bool shortened = false;
    // once the map is flip-free, a step that would flip a face is shortened
    if(flip_free && arap.has_flip(next)) {
      shortened = true;
      double t = 0.5;
      bool found = false;
      for(int k = 0; k < 10 && !found; ++k, t *= 0.5) {
        trial = u;
        for(std::size_t i = 0; i < nv; ++i)
          for(int c = 0; c < 2; ++c) trial[i][c] = (1 - t) * u[i][c] + t * next[i][c];
        found = !arap.has_flip(trial);
      }
      ++result.shortened_steps;
      if(!found) break;
      next.swap(trial);
    }
    // once the map is flip-free, the accelerated point replaces the plain
    // step where it keeps the map flip-free and has a lower energy; otherwise
    // the history starts again (a map with flipped faces unfolds by plain
    // steps: accelerated, it may settle with its folds)
    bool have_energy = false;
    double e = 0;
    if(anderson && flip_free) {
      accelerated.resize(nv);
      auto out = as_vector(accelerated);
      if(shortened) {
        anderson->reset();  // a shortened step is no image of the map
      } else if(anderson->compute(as_vector(u), as_vector(next), out)) {
        if(out.allFinite() && !arap.has_flip(accelerated)) {
          e = arap.local_step(accelerated);
          if(e < energy) {
            next.swap(accelerated);
            have_energy = true;
          } else {
            anderson->reset();
          }
        } else {
          anderson->reset();
        }
      }
    }
    u.swap(next);
    ++result.iterations;
    if(callback(result.iterations, u)) {
      result.stopped_by_callback = true;
      break;
    }
    flip_free = flip_free || !arap.has_flip(u);
    if(!have_energy) e = arap.local_step(u);
    const bool small = energy - e <= opt.relative_decrease * energy;
    energy = e;
    if(small) break;
  }
  result.energy_after = energy;
  result.time_ms = milliseconds_since(start);
  return result;
}

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_INTERNAL_ARAP_ITERATION_H
