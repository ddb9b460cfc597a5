// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_INTERNAL_VALIDATION_H
#define CGAL_QD_INTERNAL_VALIDATION_H

// Checks of a triangle patch done at the entry of every algorithm, in Release
// builds too. The patch is the connected component (through edges) of a start
// face; `require_single_component` also rejects meshes with other components.

#include <CGAL_QD/Error_code.h>
#include <CGAL_QD/internal/constants.h>
#include <CGAL_QD/internal/point_scale.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL_QD {
namespace internal {

template <class TriangleMesh>
struct Patch
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;

  std::vector<face_descriptor> faces;
  std::vector<vertex_descriptor> vertices;
  // one border halfedge (face(h) null) per border loop
  std::vector<halfedge_descriptor> loops;
  std::vector<double> loop_length;
  std::size_t number_of_edges = 0;
};

template <class TriangleMesh, class VPM>
std::array<double, 3> point_of(typename boost::graph_traits<TriangleMesh>::vertex_descriptor v,
                               const VPM& vpm)
{
  const auto& p = get(vpm, v);
  return {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
}

inline double distance3(const std::array<double, 3>& a, const std::array<double, 3>& b)
{
  const double x = a[0] - b[0], y = a[1] - b[1], z = a[2] - b[2];
  return std::sqrt(x * x + y * y + z * z);
}

// twice the area of a triangle, in double
inline double double_area3(const std::array<double, 3>& a, const std::array<double, 3>& b,
                           const std::array<double, 3>& c)
{
  const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const double w[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  const double n[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2],
                       u[0] * w[1] - u[1] * w[0]};
  return std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
}

// whether a vertex of the range has a NaN or infinite coordinate
template <class TriangleMesh, class VertexRange, class VPM>
bool has_non_finite_point(const VertexRange& vs, const VPM& vpm)
{
  for(const auto& v : vs) {
    const auto p = point_of<TriangleMesh>(v, vpm);
    if(!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) return true;
  }
  return false;
}

// whether a face of the range has collinear corners (exact predicate of the
// points' kernel)
template <class TriangleMesh, class FaceRange, class VPM>
bool has_degenerate_face(const TriangleMesh& tm, const FaceRange& fs, const VPM& vpm)
{
  typedef typename boost::property_traits<VPM>::value_type Point;
  const typename CGAL::Kernel_traits<Point>::Kernel::Collinear_3 collinear =
      typename CGAL::Kernel_traits<Point>::Kernel().collinear_3_object();
  for(const auto& f : fs) {
    const auto h = halfedge(f, tm);
    if(collinear(get(vpm, source(h, tm)), get(vpm, target(h, tm)), get(vpm, target(next(h, tm), tm)))) return true;
  }
  return false;
}

// Gathers the patch of `start` (a face) and checks it. Writes `patch` and
// returns OK, or the first problem found. `vim`/`fim` are initialised index maps.
// Checks for a mesh to segment: it may be closed, have borders, several
// components or handles, but its faces must be proper triangles.
template <class TriangleMesh, class VPM>
Error_code validate_mesh_to_segment(const TriangleMesh& tm, const VPM& vpm)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  if(faces(tm).empty()) return Error_code::EMPTY_MESH;
  for(typename GT::face_descriptor f : faces(tm))
    if(CGAL::halfedges_around_face(halfedge(f, tm), tm).size() != 3) return Error_code::NOT_TRIANGLE_MESH;
  // one pass: the largest |coordinate| is NaN where one is not finite
  const double largest = largest_coordinate(vertices(tm), vpm);
  if(std::isnan(largest)) return Error_code::INVALID_COORDINATES;
  if(!coordinates_in_range(largest)) return Error_code::COORDINATES_OUT_OF_RANGE;
  if(has_degenerate_face(tm, faces(tm), vpm)) return Error_code::DEGENERATE_FACE;
  return Error_code::OK;
}

