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
#include <CGAL_QD/parameters.h>
#include <CGAL_QD/internal/chart_bisection.h>
#include <CGAL_QD/internal/charts.h>
#include <CGAL_QD/internal/parallel.h>
#include <CGAL_QD/internal/union_find.h>
#include <CGAL_QD/vsa_segmentation.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/tags.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <functional>
#include <iostream>
#include <queue>
#include <tuple>
#include <type_traits>
#include <utility>
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
/// the order in which `merge_charts_by_boundaries()` tries the boundary curves.
enum class Merge_order
{
  /// the paper's: the curve whose two charts have the largest total area first
  LARGEST_AREA_FIRST,
  /// the curve whose two charts have the smallest total area first: small, cheap trials first
  SMALLEST_AREA_FIRST,
  /// the curve with the largest length / sqrt(area of its two charts) first: charts that share much border
  LONGEST_RELATIVE_CURVE_FIRST,
  /// the curve whose removal gives the most compact chart first (largest 4 pi area / perimeter^2, the
  /// perimeter in 3D with cuts inside the chart counted twice): round pieces rather than sprawling ones
  MOST_COMPACT_FIRST
};

namespace internal {

// The state of a boundary-based merging over a fixed set of initial charts.
template <class TriangleMesh, class FIM, class HIM, class VIM>
class Boundary_merger
{
public:
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::face_descriptor face_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::edge_descriptor edge_descriptor;
  typedef Chart_evaluator<TriangleMesh, FIM, VIM> Evaluator;
  typedef std::function<void(const char*, double)> Progress;

  struct Curve
  {
    std::size_t a, b;  // initial charts on either side, a < b
    std::vector<halfedge_descriptor> halfedges;  // one per edge, in a face of chart a
    double length = 0;
    bool eliminated = false;
    bool active = true;  // in the heap, or to be tried again when a side changes
  };

  Boundary_merger(const TriangleMesh& tm, const FIM& fim, const HIM& him, const Evaluator& evaluator,
                  std::vector<std::size_t>& chart, std::size_t n, const std::vector<std::array<double, 3>>& points,
                  const VIM& vim)
      : m_tm(tm), m_fim(fim), m_him(him), m_eval(evaluator), m_chart(chart), m_n(n), m_points(points), m_vim(vim)
  {
    m_face_of.resize(chart.size());
    for(face_descriptor f : faces(tm)) m_face_of[get(fim, f)] = f;
  }

  // Splits every chart that does not flatten within the thresholds, until all do.
  template <class ConcurrencyTag>
  std::size_t split_failing_charts(const std::vector<Face_geometry>& geo, const Progress& progress)
  {
    const std::size_t before = m_n;
    std::vector<std::size_t> todo(m_n);
    for(std::size_t k = 0; k < m_n; ++k) todo[k] = k;
    const auto no_cut = [](halfedge_descriptor) { return false; };
    while(!todo.empty()) {
      std::vector<std::vector<face_descriptor>> members(m_n);
      for(std::size_t i = 0; i < m_chart.size(); ++i) members[m_chart[i]].push_back(m_face_of[i]);
      std::vector<char> ok(todo.size(), 0);
      for_each_index<ConcurrencyTag>(todo.size(), [&](std::size_t t) {
        ok[t] = members[todo[t]].size() <= 1 || m_eval.evaluate(members[todo[t]], no_cut).accepted;
      });
      std::vector<std::size_t> next;
      for(std::size_t t = 0; t < todo.size(); ++t) {
        if(ok[t]) continue;
        split_in_two(m_tm, m_fim, geo, members[todo[t]], m_chart, m_n);
        next.push_back(todo[t]);
        next.push_back(m_n++);
      }
      todo.swap(next);
      if(progress) progress("split", 0.5);
    }
    return m_n - before;
  }

