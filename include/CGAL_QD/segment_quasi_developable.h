// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_SEGMENT_QUASI_DEVELOPABLE_H
#define CGAL_QD_SEGMENT_QUASI_DEVELOPABLE_H

/// \file segment_quasi_developable.h
/// The quasi-developable segmentation of the paper, Section 2: error-controlled
/// VSA, minimum-cut boundary refinement, optional least-squares boundary
/// denoising and LPFB-based boundary merging, then the LPFB+IP flattening of
/// every final chart.

#include <CGAL_QD/Error_code.h>
#include <CGAL_QD/boundary_denoising.h>
#include <CGAL_QD/boundary_refinement.h>
#include <CGAL_QD/chart_merging.h>
#include <CGAL_QD/flatten_charts.h>
#include <CGAL_QD/internal/chart_evaluator.h>
#include <CGAL_QD/internal/chart_sharing.h>
#include <CGAL_QD/internal/constants.h>
#include <CGAL_QD/internal/point_scale.h>
#include <CGAL_QD/segmentation_measures.h>
#include <CGAL_QD/parameters.h>
#include <CGAL_QD/vsa_segmentation.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/tags.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <chrono>
#include <cstddef>
#include <functional>
#include <set>
#include <iostream>
#include <memory>
#include <vector>

namespace CGAL_QD {

/// \ingroup PkgCGAL_QDRef
/// everything `segment_quasi_developable()` computed.
template <class TriangleMesh>
struct Segmentation_result : Chart_flattening_result<TriangleMesh>
{
  std::size_t charts_after_vsa = 0;
  std::size_t charts_after_refinement = 0;
  /// charts after splitting those beyond the thresholds, before merging
  std::size_t charts_before_merging = 0;

  Vsa_result vsa;
  Refinement_result refinement;  ///< empty when the step was switched off
  Denoising_result denoising;    ///< empty when the step was switched off
  Merging_result<TriangleMesh> merging;

