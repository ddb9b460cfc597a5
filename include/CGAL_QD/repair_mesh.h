// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_REPAIR_MESH_H
#define CGAL_QD_REPAIR_MESH_H

/// \file repair_mesh.h
/// Input validation and repair in one place. `inspect_mesh()` reports what is
/// wrong with a face graph without changing it; `repair_polygon_soup_to_mesh()`
/// turns a polygon soup (what every file format holds) into a triangle mesh that
/// the algorithms of CGAL_QD accept, with CGAL's Polygon Mesh Processing, and
/// says what it repaired. `IO::read_and_repair_mesh()` (IO/read_mesh.h) reads a
/// file and calls it.

#include <CGAL_QD/Error_code.h>
#include <CGAL_QD/internal/oriented_manifold_soup.h>
#include <CGAL_QD/internal/soup_duplicates.h>
#include <CGAL_QD/internal/validation.h>
#include <CGAL_QD/parameters.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_mesh_to_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair.h>
#include <CGAL/Polygon_mesh_processing/repair_degeneracies.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Surface_mesh/Surface_mesh_fwd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL_QD {

/// What `inspect_mesh()` found in a face graph. `status` is the first problem
/// that the algorithms of CGAL_QD refuse (`EMPTY_MESH`, `NOT_TRIANGLE_MESH`,
/// `INVALID_COORDINATES`, `DEGENERATE_FACE`), or `OK`; the other counts are
/// facts a user may want to know (non-manifold vertices, needles, several
/// components are accepted by `segment_quasi_developable()`).
struct Mesh_inspection
{
  Error_code status = Error_code::OK;
  std::size_t number_of_vertices = 0;
  std::size_t number_of_faces = 0;
  std::size_t non_triangle_faces = 0;
  std::size_t non_finite_vertices = 0;   ///< a NaN or infinite coordinate
  std::size_t non_manifold_vertices = 0; ///< several umbrellas meet at the vertex
  std::size_t degenerate_faces = 0;      ///< triangles with collinear corners (exact predicate)
  std::size_t needle_faces = 0;          ///< triangles whose longest edge exceeds `needle_threshold` times the shortest
  std::size_t isolated_vertices = 0;     ///< vertices without a face
  std::size_t duplicated_vertices = 0;   ///< vertices at the position of another vertex
  std::size_t connected_components = 0;  ///< through edges
  std::size_t border_loops = 0;

  explicit operator bool() const { return status == Error_code::OK; }
};

/// What `repair_polygon_soup_to_mesh()` did. The counts are those of the
/// repairs made; `result` inspects the mesh written. When `status` is not `OK`,
/// `message` says what is wrong in words a user understands.
struct Repair_report
{
  Error_code status = Error_code::OK;
  std::string message;
  std::size_t points_read = 0;
  std::size_t polygons_read = 0;
  std::size_t duplicate_points_merged = 0;        ///< points at the position of an earlier point
  std::size_t invalid_polygons_removed = 0;       ///< fewer than 3 distinct corners, or a corner repeated
  std::size_t duplicate_polygons_removed = 0;     ///< polygons with the same corners as another
  std::size_t isolated_points_removed = 0;        ///< points that no polygon uses
  std::size_t polygons_reoriented = 0;            ///< reversed to agree with their neighbours
  std::size_t non_manifold_vertices_duplicated = 0; ///< points added to make vertices and edges manifold
  std::size_t polygons_triangulated = 0;          ///< faces with more than 3 corners
  std::size_t triangles_added = 0;                ///< by the triangulation of those faces
  std::size_t degenerate_faces_removed = 0;       ///< zero-area triangles collapsed
  Mesh_inspection result;

  explicit operator bool() const { return status == Error_code::OK; }

