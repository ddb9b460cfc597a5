// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_INTERNAL_CHART_SHARING_H
#define CGAL_QD_INTERNAL_CHART_SHARING_H

// After the merging: a small chart that no neighbour can take whole is
// shared out among its neighbours, each taking the faces nearer to its side
// than to the others', where every neighbour so enlarged still passes the
// merging's trial and stays nearly as compact as it was.

#include <CGAL_QD/internal/charts.h>
#include <CGAL_QD/internal/parallel.h>

#include <CGAL/boost/graph/iterator.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <map>
#include <queue>
#include <utility>
#include <vector>

namespace CGAL_QD {
namespace internal {

// Charts of at most this share of the mesh's area are shared out.
inline constexpr double shared_chart_max_area_share = 0.05;
// Each neighbour that takes faces keeps at least this share of its compactness 4 pi A / P^2.
inline constexpr double shared_chart_compactness_kept = 0.9;

// `chart`: the chart of every face by face index, ids 0 to n - 1; `seam`: by
// halfedge index (both halfedges of an edge), the edges cut (between two
// charts, and the cuts inside charts). `evaluate(faces, is_cut)` is the
// merging's trial of a chart. Charts are visited from the smallest; each is
// shared out among its neighbours (by a Dijkstra over its faces from its
// border with each of them, along the distances between face centroids); a
// neighbour whose enlarged chart fails the trial is left out and the others
// share the chart again, while at least two remain. Once a chart is shared
// out, the charts that took it and their neighbours are visited again.
// Returns the number of charts shared out and the number of trials; `chart`
// (renumbered by smallest face index), `n` and `seam` are updated.
template <class ConcurrencyTag, class TriangleMesh, class FIM, class HIM, class VIM, class Evaluate>
std::pair<std::size_t, std::size_t> share_out_small_charts(const TriangleMesh& tm, const FIM& fim, const HIM& him,
                                                           const VIM& vim,
                                                           const std::vector<std::array<double, 3>>& points,
                                                           const std::vector<Face_geometry>& geo,
                                                           const Evaluate& evaluate, std::vector<std::size_t>& chart,
                                                           std::size_t& n, std::vector<char>& seam)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::face_descriptor face_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  const std::size_t nf = chart.size();
  std::vector<face_descriptor> face_of(nf);
  for(face_descriptor f : faces(tm)) face_of[get(fim, f)] = f;
  auto length = [&](halfedge_descriptor h) {
    return distance3(points[get(vim, source(h, tm))], points[get(vim, target(h, tm))]);
  };
  auto centroid_distance = [&](std::size_t i, std::size_t j) { return distance3(geo[i].centroid, geo[j].centroid); };
  auto face_across = [&](halfedge_descriptor h) -> long {
    const halfedge_descriptor o = opposite(h, tm);
    return is_border(o, tm) ? -1 : static_cast<long>(get(fim, face(o, tm)));
  };

