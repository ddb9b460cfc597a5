// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_SMOOTH_SEGMENTATION_SEAMS_H
#define CGAL_QD_SMOOTH_SEGMENTATION_SEAMS_H

/// \file smooth_segmentation_seams.h
/// The seams of a finished segmentation made smooth wherever the pieces allow
/// it: `smooth_chart_boundaries()` and `smooth_chart_cuts()` tried with less
/// and less smoothing until every chart flattens within the thresholds again
/// and every seam whose two sides matched in length still does.

#include <CGAL_QD/Error_code.h>
#include <CGAL_QD/flatten_charts.h>
#include <CGAL_QD/internal/point_scale.h>
#include <CGAL_QD/internal/smoothing_try.h>
#include <CGAL_QD/parameters.h>
#include <CGAL_QD/segmentation_measures.h>
#include <CGAL_QD/smooth_chart_boundaries.h>
#include <CGAL_QD/smooth_chart_cuts.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/tags.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstddef>
#include <functional>
#include <map>
#include <memory>
#include <set>
#include <utility>
#include <vector>

namespace CGAL_QD {

/// \ingroup PkgCGAL_QDRef
/// what `smooth_segmentation_seams()` did.
template <class TriangleMesh>
struct Seam_smoothing_result
{
  Error_code status = Error_code::OK;
  /// whether smoothed seams were kept: the output mesh holds them, and `flattening` its charts
  bool kept = false;
  /// the smoothing calls of the try that was kept, summed (`zigzag_before` of the input's seams,
  /// `zigzag_after` of the kept ones); of the first try when none was kept
  Boundary_smoothing_result smoothing;
  /// the seam curves smoothing started from: the borders between two charts and the cuts inside charts
  std::size_t number_of_curves = 0;
  /// when nothing was kept: the charts beyond the thresholds after the first try
  std::size_t rejected_charts = 0;
  std::size_t tries = 0;  ///< smoothings tried and flattened
  /// the flattening of the charts of the output mesh, when `kept` (its `flattened` is `false` otherwise)
  Chart_flattening_result<TriangleMesh> flattening;
  /// for a `segmentation` given without its flattening (`segment_quasi_developable()` with
  /// `CGAL_QD::parameters::final_flattening(false)`): the flattening of its charts as they are, made
  /// where it was needed, and always when nothing was kept (`flattened` is `false` otherwise)
  Chart_flattening_result<TriangleMesh> input_flattening;
  double time_ms = 0;  ///< every try: smoothing and flattening