  // `points` (inherited): the denoised positions when the denoising ran, the input positions otherwise
  double time_vsa_ms = 0, time_refine_ms = 0, time_denoise_ms = 0, time_merge_ms = 0, time_total_ms = 0;
};

namespace internal {

// the results of a segmentation of the mesh scaled by `scale` (a power of
// two), in the units of the mesh (but `points`, which the caller sets)
template <class TriangleMesh>
void scale_back(Segmentation_result<TriangleMesh>& r, double scale)
{
  const double length = 1. / scale, area = length * length;
  scale_flattening_back(r, scale, false);
  r.merging.seam_length *= length;
  for(double& a : r.vsa.chart_area) a *= area;
  r.vsa.smoothing_radius *= length;
  r.vsa.min_chart_area *= area;
  r.refinement.border_cost_before *= length;
  r.refinement.border_cost_after *= length;
  r.denoising.max_displacement *= length;
}

inline bool all_finite(const std::vector<std::array<double, 2>>& uv)
{
  for(const auto& p : uv)
    if(!std::isfinite(p[0]) || !std::isfinite(p[1])) return false;
  return true;
}

} // namespace internal

/// \ingroup PkgCGAL_QDRef
/// segments `tm` into charts that each flatten by LPFB+IP within the
/// distortion thresholds and without overlap (paper Section 2):
/// \param tm the triangle mesh
/// \param face_chart the chart id of every face
/// 1. `segment_by_error_controlled_vsa()`: nearly planar charts;
/// 2. `refine_chart_boundaries()`: minimum-cut borders (named parameter `refine_boundaries`, default on);
/// 3. `denoise_chart_boundaries()` on a copy of the points (`denoise_boundaries`, default off);
/// 4. `merge_charts_by_boundaries()` (`merge_charts`, default on), which first splits the
///    charts beyond the thresholds; then every small chart that two or more of its neighbours
///    can share is shared out among them (`share_out_small_charts`, default on but with the
///    paper's criterion);
/// 5. the LPFB+IP flattening of every final chart cut open along the seams, kept in
///    `Segmentation_result::corner_uv`.
///
/// The mesh may be closed, have borders, several connected components or
/// handles: the charts are disks with holes, and the seams open the rest.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or
///         `CGAL::Parallel_if_available_tag` (the normal smoothing of step 1, the trials of the
///         merging and the final flattenings run in parallel with TBB; the result is the same)
/// \tparam TriangleMesh a model of `FaceListGraph`
/// \tparam FaceChartMap a model of `WritablePropertyMap` from faces to an integral type; receives a
///         chart id in `[0, n)` per face
/// \param np optional named parameters: those of the steps (`CGAL_QD::parameters::vsa_tolerance`,
///   `max_number_of_proxies`, `number_of_relaxations`, `CGAL_QD::parameters::refinement_band_width`,
///   `CGAL_QD::parameters::denoising_iterations`, `CGAL_QD::parameters::max_area_distortion`,
///   `CGAL_QD::parameters::max_l2_stretch`, `CGAL_QD::parameters::overlap_tolerance`, `CGAL_QD::parameters::merge_order`,
///   `CGAL_QD::parameters::compactness_ratio`,
///   `CGAL_QD::parameters::max_local_area_distortion`, `CGAL_QD::parameters::chart_criterion`,
///   `CGAL_QD::parameters::area_preservation`), the switches `CGAL_QD::parameters::refine_boundaries`,
///   `CGAL_QD::parameters::denoise_boundaries`, `CGAL_QD::parameters::merge_charts`,
///   `CGAL_QD::parameters::share_out_small_charts`,
///   `CGAL_QD::parameters::denoised_point_map` (receives the denoised points), `callback` (called with a
///   step name, "vsa", "refine", "denoise", "split", "merge", "share" or "flatten", and the fraction done, always
///   on the calling thread), `verbose`
///   (a line per step and per trial on `std::cerr`), and `vertex_point_map`, `vertex_index_map`,
///   `face_index_map`, `halfedge_index_map`.
/// \returns a `Segmentation_result`; `EMPTY_MESH`, `NOT_TRIANGLE_MESH`, `INVALID_COORDINATES` or
///          `DEGENERATE_FACE` on invalid input, `INVALID_ARGUMENT` for an `area_preservation` or a
///          `compactness_ratio` outside [0, 1], in which case nothing is written.
template <class ConcurrencyTag = CGAL::Parallel_if_available_tag, class TriangleMesh, class FaceChartMap,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
Segmentation_result<TriangleMesh> segment_quasi_developable(const TriangleMesh& tm, FaceChartMap face_chart,
                                                            const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::face_descriptor face_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::edge_descriptor edge_descriptor;

  const auto start = std::chrono::steady_clock::now();
  Segmentation_result<TriangleMesh> result;
  const auto input_vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                          get_const_property_map(CGAL::vertex_point, tm));
  // coordinates beyond [2^-64, 2^64] are scaled by a power of two, which is
  // exact (internal/point_scale.h): every step sees the scaled points, and the
  // results in units of length are scaled back at the end
  const double scale = internal::normalizing_scale(internal::largest_coordinate(vertices(tm), input_vpm));
  const internal::Scaled_point_map<typename std::remove_const<decltype(input_vpm)>::type> vpm{input_vpm, scale};
  const auto snp = np.vertex_point_map(vpm);
  const auto vim = CGAL::get_initialized_vertex_index_map(tm, snp);
  const auto fim = CGAL::get_initialized_face_index_map(tm, snp);
  const auto him = CGAL::get_initialized_halfedge_index_map(tm, snp);
  const bool refine = choose_parameter(get_parameter(snp, internal_np::refine_boundaries_t()), true);
  const bool denoise = choose_parameter(get_parameter(snp, internal_np::denoise_boundaries_t()), false);
  const bool merge = choose_parameter(get_parameter(snp, internal_np::merge_charts_t()), true);
  const bool verbose = choose_parameter(get_parameter(snp, CGAL::internal_np::verbose), false);
  const std::function<void(const char*, double)> progress =
      choose_parameter(get_parameter(snp, CGAL::internal_np::callback), std::function<void(const char*, double)>());
  typedef typename std::remove_const<decltype(fim)>::type FIM;
  typedef typename std::remove_const<decltype(him)>::type HIM;
  typedef typename std::remove_const<decltype(vim)>::type VIM;