  std::vector<std::vector<std::size_t>> members(n);
  std::vector<double> area(n, 0.), perimeter(n, 0.);  // the perimeter counts cuts twice
  for(std::size_t i = 0; i < nf; ++i) {
    members[chart[i]].push_back(i);
    area[chart[i]] += geo[i].area;
    for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(face_of[i], tm), tm))
      if(face_across(h) < 0 || seam[get(him, h)]) perimeter[chart[i]] += length(h);
  }
  double total_area = 0;
  for(double a : area) total_area += a;

  // during an attempt: the position of a face in the chart shared out, and
  // the new cut flag of the halfedges of its faces (-1: as in `seam`)
  std::vector<long> local(nf, -1);
  std::vector<signed char> pending(seam.size(), -1);
  std::vector<char> tried(n, 0);  // shared out in vain, with its neighbours as they are now
  std::size_t shared = 0, trials = 0;
  for(bool again = true; again;) {
    again = false;
    std::vector<std::size_t> order;
    for(std::size_t k = 0; k < n; ++k)
      if(!members[k].empty() && !tried[k] && area[k] <= shared_chart_max_area_share * total_area) order.push_back(k);
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return area[a] < area[b] || (area[a] == area[b] && a < b);
    });
    for(std::size_t c : order) {
      const std::vector<std::size_t>& fs = members[c];
      for(std::size_t p = 0; p < fs.size(); ++p) local[fs[p]] = static_cast<long>(p);
      std::vector<char> left_out(n, 0);
      bool done = false;
      for(;;) {
        // a Dijkstra over the faces of c from its border with every neighbour not left out
        std::vector<double> dist(fs.size(), std::numeric_limits<double>::infinity());
        std::vector<std::size_t> taker(fs.size(), n);
        typedef std::pair<double, std::size_t> Entry;
        std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
        for(std::size_t p = 0; p < fs.size(); ++p)
          for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(face_of[fs[p]], tm), tm)) {
            const long j = face_across(h);
            if(j < 0 || chart[j] == c || left_out[chart[j]]) continue;
            const double d = centroid_distance(fs[p], std::size_t(j)) / 2;
            if(d < dist[p] || (d == dist[p] && chart[j] < taker[p])) {
              dist[p] = d;
              taker[p] = chart[j];
            }
          }
        for(std::size_t p = 0; p < fs.size(); ++p)
          if(taker[p] < n) queue.push({dist[p], p});
        while(!queue.empty()) {
          const Entry e = queue.top();
          queue.pop();
          const std::size_t p = e.second;
          if(e.first > dist[p]) continue;
          for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(face_of[fs[p]], tm), tm)) {
            const long j = face_across(h);
            if(j < 0 || chart[j] != c) continue;
            const std::size_t q = static_cast<std::size_t>(local[j]);
            const double d = e.first + centroid_distance(fs[p], std::size_t(j));
            if(d < dist[q]) {
              dist[q] = d;
              taker[q] = taker[p];
              queue.push({d, q});
            }
          }
        }
        std::vector<std::size_t> takers;
        bool reached = true;
        for(std::size_t p = 0; p < fs.size(); ++p) {
          reached = reached && taker[p] < n;
          if(taker[p] < n && std::find(takers.begin(), takers.end(), taker[p]) == takers.end())
            takers.push_back(taker[p]);
        }
        if(!reached || takers.size() < 2) break;
        std::sort(takers.begin(), takers.end());
        // the cuts after the sharing: between charts, and the cuts of c that stay inside one chart
        auto new_chart = [&](std::size_t i) { return local[i] >= 0 ? taker[std::size_t(local[i])] : chart[i]; };
        std::map<std::size_t, std::pair<double, double>> grown;  // taker -> its area and perimeter after
        for(std::size_t k : takers) grown[k] = {area[k], perimeter[k]};
        for(std::size_t i : fs) {
          auto& g = grown[new_chart(i)];
          g.first += geo[i].area;
          for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(face_of[i], tm), tm)) {
            const long j = face_across(h);
            const std::size_t hi = get(him, h);
            if(j < 0) {
              g.second += length(h);
              continue;
            }
            const bool was_cut = seam[hi] != 0 && chart[j] == c;
            const bool cut = new_chart(std::size_t(j)) != new_chart(i) || was_cut;
            pending[hi] = pending[get(him, opposite(h, tm))] = cut ? 1 : 0;
            if(cut) g.second += length(h);
            // an edge of the taker's border with c that is no longer cut
            if(chart[j] == new_chart(i) && !cut) g.second -= length(h);
            // the taker's side of an edge between c and it that stays cut (between two takers) counts already
          }
        }
        bool compact = true;
        for(std::size_t k : takers)
          compact = compact && compactness_of(grown[k].first, grown[k].second) >=
                                   shared_chart_compactness_kept * compactness_of(area[k], perimeter[k]);
        // the cut flags as in `seam` again
        auto drop_pending = [&] {
          for(std::size_t i : fs)
            for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(face_of[i], tm), tm))
              pending[get(him, h)] = pending[get(him, opposite(h, tm))] = -1;
        };
        if(!compact) {
          drop_pending();
          break;
        }
        // every enlarged neighbour tried
        std::vector<char> ok(takers.size(), 0);
        const auto is_cut = [&](halfedge_descriptor h) {
          const std::size_t hi = get(him, h);
          return pending[hi] >= 0 ? pending[hi] != 0 : seam[hi] != 0;
        };
        for_each_index<ConcurrencyTag>(takers.size(), [&](std::size_t t) {
          std::vector<std::size_t> ids = members[takers[t]];
          for(std::size_t p = 0; p < fs.size(); ++p)
            if(taker[p] == takers[t]) ids.push_back(fs[p]);
          std::sort(ids.begin(), ids.end());
          std::vector<face_descriptor> chart_faces;
          chart_faces.reserve(ids.size());
          for(std::size_t i : ids) chart_faces.push_back(face_of[i]);
          ok[t] = evaluate(chart_faces, is_cut) ? 1 : 0;
        });
        trials += takers.size();
        if(std::all_of(ok.begin(), ok.end(), [](char x) { return x != 0; })) {
          for(std::size_t i : fs) {
            const std::size_t k = new_chart(i);
            members[k].push_back(i);
            for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(face_of[i], tm), tm)) {
              const std::size_t hi = get(him, h);
              if(pending[hi] >= 0) seam[hi] = seam[get(him, opposite(h, tm))] = static_cast<char>(pending[hi]);
            }
          }
          drop_pending();
          for(std::size_t t = 0; t < takers.size(); ++t) {
            const std::size_t k = takers[t];
            std::sort(members[k].begin(), members[k].end());
            std::tie(area[k], perimeter[k]) = grown[k];
            for(std::size_t i : members[k]) chart[i] = k;
          }
          for(std::size_t i : fs) local[i] = -1;
          members[c].clear();
          area[c] = perimeter[c] = 0;
          ++shared;
          // the takers and the charts next to them are tried again (a chart
          // none of whose neighbours changed would fail as it did)
          for(std::size_t k : takers) {
            tried[k] = 0;
            for(std::size_t i : members[k])
              for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(face_of[i], tm), tm)) {
                const long j = face_across(h);
                if(j >= 0) tried[chart[std::size_t(j)]] = 0;
              }
          }
          done = true;
          break;
        }
        drop_pending();
        for(std::size_t t = 0; t < takers.size(); ++t)
          if(!ok[t]) left_out[takers[t]] = 1;
      }
      if(done) {
        again = true;
        break;
      }
      for(std::size_t i : fs) local[i] = -1;
      tried[c] = 1;
    }
  }
  // charts numbered by their smallest face index, as the merging numbers them
  std::vector<std::size_t> id(n, std::size_t(-1));
  std::size_t count = 0;
  for(std::size_t i = 0; i < nf; ++i)
    if(id[chart[i]] == std::size_t(-1)) id[chart[i]] = count++;
  for(std::size_t& k : chart) k = id[k];
  n = count;
  return {shared, trials};
}

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_INTERNAL_CHART_SHARING_H