  explicit operator bool() const { return status == Error_code::OK; }
};

/// \ingroup PkgCGAL_QDRef
/// replaces the seams of a segmentation, which follow triangle edges, by
/// smooth curves through the triangles wherever the charts stay within the
/// thresholds, and returns the refined mesh with its charts and their
/// flattening. It works on copies; the input is not changed.
///
/// Every border between two charts (`smooth_chart_boundaries()`) and the cuts
/// inside every chart (`smooth_chart_cuts()`) start with the full smoothing
/// (32 rounds). After each try the charts are flattened again
/// (`flatten_charts()`; a chart that the try left as it was takes its
/// flattening from the try before); the borders and cuts of a chart that
/// leaves the thresholds are smoothed less at the next try (8 rounds, then 2:
/// the staircase goes and the course of the seam stays), then left along the
/// edges. Where every chart is accepted, the seams are fitted to common
/// lengths as `flatten_charts()` does, and a seam (a border between two
/// charts, or the cuts of a chart) that no longer matches in length where it
/// did (its two sides within 0.5 %), or that did not match and whose sides end
/// further apart than the worst seam of the input, is smoothed less in the
/// same way; once it follows
/// the edges, the curves of its charts are (or, where those follow the edges
/// too, of the charts next to them). Each curve goes one step per try, at most
/// 10 tries. The try kept is the one with every chart accepted and the most
/// seams matched (as many: the smallest zigzag).
///
/// `segmentation` may come without its flattening
/// (`CGAL_QD::parameters::final_flattening(false)`): the charts as they are
/// are then flattened only where that is needed, to compare the seams of a try
/// whose charts are all accepted but not all of whose seams match, and when no
/// try is kept; `input_flattening` returns it. With every seam of the first
/// kept try matched, that saves a flattening of the whole mesh.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or
///         `CGAL::Parallel_if_available_tag` (for the flattenings); the result is the same
/// \tparam TriangleMesh a model of `MutableFaceGraph` and `FaceListGraph` with an internal
///         vertex point property map
/// \tparam FaceChartMap a model of `ReadablePropertyMap` from faces to an integral chart id
/// \tparam OutputFaceChartMap a model of `WritablePropertyMap` from the faces of `out` to an
///         integral chart id, that accepts the faces added to `out` (e.g. a `Surface_mesh`
///         property map of `out`, or an associative map)
/// \param tm the triangle mesh
/// \param face_chart the charts of the segmentation
/// \param segmentation the flattening of those charts (`segment_quasi_developable()`'s result, or
///        `flatten_charts()`'s): its `seam_edges` (the borders and the cuts inside charts),
///        `unmatched_seams` and `max_seam_length_mismatch` are used; or
///        `segment_quasi_developable()`'s result without its flattening (see above)
/// \param out an empty mesh that receives the refined mesh when smoothed seams are kept
/// \param out_chart receives the chart of every face of `out`
/// \param np optional named parameters: the thresholds and criterion of the segmentation
///   (`CGAL_QD::parameters::max_area_distortion`, `max_l2_stretch`, `max_local_area_distortion`,
///   `chart_criterion`, `overlap_tolerance`, `area_preservation`), as given to it
/// \returns a `Seam_smoothing_result`; with `kept` false, `out` stays empty and the input's
///          segmentation stands. `INVALID_ARGUMENT` if `out` is not empty, `segmentation` is not
///          a successful result for `tm` or `area_preservation` is outside [0, 1]; the statuses of `smooth_chart_boundaries()` on invalid
///          input. On any status but `OK`, `out` stays empty.
/// \sa `smooth_chart_boundaries()`, `smooth_chart_cuts()`, `seam_zigzag()`
template <class ConcurrencyTag = CGAL::Parallel_if_available_tag, class TriangleMesh, class FaceChartMap,
          class OutputFaceChartMap, class NamedParameters = CGAL::parameters::Default_named_parameters>
Seam_smoothing_result<TriangleMesh> smooth_segmentation_seams(
    const TriangleMesh& tm, const FaceChartMap& face_chart, const Chart_flattening_result<TriangleMesh>& segmentation,
    TriangleMesh& out, OutputFaceChartMap out_chart, const NamedParameters& np = CGAL::parameters::default_values())
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::edge_descriptor edge_descriptor;
  typedef internal::Smoothing_try<TriangleMesh> Try;
  typedef std::pair<std::size_t, std::size_t> Chart_pair;

