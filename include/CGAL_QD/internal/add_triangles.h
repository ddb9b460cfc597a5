// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_INTERNAL_ADD_TRIANGLES_H
#define CGAL_QD_INTERNAL_ADD_TRIANGLES_H

// The triangles of a chart cut open added to a `CGAL::Surface_mesh` in one
// pass: every trial of the segmentation builds such a mesh, and adding its
// faces one at a time with `CGAL::Euler::add_face()` (which looks for every
// edge around its vertex and relinks the border at every face) was a tenth of
// a trial.

#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace CGAL_QD {
namespace internal {

// Adds the triangles `corner` (three vertex indices per face, in
// `[0, sm.number_of_vertices())`) to `sm`, which has its vertices and no
// face: the faces and edges get the indices that `add_face()` face after face
// gives them (an edge at its first use, its first halfedge in the direction of
// that face), every border halfedge the next one along the border, and every
// vertex an incoming halfedge, on the border for a border vertex. Returns
// false, with `sm` half built, where the triangles do not make an oriented
// surface that is manifold at every vertex (an edge used twice in the same
// direction or by three faces, a vertex with two gaps in its fan, a
// triangle with a repeated vertex): the caller then clears the faces and
// adds them with `add_face()`, which tells which one fails.
template <class Point>
bool add_triangles(CGAL::Surface_mesh<Point>& sm, const std::vector<std::size_t>& corner)
{
  typedef CGAL::Surface_mesh<Point> Mesh;
  typedef typename Mesh::Vertex_index V;
  typedef typename Mesh::Halfedge_index H;
  typedef typename Mesh::size_type size_type;
  const std::size_t nv = sm.number_of_vertices(), nf = corner.size() / 3;
  // the edges from every vertex to a vertex of higher index, as linked lists
  std::vector<long> head(nv, -1), link;
  std::vector<std::size_t> other;
  std::vector<H> first;       // by edge: its halfedge in the direction of its first use
  std::vector<char> uses;     // by edge: 1 or 2
  link.reserve(3 * nf / 2 + 3);
  other.reserve(3 * nf / 2 + 3);
  first.reserve(3 * nf / 2 + 3);
  uses.reserve(3 * nf / 2 + 3);
  // the halfedge from a to b
  auto halfedge_from = [&](std::size_t a, std::size_t b, H& out) {
    const std::size_t lo = (std::min)(a, b), hi = (std::max)(a, b);
    for(long e = head[lo]; e >= 0; e = link[std::size_t(e)])
      if(other[std::size_t(e)] == hi) {
        const H h = first[std::size_t(e)];
        if(uses[std::size_t(e)] != 1 || sm.target(h) != V(static_cast<size_type>(a))) return false;
        uses[std::size_t(e)] = 2;
        out = sm.opposite(h);
        return true;
      }
    out = sm.add_edge();
    sm.set_target(out, V(static_cast<size_type>(b)));
    sm.set_target(sm.opposite(out), V(static_cast<size_type>(a)));
    link.push_back(head[lo]);
    head[lo] = static_cast<long>(other.size());
    other.push_back(hi);
    first.push_back(out);
    uses.push_back(1);
    return true;
  };
  for(std::size_t i = 0; i < nf; ++i) {
    const std::size_t* c = &corner[3 * i];
    if(c[0] == c[1] || c[1] == c[2] || c[2] == c[0] || c[0] >= nv || c[1] >= nv || c[2] >= nv) return false;
    H h[3];
    for(int k = 0; k < 3; ++k)
      if(!halfedge_from(c[k], c[(k + 1) % 3], h[k])) return false;
    const typename Mesh::Face_index f = sm.add_face();
    sm.set_halfedge(f, h[2]);
    for(int k = 0; k < 3; ++k) {
      sm.set_face(h[k], f);
      sm.set_next(h[k], h[(k + 1) % 3]);
      sm.set_halfedge(sm.target(h[k]), h[k]);
    }
  }
  // the border: the other halfedge of every edge used once
  std::vector<H> border_from(nv, Mesh::null_halfedge());
  for(std::size_t e = 0; e < first.size(); ++e) {
    if(uses[e] != 1) continue;
    const H b = sm.opposite(first[e]);
    sm.set_face(b, Mesh::null_face());
    H& slot = border_from[std::size_t(sm.source(b))];
    if(slot != Mesh::null_halfedge()) return false;  // two gaps in the fan of the vertex
    slot = b;
  }
  for(std::size_t e = 0; e < first.size(); ++e) {
    if(uses[e] != 1) continue;
    const H b = sm.opposite(first[e]);
    const H n = border_from[std::size_t(sm.target(b))];
    if(n == Mesh::null_halfedge()) return false;
    sm.set_next(b, n);
    sm.set_halfedge(sm.target(b), b);
  }
  // one fan at every vertex: its faces, walked from its halfedge, are all
  // the triangles at the vertex
  std::vector<std::size_t> at(nv, 0);
  for(std::size_t c : corner) ++at[c];
  for(std::size_t v = 0; v < nv; ++v) {
    const H start = sm.halfedge(V(static_cast<size_type>(v)));
    if(start == Mesh::null_halfedge()) {
      if(at[v] != 0) return false;
      continue;
    }
    std::size_t fan = 0;
    H h = start;
    do {
      if(sm.face(h) != Mesh::null_face()) ++fan;
      h = sm.opposite(sm.next(h));
    } while(h != start && fan <= at[v]);
    if(fan != at[v]) return false;
  }
  return true;
}

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_INTERNAL_ADD_TRIANGLES_H
