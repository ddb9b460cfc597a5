// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_FLATTEN_CHARTS_H
#define CGAL_QD_FLATTEN_CHARTS_H

/// \file flatten_charts.h
/// The last step of the segmentation on its own: every chart of a given
/// segmentation cut open along its seams, flattened and measured, with the two
/// sides of every seam given a common length where the charts allow it.

#include <CGAL_QD/Error_code.h>
#include <CGAL_QD/chart_criterion.h>
#include <CGAL_QD/chart_flattening_result.h>
#include <CGAL_QD/internal/chart_evaluator.h>
#include <CGAL_QD/internal/charts.h>
#include <CGAL_QD/internal/constants.h>
#include <CGAL_QD/internal/parallel.h>
#include <CGAL_QD/parameters.h>
#include <CGAL_QD/segmentation_measures.h>
#include <CGAL_QD/vsa_segmentation.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>
#include <CGAL/tags.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <memory>
#include <set>
#include <utility>
#include <vector>

namespace CGAL_QD {

namespace internal {

// the rounds of the final flattening that pull every chart's border towards
// the mean lengths of its seams, and the weight of the pull
// (`border_length_weight`): measured on CGAL's meshes, 4 to 6 rounds match as
// many curves as more, and a weight of 30 more than 3, 10 or 100
inline constexpr std::size_t seam_pull_rounds = 6;
inline constexpr double seam_pull_weight = 30.;

// What `flatten_final_charts()` does with a chart, given a flattening of the
// same charts before (`before`): by chart, in a vector of `char`.
enum Flattening_from_before : char {
  FLATTEN_AGAIN = 0,  // flattened again, and fitted with the others
  KEEP_AS_BEFORE = 1, // its flattening and report from `before`, never fitted: the sides of its seams are the
                      // lengths its neighbours fit to
  FIT_FROM_BEFORE = 2 // its flattening from `before` as the start of its fit with the others
};

// the 3D length of the edges `seams`, with the points `points` by vertex index
template <class TriangleMesh, class VIM>
double seam_length_of(const TriangleMesh& tm,
                      const std::vector<typename boost::graph_traits<TriangleMesh>::edge_descriptor>& seams,
                      const std::vector<std::array<double, 3>>& points, const VIM& vim)
{
  double length = 0;
  for(const auto& e : seams) {
    const auto h = halfedge(e, tm);
    const std::array<double, 3>&p = points[get(vim, source(h, tm))], &q = points[get(vim, target(h, tm))];
    length += std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]));
  }
  return length;
}