  const auto start = std::chrono::steady_clock::now();
  Seam_smoothing_result<TriangleMesh> result;
  result.flattening.flattened = false;  // on every return until one is kept
  result.input_flattening.flattened = false;  // on every return until it is made
  if(num_vertices(out) != 0 || num_faces(out) != 0 || !segmentation ||
     segmentation.number_of_faces != static_cast<std::size_t>(num_faces(tm))) {
    result.status = Error_code::INVALID_ARGUMENT;
    return result;
  }
  const internal::Merge_thresholds thresholds = internal::merge_thresholds_from<TriangleMesh>(np);
  // coordinates beyond [2^-64, 2^64] are scaled by a power of two, which is
  // exact (internal/point_scale.h): the tries are copies of the mesh with the
  // points scaled, and what is returned is scaled back
  const auto input_vpm = get(CGAL::vertex_point, tm);
  const double scale = internal::normalizing_scale(internal::largest_coordinate(vertices(tm), input_vpm));
  const internal::Scaled_point_map<decltype(input_vpm)> vpm{input_vpm, scale};
  result.status = internal::validate_mesh_to_segment(tm, vpm);
  if(result.status == Error_code::OK && !internal::thresholds_valid(thresholds)) result.status = Error_code::INVALID_ARGUMENT;
  if(result.status != Error_code::OK) return result;
  // the flattening of the charts as they are: `segmentation` itself, or made
  // here as `segment_quasi_developable()` would have made it
  auto input_flattening = [&]() -> const Chart_flattening_result<TriangleMesh>& {
    if(segmentation.flattened) return segmentation;
    if(!result.input_flattening.flattened) {
      const auto vim = CGAL::get_initialized_vertex_index_map(tm);
      const auto fim = CGAL::get_initialized_face_index_map(tm);
      const auto him = CGAL::get_initialized_halfedge_index_map(tm);
      std::vector<std::size_t> chart(static_cast<std::size_t>(num_faces(tm)));
      for(auto f : faces(tm)) {
        chart[get(fim, f)] = static_cast<std::size_t>(get(face_chart, f));
        if(chart[get(fim, f)] >= segmentation.number_of_charts) {  // charts not numbered as in `segmentation`
          result.status = Error_code::INVALID_ARGUMENT;
          return result.input_flattening;
        }
      }
      Chart_flattening_result<TriangleMesh>& made = result.input_flattening;
      made = Chart_flattening_result<TriangleMesh>();
      if(segmentation.points.size() == static_cast<std::size_t>(num_vertices(tm))) {
        made.points = segmentation.points;
        for(auto& p : made.points)
          for(double& x : p) x *= scale;
      } else {
        made.points = internal::points_by_index(tm, vpm, vim);
      }
      internal::flatten_final_charts<ConcurrencyTag>(tm, vpm, fim, vim, him, chart,
                                                     segmentation.number_of_charts, segmentation.seam_edges,
                                                     thresholds, std::function<void(const char*, double)>(), made);
    }
    return result.input_flattening;
  };
  // the charts as they are when nothing was kept, whatever stopped the smoothing
  const auto finish = [&]() {
    if(!result.kept && !segmentation.flattened) {
      const Error_code smoothing_status = result.status;
      result.status = Error_code::OK;
      input_flattening();
      if(result.status == Error_code::OK) result.status = smoothing_status;
    }
    if(scale != 1.) {
      if(result.input_flattening.flattened) internal::scale_flattening_back(result.input_flattening, scale, true);
      result.smoothing.max_border_move *= 1. / scale;
    }
    result.time_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return result;
  };
  if(segmentation.number_of_charts < 2) return finish();

  auto pair_of = [](std::size_t a, std::size_t b) { return Chart_pair((std::min)(a, b), (std::max)(a, b)); };
  const std::array<std::size_t, 3> strengths = {{32, 8, 2}};  // smoothing rounds; level 3: along the edges
  const int max_tries = 10;
  const std::size_t along_edges = strengths.size();

  // the cuts inside charts of the input
  std::set<edge_descriptor> seams(segmentation.seam_edges.begin(), segmentation.seam_edges.end());
  auto input_chart = [&](halfedge_descriptor h) { return static_cast<std::size_t>(get(face_chart, face(h, tm))); };
  auto is_input_cut = [&](edge_descriptor e) {
    const halfedge_descriptor h = halfedge(e, tm);
    return seams.count(e) > 0 && !is_border_edge(h, tm) && input_chart(h) == input_chart(opposite(h, tm));
  };

