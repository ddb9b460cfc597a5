// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_INTERNAL_CHART_BISECTION_H
#define CGAL_QD_INTERNAL_CHART_BISECTION_H

#include <CGAL_QD/internal/charts.h>
#include <CGAL_QD/internal/validation.h>

#include <CGAL/boost/graph/iterator.h>

#include <boost/graph/graph_traits.hpp>

#include <cstddef>
#include <functional>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

namespace CGAL_QD {
namespace internal {

// Splits a connected set of faces in two connected halves: the faces closer
// (along face centroids) to one of two far-apart seed faces than to the other.
template <class TriangleMesh, class FIM>
void split_in_two(const TriangleMesh& tm, const FIM& fim, const std::vector<Face_geometry>& geo,
                  const std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>& members,
                  std::vector<std::size_t>& chart, std::size_t new_id)
{
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  const std::size_t id = chart[get(fim, members.front())];
  std::vector<double> dist(chart.size(), std::numeric_limits<double>::infinity());
  std::vector<std::size_t> side(chart.size(), 0);
  std::vector<face_descriptor> face_of(chart.size());
  for(face_descriptor f : members) face_of[get(fim, f)] = f;
  // Dijkstra from seeds; each face takes the side of its parent, so both sides are connected
  auto run = [&](const std::vector<std::size_t>& seeds) {
    for(face_descriptor f : members) dist[get(fim, f)] = std::numeric_limits<double>::infinity();
    typedef std::pair<double, std::size_t> Item;
    std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
    for(std::size_t s = 0; s < seeds.size(); ++s) {
      dist[seeds[s]] = 0;
      side[seeds[s]] = s;
      queue.emplace(0., seeds[s]);
    }
    std::size_t last = seeds.front();
    while(!queue.empty()) {
      const Item it = queue.top();
      queue.pop();
      if(it.first > dist[it.second]) continue;
      last = it.second;
      for(auto h : CGAL::halfedges_around_face(halfedge(face_of[it.second], tm), tm)) {
        const auto o = opposite(h, tm);
        if(is_border(o, tm)) continue;
        const std::size_t g = get(fim, face(o, tm));
        if(chart[g] != id) continue;
        const double d = it.first + distance3(geo[it.second].centroid, geo[g].centroid);
        if(d < dist[g]) {
          dist[g] = d;
          side[g] = side[it.second];
          queue.emplace(d, g);
        }
      }
    }
    return last;  // the furthest face
  };
  const std::size_t a = run({get(fim, members.front())});
  const std::size_t b = run({a});
  run({a, b});
  for(face_descriptor f : members)
    if(side[get(fim, f)] == 1) chart[get(fim, f)] = new_id;
}

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_INTERNAL_CHART_BISECTION_H
