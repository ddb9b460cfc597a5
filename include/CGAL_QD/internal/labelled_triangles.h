// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_INTERNAL_LABELLED_TRIANGLES_H
#define CGAL_QD_INTERNAL_LABELLED_TRIANGLES_H

// Triangles given by node ids, each with the label of its chart, and the
// topology of the triangles of one label: what the seam smoothing compares
// before and after a planned cut, without touching the mesh.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <unordered_map>
#include <utility>
#include <array>
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
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> edge_tris;
  std::vector<char> used(number_of_nodes, 0);
  std::size_t vertices = 0;
  for(std::size_t i = 0; i < tris.size(); ++i) {
    if(tris[i].label != label) continue;
    ++t.faces;
    for(int k = 0; k < 3; ++k) {
      edge_tris[edge_key(tris[i].n[k], tris[i].n[(k + 1) % 3])].push_back(i);
      if(!used[tris[i].n[k]]) {
        used[tris[i].n[k]] = 1;
        ++vertices;
      }
    }
  }
  t.euler = long(vertices) - long(edge_tris.size()) + long(t.faces);
  // components of the faces through edges
  std::unordered_map<std::size_t, std::size_t> parent;
  std::function<std::size_t(std::size_t)> find = [&](std::size_t x) {
    while(parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for(std::size_t i = 0; i < tris.size(); ++i)
    if(tris[i].label == label) parent[i] = i;
  std::unordered_map<std::size_t, std::size_t> border_parent, border_degree;
  std::function<std::size_t(std::size_t)> border_find = [&](std::size_t x) {
    while(border_parent[x] != x) x = border_parent[x] = border_parent[border_parent[x]];
    return x;
  };
  for(const auto& e : edge_tris) {
    if(e.second.size() >= 2) {
      for(std::size_t k = 1; k < e.second.size(); ++k) parent[find(e.second[k])] = find(e.second[0]);
      continue;
    }
    const std::size_t a = std::size_t(e.first >> 32), b = std::size_t(e.first & 0xffffffffu);
    for(std::size_t x : {a, b})
      if(border_parent.emplace(x, x).second) border_degree[x] = 0;
    ++border_degree[a];
    ++border_degree[b];
    border_parent[border_find(a)] = border_find(b);
  }
  for(const auto& p : parent)
    if(find(p.first) == p.first) ++t.components;
  for(const auto& p : border_parent)
    if(border_find(p.first) == p.first) ++t.border_loops;
  for(const auto& d : border_degree)
    if(d.second > 2) ++t.pinches;
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
