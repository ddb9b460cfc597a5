// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_INTERNAL_BOUNDARY_MERGER_H
#define CGAL_QD_INTERNAL_BOUNDARY_MERGER_H

// The state of the boundary-based merging of `merge_charts_by_boundaries()`
// and `segment_quasi_developable()`: the charts, the boundary curves between
// them, the splitting of charts that fail on their own and the greedy merging.

#include <CGAL_QD/Error_code.h>
#include <CGAL_QD/chart_criterion.h>
#include <CGAL_QD/merge_order.h>
#include <CGAL_QD/internal/chart_bisection.h>
#include <CGAL_QD/internal/chart_evaluator.h>
#include <CGAL_QD/internal/charts.h>
#include <CGAL_QD/internal/parallel.h>
#include <CGAL_QD/internal/union_find.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <functional>
#include <iostream>
#include <memory>
#include <mutex>
#include <queue>
#include <tuple>
#include <utility>
#include <vector>

namespace CGAL_QD {
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
      std::vector<std::size_t> size(todo.size());
      for(std::size_t t = 0; t < todo.size(); ++t) size[t] = members[todo[t]].size();
      const std::vector<std::size_t> largest_first = dearest_first(size);
      for_each_index<ConcurrencyTag>(todo.size(), [&](std::size_t i) {
        const std::size_t t = largest_first[i];
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
      // the largest merged charts first
      std::vector<std::size_t> size(to_evaluate.size(), 0);
      for(std::size_t t = 0; t < to_evaluate.size(); ++t) {
        const std::size_t r1 = find(m_curves[to_evaluate[t]].a), r2 = find(m_curves[to_evaluate[t]].b);
        for(std::size_t r : {r1, r2}) {
          for(std::size_t k : m_members[r]) size[t] += m_faces_of_chart[k].size();
          if(r1 == r2) break;
        }
      }
      const std::vector<std::size_t> largest_first = dearest_first(size);
      // As the trials of the batch end, the first one in the order of `take`
      // whose every predecessor is known to be rejected is known to be
      // accepted: the trials after it that share one of its charts are then
      // stale (the loop below takes it and pushes them back), and stop.
      Batch_outcome outcome(take.size());
      std::vector<std::size_t> position(to_evaluate.size());
      for(std::size_t t = 0, k = 0; t < take.size(); ++t) {
        if(k < to_evaluate.size() && to_evaluate[k] == take[t])
          position[k++] = t;
        else
          outcome.known(t, cache[take[t]].report.accepted);
      }
      std::unique_ptr<std::atomic<bool>[]> stale(new std::atomic<bool>[to_evaluate.size()]);
      for(std::size_t k = 0; k < to_evaluate.size(); ++k) stale[k] = false;
      std::atomic<std::size_t> evaluated{0};
      std::mutex mutex;
      for_each_index<ConcurrencyTag>(to_evaluate.size(), [&](std::size_t i) {
        const std::size_t k = largest_first[i], c = to_evaluate[k];
        if(stale[k]) return;
        Cached x;
        x.r1 = find(m_curves[c].a);
        x.r2 = find(m_curves[c].b);
        x.v1 = m_version[x.r1];
        x.v2 = m_version[x.r2];
        x.report = trial(c, &stale[k]);
        if(stale[k]) return;  // it may have given up: not kept
        cache[c] = x;
        ++evaluated;
        std::lock_guard<std::mutex> lock(mutex);
        outcome.known(position[k], x.report.accepted);
        const std::size_t first = outcome.first_accepted();
        if(first == Batch_outcome::none) return;
        const std::size_t a = find(m_curves[take[first]].a), b = find(m_curves[take[first]].b);
        for(std::size_t j = 0; j < to_evaluate.size(); ++j) {
          const std::size_t r1 = find(m_curves[to_evaluate[j]].a), r2 = find(m_curves[to_evaluate[j]].b);
          if(position[j] > first && (r1 == a || r1 == b || r2 == a || r2 == b)) stale[j] = true;
        }
      });
      trials += evaluated;
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

  // the area and the perimeter (cuts counted twice) of the chart that removing curve `c` gives
  std::pair<double, double> merged_chart(std::size_t c) const
  {
    const std::size_t r1 = find(m_curves[c].a), r2 = find(m_curves[c].b);
    if(r1 == r2) return {m_area[r1], m_perimeter[r1] - 2 * m_curves[c].length};
    return {m_area[r1] + m_area[r2], m_perimeter[r1] + m_perimeter[r2] - 2 * m_curves[c].length};
  }

  // compactness 4 pi A / P^2 of a chart of area `area` and perimeter `perimeter` (1 without perimeter)
  static double compactness(double area, double perimeter)
  {
    return perimeter > 0 ? 4 * 3.14159265358979323846 * area / (perimeter * perimeter) : 1.;
  }

  double key(std::size_t c) const
  {
    const std::pair<double, double> merged = merged_chart(c);
    const double area = merged.first;
    switch(m_order) {
    case Merge_order::SMALLEST_AREA_FIRST: return -area;
    case Merge_order::LONGEST_RELATIVE_CURVE_FIRST: return m_curves[c].length / std::sqrt(area);
    case Merge_order::MOST_COMPACT_FIRST: return merged.second > 0 ? compactness(area, merged.second) : 0.;
    default: return area;
    }
  }

  // whether removing curve `c` gives a chart at least `m_compactness_ratio`
  // times as compact as the less compact of its two charts (a curve inside a
  // chart: always, its removal shortens the perimeter)
  bool compact_enough(std::size_t c) const
  {
    const std::size_t r1 = find(m_curves[c].a), r2 = find(m_curves[c].b);
    if(r1 == r2 || !(m_compactness_ratio > 0)) return true;
    const std::pair<double, double> merged = merged_chart(c);
    return compactness(merged.first, merged.second) >=
           m_compactness_ratio * (std::min)(compactness(m_area[r1], m_perimeter[r1]),
                                            compactness(m_area[r2], m_perimeter[r2]));
  }

  // What is known of the trials of a batch, in the order of the batch.
  class Batch_outcome
  {
  public:
    static constexpr std::size_t none = std::size_t(-1);
    explicit Batch_outcome(std::size_t n) : m_state(n, unknown) {}
    void known(std::size_t t, bool accepted) { m_state[t] = accepted ? yes : no; }
    // the first trial accepted after trials all known to be rejected, or `none`
    std::size_t first_accepted() const
    {
      for(std::size_t t = 0; t < m_state.size(); ++t) {
        if(m_state[t] == unknown) return none;
        if(m_state[t] == yes) return t;
      }
      return none;
    }

  private:
    enum State : char { unknown, no, yes };
    std::vector<State> m_state;
  };

  // the merging trial of curve `c`, which gives up once `stop` is set
  Chart_report trial(std::size_t c, const std::atomic<bool>* stop = nullptr) const
  {
    std::vector<face_descriptor> fs;
    const std::size_t r1 = find(m_curves[c].a), r2 = find(m_curves[c].b);
    for(std::size_t r : {r1, r2}) {
      for(std::size_t k : m_members[r]) fs.insert(fs.end(), m_faces_of_chart[k].begin(), m_faces_of_chart[k].end());
      if(r1 == r2) break;
    }
    std::sort(fs.begin(), fs.end(), [&](face_descriptor x, face_descriptor y) { return get(m_fim, x) < get(m_fim, y); });
    return m_eval.evaluate(
        fs,
        [&](halfedge_descriptor h) {
          const long d = m_curve_of[get(m_him, h)];
          return d >= 0 && std::size_t(d) != c && !m_curves[d].eliminated;
        },
        nullptr, nullptr, nullptr, 1000., true, stop);
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
} // namespace CGAL_QD

#endif // CGAL_QD_INTERNAL_BOUNDARY_MERGER_H