  // the smoothing level of every border, and of the cuts of every chart
  std::map<Chart_pair, std::size_t> level;
  std::vector<std::vector<Chart_pair>> pairs_of(segmentation.number_of_charts);
  for(edge_descriptor e : edges(tm)) {
    const halfedge_descriptor h = halfedge(e, tm);
    if(is_border_edge(h, tm)) continue;
    const std::size_t a = input_chart(h), b = input_chart(opposite(h, tm));
    if(a == b && !is_input_cut(e)) continue;
    if(a >= pairs_of.size() || b >= pairs_of.size()) {  // charts not numbered as in `segmentation`
      result.status = Error_code::INVALID_ARGUMENT;
      return result;
    }
    const Chart_pair p = pair_of(a, b);
    if(level.emplace(p, 0).second) {
      pairs_of[a].push_back(p);
      if(a != b) pairs_of[b].push_back(p);
    }
  }
  auto smooth_less = [&](const Chart_pair& p) {
    std::size_t& l = level[p];
    if(l == along_edges) return false;
    ++l;
    return true;
  };
  // a seam along the edges already that stops matching: the curves of its
  // charts still smoothed go into `less`; where there is none, those of the
  // charts next to them, ring by ring
  auto lower_around = [&](const Chart_pair& pair, std::set<Chart_pair>& less) {
    std::set<std::size_t> ring = {pair.first, pair.second}, seen = ring;
    while(!ring.empty()) {
      bool found = false;
      for(std::size_t c : ring)
        for(const Chart_pair& p : pairs_of[c])
          if(level[p] < along_edges) {
            less.insert(p);
            found = true;
          }
      if(found) return;
      std::set<std::size_t> next;
      for(std::size_t c : ring)
        for(const Chart_pair& p : pairs_of[c])
          for(std::size_t x : {p.first, p.second})
            if(seen.insert(x).second) next.insert(x);
      ring.swap(next);
    }
  };

  // the charts that a try leaves as they were flatten as they did at the try
  // before; a chart smoothed as at an earlier try takes the orderings found then
  internal::Flattening_cache<Chart_report> cache;
  const auto orderings = std::make_shared<Ordering_cache>();
  // the try kept (every chart accepted, the most seams matched): its
  // flattening, and its levels; its mesh while no later try is made (a later
  // try frees it, and it is made again from its levels at the end: two
  // copies of a mesh of a million faces are a few hundred megabytes)
  std::unique_ptr<Try> best;
  bool have_best = false;
  std::map<Chart_pair, std::size_t> best_level;
  Chart_flattening_result<TriangleMesh> best_flattening;
  double zigzag_before = 1;
  std::size_t most_faces_added = 0;

