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
#include <CGAL_QD/internal/chart_border_curves.h>
#include <CGAL_QD/internal/chart_evaluator.h>
#include <CGAL_QD/internal/charts.h>
#include <CGAL_QD/internal/parallel.h>
#include <CGAL_QD/internal/union_find.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <exception>
#include <functional>
#include <iostream>
#include <iterator>
#include <list>
#include <memory>
#include <mutex>
#include <queue>
#include <thread>
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

  // a curve between two initial charts
  struct Curve : Chart_border_curve<halfedge_descriptor>
  {
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
    std::vector<Chart_border_curve<halfedge_descriptor>> found = chart_border_curves(
        m_tm, m_him, [&](halfedge_descriptor h) { return chart_of(h); },
        [&](halfedge_descriptor h) {
          return distance3(m_points[get(m_vim, source(h, m_tm))], m_points[get(m_vim, target(h, m_tm))]);
        },
        m_curve_of);
    m_curves.clear();
    for(Chart_border_curve<halfedge_descriptor>& c : found) m_curves.push_back(Curve{std::move(c)});
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
    // a trial under way: its curve, the charts and versions it started from
    // (its result once it ends), and the flag that stops it once an
    // acceptance makes it stale
    struct Running
    {
      std::size_t c = 0;
      Cached x;
      std::atomic<bool> stop{false};
    };
    std::list<Running> running;

    std::size_t trials = 0, merges = 0, decided = 0;
    // The curves taken from the heap, in heap order, and not decided yet.
    // Every decision is taken at the front of this window, one at a time and
    // in heap order, exactly as the sequential run takes it, while the
    // threads run the trials of the curves behind the front ahead of time
    // and keep their results for as long as the charts on either side are
    // unchanged. A curve enters the window with the charts as the decisions
    // before it leave them, unless one of those decisions is an acceptance,
    // which puts the rest of the window back into the heap.
    std::deque<std::size_t> window;
    const std::size_t window_size = batch_size<ConcurrencyTag>();
    std::mutex mutex;
    std::condition_variable changed;
    std::exception_ptr failure;
    const std::thread::id caller = std::this_thread::get_id();
    auto report_progress = [&] {
      progress("merge", (std::min)(1., double(decided) / double((std::max<std::size_t>)(1, m_curves.size() + merges))));
    };

    auto fill_window = [&] {
      while(window.size() < window_size && !heap.empty()) {
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
        window.push_back(c);
      }
    };
    // takes every decision whose trial is known, in order
    auto decide = [&] {
      for(;;) {
        fill_window();
        if(window.empty() || !cache_valid(window.front())) return;
        const std::size_t c = window.front();
        window.pop_front();
        const Chart_report& rep = cache[c].report;
        if(verbose) {
          std::cerr << "  curve " << c << " between charts " << find(m_curves[c].a) << " and " << find(m_curves[c].b)
                    << ": " << (rep.accepted ? "merged" : "kept") << " (";
          if(rep.status != Error_code::OK)
            std::cerr << error_message(rep.status);
          else if(rep.given_up_after > 0)
            std::cerr << "ARAP given up after " << rep.given_up_after << " iterations, A_loc "
                      << rep.local_area_distortion << " %";
          else
            std::cerr << (rep.optimized ? "ARAP" : "LPFB+IP") << ": A " << rep.area_distortion << " %, L2 "
                      << rep.l2_stretch << ", A_loc " << rep.local_area_distortion << " %"
                      << (rep.overlap ? ", overlap" : "");
          std::cerr << ")\n";
        }
        ++decided;
        if(!rep.accepted) {
          m_curves[c].active = false;
        } else {
          ++merges;
          const std::size_t a = find(m_curves[c].a), b = find(m_curves[c].b);
          accept(c);
          // the trials that started from one of the two charts are stale
          for(Running& r : running)
            if(r.x.r1 == a || r.x.r1 == b || r.x.r2 == a || r.x.r2 == b) r.stop = true;
          // the rest of the window goes back: the sequential run would see the new keys
          for(std::size_t u : window) push(u);
          window.clear();
          for(std::size_t k : m_members[find(m_curves[c].a)])
            for(std::size_t d : m_curves_of_chart[k])
              if(!m_curves[d].eliminated) push(d);
        }
        // on the calling thread only, like every other call of `progress`
        if(progress && std::this_thread::get_id() == caller) report_progress();
      }
    };
    auto work = [&] {
      std::unique_lock<std::mutex> lock(mutex);
      try {
        for(;;) {
          if(failure) return;
          decide();
          if(window.empty() && running.empty()) break;  // the heap is empty too
          // the first curve of the window with no result and no trial under way
          auto pick = window.end();
          for(auto w = window.begin(); w != window.end() && pick == window.end(); ++w)
            if(!cache_valid(*w) && std::none_of(running.begin(), running.end(),
                                                [&](const Running& r) { return r.c == *w && !r.stop; }))
              pick = w;
          if(pick == window.end()) {
            changed.wait(lock);
            continue;
          }
          running.emplace_back();
          const auto me = std::prev(running.end());
          Running& r = *me;
          r.c = *pick;
          r.x.r1 = find(m_curves[r.c].a);
          r.x.r2 = find(m_curves[r.c].b);
          r.x.v1 = m_version[r.x.r1];
          r.x.v2 = m_version[r.x.r2];
          const Trial_input input = trial_input(r.c);
          lock.unlock();
          try {
            r.x.report = trial(input, &r.stop);
          } catch(...) {
            lock.lock();
            running.erase(me);
            throw;
          }
          lock.lock();
          if(!r.stop) {
            cache[r.c] = std::move(r.x);
            ++trials;
          }
          running.erase(me);
          changed.notify_all();
        }
      } catch(...) {
        if(!failure) failure = std::current_exception();
      }
      changed.notify_all();
    };
    for_each_index<ConcurrencyTag>(number_of_workers<ConcurrencyTag>(), [&](std::size_t) { work(); });
    if(failure) std::rethrow_exception(failure);
    if(progress) report_progress();
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

  double key(std::size_t c) const
  {
    const std::pair<double, double> merged = merged_chart(c);
    const double area = merged.first;
    switch(m_order) {
    case Merge_order::SMALLEST_AREA_FIRST: return -area;
    case Merge_order::LONGEST_RELATIVE_CURVE_FIRST: return m_curves[c].length / std::sqrt(area);
    case Merge_order::MOST_COMPACT_FIRST: return merged.second > 0 ? compactness_of(area, merged.second) : 0.;
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
    return compactness_of(merged.first, merged.second) >=
           m_compactness_ratio * (std::min)(compactness_of(m_area[r1], m_perimeter[r1]),
                                            compactness_of(m_area[r2], m_perimeter[r2]));
  }

  // what the trial of curve `c` needs of the merging's state, taken while no
  // decision changes it: the initial charts of the two sides, and which
  // curves are still seams
  struct Trial_input
  {
    std::vector<std::size_t> members;
    std::vector<char> seam;  // by curve
  };
  Trial_input trial_input(std::size_t c) const
  {
    Trial_input input;
    const std::size_t r1 = find(m_curves[c].a), r2 = find(m_curves[c].b);
    input.members = m_members[r1];
    if(r1 != r2) input.members.insert(input.members.end(), m_members[r2].begin(), m_members[r2].end());
    input.seam.resize(m_curves.size());
    for(std::size_t d = 0; d < m_curves.size(); ++d) input.seam[d] = d != c && !m_curves[d].eliminated;
    return input;
  }

  // the merging trial of `input`, which gives up once `stop` is set
  Chart_report trial(const Trial_input& input, const std::atomic<bool>* stop = nullptr) const
  {
    std::vector<face_descriptor> fs;
    for(std::size_t k : input.members) fs.insert(fs.end(), m_faces_of_chart[k].begin(), m_faces_of_chart[k].end());
    std::sort(fs.begin(), fs.end(), [&](face_descriptor x, face_descriptor y) { return get(m_fim, x) < get(m_fim, y); });
    return m_eval.evaluate(
        fs,
        [&](halfedge_descriptor h) {
          const long d = m_curve_of[get(m_him, h)];
          return d >= 0 && input.seam[std::size_t(d)] != 0;
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
