// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_SHORTEN_CHART_CUTS_H
#define CGAL_QD_SHORTEN_CHART_CUTS_H

/// \file shorten_chart_cuts.h
/// Closes the cuts inside the charts of a finished segmentation, whole or
/// from their loose end, wherever the chart still flattens within the
/// thresholds without them.

#include <CGAL_QD/Error_code.h>
#include <CGAL_QD/chart_criterion.h>
#include <CGAL_QD/flatten_charts.h>
#include <CGAL_QD/internal/chart_evaluator.h>
#include <CGAL_QD/internal/constants.h>
#include <CGAL_QD/internal/flattening_cache.h>
#include <CGAL_QD/internal/cut_shortening.h>
#include <CGAL_QD/internal/point_scale.h>
#include <CGAL_QD/internal/validation.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>
#include <CGAL/tags.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstddef>
#include <functional>
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL_QD {

/// \ingroup PkgCGAL_QDRef
/// what `shorten_chart_cuts()` did.
template <class TriangleMesh>
struct Cut_shortening_result
{
  Error_code status = Error_code::OK;
  /// whether shortened cuts were kept: `flattening` then holds the charts flattened with them
  bool kept = false;
  std::size_t cut_curves = 0;      ///< the cut curves inside the charts of the input
  /// of them, those that the charts' trials closed whole or in part, before the flattening that
  /// decides what is kept
  std::size_t cuts_passing_trials = 0;
  std::size_t cuts_shortened = 0;  ///< of them, those closed whole or in part in the end (when `kept`)
  std::size_t cuts_closed = 0;     ///< of `cuts_shortened`, those closed whole
  double cut_length = 0;           ///< the length of the input's cuts
  double cut_length_closed = 0;    ///< the length closed (when `kept`)
  std::size_t trials = 0;          ///< charts flattened and measured to decide
  /// the flattenings after the trials: one, and one more each time the cuts of charts that then
  /// failed were put back
  std::size_t flattenings = 0;
  /// the flattening of the charts with the shortened cuts, when `kept` (its `flattened` is `false`
  /// otherwise)
  Chart_flattening_result<TriangleMesh> flattening;
  double time_ms = 0;

  explicit operator bool() const { return status == Error_code::OK; }
};

/// \ingroup PkgCGAL_QDRef
/// closes the cuts inside the charts of a segmentation where the charts still
/// flatten within the thresholds without them, flattens again the charts it
/// changed, and fits their neighbours to them.
///
/// A cut is a seam with the same chart on both sides (a slit that lets a
/// chart flatten, as the merging leaves them); most end loose inside their
/// chart (darts). The merging removes a border between two charts only whole,
/// so many cuts are longer than their chart needs. Each cut curve (a chain of
/// cut edges between the chart's border, the mesh's border, junctions of three
/// or more cuts and loose ends) is tried, in each chart from the longest: it
/// is closed whole if the chart, flattened as a merging trial flattens it
/// (`Chart_criterion`) but with the optimisation started from the chart's
/// flattening in `segmentation` instead of LPFB+IP (the two sides of the
/// edges closed meet halfway, so the chart's seams keep lengths near those
/// its neighbours match), stays within the thresholds with a margin of 5 % on
/// A_loc, else over half of its edges from its loose end, else a quarter, and
/// so on down to one edge, the first that passes being kept; a cut without a
/// loose end is closed whole or not at all. The charts do not change. Then
/// the charts with shortened cuts are flattened again as `flatten_charts()`
/// does, and the charts next to them start from their flattenings in
/// `segmentation`; the two sides of their seams are fitted to a common length.
/// Every other chart keeps its flattening from `segmentation`,
/// and the sides of its seams are the lengths its neighbours fit to (a
/// flattening made afresh need not match the seams an earlier one matched:
/// seams just within 0.5 % can flip). The last cut closed in a chart that is
/// then rejected or overlaps, or one of whose seams no longer matches in
/// length, is put back as it was, which leaves the chart as it passed the
/// trial of the cut before (or, where none of the charts in the failure was
/// shortened, the last cuts of the charts next to them: the fit couples the
/// charts), and the charts flattened again, until every
/// chart is accepted, none overlaps and no more seam curves end unmatched than
/// in `segmentation`: the shortened cuts are then kept. A shorter cut is
/// shorter to cut and to sew, and a chart with shorter cuts is rounder (a cut
/// counts twice in its perimeter).
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or
///         `CGAL::Parallel_if_available_tag` (the charts are tried in parallel, the trials of a
///         curve two at a time, and the charts flattened as `flatten_charts()` does); the result,
///         trials included, is the same
/// \tparam TriangleMesh a model of `FaceListGraph`
/// \tparam FaceChartMap a model of `ReadablePropertyMap` from faces to an integral chart id in
///         `[0, segmentation.number_of_charts)`
/// \param tm the triangle mesh
/// \param face_chart the charts of the segmentation
/// \param segmentation the flattening of those charts (`segment_quasi_developable()`'s result,
///        `smooth_segmentation_seams()`'s `flattening` for its mesh, or `flatten_charts()`'s):
///        its `seam_edges`, `seam_curves_matched`, `unmatched_seams`, `charts`, `corner_uv` and
///        `points` (the positions the charts are flattened with, when there is one per vertex)
///        are used
/// \param np optional named parameters: the thresholds and criterion of the segmentation
///   (`CGAL_QD::parameters::max_area_distortion`, `max_l2_stretch`, `max_local_area_distortion`,
///   `chart_criterion`, `overlap_tolerance`, `area_preservation`), as given to it, and
///   `vertex_point_map`, `vertex_index_map`, `face_index_map`, `halfedge_index_map`
/// \returns a `Cut_shortening_result`; with `kept` false, the input's segmentation stands.
///          `INVALID_ARGUMENT` if `segmentation` is not a flattened, successful result for `tm`,
///          a chart id is out of range, or a threshold is invalid; the statuses of
///          `flatten_charts()` on invalid input.
/// \sa `smooth_chart_cuts()`, which makes the cuts smooth instead
template <class ConcurrencyTag = CGAL::Parallel_if_available_tag, class TriangleMesh, class FaceChartMap,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
Cut_shortening_result<TriangleMesh> shorten_chart_cuts(const TriangleMesh& tm, const FaceChartMap& face_chart,
                                                       const Chart_flattening_result<TriangleMesh>& segmentation,
                                                       const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::edge_descriptor edge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;

  const auto start = std::chrono::steady_clock::now();
  Cut_shortening_result<TriangleMesh> result;
  result.flattening.flattened = false;  // on every return until one is kept
  // coordinates beyond [2^-64, 2^64] are scaled by a power of two, which is
  // exact (internal/point_scale.h): the points and the flattening of
  // `segmentation`, and what is returned is scaled back
  const auto input_vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                          get_const_property_map(CGAL::vertex_point, tm));
  const double scale = internal::normalizing_scale(internal::largest_coordinate(vertices(tm), input_vpm));
  const internal::Scaled_point_map<typename std::remove_const<decltype(input_vpm)>::type> vpm{input_vpm, scale};
  Chart_flattening_result<TriangleMesh> scaled_segmentation;
  if(scale != 1.) {
    scaled_segmentation = segmentation;
    internal::scale_flattening_back(scaled_segmentation, 1. / scale, true);
  }
  const Chart_flattening_result<TriangleMesh>& seg = scale != 1. ? scaled_segmentation : segmentation;
  auto finish = [&]() {
    if(scale != 1.) {
      if(result.kept) internal::scale_flattening_back(result.flattening, scale, true);
      result.cut_length *= 1. / scale;
      result.cut_length_closed *= 1. / scale;
    }
    result.time_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return result;
  };
  const auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
  const auto fim = CGAL::get_initialized_face_index_map(tm, np);
  const auto him = CGAL::get_initialized_halfedge_index_map(tm, np);
  typedef typename std::remove_const<decltype(fim)>::type FIM;
  typedef typename std::remove_const<decltype(vim)>::type VIM;
  const internal::Merge_thresholds thresholds = internal::merge_thresholds_from<TriangleMesh>(np);

  result.status = internal::validate_mesh_to_segment(tm, vpm);
  if(result.status != Error_code::OK) return finish();
  const std::size_t nf = static_cast<std::size_t>(num_faces(tm)), n = seg.number_of_charts;
  if(!internal::thresholds_valid(thresholds) || !seg || !seg.flattened ||
     seg.number_of_faces != nf || seg.corner_uv.size() != 3 * nf ||
     seg.charts.size() != n) {
    result.status = Error_code::INVALID_ARGUMENT;
    return finish();
  }
  std::vector<std::size_t> chart(nf);
  for(face_descriptor f : faces(tm)) {
    const long long id = static_cast<long long>(get(face_chart, f));
    if(id < 0 || static_cast<unsigned long long>(id) >= n) {
      result.status = Error_code::INVALID_ARGUMENT;
      return finish();
    }
    chart[get(fim, f)] = static_cast<std::size_t>(id);
  }
  // the seams (the mesh border is open anyway)
  std::vector<char> seam(num_halfedges(tm), 0);
  for(edge_descriptor e : seg.seam_edges)
    if(!is_border_edge(halfedge(e, tm), tm))
      seam[get(him, halfedge(e, tm))] = seam[get(him, opposite(halfedge(e, tm), tm))] = 1;

  // the points the segmentation was flattened with (the denoised ones, say)
  const std::vector<std::array<double, 3>> points =
      seg.points.size() == static_cast<std::size_t>(num_vertices(tm))
          ? seg.points
          : internal::points_by_index(tm, vpm, vim);
  // the cuts tried as the merging tries a chart, with its margin below the A_loc bound
  internal::Merge_thresholds trial_thresholds = thresholds;
  trial_thresholds.max_local_area_distortion *= 1. - internal::local_area_distortion_margin;
  // the charts whose cuts are shortened are flattened again from their last
  // accepted trial
  internal::Chart_evaluator<TriangleMesh, FIM, VIM> evaluator(tm, fim, vim, points, trial_thresholds);
  evaluator.set_trial_memory(std::make_shared<internal::Trial_memory>());
  // a trial starts from the chart's flattening in `segmentation`, the cuts it
  // closes closed halfway between their two sides: the lengths of the
  // chart's seams stay near those its neighbours match
  const auto trial = [&](const std::vector<face_descriptor>& fs, const auto& is_cut) {
    std::vector<std::array<double, 2>> start(3 * fs.size());
    for(std::size_t i = 0; i < fs.size(); ++i)
      for(std::size_t j = 0; j < 3; ++j) start[3 * i + j] = seg.corner_uv[3 * get(fim, fs[i]) + j];
    return evaluator.evaluate(fs, is_cut, nullptr, nullptr, &start, 1000., true, nullptr).accepted;
  };
  std::vector<std::vector<internal::Closed_cut>> closed;
  const internal::Cut_shortening s =
      internal::shorten_cuts<ConcurrencyTag>(tm, fim, him, vim, points, trial, chart, n, seam, closed);
  result.cut_curves = s.cut_curves;
  result.cut_length = s.length_before;
  result.trials = s.trials;
  result.cuts_passing_trials = s.curves_shortened;
  // whether each chart has a cut closed
  auto shortened_charts = [&] {
    std::vector<char> out(n, 0);
    for(std::size_t k = 0; k < n; ++k) out[k] = closed[k].empty() ? 0 : 1;
    return out;
  };

  // the charts shortened flattened again with the cuts left, and their
  // neighbours fitted to them; where a chart shortened is then rejected or
  // overlaps, or a seam of it stops matching in length, the last cut it
  // closed is put back as it was (the chart as it was when the cut before
  // passed its trial), and the charts flattened again
  const std::size_t unmatched_before = seg.number_of_seam_curves - seg.seam_curves_matched;
  auto unmatched_before_too = [&](const std::pair<std::size_t, std::size_t>& pair) {
    return std::find(seg.unmatched_seams.begin(), seg.unmatched_seams.end(), pair) !=
           seg.unmatched_seams.end();
  };
  Chart_flattening_result<TriangleMesh>& f = result.flattening;
  // a chart whose cuts stay as they were is flattened again, or fitted to
  // the same lengths, in the same way as the last time: looked up
  internal::Flattening_cache<Chart_report> cache;
  for(std::vector<char> shortened = shortened_charts();
      std::find(shortened.begin(), shortened.end(), 1) != shortened.end(); shortened = shortened_charts()) {
    std::vector<edge_descriptor> seams;
    for(edge_descriptor e : edges(tm))
      if(seam[get(him, halfedge(e, tm))]) seams.push_back(e);
    // the charts marked, and the charts across a seam from them
    auto with_neighbours = [&](std::vector<char> marked) {
      std::vector<char> out = marked;
      for(edge_descriptor e : seams) {
        const halfedge_descriptor h = halfedge(e, tm);
        const std::size_t a = chart[get(fim, face(h, tm))], b = chart[get(fim, face(opposite(h, tm), tm))];
        if(marked[a]) out[b] = 1;
        if(marked[b]) out[a] = 1;
      }
      return out;
    };
    // the charts shortened are flattened again, and their neighbours fitted
    // from their flattenings; the others keep their flattening
    const std::vector<char> near = with_neighbours(shortened);
    std::vector<char> frozen(n, internal::KEEP_AS_BEFORE);
    for(std::size_t k = 0; k < n; ++k)
      if(near[k]) frozen[k] = shortened[k] ? internal::FLATTEN_AGAIN : internal::FIT_FROM_BEFORE;
    f = Chart_flattening_result<TriangleMesh>();
    f.points = points;
    internal::flatten_final_charts<ConcurrencyTag>(tm, vpm, fim, vim, him, chart, n, seams, thresholds,
                                                   std::function<void(const char*, double)>(), f, &cache, false,
                                                   evaluator.orderings(), &frozen, &seg,
                                                   evaluator.trial_memory());
    ++result.flattenings;
    cache.next_generation();
    if(!f) {
      result.status = f.status;
      break;
    }
    if(f.rejected_charts == 0 && f.overlapping_charts == 0 &&
       f.number_of_seam_curves - f.seam_curves_matched <= unmatched_before) {
      result.kept = true;
      break;
    }
    std::vector<char> restore(n, 0);
    for(std::size_t k = 0; k < n; ++k)
      if(!f.charts[k].accepted || f.charts[k].overlap) restore[k] = 1;
    for(const auto& pair : f.unmatched_seams)
      if(!unmatched_before_too(pair)) restore[pair.first] = restore[pair.second] = 1;
    // the fit of the seams couples the charts: where no chart in the failure
    // was shortened, the last cuts of the shortened charts next to them are
    // put back
    bool restored = false;
    for(int ring = 0; ring < 2 && !restored; ++ring) {
      if(ring == 1) restore = with_neighbours(restore);
      for(std::size_t k = 0; k < n; ++k)
        if(restore[k] && shortened[k]) {
          for(std::size_t h : closed[k].back().halfedges) seam[h] = 1;
          closed[k].pop_back();
          restored = true;
        }
    }
    if(!restored) break;
  }
  if(!result.kept) {
    result.flattening = Chart_flattening_result<TriangleMesh>();
    result.flattening.flattened = false;
    return finish();
  }
  for(std::size_t k = 0; k < n; ++k)
    for(const internal::Closed_cut& c : closed[k]) {
      ++result.cuts_shortened;
      if(c.whole) ++result.cuts_closed;
      result.cut_length_closed += c.length;
    }
  return finish();
}

} // namespace CGAL_QD

#endif // CGAL_QD_SHORTEN_CHART_CUTS_H
