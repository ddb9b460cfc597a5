// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

// Disk patches grown on a mesh, for the robustness sweep and the property
// tests: a patch grows face by face and stays a topological disk; holes can
// then be punched into it; the patch is copied out as a mesh of its own.

#ifndef CGAL_QD_TEST_DISK_PATCHES_H
#define CGAL_QD_TEST_DISK_PATCHES_H

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/boost/graph/Face_filtered_graph.h>
#include <CGAL/boost/graph/copy_face_graph.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <deque>
#include <random>
#include <vector>

namespace qd_test {

template <class Mesh>
struct Disk_patch
{
  typedef typename boost::graph_traits<Mesh>::face_descriptor face_descriptor;
  std::vector<face_descriptor> faces;
  std::size_t holes = 0;
};

// Grows a disk from `seed` over the faces of `tm` (a manifold triangle mesh):
// a face joins if it shares one edge with the patch and its third corner is not
// on the patch, or two edges; any other face would make a handle, a pinch or a
// closed surface. Stops at `max_faces` faces or `max_area` area. With an `rng`
// the next face is drawn at random from the front, otherwise the growth is
// breadth-first.
template <class Mesh>
Disk_patch<Mesh> grow_disk(const Mesh& tm, typename boost::graph_traits<Mesh>::face_descriptor seed,
                                 std::size_t max_faces, double max_area, std::mt19937* rng = nullptr)
{
  typedef boost::graph_traits<Mesh> GT;
  typedef typename GT::face_descriptor face_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  const auto fim = CGAL::get_initialized_face_index_map(tm);
  const auto vim = CGAL::get_initialized_vertex_index_map(tm);
  std::vector<char> in(num_faces(tm), 0);
  std::vector<std::size_t> on_patch(num_vertices(tm), 0);
  Disk_patch<Mesh> patch;
  double area = 0;
  std::deque<face_descriptor> front;
  auto add = [&](face_descriptor f) {
    in[get(fim, f)] = 1;
    patch.faces.push_back(f);
    const halfedge_descriptor h = halfedge(f, tm);
    area += CGAL::to_double(CGAL::Polygon_mesh_processing::face_area(f, tm));
    for(const halfedge_descriptor g : CGAL::halfedges_around_face(h, tm)) {
      ++on_patch[get(vim, target(g, tm))];
      const face_descriptor n = face(opposite(g, tm), tm);
      if(n != GT::null_face() && !in[get(fim, n)]) front.push_back(n);
    }
  };
  add(seed);
  while(!front.empty() && patch.faces.size() < max_faces && area < max_area) {
    std::size_t pick = 0;
    if(rng) pick = std::uniform_int_distribution<std::size_t>(0, front.size() - 1)(*rng);
    const face_descriptor f = front[pick];
    front[pick] = front.front();
    front.pop_front();
    if(in[get(fim, f)]) continue;
    int shared = 0;
    halfedge_descriptor lone = GT::null_halfedge();
    for(const halfedge_descriptor g : CGAL::halfedges_around_face(halfedge(f, tm), tm)) {
      const face_descriptor n = face(opposite(g, tm), tm);
      if(n != GT::null_face() && in[get(fim, n)]) {
        ++shared;
        lone = g;
      }
    }
    // one shared edge: the corner opposite it must be new
    if(shared == 1 && on_patch[get(vim, target(next(lone, tm), tm))] > 0) continue;
    if(shared == 0 || shared == 3) continue;
    add(f);
  }
  return patch;
}

// Removes up to `count` faces strictly inside the patch, each away from the
// border and from the other holes, so that every removal adds one border loop.
template <class Mesh>
void punch_holes(const Mesh& tm, Disk_patch<Mesh>& patch, std::size_t count, std::mt19937& rng)
{
  typedef boost::graph_traits<Mesh> GT;
  typedef typename GT::face_descriptor face_descriptor;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  const auto fim = CGAL::get_initialized_face_index_map(tm);
  const auto vim = CGAL::get_initialized_vertex_index_map(tm);
  std::vector<char> in(num_faces(tm), 0), blocked(num_vertices(tm), 0);
  for(const face_descriptor f : patch.faces) in[get(fim, f)] = 1;
  auto interior = [&](vertex_descriptor v) {
    if(blocked[get(vim, v)]) return false;
    for(const face_descriptor g : CGAL::faces_around_target(halfedge(v, tm), tm))
      if(g == GT::null_face() || !in[get(fim, g)]) return false;
    return true;
  };
  std::vector<face_descriptor> order = patch.faces;
  std::shuffle(order.begin(), order.end(), rng);
  for(const face_descriptor f : order) {
    if(patch.holes == count) break;
    bool ok = true;
    for(const vertex_descriptor v : CGAL::vertices_around_face(halfedge(f, tm), tm)) ok = ok && interior(v);
    if(!ok) continue;
    in[get(fim, f)] = 0;
    ++patch.holes;
    // no later hole may touch this one
    for(const vertex_descriptor v : CGAL::vertices_around_face(halfedge(f, tm), tm))
      for(const vertex_descriptor w : CGAL::vertices_around_target(halfedge(v, tm), tm)) blocked[get(vim, w)] = 1;
  }
  std::vector<face_descriptor> kept;
  for(const face_descriptor f : patch.faces)
    if(in[get(fim, f)]) kept.push_back(f);
  patch.faces.swap(kept);
}

// copies the faces into `out` (cleared), with their own vertices
template <class Mesh, class OutMesh>
void copy_faces(const Mesh& tm, const std::vector<typename boost::graph_traits<Mesh>::face_descriptor>& faces_in,
                OutMesh& out)
{
  CGAL::clear(out);
  CGAL::copy_face_graph(CGAL::Face_filtered_graph<Mesh>(tm, faces_in), out);
}

} // namespace qd_test

#endif // CGAL_QD_TEST_DISK_PATCHES_H