  void build_curves()
  {
    m_curve_of.assign(num_halfedges(m_tm), -1);
    m_curves.clear();
    // group the border edges of each pair of charts into connected chains:
    // edges of the same pair that share a vertex are in the same curve
    std::vector<halfedge_descriptor> border;
    for(auto e : edges(m_tm)) {
      const halfedge_descriptor h = halfedge(e, m_tm);
      if(is_border_edge(h, m_tm)) continue;
      if(chart_of(h) != chart_of(opposite(h, m_tm))) border.push_back(h);
    }
    Union_find chains(border.size());
    auto pair_of = [&](halfedge_descriptor h) {
      const std::size_t x = chart_of(h), y = chart_of(opposite(h, m_tm));
      return std::make_pair((std::min)(x, y), (std::max)(x, y));
    };
    std::vector<long> edge_at(num_halfedges(m_tm), -1);  // border edge index by halfedge
    for(std::size_t i = 0; i < border.size(); ++i) {
      edge_at[get(m_him, border[i])] = static_cast<long>(i);
      edge_at[get(m_him, opposite(border[i], m_tm))] = static_cast<long>(i);
    }
    for(std::size_t i = 0; i < border.size(); ++i)
      for(halfedge_descriptor end : {border[i], opposite(border[i], m_tm)})
        for(halfedge_descriptor h : CGAL::halfedges_around_target(end, m_tm)) {
          const long j = edge_at[get(m_him, h)];
          if(j < 0 || std::size_t(j) == i || pair_of(border[j]) != pair_of(border[i])) continue;
          chains.unite(i, std::size_t(j));
        }
    std::vector<long> curve_of_root(border.size(), -1);
    for(std::size_t i = 0; i < border.size(); ++i) {
      const std::size_t r = chains.find(i);
      if(curve_of_root[r] < 0) {
        curve_of_root[r] = static_cast<long>(m_curves.size());
        Curve c;
        std::tie(c.a, c.b) = pair_of(border[i]);
        m_curves.push_back(c);
      }
      Curve& c = m_curves[curve_of_root[r]];
      c.halfedges.push_back(chart_of(border[i]) == c.a ? border[i] : opposite(border[i], m_tm));
      c.length += distance3(m_points[get(m_vim, source(border[i], m_tm))], m_points[get(m_vim, target(border[i], m_tm))]);
      m_curve_of[get(m_him, border[i])] = m_curve_of[get(m_him, opposite(border[i], m_tm))] = curve_of_root[r];
    }
    m_curves_of_chart.assign(m_n, {});
    for(std::size_t c = 0; c < m_curves.size(); ++c) {
      m_curves_of_chart[m_curves[c].a].push_back(c);
      m_curves_of_chart[m_curves[c].b].push_back(c);
    }
  }

  std::size_t number_of_curves() const { return m_curves.size(); }

  void set_order(Merge_order order) { m_order = order; }
  void set_compactness_ratio(double ratio) { m_compactness_ratio = ratio; }