  // the zigzag of every seam of a try: borders between charts and cuts
  auto zigzag = [&](const Try& t) {
    std::vector<edge_descriptor> all;
    for(edge_descriptor e : edges(t.mesh)) {
      const halfedge_descriptor h = halfedge(e, t.mesh);
      if(!is_border_edge(h, t.mesh) &&
         (get(t.cut, e) || get(t.chart, face(h, t.mesh)) != get(t.chart, face(opposite(h, t.mesh), t.mesh))))
        all.push_back(e);
    }
    return seam_zigzag(t.mesh, all).zigzag;
  };
  // a copy of the input with its seams smoothed at the levels `lv` (which
  // get level 0 for a pair of charts that only the smoothing brings
  // together), and what the smoothing did; `zigzag_of_copy`, if given,
  // receives the zigzag of the copy before the smoothing. The copy has room
  // for the faces the smoothing adds: a tenth of the mesh until a try added
  // some, then a little more than the most a try added.
  struct Smoothed
  {
    std::unique_ptr<Try> t;
    Boundary_smoothing_result sr;
    bool called = false;
  };
  auto smooth_at = [&](std::map<Chart_pair, std::size_t>& lv, double* zigzag_of_copy) {
    Smoothed out;
    out.t = std::make_unique<Try>();
    out.t->copy(tm, face_chart, is_input_cut, scale);
    TriangleMesh& mesh = out.t->mesh;
    auto& chart = out.t->chart;
    auto& cut = out.t->cut;
    auto cut_now = get(CGAL::dynamic_edge_property_t<bool>(), mesh);
    auto keep = get(CGAL::dynamic_edge_property_t<bool>(), mesh);
    auto stays = get(CGAL::dynamic_edge_property_t<bool>(), mesh);
    internal::reserve_for_faces(mesh, most_faces_added == 0 ? num_faces(tm) / 10
                                                            : most_faces_added + most_faces_added / 4);
    auto chart_of = [&](halfedge_descriptor h) -> std::size_t { return get(chart, face(h, mesh)); };
    for(edge_descriptor e : edges(mesh)) {
      const halfedge_descriptor h = halfedge(e, mesh);
      put(cut_now, e, false);
      put(keep, e, false);
      put(stays, e, false);
      if(is_border_edge(h, mesh)) continue;
      const std::size_t a = chart_of(h), b = chart_of(opposite(h, mesh));
      if(a != b && lv[pair_of(a, b)] == along_edges) put(stays, e, true);
    }
    if(zigzag_of_copy) *zigzag_of_copy = zigzag(*out.t);
    Boundary_smoothing_result& sr = out.sr;
    auto add = [&](const Boundary_smoothing_result& s) {
      sr.status = s.status;
      sr.number_of_curves += s.number_of_curves;
      sr.curves_smoothed += s.curves_smoothed;
      sr.curves_failed += s.curves_failed;
      sr.vertices_added += s.vertices_added;
      sr.faces_added += s.faces_added;
      sr.max_border_move = (std::max)(sr.max_border_move, s.max_border_move);
      sr.max_relative_border_move = (std::max)(sr.max_relative_border_move, s.max_relative_border_move);
      sr.time_ms += s.time_ms;
      out.called = true;
    };
    for(std::size_t l = 0; l < strengths.size() && sr; ++l) {
      if(std::none_of(lv.begin(), lv.end(), [&](const auto& p) { return p.second == l; })) continue;
      // the borders at level l, every other one and the cuts staying
      bool borders = false;
      for(edge_descriptor e : edges(mesh)) {
        const halfedge_descriptor h = halfedge(e, mesh);
        if(is_border_edge(h, mesh)) continue;
        const std::size_t a = chart_of(h), b = chart_of(opposite(h, mesh));
        const bool smooth = a != b && !get(stays, e) && lv[pair_of(a, b)] == l;
        put(keep, e, get(cut, e) || (a != b && !smooth));
        borders = borders || smooth;
      }
      if(borders) {
        add(smooth_chart_boundaries<ConcurrencyTag>(
            mesh, chart, CGAL::parameters::edge_is_constrained_map(keep).number_of_iterations(strengths[l])));
        // the halves of a cut edge that the smoothing split stay cuts
        for(edge_descriptor e : edges(mesh)) {
          const halfedge_descriptor h = halfedge(e, mesh);
          if(get(keep, e) && !is_border_edge(h, mesh) && chart_of(h) == chart_of(opposite(h, mesh))) put(cut, e, true);
        }
        if(!sr) break;
      }
      // the cuts of the charts at level l, the other cuts staying
      bool cuts = false;
      for(edge_descriptor e : edges(mesh)) {
        const std::size_t c = get(cut, e) ? chart_of(halfedge(e, mesh)) : 0;  // a cut is never on the mesh border
        const bool now = get(cut, e) && lv[pair_of(c, c)] == l;
        put(cut_now, e, now);
        if(now) put(cut, e, false);
        cuts = cuts || now;
      }
      if(cuts) {
        add(smooth_chart_cuts<ConcurrencyTag>(
            mesh, chart, cut_now, CGAL::parameters::edge_is_constrained_map(cut).number_of_iterations(strengths[l])));
        for(edge_descriptor e : edges(mesh))
          if(get(cut_now, e)) put(cut, e, true);
      }
    }
    return out;
  };