// Flattens the charts `chart` (compact ids by face index, n charts) cut open
// along `seams`, and fills the chart and seam fields of `result` (whose
// `points` hold the points by vertex index). With `fit_only_if_accepted`, the
// seams are fitted to common lengths only when every chart is accepted. With
// `frozen` (by chart, `Flattening_from_before`) and `before` (a flattening of
// the same charts), a chart is flattened again, kept as in `before`, or
// fitted from its flattening in `before`. A chart flattened again whose
// trial is remembered in `trials` starts from it (trial_memory.h).
template <class ConcurrencyTag, class TriangleMesh, class VPM, class FIM, class VIM, class HIM>
void flatten_final_charts(const TriangleMesh& tm, const VPM& vpm, const FIM& fim, const VIM& vim, const HIM& him,
                          const std::vector<std::size_t>& chart, std::size_t n,
                          const std::vector<typename boost::graph_traits<TriangleMesh>::edge_descriptor>& seams,
                          const Merge_thresholds& thresholds, const std::function<void(const char*, double)>& progress,
                          Chart_flattening_result<TriangleMesh>& result,
                          Flattening_cache<Chart_report>* cache = nullptr, bool fit_only_if_accepted = false,
                          std::shared_ptr<Ordering_cache> orderings = nullptr,
                          const std::vector<char>* frozen = nullptr,
                          const Chart_flattening_result<TriangleMesh>* before = nullptr,
                          std::shared_ptr<Trial_memory> trials = nullptr)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::edge_descriptor edge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;

  const auto t = std::chrono::steady_clock::now();
  if(progress) progress("flatten", 0.);
  const std::size_t nf = static_cast<std::size_t>(num_faces(tm));
  result.number_of_faces = nf;
  result.number_of_charts = n;
  result.seam_edges = seams;
  std::vector<char> is_seam(num_halfedges(tm), 0);
  std::vector<halfedge_descriptor> seam_halfedges;
  result.seam_length = seam_length_of(tm, seams, result.points, vim);
  for(edge_descriptor e : seams) {
    const halfedge_descriptor h = halfedge(e, tm);
    is_seam[get(him, h)] = is_seam[get(him, opposite(h, tm))] = 1;
    seam_halfedges.push_back(h);
  }
  const auto seam = [&](halfedge_descriptor h) { return is_seam[get(him, h)] != 0; };
  // the seam curves, each as its halfedges along one side
  std::vector<std::vector<halfedge_descriptor>> curves;
  for(const auto& c : seam_curves(tm, seam_halfedges, vim, him, [](vertex_descriptor) { return false; })) {
    std::vector<halfedge_descriptor> hs;
    const std::size_t m = c.vertices.size(), ne = c.closed ? m : m - 1;
    for(std::size_t i = 0; i < ne; ++i) {
      const auto h = halfedge(c.vertices[i], c.vertices[(i + 1) % m], tm);
      if(!h.second) continue;
      // the side in a face: a seam edge is never a mesh border edge
      hs.push_back(is_border(h.first, tm) ? opposite(h.first, tm) : h.first);
    }
    if(!hs.empty()) curves.push_back(hs);
  }

  Chart_evaluator<TriangleMesh, FIM, VIM> evaluator(tm, fim, vim, result.points, thresholds, std::move(orderings));
  evaluator.set_cache(cache);
  evaluator.set_trial_memory(std::move(trials));
  std::vector<std::vector<face_descriptor>> members(n);
  for(face_descriptor f : faces(tm)) members[chart[get(fim, f)]].push_back(f);
  for(auto& m : members)
    std::sort(m.begin(), m.end(), [&](face_descriptor x, face_descriptor y) { return get(fim, x) < get(fim, y); });
  result.charts.assign(n, Chart_report());
  // the UVs of the corners chart by chart (3 per face of `members[k]`), and
  // the position of every face in its chart's list: the corners of the whole
  // mesh are gathered only at the end (each copy of them is 48 bytes a face)
  std::vector<std::vector<std::array<double, 2>>> uvs(n);
  std::vector<std::uint32_t> local(nf, 0);
  for(const std::vector<face_descriptor>& m : members)
    for(std::size_t i = 0; i < m.size(); ++i) local[get(fim, m[i])] = static_cast<std::uint32_t>(i);
  std::vector<std::size_t> size(n);
  for(std::size_t k = 0; k < n; ++k) size[k] = members[k].size();
  const std::vector<std::size_t> largest_first = dearest_first(size);
  auto never_fitted = [&](std::size_t k) { return frozen && before && (*frozen)[k] == KEEP_AS_BEFORE; };
  auto starts_from_before = [&](std::size_t k) { return frozen && before && (*frozen)[k] != FLATTEN_AGAIN; };
  for_each_index<ConcurrencyTag>(n, [&](std::size_t i) {
    const std::size_t k = largest_first[i];
    if(members[k].empty()) return;
    if(!starts_from_before(k)) {
      result.charts[k] = evaluator.evaluate(members[k], seam, &uvs[k]);
      return;
    }
    result.charts[k] = before->charts[k];
    result.charts[k].seams_matched = true;  // measured again below
    uvs[k].resize(3 * members[k].size());
    for(std::size_t f = 0; f < members[k].size(); ++f)
      for(int j = 0; j < 3; ++j) uvs[k][3 * f + j] = before->corner_uv[3 * get(fim, members[k][f]) + j];
  });
  const std::array<double, 2> origin = {0., 0.};
  auto corner_uv = [&](std::size_t i, int k) -> const std::array<double, 2>& {
    const std::vector<std::array<double, 2>>& u = uvs[chart[i]];
    return u.empty() ? origin : u[3 * std::size_t(local[i]) + std::size_t(k)];
  };
  // the position of halfedge g in its face, and its 2D length in the face's chart
  auto position = [&](halfedge_descriptor g) {
    int k = 0;
    for(halfedge_descriptor x = halfedge(face(g, tm), tm); x != g; x = next(x, tm)) ++k;
    return k;
  };
  auto uv_length = [&](halfedge_descriptor g) {
    const std::size_t i = get(fim, face(g, tm));
    const int k = position(g);
    // corner k of a face holds the UV of the target of its k-th halfedge
    const std::array<double, 2>&p = corner_uv(i, k), &q = corner_uv(i, (k + 2) % 3);
    return std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]));
  };
  const bool all_accepted =
      std::all_of(result.charts.begin(), result.charts.end(), [](const Chart_report& c) { return c.accepted; });
  if(thresholds.criterion != Chart_criterion::LPFB_IP && (all_accepted || !fit_only_if_accepted)) {
    // the two sides of every seam edge get a common length: every chart is
    // fitted exactly to the mean of the two sides of its curves (every border
    // edge at its share), or, where that leaves the thresholds, keeps its
    // lengths and its neighbours are fitted to them. The free flattenings can
    // give the two sides of a curve lengths several per cent apart, more than
    // a chart near the local area bound can take at once: where curves still
    // differ, a few rounds (`seam_pull_rounds`) pull the border of every chart
    // along such a curve towards the mean of the two sides of each of its
    // curves, each chart as far as its rigidity lets it, so that the stiffer
    // side moves less (a pull that leaves the thresholds is not taken), and
    // the charts are fitted exactly again from there.
    std::vector<char> kept(n, 0), todo(n, 1);
    std::vector<double> factor(num_halfedges(tm), 1.);
    // each side of a curve scaled along itself to the common length: the
    // factor of every seam halfedge; whether a curve's sides differ by more
    // than the 0.5 % of a matched seam, and the charts along such a curve
    std::vector<char> on_unmatched(n, 0);
    auto common_lengths = [&]() {
      bool unmatched = false;
      std::fill(on_unmatched.begin(), on_unmatched.end(), 0);
      for(const std::vector<halfedge_descriptor>& curve : curves) {
        double side[2] = {0., 0.};
        for(halfedge_descriptor h : curve) {
          side[0] += uv_length(h);
          side[1] += uv_length(opposite(h, tm));
        }
        const std::size_t a = chart[get(fim, face(curve.front(), tm))],
                          b = chart[get(fim, face(opposite(curve.front(), tm), tm))];
        const double common = kept[a] || never_fitted(a)   ? side[0]
                              : kept[b] || never_fitted(b) ? side[1]
                                                           : (side[0] + side[1]) / 2;
        if(std::abs(side[0] - side[1]) > matched_seam_tolerance * (std::max)(side[0], side[1])) {
          unmatched = true;
          on_unmatched[a] = on_unmatched[b] = 1;
        }
        for(halfedge_descriptor h : curve) {
          factor[get(him, h)] = side[0] > 0 ? common / side[0] : 1.;
          factor[get(him, opposite(h, tm))] = side[1] > 0 ? common / side[1] : 1.;
        }
      }
      return unmatched;
    };
    // the accepted charts with `todo` set, fitted to the lengths `factor`
    // gives their border edges from the flattenings `first[k]` where it is
    // not empty, else `uvs[k]` (see `Chart_evaluator::evaluate()`); `uvs`
    // stays as it is until every chart is fitted
    std::vector<std::size_t> list;
    std::vector<Chart_report> fitted;
    std::vector<std::vector<std::array<double, 2>>> fitted_uv, first(n);
    auto fit = [&](double pull_weight, bool exact) {
      list.clear();
      for(std::size_t k : largest_first)
        if(todo[k] && !kept[k] && !never_fitted(k) && result.charts[k].accepted) list.push_back(k);
      fitted.assign(list.size(), Chart_report());
      fitted_uv.assign(list.size(), {});
      for_each_index<ConcurrencyTag>(list.size(), [&](std::size_t i) {
        const std::size_t k = list[i];
        std::vector<double> target(3 * members[k].size());
        for(std::size_t f = 0; f < members[k].size(); ++f) {
          int j = 0;
          for(halfedge_descriptor g : CGAL::halfedges_around_face(halfedge(members[k][f], tm), tm))
            target[3 * f + j++] = factor[get(him, g)] * uv_length(g);
        }
        const std::vector<std::array<double, 2>>& start = first[k].empty() ? uvs[k] : first[k];
        fitted[i] = evaluator.evaluate(members[k], seam, &fitted_uv[i], &target, &start, pull_weight, exact);
      });
    };
    // calls f with the chart across every seam edge of chart k
    auto for_each_neighbour = [&](std::size_t k, auto&& f) {
      for(face_descriptor face_k : members[k])
        for(halfedge_descriptor g : CGAL::halfedges_around_face(halfedge(face_k, tm), tm)) {
          const halfedge_descriptor o = opposite(g, tm);
          if(!is_border(o, tm) && seam(g)) f(chart[get(fim, face(o, tm))]);
        }
    };
    // the charts of `todo` fitted exactly from their flattenings as they are
    // now (`kept` is all 0 before and after)
    auto fit_exactly = [&]() {
      // every fit starts from the flattenings as they are now: a chart's is
      // kept in `first` once a fit replaces it
      for(int round = 0; round < 3; ++round) {
        common_lengths();
        fit(1000., true);
        std::fill(todo.begin(), todo.end(), 0);
        bool again = false;
        for(std::size_t i = 0; i < list.size(); ++i) {
          const std::size_t k = list[i];
          if(fitted[i].accepted) {
            result.charts[k] = fitted[i];
            uvs[k].swap(fitted_uv[i]);
            if(first[k].empty()) first[k].swap(fitted_uv[i]);
            continue;
          }
          // kept with its own lengths: its neighbours fit to them
          kept[k] = 1;
          for_each_neighbour(k, [&](std::size_t other) {
            if(other != k && !kept[other]) todo[other] = again = true;
          });
        }
        fitted_uv.clear();
        if(!again) break;
      }
      std::fill(kept.begin(), kept.end(), 0);
      for(std::vector<std::array<double, 2>>& f : first) std::vector<std::array<double, 2>>().swap(f);
    };
    std::fill(todo.begin(), todo.end(), 1);
    fit_exactly();
    if(common_lengths()) {
      // curves whose sides still differ: their charts pulled towards the
      // mean, then the charts pulled and their neighbours fitted exactly again
      std::vector<char> pulled(n, 0);
      for(std::size_t round = 0; round < seam_pull_rounds; ++round) {
        todo = on_unmatched;
        fit(seam_pull_weight, false);
        bool moved = false;
        for(std::size_t i = 0; i < list.size(); ++i)
          if(fitted[i].accepted) {
            result.charts[list[i]] = fitted[i];
            uvs[list[i]].swap(fitted_uv[i]);
            pulled[list[i]] = 1;
            moved = true;
          }
        fitted_uv.clear();
        if(!moved || !common_lengths()) break;
      }
      todo = pulled;
      for(std::size_t k = 0; k < n; ++k)
        if(pulled[k]) for_each_neighbour(k, [&](std::size_t other) { todo[other] = 1; });
      fit_exactly();
    }
  }
  for(std::size_t k = 0; k < n; ++k) {
    const Chart_report& c = result.charts[k];
    result.max_area_distortion = (std::max)(result.max_area_distortion, c.area_distortion);
    result.max_l2_stretch = (std::max)(result.max_l2_stretch, c.l2_stretch);
    result.max_local_area_distortion = (std::max)(result.max_local_area_distortion, c.local_area_distortion);
    if(c.overlap) ++result.overlapping_charts;
    if(!c.accepted) ++result.rejected_charts;
  }
  // the two sides of every seam curve in the flattenings
  for(const std::vector<halfedge_descriptor>& curve : curves) {
    double side[2] = {0., 0.};
    for(halfedge_descriptor h : curve) {
      side[0] += uv_length(h);
      side[1] += uv_length(opposite(h, tm));
    }
    const double longer = (std::max)(side[0], side[1]);
    const double mismatch = longer > 0 ? std::abs(side[0] - side[1]) / longer : 0.;
    result.max_seam_length_mismatch = (std::max)(result.max_seam_length_mismatch, mismatch);
    ++result.number_of_seam_curves;
    if(mismatch <= matched_seam_tolerance) {
      ++result.seam_curves_matched;
    } else {
      const std::size_t a = chart[get(fim, face(curve.front(), tm))],
                        b = chart[get(fim, face(opposite(curve.front(), tm), tm))];
      result.charts[a].seams_matched = result.charts[b].seams_matched = false;
      result.unmatched_seams.push_back({(std::min)(a, b), (std::max)(a, b)});
      result.unmatched_seam_mismatch.push_back(mismatch);
    }
  }
  // how a person would cut the pieces: the zigzag of the seams, the compactness of the pieces
  result.seam_zigzag =
      seam_zigzag(tm, seams, CGAL::parameters::vertex_point_map(vpm).vertex_index_map(vim).halfedge_index_map(him)).zigzag;
  std::set<edge_descriptor> cuts;  // seams with the same chart on both sides
  for(edge_descriptor e : seams) {
    const halfedge_descriptor h = halfedge(e, tm);
    if(!is_border_edge(h, tm) && chart[get(fim, face(h, tm))] == chart[get(fim, face(opposite(h, tm), tm))])
      cuts.insert(e);
  }
  const Chart_compactness compactness =
      chart_compactness(tm, boost::make_iterator_property_map(chart.cbegin(), fim),
                        CGAL::parameters::vertex_point_map(vpm).face_index_map(fim).edge_is_constrained_map(
                            CGAL::make_boolean_property_map(cuts)));
  result.compactness = compactness.compactness;
  for(std::size_t k = 0; k < compactness.number_of_charts; ++k)
    if(compactness.chart_id[k] < result.charts.size())
      result.charts[compactness.chart_id[k]].compactness = compactness.chart_compactness[k];
  // the corners of the whole mesh, each chart's UVs freed once copied
  result.corner_uv.assign(3 * nf, {0., 0.});
  for(std::size_t k = 0; k < n; ++k) {
    for(std::size_t i = 0; i < members[k].size() && !uvs[k].empty(); ++i)
      for(int j = 0; j < 3; ++j) result.corner_uv[3 * get(fim, members[k][i]) + j] = uvs[k][3 * i + j];
    std::vector<std::array<double, 2>>().swap(uvs[k]);
  }
  result.time_flatten_ms = milliseconds_since(t);
  if(progress) progress("flatten", 1.);
}

