// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_INTERNAL_CHART_MESH_H
#define CGAL_QD_INTERNAL_CHART_MESH_H

// A chart cut open as a mesh of its own (one vertex per wedge), and the
// measures of a flattening of it against the thresholds: what
// `Chart_evaluator` builds for every trial, fit and final flattening.

#include <CGAL_QD/Error_code.h>
#include <CGAL_QD/chart_criterion.h>
#include <CGAL_QD/distortion.h>
#include <CGAL_QD/extract_chart.h>
#include <CGAL_QD/parameters.h>
#include <CGAL_QD/internal/add_triangles.h>
#include <CGAL_QD/internal/validation.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL_QD {
namespace internal {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Chart_kernel;
typedef CGAL::Surface_mesh<Chart_kernel::Point_3> Chart_mesh;

// `sm` (empty) becomes the chart of `n_faces` faces cut open into `wedges`:
// vertex w at the point of wedge w (`points` by the index `vim` gives), face
// i on the wedges of corners 3i to 3i + 2; `area` receives the chart's 3D
// area. NON_MANIFOLD where the wedges do not make a manifold surface.
template <class TriangleMesh, class VIM>
Error_code build_chart_mesh(const Wedges<TriangleMesh>& wedges, std::size_t n_faces, const VIM& vim,
                            const std::vector<std::array<double, 3>>& points, Chart_mesh& sm, double& area)
{
  typedef Chart_mesh::Vertex_index V;
  typedef Chart_mesh::size_type S;
  sm.reserve(static_cast<S>(wedges.size()), static_cast<S>(3 * n_faces), static_cast<S>(n_faces));
  auto add_vertices = [&] {
    for(std::size_t w = 0; w < wedges.size(); ++w) {
      const std::array<double, 3>& p = points[get(vim, wedges.vertex_of_wedge[w])];
      sm.add_vertex(Chart_kernel::Point_3(p[0], p[1], p[2]));
    }
  };
  add_vertices();
  if(!add_triangles(sm, wedges.wedge_of_corner)) {
    // not a manifold surface: `add_face()` tells
    sm.clear_without_removing_property_maps();
    add_vertices();
    for(std::size_t i = 0; i < n_faces; ++i) {
      const auto f = sm.add_face(V(static_cast<S>(wedges.wedge_of_corner[3 * i])),
                                 V(static_cast<S>(wedges.wedge_of_corner[3 * i + 1])),
                                 V(static_cast<S>(wedges.wedge_of_corner[3 * i + 2])));
      if(f == Chart_mesh::null_face()) return Error_code::NON_MANIFOLD;
    }
  }
  area = 0;
  auto corner_point = [&](std::size_t c) -> const std::array<double, 3>& {
    return points[get(vim, wedges.vertex_of_wedge[wedges.wedge_of_corner[c]])];
  };
  for(std::size_t i = 0; i < n_faces; ++i)
    area += double_area3(corner_point(3 * i), corner_point(3 * i + 1), corner_point(3 * i + 2)) / 2;
  return Error_code::OK;
}

// the number of border loops of `sm`, each counted at its smallest halfedge
inline std::size_t number_of_border_loops(const Chart_mesh& sm)
{
  std::size_t loops = 0;
  for(auto h : halfedges(sm))
    if(is_border(h, sm)) {
      auto g = next(h, sm);
      while(g != h && h < g) g = next(g, sm);
      if(g == h) ++loops;
    }
  return loops;
}

// measures the flattening `uv` of `sm` into `rep` and tells whether the
// thresholds accept it; false if it cannot be measured (`rep` then says why)
template <class UVMap>
bool measure_chart_flattening(const Chart_mesh& sm, const UVMap& uv, const Merge_thresholds& thresholds,
                              Chart_report& rep)
{
  const Distortion_report<Chart_mesh> d =
      acceptance_measures(sm, uv, parameters::overlap_tolerance(thresholds.overlap_tolerance));
  if(!d) {
    rep.status = d.status;
    rep.accepted = false;
    return false;
  }
  rep.area_distortion = d.area_distortion;
  rep.l2_stretch = d.l2_stretch;
  rep.local_area_distortion = d.local_area_distortion;
  rep.overlap = d.overlap;
  rep.max_border_length_error = 0;
  for(auto h : halfedges(sm))
    if(is_border(h, sm)) {
      const Chart_kernel::Point_3 &p = sm.point(source(h, sm)), &q = sm.point(target(h, sm));
      const double l3 = std::sqrt(CGAL::squared_distance(p, q));
      const double l2 = std::sqrt(CGAL::squared_distance(get(uv, source(h, sm)), get(uv, target(h, sm))));
      rep.max_border_length_error = (std::max)(rep.max_border_length_error, std::abs(l2 - l3) / l3);
    }
  rep.accepted = rep.area_distortion <= 100. * thresholds.max_area_distortion &&
                 rep.l2_stretch <= thresholds.max_l2_stretch && !rep.overlap &&
                 (thresholds.criterion == Chart_criterion::LPFB_IP ||
                  rep.local_area_distortion <= 100. * thresholds.max_local_area_distortion);
  return true;
}

// of two flattenings beyond the thresholds, whether `a` is nearer them than
// `b`: without an overlap where `b` has one, else with the smaller largest
// ratio of A(Omega), L2 and A_loc to their bounds
inline bool nearer_thresholds(const Chart_report& a, const Chart_report& b, const Merge_thresholds& thresholds)
{
  if(a.overlap != b.overlap) return !a.overlap;
  auto excess = [&](const Chart_report& r) {
    double e = 0;
    if(thresholds.max_l2_stretch > 0) e = r.l2_stretch / thresholds.max_l2_stretch;
    if(thresholds.max_area_distortion > 0)
      e = (std::max)(e, r.area_distortion / (100. * thresholds.max_area_distortion));
    if(thresholds.max_local_area_distortion > 0)
      e = (std::max)(e, r.local_area_distortion / (100. * thresholds.max_local_area_distortion));
    return e;
  };
  return excess(a) < excess(b);
}

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_INTERNAL_CHART_MESH_H
