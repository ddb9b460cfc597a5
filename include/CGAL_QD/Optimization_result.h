// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_OPTIMIZATION_RESULT_H
#define CGAL_QD_OPTIMIZATION_RESULT_H

/// \file Optimization_result.h
/// The border treatments and the diagnostics of `optimize_flattening()`.

#include <CGAL_QD/Error_code.h>

#include <cstddef>

namespace CGAL_QD {

/// \ingroup PkgCGAL_QDRef
/// how `optimize_flattening()` treats the border of the patch.
enum class Arap_border
{
  /// the border moves freely (the free-boundary ARAP of Liu et al. 2008)
  FREE,
  /// the border moves, and every border edge is pulled towards its target length (its 3D length, or
  /// the one given by `CGAL_QD::parameters::border_edge_length_map`) with the weight
  /// `CGAL_QD::parameters::border_length_weight`, relative to the cotangent weights of the faces
  KEEP_LENGTHS,
  /// the border vertices keep their given positions (for instance the LPFB border); only the interior moves
  FIXED,
  /// every border edge gets its exact target length (its 3D length, or the one given by
  /// `CGAL_QD::parameters::border_edge_length_map`): `FREE`, then the length-preserved free boundary
  /// whose target angles are the border angles of that map (instead of the surface's), then `FIXED`
  /// with that border. Two pieces given the same lengths on the two sides of a seam match along it.
  LENGTH_PRESERVED
};

/// \ingroup PkgCGAL_QDRef
/// diagnostics of `optimize_flattening()`.
struct Optimization_result
{
  Error_code status = Error_code::OK;
  std::size_t iterations = 0;  ///< local/global iterations done
  /// the ARAP energy sum_T sum_{edges ij of T} cot(alpha_ij) |(u_i - u_j) - R_T (x_i - x_j)|^2 divided by the
  /// 3D area, before and after (0 for an isometry); with `CGAL_QD::parameters::area_preservation` > 0, the
  /// same sum with every face's target map of determinant 1 in place of its rotation R_T
  double energy_before = 0;
  double energy_after = 0;
  /// whether the input map had a flipped triangle (the optimisation may unfold it)
  bool input_flipped = false;
  /// iterations whose step was shortened so that no triangle flips
  std::size_t shortened_steps = 0;
  /// with `LENGTH_PRESERVED`: the status of the length-preserved free boundary fitted to the map
  /// (`OK`, or `NOT_CONVERGED`, ...: then the map is the free one and `lengths_preserved` is false)
  Error_code border_status = Error_code::OK;
  /// with `LENGTH_PRESERVED`: whether every border edge has its target length (up to the border solver's tolerance)
  bool lengths_preserved = false;
  /// whether `CGAL_QD::parameters::iteration_callback` stopped the iteration
  bool stopped_by_callback = false;
  double time_ms = 0;

  explicit operator bool() const { return status == Error_code::OK; }
};

} // namespace CGAL_QD

#endif // CGAL_QD_OPTIMIZATION_RESULT_H
