// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_DISTORTION_H
#define CGAL_QD_DISTORTION_H

/// \file distortion.h
/// Distortion measures of a UV map on any triangle mesh: area distortion A(Omega),
/// Sander's L2 and Linf stretch, angle distortion, border length and angle
/// errors Pi_L and Pi_theta, flipped faces and exact global overlap S(Omega).

#include <CGAL_QD/distortion_report.h>
#include <CGAL_QD/parameters.h>
#include <CGAL_QD/internal/distortion_pass.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace CGAL_QD {

/// \ingroup PkgCGAL_QDRef
/// computes every distortion measure of the UV map `uv` on `tm` in one pass
/// over the faces, plus an exact test of the border polygons for crossings
/// (`CGAL::box_self_intersection_d` and exact predicates; the paper rasterises
/// on a GPU instead).
///
/// A locally injective, orientation-preserving map whose border polygons are
/// simple and disjoint is globally one-to-one; so `overlap` (S(Omega)) is set
/// when a face is flipped, an interior vertex is a branch point (its 1-ring
/// wraps around it twice without any flipped face) or two border edges cross.
///
/// \tparam TriangleMesh a model of `FaceListGraph`
/// \tparam VertexUVMap a model of `ReadablePropertyMap` from vertices to a 2D point type
/// \param tm the triangle mesh
/// \param uv the UV of every vertex
/// \param np optional: `vertex_point_map`, `vertex_index_map`, and
///   `CGAL_QD::parameters::overlap_tolerance`: border edges closer than this
///   fraction of the diagonal of the border's UV bounding box touch rather than
///   cross (default 0: exact tests, where touching is crossing). Two sides of a
///   cut that develop onto each other touch. Where border edges touch within
///   the tolerance, the faces around them are compared (shrunk by a relative
///   1e-6 toward their centroids, then tested exactly): the touch is an
///   overlap if they overlap.
/// \returns a report whose `status` is `OK`, `EMPTY_MESH`, `NOT_TRIANGLE_MESH` or
///          `INVALID_COORDINATES` (a NaN or infinite 3D or UV coordinate). Coordinates in
///          any finite range are measured: beyond [2^-64, 2^64] the mesh and its UVs are
///          scaled by a power of two (exact), and `area_3d`, `area_2d` and
///          `boundary_length_error` scaled back.
template <class TriangleMesh, class VertexUVMap, class NamedParameters = CGAL::parameters::Default_named_parameters>
Distortion_report<TriangleMesh> compute_distortion(const TriangleMesh& tm, const VertexUVMap& uv,
                                                   const NamedParameters& np = CGAL::parameters::default_values())
{
  return internal::compute_distortion_with(tm, uv, np, internal::Distortion_options());
}


/// \ingroup PkgCGAL_QDRef
/// applies to `uv` the similarity (uniform scale about one of its points, no
/// rotation) that puts the endpoints of the longest border edge at their 3D
/// distance: the normalisation the paper applies to free-border methods before
/// measuring them. Does nothing if `tm` has no border or that edge has zero
/// length in `uv`.
/// \param tm the triangle mesh
/// \param uv the UV of every vertex
/// \param np optional: `vertex_point_map`
template <class TriangleMesh, class VertexUVMap, class NamedParameters = CGAL::parameters::Default_named_parameters>
void normalize_by_longest_border_edge(const TriangleMesh& tm, VertexUVMap uv,
                                      const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename boost::property_traits<VertexUVMap>::value_type Point_2;
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, tm));
  typename GT::halfedge_descriptor longest = GT::null_halfedge();
  double best = -1;
  for(typename GT::halfedge_descriptor h : halfedges(tm))
    if(is_border(h, tm)) {
      const double l = internal::distance3(internal::point_of<TriangleMesh>(source(h, tm), vpm),
                                           internal::point_of<TriangleMesh>(target(h, tm), vpm));
      if(l > best) { best = l; longest = h; }
    }
  if(longest == GT::null_halfedge()) return;
  const auto a = internal::uv_of(uv, source(longest, tm)), b = internal::uv_of(uv, target(longest, tm));
  const double l2 = std::hypot(b[0] - a[0], b[1] - a[1]);
  if(!(l2 > 0)) return;
  const double s = best / l2;
  for(typename GT::vertex_descriptor v : vertices(tm)) {
    const auto p = internal::uv_of(uv, v);
    put(uv, v, Point_2(a[0] + s * (p[0] - a[0]), a[1] + s * (p[1] - a[1])));
  }
}

// The single measures below return, on invalid input (no face, a face that is
// not a triangle, a non-finite coordinate), the value that judges the map worst:
// infinite distortion, every face flipped, an overlap. `compute_distortion()`
// tells why.

/// \ingroup PkgCGAL_QDRef
/// returns A(Omega) in percent (see `Distortion_report::area_distortion`);
/// +infinity on invalid input.
template <class TriangleMesh, class VertexUVMap, class NamedParameters = CGAL::parameters::Default_named_parameters>
double area_distortion(const TriangleMesh& tm, const VertexUVMap& uv,
                       const NamedParameters& np = CGAL::parameters::default_values())
{
  const auto r = internal::face_measures(tm, uv, np);
  return r ? r.area_distortion : std::numeric_limits<double>::infinity();
}

/// \ingroup PkgCGAL_QDRef
/// returns the local area distortion A_loc in percent (see
/// `Distortion_report::local_area_distortion`); +infinity on invalid input.
template <class TriangleMesh, class VertexUVMap, class NamedParameters = CGAL::parameters::Default_named_parameters>
double local_area_distortion(const TriangleMesh& tm, const VertexUVMap& uv,
                             const NamedParameters& np = CGAL::parameters::default_values())
{
  const auto r = internal::face_measures(tm, uv, np);
  return r ? r.local_area_distortion : std::numeric_limits<double>::infinity();
}

/// \ingroup PkgCGAL_QDRef
/// returns Sander's L2 stretch (see `Distortion_report::l2_stretch`); +infinity on invalid input.
template <class TriangleMesh, class VertexUVMap, class NamedParameters = CGAL::parameters::Default_named_parameters>
double l2_stretch(const TriangleMesh& tm, const VertexUVMap& uv,
                  const NamedParameters& np = CGAL::parameters::default_values())
{
  const auto r = internal::face_measures(tm, uv, np);
  return r ? r.l2_stretch : std::numeric_limits<double>::infinity();
}

/// \ingroup PkgCGAL_QDRef
/// returns the number of faces whose 2D orientation is not positive; the number
/// of faces on invalid input.
template <class TriangleMesh, class VertexUVMap, class NamedParameters = CGAL::parameters::Default_named_parameters>
std::size_t number_of_flipped_faces(const TriangleMesh& tm, const VertexUVMap& uv,
                                    const NamedParameters& np = CGAL::parameters::default_values())
{
  const auto r = internal::face_measures(tm, uv, np);
  return r ? r.flipped_faces : static_cast<std::size_t>(num_faces(tm));
}

/// \ingroup PkgCGAL_QDRef
/// returns S(Omega): whether the map fails to be one-to-one (see
/// `compute_distortion()`); `true` on invalid input.
template <class TriangleMesh, class VertexUVMap, class NamedParameters = CGAL::parameters::Default_named_parameters>
bool has_global_overlap(const TriangleMesh& tm, const VertexUVMap& uv,
                        const NamedParameters& np = CGAL::parameters::default_values())
{
  const auto r = internal::acceptance_measures(tm, uv, np);  // the same `overlap`, no corner angles
  return !r || r.overlap;
}

} // namespace CGAL_QD

#endif // CGAL_QD_DISTORTION_H