  /// one sentence per kind of repair made, for a user
  std::vector<std::string> repairs() const
  {
    std::vector<std::string> out;
    auto add = [&out](std::size_t n, const char* one, const char* many) {
      if(n > 0) out.push_back(std::to_string(n) + " " + (n == 1 ? one : many));
    };
    add(duplicate_points_merged, "duplicated point merged", "duplicated points merged");
    add(invalid_polygons_removed, "polygon with repeated corners removed", "polygons with repeated corners removed");
    add(duplicate_polygons_removed, "duplicated polygon removed", "duplicated polygons removed");
    add(isolated_points_removed, "isolated point removed", "isolated points removed");
    add(polygons_reoriented, "polygon reoriented to agree with its neighbours",
        "polygons reoriented to agree with their neighbours");
    add(non_manifold_vertices_duplicated, "point duplicated to make the mesh manifold",
        "points duplicated to make the mesh manifold");
    if(polygons_triangulated > 0)
      out.push_back(std::to_string(polygons_triangulated) + (polygons_triangulated == 1 ? " polygon" : " polygons") +
                    " triangulated (" + std::to_string(triangles_added) +
                    (triangles_added == 1 ? " triangle added)" : " triangles added)"));
    add(degenerate_faces_removed, "degenerate face removed", "degenerate faces removed");
    return out;
  }
};

namespace internal {

// Triangles (corner numbers) that cover a polygon given by its corners in
// order: ear clipping in the plane of its Newell normal, keeping the order's
// orientation; a fan from the first corner when the polygon is degenerate
// (no normal), very large, or has no ear left (it crosses itself).
inline std::vector<std::array<std::size_t, 3>> ear_clipping(const std::vector<std::array<double, 3>>& c)
{
  const std::size_t k = c.size();
  std::vector<std::array<std::size_t, 3>> out;
  auto fan = [&](const std::vector<std::size_t>& left) {
    for(std::size_t i = 1; i + 1 < left.size(); ++i) out.push_back({{left[0], left[i], left[i + 1]}});
  };
  std::vector<std::size_t> left(k);
  for(std::size_t i = 0; i < k; ++i) left[i] = i;
  if(k <= 3 || k > 1000) {
    fan(left);
    return out;
  }
  double n[3] = {0, 0, 0};
  for(std::size_t i = 0; i < k; ++i) {
    const std::array<double, 3>&a = c[i], &b = c[(i + 1) % k];
    n[0] += (a[1] - b[1]) * (a[2] + b[2]);
    n[1] += (a[2] - b[2]) * (a[0] + b[0]);
    n[2] += (a[0] - b[0]) * (a[1] + b[1]);
  }
  const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  if(!(length > 0) || !std::isfinite(length)) {
    fan(left);
    return out;
  }
  for(double& x : n) x /= length;
  // u, v: a basis of the plane such that (u, v, n) is right-handed
  double u[3] = {0, 0, 0};
  const int axis = std::abs(n[0]) < 0.6 ? 0 : (std::abs(n[1]) < 0.6 ? 1 : 2);
  u[axis] = 1;
  const double along = u[0] * n[0] + u[1] * n[1] + u[2] * n[2];
  for(int j = 0; j < 3; ++j) u[j] -= along * n[j];
  const double ul = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
  for(double& x : u) x /= ul;
  const double v[3] = {n[1] * u[2] - n[2] * u[1], n[2] * u[0] - n[0] * u[2], n[0] * u[1] - n[1] * u[0]};
  std::vector<std::array<double, 2>> q(k);
  for(std::size_t i = 0; i < k; ++i)
    q[i] = {{c[i][0] * u[0] + c[i][1] * u[1] + c[i][2] * u[2], c[i][0] * v[0] + c[i][1] * v[1] + c[i][2] * v[2]}};
  auto cross = [&](std::size_t a, std::size_t b, std::size_t p) {
    return (q[b][0] - q[a][0]) * (q[p][1] - q[a][1]) - (q[b][1] - q[a][1]) * (q[p][0] - q[a][0]);
  };
  while(left.size() > 3) {
    bool clipped = false;
    const std::size_t m = left.size();
    for(std::size_t i = 0; i < m && !clipped; ++i) {
      const std::size_t a = left[(i + m - 1) % m], b = left[i], d = left[(i + 1) % m];
      if(!(cross(a, b, d) > 0)) continue;  // reflex or flat
      bool empty = true;
      for(std::size_t p : left)
        if(p != a && p != b && p != d && cross(a, b, p) >= 0 && cross(b, d, p) >= 0 && cross(d, a, p) >= 0) {
          empty = false;
          break;
        }
      if(!empty) continue;
      out.push_back({{a, b, d}});
      left.erase(left.begin() + static_cast<std::ptrdiff_t>(i));
      clipped = true;
    }
    if(!clipped) {
      fan(left);
      return out;
    }
  }
  out.push_back({{left[0], left[1], left[2]}});
  return out;
}

template <class TriangleMesh>
void collect_garbage_if_any(TriangleMesh&) {}

template <class P>
void collect_garbage_if_any(CGAL::Surface_mesh<P>& sm) { sm.collect_garbage(); }

template <class Point>
bool is_finite_point(const Point& p)
{
  return std::isfinite(CGAL::to_double(p.x())) && std::isfinite(CGAL::to_double(p.y())) &&
         std::isfinite(CGAL::to_double(p.z()));
}

// Removes cyclically repeated consecutive corners; a polygon left with fewer
// than 3 corners or with a corner twice is removed. Returns the number removed.
template <class PolygonRange>
std::size_t remove_invalid_polygons(PolygonRange& polygons)
{
  std::size_t removed = 0, kept = 0;
  for(std::size_t i = 0; i < polygons.size(); ++i) {
    auto polygon = polygons[i];
    polygon.erase(std::unique(polygon.begin(), polygon.end()), polygon.end());
    while(polygon.size() > 1 && polygon.front() == polygon.back()) polygon.pop_back();
    auto sorted = polygon;
    std::sort(sorted.begin(), sorted.end());
    if(polygon.size() < 3 || std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) {
      ++removed;
      continue;
    }
    polygons[kept++] = polygon;
  }
  polygons.resize(kept);
  return removed;
}

} // namespace internal