  // The greedy merging of the paper, Section 4.2. Returns (trials, merges).
  template <class ConcurrencyTag>
  std::pair<std::size_t, std::size_t> merge(const std::vector<Face_geometry>& geo, const Progress& progress,
                                            bool verbose, bool run = true)
  {
    m_sets.reset(m_n);
    m_members.assign(m_n, {});
    m_area.assign(m_n, 0.);
    m_version.assign(m_n, 0);
    for(std::size_t k = 0; k < m_n; ++k) m_members[k].push_back(k);
    m_faces_of_chart.assign(m_n, {});
    for(std::size_t i = 0; i < m_chart.size(); ++i) {
      m_faces_of_chart[m_chart[i]].push_back(m_face_of[i]);
      m_area[m_chart[i]] += geo[i].area;
    }
    m_perimeter.assign(m_n, 0.);
    for(const Curve& c : m_curves) {
      m_perimeter[c.a] += c.length;
      m_perimeter[c.b] += c.length;
    }
    for(std::size_t k = 0; k < m_n; ++k)
      for(face_descriptor f : m_faces_of_chart[k])
        for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, m_tm), m_tm))
          if(is_border(opposite(h, m_tm), m_tm))
            m_perimeter[k] += distance3(m_points[get(m_vim, source(h, m_tm))], m_points[get(m_vim, target(h, m_tm))]);
    // heap of (key, -curve); the stamp of a curve invalidates its older entries
    typedef std::tuple<double, long, std::size_t> Entry;
    std::priority_queue<Entry> heap;
    std::vector<std::size_t> stamp(m_curves.size(), 0);
    auto push = [&](std::size_t c) {
      m_curves[c].active = true;
      heap.emplace(key(c), -static_cast<long>(c), ++stamp[c]);
    };
    if(run)
      for(std::size_t c = 0; c < m_curves.size(); ++c) push(c);

    struct Cached
    {
      std::size_t r1 = std::size_t(-1), r2 = 0, v1 = 0, v2 = 0;
      Chart_report report;
    };
    std::vector<Cached> cache(m_curves.size());
    auto cache_valid = [&](std::size_t c) {
      const Cached& x = cache[c];
      const std::size_t r1 = find(m_curves[c].a), r2 = find(m_curves[c].b);
      return x.r1 == r1 && x.r2 == r2 && x.v1 == m_version[r1] && x.v2 == m_version[r2];
    };

    std::size_t trials = 0, merges = 0, decided = 0;
    const std::size_t batch = batch_size<ConcurrencyTag>();
    while(!heap.empty()) {
      std::vector<std::size_t> take;
      while(!heap.empty() && take.size() < batch) {
        const Entry e = heap.top();
        heap.pop();
        const std::size_t c = static_cast<std::size_t>(-std::get<1>(e));
        if(std::get<2>(e) != stamp[c] || !m_curves[c].active || m_curves[c].eliminated) continue;
        if(!compact_enough(c)) {
          // no trial: tried again if one of its charts changes
          if(verbose)
            std::cerr << "  curve " << c << " between charts " << find(m_curves[c].a) << " and "
                      << find(m_curves[c].b) << ": kept (the merged chart would sprawl)\n";
          m_curves[c].active = false;
          ++decided;
          continue;
        }
        take.push_back(c);
      }
      std::vector<std::size_t> to_evaluate;
      for(std::size_t c : take)
        if(!cache_valid(c)) to_evaluate.push_back(c);
      for_each_index<ConcurrencyTag>(to_evaluate.size(), [&](std::size_t t) {
        const std::size_t c = to_evaluate[t];
        Cached x;
        x.r1 = find(m_curves[c].a);
        x.r2 = find(m_curves[c].b);
        x.v1 = m_version[x.r1];
        x.v2 = m_version[x.r2];
        x.report = trial(c);
        cache[c] = x;
      });
      trials += to_evaluate.size();
      for(std::size_t t = 0; t < take.size(); ++t) {
        const std::size_t c = take[t];
        const Chart_report& rep = cache[c].report;
        if(verbose)
          std::cerr << "  curve " << c << " between charts " << find(m_curves[c].a) << " and " << find(m_curves[c].b)
                    << ": " << (rep.accepted ? "merged" : "kept") << " (" << error_message(rep.status) << ", A "
                    << rep.area_distortion << " %, L2 " << rep.l2_stretch << (rep.overlap ? ", overlap" : "") << ")\n";
        if(!rep.accepted) {
          m_curves[c].active = false;
          ++decided;
          continue;
        }
        ++merges;
        ++decided;
        accept(c);
        // the rest of the batch goes back: the sequential run would see the new keys
        for(std::size_t u = t + 1; u < take.size(); ++u) push(take[u]);
        for(std::size_t k : m_members[find(m_curves[c].a)])
          for(std::size_t d : m_curves_of_chart[k])
            if(!m_curves[d].eliminated) push(d);
        break;
      }
      if(progress) progress("merge", (std::min)(1., double(decided) / double((std::max<std::size_t>)(1, m_curves.size() + merges))));
    }
    // final chart ids: patches numbered by their smallest face index
    std::vector<std::size_t> id(m_n, std::size_t(-1));
    std::size_t count = 0;
    for(std::size_t i = 0; i < m_chart.size(); ++i) {
      const std::size_t r = find(m_chart[i]);
      if(id[r] == std::size_t(-1)) id[r] = count++;
    }
    for(std::size_t& k : m_chart) k = id[find(k)];
    m_final_count = count;
    return std::make_pair(trials, merges);
  }

  std::size_t number_of_final_charts() const { return m_final_count; }

  // whether the edge of h is cut: a curve not eliminated
  bool is_seam(halfedge_descriptor h) const
  {
    const long c = m_curve_of[get(m_him, h)];
    return c >= 0 && !m_curves[c].eliminated;
  }

  // the halfedges of every remaining curve, each in a face of the curve's first side
  std::vector<std::vector<halfedge_descriptor>> remaining_curves() const
  {
    std::vector<std::vector<halfedge_descriptor>> out;
    for(const Curve& c : m_curves)
      if(!c.eliminated) out.push_back(c.halfedges);
    return out;
  }

  template <class OutputIterator>
  double seams(OutputIterator out) const
  {
    double length = 0;
    for(const Curve& c : m_curves) {
      if(c.eliminated) continue;
      length += c.length;
      for(halfedge_descriptor h : c.halfedges) *out++ = edge(h, m_tm);
    }
    return length;
  }