  for(int round = 0; round < max_tries; ++round) {
    best.reset();  // the try kept is made again at the end if it is not this one
    const std::map<Chart_pair, std::size_t> level_of_try = level;
    Smoothed smoothed = smooth_at(level, round == 0 ? &zigzag_before : nullptr);
    std::unique_ptr<Try> trial = std::move(smoothed.t);
    TriangleMesh& mesh = trial->mesh;
    auto& chart = trial->chart;
    auto& cut = trial->cut;
    Boundary_smoothing_result& sr = smoothed.sr;
    const bool called = smoothed.called;
    if(round == 0) {
      result.number_of_curves = sr.number_of_curves;
      result.smoothing = sr;
      result.smoothing.zigzag_before = result.smoothing.zigzag_after = zigzag_before;
    }
    if(!sr) {
      result.status = sr.status;
      break;
    }
    if(!called || sr.curves_smoothed == 0) break;  // nothing smoothed in this try
    sr.zigzag_before = zigzag_before;
    sr.zigzag_after = zigzag(*trial);
    most_faces_added = (std::max)(most_faces_added, sr.faces_added);
    // the cuts inside charts, and the halves of a cut edge that the smoothing
    // split: with the borders, they are the seams
    const auto fnp = parameters::max_local_area_distortion(
        thresholds.max_local_area_distortion,
        parameters::chart_criterion(
            thresholds.criterion,
            parameters::max_area_distortion(
                thresholds.max_area_distortion,
                parameters::max_l2_stretch(
                    thresholds.max_l2_stretch,
                    parameters::overlap_tolerance(
                        thresholds.overlap_tolerance,
                        parameters::area_preservation(thresholds.area_preservation,
                                                      CGAL::parameters::edge_is_constrained_map(cut)))))));
    cache.next_generation();
    Chart_flattening_result<TriangleMesh> f =
        internal::flatten_charts_impl<ConcurrencyTag>(mesh, chart, fnp, &cache, true, orderings);
    ++result.tries;
    if(!f || f.number_of_charts != segmentation.number_of_charts) break;
    if(!have_best) result.rejected_charts = f.rejected_charts;
    // the borders and cuts of a rejected chart are smoothed less; where every
    // chart is accepted (the seams were fitted only then), so is a seam whose
    // sides no longer match, or differ by more than the worst seam did before
    // the smoothing (a border, or the cuts of a chart; once along the edges,
    // the curves around it)
    std::set<Chart_pair> less;  // each smoothed less once
    for(std::size_t k = 0; k < f.charts.size(); ++k)
      if(!f.charts[k].accepted) less.insert(pairs_of[k].begin(), pairs_of[k].end());
    for(std::size_t i = 0; i < f.unmatched_seams.size() && f.rejected_charts == 0; ++i) {
      // a seam of the input that did not match either, and ends no further
      // apart than the input's worst seam
      const Chart_pair& pair = f.unmatched_seams[i];
      const Chart_flattening_result<TriangleMesh>& input = input_flattening();
      if(std::find(input.unmatched_seams.begin(), input.unmatched_seams.end(), pair) != input.unmatched_seams.end() &&
         f.unmatched_seam_mismatch[i] <= input.max_seam_length_mismatch)
        continue;
      if(level[pair] < along_edges) {
        less.insert(pair);
      } else {
        lower_around(pair, less);
      }
    }
    bool changed = false;
    for(const Chart_pair& p : less) changed = smooth_less(p) || changed;
    // kept if every chart is accepted, and more seams match than in the try
    // kept before (as many: if the seams zigzag less)
    if(f.rejected_charts == 0 &&
       (!have_best || f.seam_curves_matched > best_flattening.seam_curves_matched ||
        (f.seam_curves_matched == best_flattening.seam_curves_matched &&
         f.seam_zigzag < best_flattening.seam_zigzag))) {
      result.smoothing = sr;
      best = std::move(trial);
      have_best = true;
      best_level = level_of_try;
      best_flattening = std::move(f);
    }
    if(!changed) break;
  }
  if(result.status == Error_code::OK && have_best) {
    result.kept = true;
    cache.clear();
    if(!best) best = smooth_at(best_level, nullptr).t;
    result.flattening = best->copy_into(out, out_chart, std::move(best_flattening), scale);
  }
  return finish();
}

} // namespace CGAL_QD

#endif // CGAL_QD_SMOOTH_SEGMENTATION_SEAMS_H