// `flatten_charts()`, with flattenings looked up in `cache` (nullptr: none)
// and orderings in `orderings` (nullptr: a cache of its own); with
// `fit_only_if_accepted`, the seams are not fitted where a chart is rejected
template <class ConcurrencyTag, class TriangleMesh, class FaceChartMap, class NamedParameters>
Chart_flattening_result<TriangleMesh> flatten_charts_impl(const TriangleMesh& tm, const FaceChartMap& face_chart,
                                                          const NamedParameters& np,
                                                          Flattening_cache<Chart_report>* cache,
                                                          bool fit_only_if_accepted = false,
                                                          std::shared_ptr<Ordering_cache> orderings = nullptr)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::edge_descriptor edge_descriptor;

  Chart_flattening_result<TriangleMesh> result;
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, tm));
  const auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
  const auto fim = CGAL::get_initialized_face_index_map(tm, np);
  const auto him = CGAL::get_initialized_halfedge_index_map(tm, np);
  const auto ecm = choose_parameter(get_parameter(np, CGAL::internal_np::edge_is_constrained),
                                    CGAL::Static_boolean_property_map<edge_descriptor, false>());
  const std::function<void(const char*, double)> progress =
      choose_parameter(get_parameter(np, CGAL::internal_np::callback), std::function<void(const char*, double)>());
  result.status = validate_mesh_to_segment(tm, vpm);
  if(result.status == Error_code::OK && !thresholds_valid(merge_thresholds_from<TriangleMesh>(np)))
    result.status = Error_code::INVALID_ARGUMENT;
  if(result.status != Error_code::OK) return result;

  std::vector<std::size_t> chart, ids;
  const std::size_t n = read_charts(tm, face_chart, fim, chart, ids);
  std::vector<edge_descriptor> seams;
  for(edge_descriptor e : edges(tm)) {
    const halfedge_descriptor h = halfedge(e, tm);
    if(is_border_edge(h, tm)) continue;
    if(get(ecm, e) || chart[get(fim, face(h, tm))] != chart[get(fim, face(opposite(h, tm), tm))]) seams.push_back(e);
  }
  result.points = points_by_index(tm, vpm, vim);
  flatten_final_charts<ConcurrencyTag>(tm, vpm, fim, vim, him, chart, n, seams,
                                       merge_thresholds_from<TriangleMesh>(np), progress, result, cache,
                                       fit_only_if_accepted, std::move(orderings));
  return result;
}

} // namespace internal