template <class TriangleMesh, class VPM, class VIM, class FIM>
Error_code collect_and_validate_patch(const TriangleMesh& tm,
                                      typename boost::graph_traits<TriangleMesh>::face_descriptor start,
                                      bool require_single_component,
                                      const VPM& vpm, const VIM& vim, const FIM& fim,
                                      Patch<TriangleMesh>& patch)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;

  if(start == GT::null_face()) return Error_code::EMPTY_MESH;

  const std::size_t nf = num_faces(tm), nv = num_vertices(tm);
  std::vector<char> face_seen(nf, 0), vertex_seen(nv, 0);

  // breadth-first over faces through interior edges
  patch.faces.clear();
  patch.vertices.clear();
  patch.faces.push_back(start);
  face_seen[get(fim, start)] = 1;
  std::size_t halfedge_count = 0, border_halfedges = 0;
  for(std::size_t q = 0; q < patch.faces.size(); ++q) {
    const face_descriptor f = patch.faces[q];
    std::size_t degree = 0;
    for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, tm), tm)) {
      ++degree;
      if(degree > 3) break;
      ++halfedge_count;
      const vertex_descriptor v = target(h, tm);
      if(!vertex_seen[get(vim, v)]) {
        vertex_seen[get(vim, v)] = 1;
        patch.vertices.push_back(v);
      }
      const halfedge_descriptor o = opposite(h, tm);
      if(is_border(o, tm)) { ++border_halfedges; continue; }
      const face_descriptor g = face(o, tm);
      if(!face_seen[get(fim, g)]) {
        face_seen[get(fim, g)] = 1;
        patch.faces.push_back(g);
      }
    }
    if(degree != 3) return Error_code::NOT_TRIANGLE_MESH;
  }
  if(require_single_component && patch.faces.size() != nf) {
    // the other faces may still be broken: report the worse problem first
    for(face_descriptor f : faces(tm))
      if(!face_seen[get(fim, f)] && CGAL::halfedges_around_face(halfedge(f, tm), tm).size() != 3)
        return Error_code::NOT_TRIANGLE_MESH;
  }

  // one pass: the largest |coordinate| is NaN where one is not finite
  const double largest = largest_coordinate(patch.vertices, vpm);
  if(std::isnan(largest)) return Error_code::INVALID_COORDINATES;
  if(!coordinates_in_range(largest)) return Error_code::COORDINATES_OUT_OF_RANGE;
  {
    // A vertex is manifold iff the circulation around halfedge(v) reaches every
    // halfedge that ends at v and meets at most one border halfedge: a pinched
    // vertex is circulated through its border links, and shows as two border
    // halfedges. (PMP::is_non_manifold_vertex tests the same but scans the whole
    // mesh for every vertex.)
    std::vector<std::size_t> in_degree(nv, 0);
    for(halfedge_descriptor h : halfedges(tm)) ++in_degree[get(vim, target(h, tm))];
    for(vertex_descriptor v : patch.vertices) {
      std::size_t umbrella = 0, borders = 0;
      for(halfedge_descriptor h : CGAL::halfedges_around_target(halfedge(v, tm), tm)) {
        if(is_border(h, tm)) ++borders;
        if(++umbrella > in_degree[get(vim, v)]) break;
      }
      if(borders > 1 || umbrella != in_degree[get(vim, v)]) return Error_code::NON_MANIFOLD;
    }
  }
  if(require_single_component && patch.faces.size() != nf) return Error_code::NOT_CONNECTED;

  // border loops
  patch.loops.clear();
  patch.loop_length.clear();
  std::vector<halfedge_descriptor> border;
  border.reserve(border_halfedges);
  for(face_descriptor f : patch.faces)
    for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, tm), tm))
      if(is_border(opposite(h, tm), tm)) border.push_back(opposite(h, tm));
  {
    std::vector<char> on_loop(nv, 0);  // marks the target vertex of a visited border halfedge
    for(halfedge_descriptor b : border) {
      if(on_loop[get(vim, target(b, tm))]) continue;  // manifold: one border halfedge per vertex
      double length = 0;
      std::size_t guard = 0;
      halfedge_descriptor h = b;
      do {
        on_loop[get(vim, target(h, tm))] = 1;
        length += distance3(point_of<TriangleMesh>(source(h, tm), vpm),
                            point_of<TriangleMesh>(target(h, tm), vpm));
        h = next(h, tm);
      } while(h != b && ++guard <= border.size());
      if(h != b) return Error_code::NON_MANIFOLD;
      patch.loops.push_back(b);
      patch.loop_length.push_back(length);
    }
  }
  if(patch.loops.empty()) return Error_code::NO_BORDER;

  // Euler characteristic of a disk with b-1 holes: V - E + F = 2 - b
  patch.number_of_edges = (halfedge_count + border_halfedges) / 2;
  const long chi = static_cast<long>(patch.vertices.size()) - static_cast<long>(patch.number_of_edges) +
                   static_cast<long>(patch.faces.size());
  if(chi != 2 - static_cast<long>(patch.loops.size())) return Error_code::NOT_A_DISK;

  for(halfedge_descriptor b : border)
    if(distance3(point_of<TriangleMesh>(source(b, tm), vpm),
                 point_of<TriangleMesh>(target(b, tm), vpm)) == 0.)
      return Error_code::DEGENERATE_EDGE;
  if(has_degenerate_face(tm, patch.faces, vpm)) return Error_code::DEGENERATE_FACE;
  return Error_code::OK;
}

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_INTERNAL_VALIDATION_H
