// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_DISTORTION_REPORT_H
#define CGAL_QD_DISTORTION_REPORT_H

/// \file distortion_report.h
/// `Distortion_report`: the measures of a UV map that `compute_distortion()`
/// (distortion.h) gives.

#include <CGAL_QD/Error_code.h>

#include <boost/graph/graph_traits.hpp>

#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL_QD {

/// \ingroup PkgCGAL_QDRef
/// all measures of a UV map, computed by `compute_distortion()` in one pass.
template <class TriangleMesh>
struct Distortion_report
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;

  Error_code status = Error_code::OK;
  std::size_t number_of_faces = 0;
  double area_3d = 0;  ///< sum of the 3D face areas
  double area_2d = 0;  ///< sum of the unsigned 2D face areas
  /// A(Omega) = |sum |A_2D| - sum A_3D| / sum A_3D x 100 (paper Eq. 19), in percent
  double area_distortion = 0;
  /// A_loc = sum |A_2D(T) - A_3D(T)| / sum A_3D(T) x 100, with unsigned 2D areas at true scale, in percent:
  /// unlike `area_distortion`, faces that grow and faces that shrink do not cancel out
  double local_area_distortion = 0;
  /// Sander et al. 2001 L2 stretch of the map 2D -> 3D, sqrt(sum L2(T)^2 A_3D(T) / sum A_3D(T));
  /// 1 only when the map is an isometry, smaller when the UVs are larger than the surface
  double l2_stretch = 0;
  /// `l2_stretch` times sqrt(area_2d / area_3d): invariant to a uniform scale of the UVs, >= 1
  double l2_stretch_normalized = 0;
  /// largest singular value of the 2D -> 3D map over all faces
  double linf_stretch = 0;
  /// mean |alpha_2D - alpha_3D| over all face corners, in radians
  double angle_distortion = 0;
  /// Pi_L: mean |l_2D - l_3D| over the edges of every border loop (paper Eq. 1)
  double boundary_length_error = 0;
  /// Pi_theta: mean |a_v - theta_v| over the vertices of every border loop, in radians (paper Eq. 2)
  double boundary_angle_error = 0;
  /// faces whose 2D orientation is not positive (zero area included)
  std::size_t flipped_faces = 0;
  /// interior vertices whose 1-ring wraps around them more than once in 2D
  std::size_t branch_vertices = 0;
  /// pairs of border halfedges whose 2D segments cross or touch
  std::vector<std::pair<halfedge_descriptor, halfedge_descriptor>> border_crossings;
  /// S(Omega): the map is not one-to-one (a flipped face, a branch vertex or a border crossing)
  bool overlap = false;

  explicit operator bool() const { return status == Error_code::OK; }
};

} // namespace CGAL_QD

#endif // CGAL_QD_DISTORTION_REPORT_H