/// \ingroup PkgCGAL_QDRef
/// flattens every chart of a given segmentation, as the last step of
/// `segment_quasi_developable()` does: each chart is cut open along the
/// borders between charts and the constrained edges (cuts inside a chart),
/// flattened by LPFB+IP and, with `Chart_criterion::LPFB_IP_THEN_ARAP`, by
/// free-boundary ARAP where that is better, and measured against the
/// thresholds; then the two sides of every seam curve get a common 2D length
/// where both charts stay within the thresholds. A chart that no flattening
/// brings within the thresholds keeps the one nearest them (without an
/// overlap before with one, then with the smallest largest ratio of A(Omega),
/// L2 and A_loc to their bounds), and its report gives that flattening's
/// measures. Use it after changing a segmentation, e.g. after
/// `smooth_chart_boundaries()`.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or
///         `CGAL::Parallel_if_available_tag`; the result is the same
/// \tparam TriangleMesh a model of `FaceListGraph`
/// \tparam FaceChartMap a model of `ReadablePropertyMap` from faces to an integral chart id
/// \param tm the triangle mesh
/// \param face_chart the chart of every face; the ids need not be consecutive: chart k of the
///        result is the k-th smallest id
/// \param np optional named parameters: the thresholds and criterion of the segmentation
///   (`CGAL_QD::parameters::max_area_distortion`, `max_l2_stretch`, `max_local_area_distortion`,
///   `chart_criterion`, `overlap_tolerance`, `area_preservation`), `edge_is_constrained_map` (edges inside a chart that
///   are cut too; default none), `callback`, and `vertex_point_map`, `vertex_index_map`,
///   `face_index_map`, `halfedge_index_map`.
/// \returns a `Chart_flattening_result`; `EMPTY_MESH`, `NOT_TRIANGLE_MESH`, `INVALID_COORDINATES`
///          or `DEGENERATE_FACE` on invalid input, `INVALID_ARGUMENT` for an `area_preservation`
///          outside [0, 1].
template <class ConcurrencyTag = CGAL::Parallel_if_available_tag, class TriangleMesh, class FaceChartMap,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
Chart_flattening_result<TriangleMesh> flatten_charts(const TriangleMesh& tm, const FaceChartMap& face_chart,
                                                     const NamedParameters& np = CGAL::parameters::default_values())
{
  return internal::flatten_charts_impl<ConcurrencyTag>(tm, face_chart, np, nullptr);
}

} // namespace CGAL_QD

#endif // CGAL_QD_FLATTEN_CHARTS_H
