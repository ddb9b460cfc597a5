// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_CHART_MERGING_H
#define CGAL_QD_CHART_MERGING_H

/// \file chart_merging.h
/// Step 4 of the quasi-developable segmentation (paper Section 4.2): the
/// boundary-based greedy merging of charts, each merge tried by LPFB+IP and
/// accepted only if the merged chart stays within the distortion thresholds.

#include <CGAL_QD/Error_code.h>
#include <CGAL_QD/chart_criterion.h>
#include <CGAL_QD/merge_order.h>
#include <CGAL_QD/parameters.h>
#include <CGAL_QD/internal/boundary_merger.h>
#include <CGAL_QD/internal/chart_evaluator.h>
#include <CGAL_QD/internal/charts.h>
#include <CGAL_QD/vsa_segmentation.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/tags.h>

#include <boost/graph/graph_traits.hpp>

#include <array>
#include <chrono>
#include <cstddef>
#include <functional>
#include <iterator>
#include <tuple>
#include <type_traits>
#include <vector>

namespace CGAL_QD {

/// \ingroup PkgCGAL_QDRef
/// diagnostics of `merge_charts_by_boundaries()`.
template <class TriangleMesh>
struct Merging_result
{
  typedef typename boost::graph_traits<TriangleMesh>::edge_descriptor edge_descriptor;
  Error_code status = Error_code::OK;
  std::size_t charts_before = 0;
  /// charts added by splitting input charts that were themselves beyond the thresholds
  std::size_t charts_split = 0;
  std::size_t number_of_charts = 0;
  std::size_t boundary_curves = 0;  ///< maximal edge chains between the same two charts, after splitting
  /// merged charts flattened and measured; a parallel run also counts the
  /// speculative trials whose result an earlier acceptance made stale
  std::size_t trials = 0;
  std::size_t merges = 0;           ///< accepted trials (curves removed)
  /// small charts shared out among their neighbours after the merging
  /// (`segment_quasi_developable()`, `CGAL_QD::parameters::share_out_small_charts`)
  std::size_t charts_shared_out = 0;
  std::size_t sharing_trials = 0;  ///< enlarged neighbours flattened and measured by the sharing
  /// flattenings of the splitting and the merging whose LPFB reached its
  /// iteration limit (`Error_code::NOT_CONVERGED`); such a chart is not
  /// accepted: a split goes on, a trial keeps its two charts
  std::size_t lpfb_not_converged = 0;
  /// the edges where the surface is cut: between two charts, or remaining curves inside a chart
  std::vector<edge_descriptor> seam_edges;
  double seam_length = 0;
  double time_split_ms = 0;
  double time_ms = 0;