  result.status = internal::validate_mesh_to_segment(tm, vpm);
  if(result.status == Error_code::OK && !internal::thresholds_valid(internal::merge_thresholds_from<TriangleMesh>(snp)))
    result.status = Error_code::INVALID_ARGUMENT;
  if(result.status != Error_code::OK) return result;
  const std::size_t nf = static_cast<std::size_t>(num_faces(tm));
  result.number_of_faces = nf;
  std::vector<std::size_t> chart(nf, 0);
  const internal::Indexed_face_writer<face_descriptor, FIM> chart_map{&chart, fim};

  // 1. error-controlled VSA
  if(progress) progress("vsa", 0.);
  result.vsa = segment_by_error_controlled_vsa<ConcurrencyTag>(tm, chart_map, snp);
  result.time_vsa_ms = result.vsa.time_ms;
  result.charts_after_vsa = result.charts_after_refinement = result.vsa.number_of_charts;
  if(verbose) std::cerr << "VSA: " << result.charts_after_vsa << " charts in " << result.time_vsa_ms << " ms\n";

  // 2. minimum-cut refinement
  if(refine) {
    if(progress) progress("refine", 0.);
    result.refinement = refine_chart_boundaries(tm, chart_map, snp);
    result.time_refine_ms = result.refinement.time_ms;
    result.charts_after_refinement = result.refinement.number_of_charts;
    if(verbose)
      std::cerr << "refinement: " << result.refinement.pairs_refined << " borders moved, "
                << result.refinement.pairs_kept << " kept, cost " << result.refinement.border_cost_before << " -> "
                << result.refinement.border_cost_after << " in " << result.time_refine_ms << " ms\n";
  }

  // 3. denoising, on a copy of the points
  result.points = internal::points_by_index(tm, vpm, vim);
  if(denoise) {
    if(progress) progress("denoise", 0.);
    internal::Vector_point_map<VIM> copy{&result.points, vim};
    result.denoising = denoise_chart_boundaries(tm, chart_map, copy, snp);
    result.time_denoise_ms = result.denoising.time_ms;
    if(verbose)
      std::cerr << "denoising: " << result.denoising.number_of_border_vertices << " vertices, largest move "
                << result.denoising.max_displacement << " in " << result.time_denoise_ms << " ms\n";
  }

  // 4. splitting and merging
  auto t = std::chrono::steady_clock::now();
  const std::vector<internal::Face_geometry> geo = internal::face_geometry(tm, vpm, fim);
  const internal::Merge_thresholds thresholds = internal::merge_thresholds_from<TriangleMesh>(snp);
  // the splitting and the merging keep every chart a little below the A_loc
  // bound: the final flattening then has room to give the two sides of every
  // seam the same length, and the seam smoothing room to move the borders
  internal::Merge_thresholds trial_thresholds = thresholds;
  trial_thresholds.max_local_area_distortion *= 1. - internal::local_area_distortion_margin;
  internal::Chart_evaluator<TriangleMesh, FIM, VIM> evaluator(tm, fim, vim, result.points, trial_thresholds);
  // the final flattening (step 5) of a chart that a trial accepted starts
  // from that trial (a scaled mesh is always flattened: see there)
  const bool final_flattening =
      choose_parameter(get_parameter(snp, internal_np::final_flattening_t()), true) || scale != 1.;
  if(final_flattening) evaluator.set_trial_memory(std::make_shared<internal::Trial_memory>());
  internal::Boundary_merger<TriangleMesh, FIM, HIM, VIM> merger(tm, fim, him, evaluator, chart,
                                                                result.charts_after_refinement, result.points, vim);
  result.merging.charts_before = result.charts_after_refinement;
  result.merging.charts_split = merger.template split_failing_charts<ConcurrencyTag>(geo, progress);
  result.merging.time_split_ms = internal::milliseconds_since(t);
  result.charts_before_merging = result.charts_after_refinement + result.merging.charts_split;
  merger.build_curves();
  result.merging.boundary_curves = merger.number_of_curves();
  merger.set_order(choose_parameter(get_parameter(snp, internal_np::merge_order_t()), Merge_order::SMALLEST_AREA_FIRST));
  merger.set_compactness_ratio(thresholds.compactness_ratio);
  if(progress && merge) progress("merge", 0.);
  std::tie(result.merging.trials, result.merging.merges) =
      merger.template merge<ConcurrencyTag>(geo, progress, verbose, merge);
  result.merging.lpfb_not_converged = evaluator.lpfb_not_converged();
  result.number_of_charts = result.merging.number_of_charts = merger.number_of_final_charts();
  result.merging.seam_length = merger.seams(std::back_inserter(result.merging.seam_edges));
  if(merge && result.number_of_charts > 2 &&
     choose_parameter(get_parameter(snp, internal_np::share_out_small_charts_t()),
                      thresholds.criterion != Chart_criterion::LPFB_IP)) {
    if(progress) progress("share", 0.);
    std::vector<char> seam(num_halfedges(tm), 0);
    for(edge_descriptor e : result.merging.seam_edges)
      seam[get(him, halfedge(e, tm))] = seam[get(him, opposite(halfedge(e, tm), tm))] = 1;
    std::size_t n = result.number_of_charts;
    std::tie(result.merging.charts_shared_out, result.merging.sharing_trials) =
        internal::share_out_small_charts<ConcurrencyTag>(
            tm, fim, him, vim, result.points, geo,
            [&](const std::vector<face_descriptor>& fs, const auto& is_cut) {
              return evaluator.evaluate(fs, is_cut, nullptr, nullptr, nullptr, 1000., true, nullptr).accepted;
            },
            chart, n, seam);
    if(result.merging.charts_shared_out > 0) {
      result.number_of_charts = result.merging.number_of_charts = n;
      result.merging.seam_edges.clear();
      for(edge_descriptor e : edges(tm))
        if(seam[get(him, halfedge(e, tm))]) result.merging.seam_edges.push_back(e);
      result.merging.seam_length = internal::seam_length_of(tm, result.merging.seam_edges, result.points, vim);
    }
    if(progress) progress("share", 1.);
  }
  result.merging.time_ms = result.time_merge_ms = internal::milliseconds_since(t);
  if(verbose)
    std::cerr << "merging: " << result.charts_before_merging << " charts (" << result.merging.charts_split
              << " from splitting) -> " << result.number_of_charts << ", " << result.merging.trials << " trials, "
              << result.merging.merges << " merges, " << result.merging.charts_shared_out << " charts shared out ("
              << result.merging.sharing_trials << " trials) in " << result.time_merge_ms << " ms\n";

