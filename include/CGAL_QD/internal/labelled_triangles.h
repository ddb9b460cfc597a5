// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_INTERNAL_LABELLED_TRIANGLES_H
#define CGAL_QD_INTERNAL_LABELLED_TRIANGLES_H

// Triangles given by node ids, each with the label of its chart, and the
// topology of the triangles of one label: what the seam smoothing compares
// before and after a planned cut, without touching the mesh.

#include <CGAL_QD/internal/union_find.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

namespace CGAL_QD {
namespace internal {

struct Labelled_triangle
{
  std::array<std::size_t, 3> n;
  int label;
};

// the key of the undirected edge between nodes a and b (ids below 2^32)
inline std::uint64_t edge_key(std::size_t a, std::size_t b)
{
  if(a > b) std::swap(a, b);
  return (std::uint64_t(a) << 32) | std::uint64_t(b);
}

struct Labelled_topology
{
  std::size_t faces = 0, components = 0, border_loops = 0, pinches = 0;
  long euler = 0;
  // the same topology; never for an empty set of triangles
  bool operator==(const Labelled_topology& o) const
  {
    return faces > 0 && o.faces > 0 && components == o.components && border_loops == o.border_loops &&
           pinches == o.pinches && euler == o.euler;
  }
};

// the topology of the triangles labelled `label` among `tris`, whose node ids are below `number_of_nodes`:
// faces, connected components through edges, Euler characteristic, border loops, and border vertices
// where more than two border edges meet (pinches)
inline Labelled_topology labelled_topology(const std::vector<Labelled_triangle>& tris, int label,
                                           std::size_t number_of_nodes)
{
  Labelled_topology t;
  // the edges of the triangles, each with the triangle it came from, sorted by edge
  std::vector<std::pair<std::uint64_t, std::size_t>> edge_tri;
  std::vector<char> used(number_of_nodes, 0);
  std::size_t vertices = 0;
  for(std::size_t i = 0; i < tris.size(); ++i) {
    if(tris[i].label != label) continue;
    ++t.faces;
    for(int k = 0; k < 3; ++k) {
      edge_tri.push_back({edge_key(tris[i].n[k], tris[i].n[(k + 1) % 3]), i});
      if(!used[tris[i].n[k]]) {
        used[tris[i].n[k]] = 1;
        ++vertices;
      }
    }
  }
  // sorted: bucketed by the smaller node (the key's high half), then each
  // bucket, a handful of edges, sorted; the order of one std::sort, in
  // linear time instead of n log n (this runs for every curve smoothed)
  {
    std::vector<std::size_t> start(number_of_nodes + 1, 0);
    for(const auto& e : edge_tri) ++start[std::size_t(e.first >> 32) + 1];
    for(std::size_t x = 0; x < number_of_nodes; ++x) start[x + 1] += start[x];
    std::vector<std::pair<std::uint64_t, std::size_t>> sorted(edge_tri.size());
    std::vector<std::size_t> fill(start.begin(), start.end() - 1);
    for(const auto& e : edge_tri) sorted[fill[std::size_t(e.first >> 32)]++] = e;
    for(std::size_t x = 0; x < number_of_nodes; ++x)
      if(start[x + 1] - start[x] > 1)
        std::sort(sorted.begin() + std::ptrdiff_t(start[x]), sorted.begin() + std::ptrdiff_t(start[x + 1]));
    edge_tri.swap(sorted);
  }
  // union-find on the triangles (components through edges) and on the nodes (border loops)
  Union_find components(tris.size()), loops(number_of_nodes);
  std::vector<std::size_t> border_degree(number_of_nodes, 0);
  std::size_t edges = 0;
  for(std::size_t first = 0; first < edge_tri.size();) {
    std::size_t last = first + 1;
    while(last < edge_tri.size() && edge_tri[last].first == edge_tri[first].first) ++last;
    ++edges;
    if(last - first >= 2) {
      for(std::size_t k = first + 1; k < last; ++k)
        components.unite(edge_tri[k].second, edge_tri[first].second);
    } else {
      const std::size_t a = std::size_t(edge_tri[first].first >> 32),
                        b = std::size_t(edge_tri[first].first & 0xffffffffu);
      ++border_degree[a];
      ++border_degree[b];
      loops.unite(a, b);
    }
    first = last;
  }
  t.euler = long(vertices) - long(edges) + long(t.faces);
  for(std::size_t i = 0; i < tris.size(); ++i)
    if(tris[i].label == label && components.find(i) == i) ++t.components;
  for(std::size_t x = 0; x < number_of_nodes; ++x)
    if(border_degree[x] > 0) {
      if(loops.find(x) == x) ++t.border_loops;
      if(border_degree[x] > 2) ++t.pinches;
    }
  return t;
}

// the edges at node x with triangles of both labels 0 and 1 on their sides
inline std::size_t border_edges_at(const std::vector<Labelled_triangle>& tris, std::size_t x)
{
  std::map<std::size_t, int> mask;  // other node -> labels seen
  for(const Labelled_triangle& t : tris)
    for(int k = 0; k < 3; ++k)
      if(t.n[k] == x)
        for(int j = 1; j < 3; ++j) mask[t.n[(k + j) % 3]] |= (1 << t.label);
  std::size_t count = 0;
  for(const auto& m : mask)
    if(m.second == 3) ++count;
  return count;
}

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_INTERNAL_LABELLED_TRIANGLES_H
