// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_INTERNAL_ORIENTED_MANIFOLD_SOUP_H
#define CGAL_QD_INTERNAL_ORIENTED_MANIFOLD_SOUP_H

// Whether a polygon soup already is a consistently oriented manifold mesh,
// the test of `CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh()`
// on arrays instead of node-based sets: every polygon has at least 3
// corners and no vertex twice; no oriented edge is used twice (so an edge has
// at most two polygons, which run along it in opposite directions); and the
// polygons around every vertex form one fan, closed or open. Such a soup is
// what `orient_polygon_soup()` leaves as it is; a mesh read from a file
// usually is one, and the repair then skips the orientation.

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL_QD {
namespace internal {

// `polygons`: sequences of indices below `number_of_points`
template <class PolygonRange>
bool is_oriented_manifold_soup(const PolygonRange& polygons, std::size_t number_of_points)
{
  const std::size_t none = std::size_t(-1);
  // the corners, polygon by polygon: corner c is at vertex[c]; its polygon's
  // corners are first[p] .. first[p + 1] (kept only where some polygon is
  // not a triangle: with triangles alone, corner c's polygon is c / 3)
  bool triangles = true;
  for(const auto& polygon : polygons) triangles = triangles && polygon.size() == 3;
  std::vector<std::size_t> first, vertex, polygon_of, sorted;
  vertex.reserve(3 * polygons.size());
  if(!triangles) {
    first.assign(1, 0);
    first.reserve(polygons.size() + 1);
    polygon_of.reserve(3 * polygons.size());
  }
  for(const auto& polygon : polygons) {
    const std::size_t n = polygon.size();
    if(n < 3) return false;
    for(const auto id : polygon) {
      if(static_cast<std::size_t>(id) >= number_of_points) return false;
      vertex.push_back(static_cast<std::size_t>(id));
      if(!triangles) polygon_of.push_back(first.size() - 1);
    }
    if(triangles) {
      const std::size_t* t = vertex.data() + vertex.size() - 3;
      if(t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) return false;  // a vertex twice
      continue;
    }
    first.push_back(vertex.size());
    sorted.assign(vertex.end() - static_cast<std::ptrdiff_t>(n), vertex.end());
    std::sort(sorted.begin(), sorted.end());
    if(std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) return false;  // a vertex twice
  }
  const std::size_t nc = vertex.size();
  auto next = [&](std::size_t c) {
    if(triangles) return c % 3 == 2 ? c - 2 : c + 1;
    return c + 1 == first[polygon_of[c] + 1] ? first[polygon_of[c]] : c + 1;
  };
  auto prev = [&](std::size_t c) {
    if(triangles) return c % 3 == 0 ? c + 2 : c - 1;
    return c == first[polygon_of[c]] ? first[polygon_of[c] + 1] - 1 : c - 1;
  };
  // the oriented edges (from the corner's vertex to the next corner's),
  // grouped by the vertex they leave (a counting sort) and, within a group of
  // a few, sorted by the vertex they reach
  std::vector<std::size_t> start(number_of_points + 1, 0);
  for(std::size_t c = 0; c < nc; ++c) ++start[vertex[c] + 1];
  for(std::size_t v = 0; v < number_of_points; ++v) start[v + 1] += start[v];
  std::vector<std::pair<std::size_t, std::size_t>> out(nc);  // (to, corner)
  {
    std::vector<std::size_t> fill(start.begin(), start.end() - 1);
    for(std::size_t c = 0; c < nc; ++c) out[fill[vertex[c]]++] = {vertex[next(c)], c};
  }
  for(std::size_t v = 0; v < number_of_points; ++v) {
    const auto b = out.begin() + static_cast<std::ptrdiff_t>(start[v]),
               e = out.begin() + static_cast<std::ptrdiff_t>(start[v + 1]);
    std::sort(b, e);
    for(auto it = b; it != e && it + 1 != e; ++it)
      if(it->first == (it + 1)->first) return false;  // an oriented edge used twice
  }
  // the corner whose edge runs from u to v, or none
  auto leaving = [&](std::size_t u, std::size_t v) {
    for(std::size_t k = start[u]; k < start[u + 1]; ++k)
      if(out[k].first == v) return out[k].second;
    return none;
  };
  // every vertex: one walk around it from its first corner reaches all of its corners
  std::vector<char> visited(nc, 0), walked(number_of_points, 0);
  for(std::size_t c = 0; c < nc; ++c) {
    if(visited[c]) continue;
    const std::size_t v = vertex[c];
    if(walked[v]) return false;  // a second fan at v
    walked[v] = 1;
    visited[c] = 1;
    // forward: across the edge from v to the next corner's vertex
    bool closed = false;
    for(std::size_t cur = c;;) {
      const std::size_t across = leaving(vertex[next(cur)], v);
      if(across == none) break;
      const std::size_t at_v = next(across);
      if(at_v == c) {
        closed = true;
        break;
      }
      if(visited[at_v]) return false;
      visited[at_v] = 1;
      cur = at_v;
    }
    if(closed) continue;
    // backward: across the edge from the previous corner's vertex to v
    for(std::size_t cur = c;;) {
      const std::size_t at_v = leaving(v, vertex[prev(cur)]);
      if(at_v == none) break;
      if(visited[at_v]) return false;
      visited[at_v] = 1;
      cur = at_v;
    }
  }
  return true;
}

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_INTERNAL_ORIENTED_MANIFOLD_SOUP_H