/// reports what is wrong with a face graph, without changing it.
///
/// \tparam FaceGraph a model of `FaceListGraph`
/// \param tm the mesh
/// \param np optional named parameters: `CGAL::parameters::vertex_point_map`,
///   `CGAL::parameters::vertex_index_map`, `CGAL::parameters::face_index_map`,
///   `CGAL_QD::parameters::needle_threshold` (default 1000).
/// \returns the counts; `status` is the first problem (in the order empty, not
///   triangles, non-finite coordinates, degenerate faces) that the algorithms of
///   CGAL_QD refuse.
template <class FaceGraph, class NamedParameters = CGAL::parameters::Default_named_parameters>
Mesh_inspection inspect_mesh(const FaceGraph& tm, const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef boost::graph_traits<FaceGraph> GT;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;

  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, tm));
  const auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
  const auto fim = CGAL::get_initialized_face_index_map(tm, np);
  const auto him = CGAL::get_initialized_halfedge_index_map(tm, np);
  const double needle = choose_parameter(get_parameter(np, internal_np::needle_threshold_t()), 1000.);
  typedef typename boost::property_traits<decltype(vpm)>::value_type Point;
  const typename CGAL::Kernel_traits<Point>::Kernel::Collinear_3 collinear =
      typename CGAL::Kernel_traits<Point>::Kernel().collinear_3_object();

  Mesh_inspection r;
  r.number_of_vertices = num_vertices(tm);
  r.number_of_faces = num_faces(tm);

  // a vertex is non-manifold when the umbrella around halfedge(v) misses some
  // of its incoming halfedges, or holds two border halfedges (the test of
  // PMP::is_non_manifold_vertex, which scans the whole mesh for every vertex)
  std::vector<std::size_t> incoming(r.number_of_vertices, 0);
  for(const halfedge_descriptor h : halfedges(tm)) ++incoming[get(vim, target(h, tm))];
  std::vector<std::array<double, 3>> xyz;
  xyz.reserve(r.number_of_vertices);
  for(const auto v : vertices(tm)) {
    const auto p = internal::point_of<FaceGraph>(v, vpm);
    xyz.push_back(p);
    if(!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) ++r.non_finite_vertices;
    if(halfedge(v, tm) == GT::null_halfedge()) {
      ++r.isolated_vertices;
      continue;
    }
    std::size_t around = 0, borders = 0;
    for(const halfedge_descriptor h : CGAL::halfedges_around_target(v, tm)) {
      ++around;
      if(CGAL::is_border(h, tm)) ++borders;
    }
    if(around != incoming[get(vim, v)] || borders > 1) ++r.non_manifold_vertices;
  }
  {
    std::vector<std::array<double, 3>> sorted = xyz;
    std::sort(sorted.begin(), sorted.end());
    for(std::size_t i = 1; i < sorted.size(); ++i)
      if(sorted[i] == sorted[i - 1]) ++r.duplicated_vertices;
  }
  for(const auto f : faces(tm)) {
    const halfedge_descriptor h = halfedge(f, tm);
    if(CGAL::halfedges_around_face(h, tm).size() != 3) {
      ++r.non_triangle_faces;
      continue;
    }
    const auto& p = get(vpm, source(h, tm));
    const auto& q = get(vpm, target(h, tm));
    const auto& s = get(vpm, target(next(h, tm), tm));
    if(!internal::is_finite_point(p) || !internal::is_finite_point(q) || !internal::is_finite_point(s)) continue;
    if(collinear(p, q, s)) {
      ++r.degenerate_faces;
      continue;
    }
    double shortest = HUGE_VAL, longest = 0;
    for(const halfedge_descriptor e : CGAL::halfedges_around_face(h, tm)) {
      const double l = internal::distance3(xyz[get(vim, source(e, tm))], xyz[get(vim, target(e, tm))]);
      shortest = (std::min)(shortest, l);
      longest = (std::max)(longest, l);
    }
    if(longest > needle * shortest) ++r.needle_faces;
  }
  // components through edges, and border loops
  std::vector<std::size_t> component(r.number_of_faces, 0);
  r.connected_components = CGAL::Polygon_mesh_processing::connected_components(
      tm, boost::make_iterator_property_map(component.begin(), fim), CGAL::parameters::face_index_map(fim));
  std::vector<char> on_loop(num_halfedges(tm), 0);
  for(const halfedge_descriptor h : halfedges(tm)) {
    if(!CGAL::is_border(h, tm) || on_loop[get(him, h)]) continue;
    ++r.border_loops;
    halfedge_descriptor g = h;
    do {
      on_loop[get(him, g)] = 1;
      g = next(g, tm);
    } while(g != h && !on_loop[get(him, g)]);
  }

  if(r.number_of_faces == 0) r.status = Error_code::EMPTY_MESH;
  else if(r.non_triangle_faces > 0) r.status = Error_code::NOT_TRIANGLE_MESH;
  else if(r.non_finite_vertices > 0) r.status = Error_code::INVALID_COORDINATES;
  else if(r.degenerate_faces > 0) r.status = Error_code::DEGENERATE_FACE;
  return r;
}