  // 5. the flattening of every final chart (always for a scaled mesh: a
  // flattening of the charts made later would see the points in the units of
  // the mesh)
  if(final_flattening) {
    // with the merging's orderings and trials: a chart made by a merging
    // trial is flattened again with the same pattern, from that trial
    internal::flatten_final_charts<ConcurrencyTag>(tm, vpm, fim, vim, him, chart, result.number_of_charts,
                                                   result.merging.seam_edges, thresholds, progress, result,
                                                   nullptr, false, evaluator.orderings(), nullptr,
                                                   static_cast<const Chart_flattening_result<TriangleMesh>*>(nullptr),
                                                   evaluator.trial_memory());
  } else {
    result.flattened = false;
    result.number_of_faces = nf;
    result.seam_edges = result.merging.seam_edges;
    result.seam_length = internal::seam_length_of(tm, result.seam_edges, result.points, vim);
  }
  if(verbose && result.flattened)
    std::cerr << "flattening: " << result.number_of_charts << " charts, max A " << result.max_area_distortion
              << " %, max L2 " << result.max_l2_stretch << ", " << result.overlapping_charts << " overlapping, in "
              << result.time_flatten_ms << " ms\n";

  if(scale != 1.) {
    internal::scale_back(result, scale);
    if(denoise)
      for(auto& p : result.points)
        for(double& x : p) x /= scale;
    else
      result.points = internal::points_by_index(tm, input_vpm, vim);  // exactly the input
    if(!internal::all_finite(result.corner_uv)) {
      // a flattening larger than its surface overflowed on the way back
      Segmentation_result<TriangleMesh> refused;
      refused.status = Error_code::COORDINATES_OUT_OF_RANGE;
      return refused;
    }
  }
  typedef typename boost::property_traits<FaceChartMap>::value_type Id;
  for(face_descriptor f : faces(tm)) put(face_chart, f, static_cast<Id>(chart[get(fim, f)]));
  if(denoise) internal::write_points(tm, result.points, vim, get_parameter(snp, internal_np::denoised_point_map_t()));
  result.time_total_ms = internal::milliseconds_since(start);
  return result;
}

} // namespace CGAL_QD

#endif // CGAL_QD_SEGMENT_QUASI_DEVELOPABLE_H