  explicit operator bool() const { return status == Error_code::OK; }
};

/// \ingroup PkgCGAL_QDRef
/// merges charts by removing the boundary curves between them (paper Section
/// 4.2). A boundary curve is a maximal chain of edges between the same two
/// charts. First, every chart that does not itself pass the test below is
/// split in two (by distance to two far-apart faces) until all pass. Then the
/// curves enter a heap ordered by `merge_order`; the top curve is tried: the
/// chart obtained by removing it, cut open along all other remaining curves
/// inside it (dangling cuts are allowed), is flattened by LPFB+IP
/// (`flatten_patch()`, virtual cutting for holes). With the paper's criterion
/// (`Chart_criterion::LPFB_IP`) the removal is accepted iff the flattening
/// succeeds, A(Omega) <= `max_area_distortion`, L2 <= `max_l2_stretch` and
/// there is no overlap. With the default `Chart_criterion::LPFB_IP_THEN_ARAP`,
/// the flattening must also keep A_loc <= `max_local_area_distortion`, and a
/// chart that LPFB+IP does not pass is flattened again by a free-boundary ARAP
/// started from LPFB+IP (`optimize_flattening()`), judged the same way. A
/// trial that would create a handle, or a chart that is not a disk with holes after cutting, fails and
/// is rejected. After an acceptance, every remaining curve of the merged chart
/// takes its new key (curves rejected before are tried again, since the chart
/// changed). Ties are broken by curve order, so the result is deterministic.
///
/// Trials of the curves at the top of the heap are independent and run in
/// parallel with `ConcurrencyTag = CGAL::Parallel_tag` when TBB is linked; the
/// decisions are taken in heap order, so the result is the sequential one.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or `CGAL::Parallel_if_available_tag`
/// \tparam FaceChartMap a model of `ReadWritePropertyMap` from faces to an integral chart id; it receives
///         ids in `[0, n)`
/// \param tm the triangle mesh
/// \param face_chart the chart id of every face
/// \param np optional named parameters:
///   - `CGAL_QD::parameters::max_area_distortion` (default 0.10), `CGAL_QD::parameters::max_l2_stretch` (default 2.0)
///   - `CGAL_QD::parameters::overlap_tolerance`: see `compute_distortion()` (default 1e-9: the sides of a
///     cut that develop onto each other touch, they do not overlap)
///   - `CGAL_QD::parameters::max_local_area_distortion` (default 0.025), `CGAL_QD::parameters::chart_criterion`
///     (default `Chart_criterion::LPFB_IP_THEN_ARAP`), and for its ARAP flattening
///     `CGAL_QD::parameters::arap_border` (default `Arap_border::FREE`),
///     `CGAL_QD::parameters::border_length_weight` and `CGAL_QD::parameters::area_preservation` (default
///     0.5) (see `optimize_flattening()`)
///   - `CGAL_QD::parameters::merge_order`: a `Merge_order` (default `SMALLEST_AREA_FIRST`; the paper's is
///     `LARGEST_AREA_FIRST`)
///   - `CGAL_QD::parameters::compactness_ratio`: a number rho in [0, 1] (default 0.6): a curve between two
///     charts is tried only when the chart its removal gives is at least rho times as compact (4 pi area /
///     perimeter^2, in 3D) as the less compact of the two; otherwise it is kept without a trial (and
///     tried again when one of its charts changes). 0 tries every curve, as the paper does
///   - `callback`: called with (step name, fraction done) during the run, on the calling thread
///   - `verbose`: print every trial to `std::cerr` (default `false`)
///   - `vertex_point_map`, `vertex_index_map`, `face_index_map`, `halfedge_index_map`
/// \returns a `Merging_result` whose `seam_edges` are the edges to cut (the
///          borders between charts and the curves left inside charts); on
///          invalid input (the statuses of `segment_by_error_controlled_vsa()`,
///          `INVALID_ARGUMENT` for an `area_preservation` or a `compactness_ratio` outside [0, 1])
///          nothing is written.
template <class ConcurrencyTag = CGAL::Parallel_if_available_tag, class TriangleMesh, class FaceChartMap,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
Merging_result<TriangleMesh> merge_charts_by_boundaries(const TriangleMesh& tm, FaceChartMap face_chart,
                                                        const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const auto start = std::chrono::steady_clock::now();
  Merging_result<TriangleMesh> result;
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, tm));
  const auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
  const auto fim = CGAL::get_initialized_face_index_map(tm, np);
  const auto him = CGAL::get_initialized_halfedge_index_map(tm, np);
  const bool verbose = choose_parameter(get_parameter(np, CGAL::internal_np::verbose), false);
  const std::function<void(const char*, double)> progress =
      choose_parameter(get_parameter(np, CGAL::internal_np::callback), std::function<void(const char*, double)>());
  result.status = internal::validate_mesh_to_segment(tm, vpm);
  if(result.status == Error_code::OK && !internal::thresholds_valid(internal::merge_thresholds_from<TriangleMesh>(np)))
    result.status = Error_code::INVALID_ARGUMENT;
  if(result.status != Error_code::OK) return result;

  std::vector<std::size_t> chart, ids;
  internal::read_charts(tm, face_chart, fim, chart, ids);
  // a chart made of several pieces counts as several charts
  const std::size_t n = internal::make_charts_connected(tm, fim, chart);
  result.charts_before = n;
  const std::vector<std::array<double, 3>> points = internal::points_by_index(tm, vpm, vim);
  const std::vector<internal::Face_geometry> geo = internal::face_geometry(tm, vpm, fim);
  typedef typename std::remove_const<decltype(fim)>::type FIM;
  typedef typename std::remove_const<decltype(him)>::type HIM;
  typedef typename std::remove_const<decltype(vim)>::type VIM;
  const internal::Merge_thresholds thresholds = internal::merge_thresholds_from<TriangleMesh>(np);
  internal::Chart_evaluator<TriangleMesh, FIM, VIM> evaluator(tm, fim, vim, points, thresholds);
  internal::Boundary_merger<TriangleMesh, FIM, HIM, VIM> merger(tm, fim, him, evaluator, chart, n, points, vim);
  auto t = std::chrono::steady_clock::now();
  result.charts_split = merger.template split_failing_charts<ConcurrencyTag>(geo, progress);
  result.time_split_ms = internal::milliseconds_since(t);
  merger.build_curves();
  result.boundary_curves = merger.number_of_curves();
  merger.set_order(choose_parameter(get_parameter(np, internal_np::merge_order_t()), Merge_order::SMALLEST_AREA_FIRST));
  merger.set_compactness_ratio(thresholds.compactness_ratio);
  std::tie(result.trials, result.merges) = merger.template merge<ConcurrencyTag>(geo, progress, verbose);
  result.lpfb_not_converged = evaluator.lpfb_not_converged();
  result.number_of_charts = merger.number_of_final_charts();
  result.seam_length = merger.seams(std::back_inserter(result.seam_edges));
  typedef typename boost::property_traits<FaceChartMap>::value_type Id;
  for(auto f : faces(tm)) put(face_chart, f, static_cast<Id>(chart[get(fim, f)]));
  result.time_ms = internal::milliseconds_since(start);
  return result;
}

} // namespace CGAL_QD

#endif // CGAL_QD_CHART_MERGING_H