/// turns a polygon soup into a triangle mesh that the algorithms of CGAL_QD
/// accept, repairing what CGAL's Polygon Mesh Processing can repair, in this
/// order: points at the same position are merged; polygons with fewer than 3
/// distinct corners are removed, then duplicated polygons and unused points;
/// the soup is oriented consistently, duplicating the points where it is not
/// manifold (`orient_polygon_soup()`, skipped where the soup already is a
/// consistently oriented manifold mesh, which it would leave as it is);
/// polygons with more than 3 corners are cut into triangles by ear clipping in
/// the plane of their Newell normal (a
/// fan where a polygon has no normal or crosses itself); zero-area triangles
/// are removed (`remove_degenerate_faces()`) with the vertices they leave
/// isolated, and a mesh that this leaves invalid is built again from its faces.
///
/// \tparam PolygonMesh a model of `MutableFaceGraph`
/// \param points the points; taken by value because the repairs change them
/// \param polygons each a `std::vector`-like sequence of indices into `points`
/// \param pm the output mesh; it is cleared first, and left empty on failure
/// \param np optional named parameters: `CGAL::parameters::vertex_point_map`
///   of `pm`, `CGAL_QD::parameters::needle_threshold` (for the inspection).
/// \returns the repairs made; on failure `status` is `EMPTY_MESH` (no polygon,
///   or none left), `INVALID_INDEX`, `INVALID_COORDINATES` (a NaN or infinite
///   coordinate), `NON_MANIFOLD` (the soup could not be made a mesh),
///   `NOT_TRIANGLE_MESH` (a polygon could not be triangulated) or
///   `DEGENERATE_FACE` (a zero-area face could not be removed), and `message`
///   says more.
template <class PolygonMesh, class Point, class Polygon,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
Repair_report repair_polygon_soup_to_mesh(std::vector<Point> points, std::vector<Polygon> polygons, PolygonMesh& pm,
                                          const NamedParameters& np = CGAL::parameters::default_values())
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;

  Repair_report r;
  CGAL::clear(pm);
  r.points_read = points.size();
  r.polygons_read = polygons.size();
  auto fail = [&r, &pm](Error_code code, const std::string& message) {
    r.status = code;
    r.message = message;
    CGAL::clear(pm);
    return r;
  };
  if(polygons.empty()) return fail(Error_code::EMPTY_MESH, "the input has no polygon");
  for(std::size_t i = 0; i < polygons.size(); ++i)
    for(const auto id : polygons[i])
      if(static_cast<std::size_t>(id) >= points.size())
        return fail(Error_code::INVALID_INDEX, "polygon " + std::to_string(i) + " refers to point " +
                                                   std::to_string(static_cast<std::size_t>(id)) + " but there are " +
                                                   std::to_string(points.size()) + " points");
  for(std::size_t i = 0; i < points.size(); ++i)
    if(!internal::is_finite_point(points[i]))
      return fail(Error_code::INVALID_COORDINATES, "point " + std::to_string(i) + " has a NaN or infinite coordinate");

  // CGAL's merges, where a sort finds something for them to merge
  if(internal::has_duplicate_points(points))
    r.duplicate_points_merged = PMP::merge_duplicate_points_in_polygon_soup(points, polygons);
  r.invalid_polygons_removed = internal::remove_invalid_polygons(polygons);
  if(internal::find_duplicate_triangles(polygons) != internal::Duplicate_triangles::NONE)
    r.duplicate_polygons_removed = PMP::merge_duplicate_polygons_in_polygon_soup(points, polygons);
  r.isolated_points_removed = PMP::remove_isolated_points_in_polygon_soup(points, polygons);
  if(polygons.empty()) return fail(Error_code::EMPTY_MESH, "no polygon has 3 distinct corners");

  // orientation: count the polygons whose corner order the orientation
  // reversed; nothing to do where the soup already is an oriented manifold
  // mesh (which `orient_polygon_soup()` would leave as it is)
  const bool oriented_manifold = internal::is_oriented_manifold_soup(polygons, points.size());
  if(!oriented_manifold) {
    const std::size_t before = points.size();
    std::vector<std::array<Point, 2>> first_edge;
    first_edge.reserve(polygons.size());
    for(const auto& polygon : polygons) first_edge.push_back({points[polygon[0]], points[polygon[1]]});
    PMP::orient_polygon_soup(points, polygons);
    r.non_manifold_vertices_duplicated = points.size() - before;
    for(std::size_t i = 0; i < polygons.size(); ++i) {
      const auto& polygon = polygons[i];
      const std::size_t n = polygon.size();
      for(std::size_t k = 0; k < n; ++k)
        if(points[polygon[k]] == first_edge[i][1] && points[polygon[(k + 1) % n]] == first_edge[i][0]) {
          ++r.polygons_reoriented;
          break;
        }
    }
  }
  if(!oriented_manifold && !PMP::is_polygon_soup_a_polygon_mesh(polygons))
    return fail(Error_code::NON_MANIFOLD, "the polygons cannot be made a manifold mesh");
  PMP::polygon_soup_to_polygon_mesh(points, polygons, pm, CGAL::parameters::default_values(), np);

  if(!CGAL::is_triangle_mesh(pm)) {
    // every polygon cut into triangles by ear clipping in the plane of its
    // Newell normal (CGAL's triangulate_faces() was found by the fuzzer of
    // fuzz/ to fail, stop on assertions, leave invalid meshes and crash on
    // polygons far from planar or degenerate), and the mesh built again
    const std::size_t before = num_faces(pm);
    std::vector<std::vector<std::size_t>> triangles;
    for(const auto& polygon : polygons) {
      std::vector<std::size_t> corners(polygon.begin(), polygon.end());
      if(corners.size() > 3) ++r.polygons_triangulated;
      std::vector<std::array<double, 3>> c;
      for(std::size_t i : corners)
        c.push_back({{CGAL::to_double(points[i].x()), CGAL::to_double(points[i].y()), CGAL::to_double(points[i].z())}});
      for(const auto& t : internal::ear_clipping(c)) triangles.push_back({corners[t[0]], corners[t[1]], corners[t[2]]});
    }
    CGAL::clear(pm);
    // a diagonal can meet an edge of other faces: orienting makes the soup manifold again
    if(!PMP::is_polygon_soup_a_polygon_mesh(triangles)) {
      const std::size_t known = points.size();
      PMP::orient_polygon_soup(points, triangles);
      r.non_manifold_vertices_duplicated += points.size() - known;
    }
    if(!PMP::is_polygon_soup_a_polygon_mesh(triangles))
      return fail(Error_code::NOT_TRIANGLE_MESH, "the polygons could not be cut into triangles that make a manifold mesh");
    PMP::polygon_soup_to_polygon_mesh(points, triangles, pm, CGAL::parameters::default_values(), np);
    r.triangles_added = num_faces(pm) - before;
  }
  r.result = inspect_mesh(pm, np);
  if(r.result.degenerate_faces > 0) {
    const std::size_t before = r.result.number_of_faces;
    PMP::remove_degenerate_faces(pm, np);
    PMP::remove_isolated_vertices(pm);
    internal::collect_garbage_if_any(pm);
    if(!CGAL::is_valid_polygon_mesh(pm)) {
      // CGAL's removal can leave a border cycle of two edges (found by the fuzzer
      // of fuzz/): the mesh is built again from its faces
      typedef typename CGAL::GetVertexPointMap<PolygonMesh, NamedParameters>::const_type VPM;
      std::vector<typename boost::property_traits<VPM>::value_type> mesh_points;
      std::vector<std::vector<std::size_t>> mesh_polygons;
      PMP::polygon_mesh_to_polygon_soup(pm, mesh_points, mesh_polygons, np);
      CGAL::clear(pm);
      PMP::merge_duplicate_points_in_polygon_soup(mesh_points, mesh_polygons);
      PMP::merge_duplicate_polygons_in_polygon_soup(mesh_points, mesh_polygons);
      PMP::remove_isolated_points_in_polygon_soup(mesh_points, mesh_polygons);
      if(mesh_polygons.empty()) return fail(Error_code::EMPTY_MESH, "every face is degenerate");
      PMP::orient_polygon_soup(mesh_points, mesh_polygons);
      if(!PMP::is_polygon_soup_a_polygon_mesh(mesh_polygons))
        return fail(Error_code::NON_MANIFOLD, "the faces left after removing the degenerate ones are not a manifold mesh");
      PMP::polygon_soup_to_polygon_mesh(mesh_points, mesh_polygons, pm, CGAL::parameters::default_values(), np);
      if(!CGAL::is_valid_polygon_mesh(pm))
        return fail(Error_code::NON_MANIFOLD, "the faces left after removing the degenerate ones are not a valid mesh");
    }
    r.result = inspect_mesh(pm, np);
    if(r.result.degenerate_faces > 0)
      return fail(Error_code::DEGENERATE_FACE,
                  std::to_string(r.result.degenerate_faces) + " degenerate (zero-area) faces could not be removed");
    r.degenerate_faces_removed = before - r.result.number_of_faces;
    if(r.result.number_of_faces == 0) return fail(Error_code::EMPTY_MESH, "every face is degenerate");
  }
  if(!r.result) return fail(r.result.status, error_message(r.result.status));
  return r;
}

} // namespace CGAL_QD

#endif // CGAL_QD_REPAIR_MESH_H