private:
  std::size_t chart_of(halfedge_descriptor h) const { return m_chart[get(m_fim, face(h, m_tm))]; }

  std::size_t find(std::size_t x) const { return m_sets.root(x); }

  double key(std::size_t c) const
  {
    const std::size_t r1 = find(m_curves[c].a), r2 = find(m_curves[c].b);
    const double area = r1 == r2 ? m_area[r1] : m_area[r1] + m_area[r2];
    switch(m_order) {
    case Merge_order::SMALLEST_AREA_FIRST: return -area;
    case Merge_order::LONGEST_RELATIVE_CURVE_FIRST: return m_curves[c].length / std::sqrt(area);
    case Merge_order::MOST_COMPACT_FIRST: {
      const double p = (r1 == r2 ? m_perimeter[r1] : m_perimeter[r1] + m_perimeter[r2]) - 2 * m_curves[c].length;
      return p > 0 ? 4 * 3.14159265358979323846 * area / (p * p) : 0.;
    }
    default: return area;
    }
  }

  // compactness 4 pi A / P^2 of a chart of area `area` and perimeter `perimeter` (1 without perimeter)
  static double compactness(double area, double perimeter)
  {
    return perimeter > 0 ? 4 * 3.14159265358979323846 * area / (perimeter * perimeter) : 1.;
  }

  // whether removing curve `c` gives a chart at least `m_compactness_ratio`
  // times as compact as the less compact of its two charts (a curve inside a
  // chart: always, its removal shortens the perimeter)
  bool compact_enough(std::size_t c) const
  {
    const std::size_t r1 = find(m_curves[c].a), r2 = find(m_curves[c].b);
    if(r1 == r2 || !(m_compactness_ratio > 0)) return true;
    const double merged =
        compactness(m_area[r1] + m_area[r2], m_perimeter[r1] + m_perimeter[r2] - 2 * m_curves[c].length);
    return merged >= m_compactness_ratio * (std::min)(compactness(m_area[r1], m_perimeter[r1]),
                                                       compactness(m_area[r2], m_perimeter[r2]));
  }

  Chart_report trial(std::size_t c) const
  {
    std::vector<face_descriptor> fs;
    const std::size_t r1 = find(m_curves[c].a), r2 = find(m_curves[c].b);
    for(std::size_t r : {r1, r2}) {
      for(std::size_t k : m_members[r]) fs.insert(fs.end(), m_faces_of_chart[k].begin(), m_faces_of_chart[k].end());
      if(r1 == r2) break;
    }
    std::sort(fs.begin(), fs.end(), [&](face_descriptor x, face_descriptor y) { return get(m_fim, x) < get(m_fim, y); });
    return m_eval.evaluate(fs, [&](halfedge_descriptor h) {
      const long d = m_curve_of[get(m_him, h)];
      return d >= 0 && std::size_t(d) != c && !m_curves[d].eliminated;
    });
  }

  void accept(std::size_t c)
  {
    m_curves[c].eliminated = true;
    std::size_t r1 = find(m_curves[c].a), r2 = find(m_curves[c].b);
    if(r1 != r2) {
      if(r2 < r1) std::swap(r1, r2);
      m_sets.unite(r1, r2);
      m_members[r1].insert(m_members[r1].end(), m_members[r2].begin(), m_members[r2].end());
      m_members[r2].clear();
      m_area[r1] += m_area[r2];
      m_perimeter[r1] += m_perimeter[r2];
    }
    m_perimeter[r1] -= 2 * m_curves[c].length;
    ++m_version[r1];
  }

  const TriangleMesh& m_tm;
  FIM m_fim;
  HIM m_him;
  const Evaluator& m_eval;
  std::vector<std::size_t>& m_chart;
  std::size_t m_n;
  const std::vector<std::array<double, 3>>& m_points;
  VIM m_vim;
  std::vector<face_descriptor> m_face_of;
  std::vector<long> m_curve_of;  // by halfedge index
  std::vector<Curve> m_curves;
  std::vector<std::vector<std::size_t>> m_curves_of_chart;
  Union_find m_sets;  // of charts
  std::vector<std::size_t> m_version;
  std::vector<std::vector<std::size_t>> m_members;
  std::vector<std::vector<face_descriptor>> m_faces_of_chart;
  std::vector<double> m_area;
  std::vector<double> m_perimeter;  // 3D length of the border of each chart, its cuts counted twice
  std::size_t m_final_count = 0;
  Merge_order m_order = Merge_order::LARGEST_AREA_FIRST;
  double m_compactness_ratio = 0;  // see `CGAL_QD::parameters::compactness_ratio`
};

} // namespace internal

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
///   - `callback`: called with (step name, fraction done) during the run
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
