// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_CHART_FLATTENING_RESULT_H
#define CGAL_QD_CHART_FLATTENING_RESULT_H

/// \file chart_flattening_result.h
/// `Chart_flattening_result`: the charts of a segmentation flattened and
/// measured, with their seams, as `flatten_charts()` (flatten_charts.h) and
/// the segmentation's last step give them.

#include <CGAL_QD/Error_code.h>
#include <CGAL_QD/chart_criterion.h>

#include <boost/graph/graph_traits.hpp>

#include <array>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL_QD {

/// \ingroup PkgCGAL_QDRef
/// the flattening of the charts of a segmentation, by `flatten_charts()` or as
/// the last step of `segment_quasi_developable()`.
template <class TriangleMesh>
struct Chart_flattening_result
{
  typedef typename boost::graph_traits<TriangleMesh>::edge_descriptor edge_descriptor;

  Error_code status = Error_code::OK;
  std::size_t number_of_faces = 0;
  std::size_t number_of_charts = 0;  ///< final

  /// per chart, in chart id order: its flattening cut open along `seam_edges`
  std::vector<Chart_report> charts;
  double max_area_distortion = 0;        ///< over the charts, in percent
  double max_l2_stretch = 0;             ///< over the charts
  double max_local_area_distortion = 0;  ///< A_loc over the charts, in percent
  std::size_t overlapping_charts = 0;
  std::size_t rejected_charts = 0;  ///< charts beyond the thresholds

  /// the edges where the surface is cut: between two charts, or curves left inside a chart
  std::vector<edge_descriptor> seam_edges;
  double seam_length = 0;
  /// the largest |l_1 - l_2| / max(l_1, l_2) over the seam curves (chains of seam edges between
  /// junctions, or closed loops), where l_1 and l_2 are the 2D lengths of the curve's two sides in
  /// `corner_uv` (in two pieces, or twice in one piece for a cut inside a chart): what a person sewing
  /// or gluing the pieces sees
  double max_seam_length_mismatch = 0;
  std::size_t number_of_seam_curves = 0;  ///< the seam curves of `max_seam_length_mismatch`
  /// the seam curves whose two sides differ by at most 0.5 % of the longer one
  std::size_t seam_curves_matched = 0;
  /// the two charts of every seam curve whose sides differ by more than 0.5 % (the smaller id first;
  /// the same chart twice for a cut inside a chart)
  std::vector<std::pair<std::size_t, std::size_t>> unmatched_seams;
  /// the relative difference |l_1 - l_2| / max(l_1, l_2) of each curve of `unmatched_seams`, in the same order
  std::vector<double> unmatched_seam_mismatch;
  /// the length-weighted zigzag of the seam curves, `seam_zigzag()`: about 1 for curves a person can
  /// follow with scissors, 1.2 to 1.4 for staircases along triangle edges
  double seam_zigzag = 1;
  /// the area-weighted mean compactness 4 pi A / P^2 of the charts, `chart_compactness()` (1 for a disc)
  double compactness = 0;

  /// the UV of every corner in its chart's flattening: `corner_uv[3 i + k]` is
  /// the UV of the target of the k-th halfedge of the face of index i, starting
  /// at `halfedge(f, tm)`. Each chart has its own frame, in the units of the mesh.
  std::vector<std::array<double, 2>> corner_uv;
  /// the point of every vertex (by vertex index) that the flattening used
  std::vector<std::array<double, 3>> points;

  double time_flatten_ms = 0;

  /// whether the charts were flattened: `false` in the result of `segment_quasi_developable()` with
  /// `CGAL_QD::parameters::final_flattening(false)`, which then holds `number_of_faces`,
  /// `number_of_charts`, `seam_edges`, `seam_length` and `points`, and leaves the rest empty
  bool flattened = true;

  explicit operator bool() const { return status == Error_code::OK; }
};

namespace internal {

// `r`, a flattening of the mesh scaled by `scale` (a power of two), in the
// units of the mesh: its UVs, lengths and areas multiplied by 1 / `scale`
// (exact), and its points too if `points` is set (the caller's otherwise)
template <class TriangleMesh>
void scale_flattening_back(Chart_flattening_result<TriangleMesh>& r, double scale, bool points)
{
  const double length = 1. / scale, area = length * length;
  for(auto& uv : r.corner_uv)
    for(double& x : uv) x *= length;
  if(points)
    for(auto& p : r.points)
      for(double& x : p) x *= length;
  for(Chart_report& c : r.charts) c.area *= area;
  r.seam_length *= length;
}

} // namespace internal

} // namespace CGAL_QD

#endif // CGAL_QD_CHART_FLATTENING_RESULT_H
