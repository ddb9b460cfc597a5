// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

// Meshes built by the tests: grids mapped onto analytic surfaces (planes,
// cylinders, cones, bumps, sphere caps), optionally with rectangular holes.
// Built through CGAL::Euler::add_face, so they work for every MutableFaceGraph.

#ifndef CGAL_QD_TEST_MESH_GENERATORS_H
#define CGAL_QD_TEST_MESH_GENERATORS_H

#include <CGAL/Polyhedron_3.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/Face_filtered_graph.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/helpers.h>

#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <set>
#include <random>
#include <vector>

namespace qd_test {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;
typedef CGAL::Simple_cartesian<double> Cartesian;
typedef CGAL::Surface_mesh<Epick::Point_3> Surface_mesh;
typedef CGAL::Polyhedron_3<Epick> Polyhedron;
typedef CGAL::Surface_mesh<Cartesian::Point_3> Cartesian_surface_mesh;

constexpr double pi = 3.14159265358979323846;

typedef std::array<double, 3> P3;
typedef std::array<std::size_t, 3> Tri;

struct Soup
{
  std::vector<P3> points;
  std::vector<Tri> triangles;
};

// Builds `tm` from a soup; the triangles must form a valid (possibly
// non-manifold at vertices) oriented surface.
template <class Mesh>
bool build(const Soup& soup, Mesh& tm)
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::property_traits<
      typename boost::property_map<Mesh, CGAL::vertex_point_t>::type>::value_type Point;
  auto vpm = get(CGAL::vertex_point, tm);
  std::vector<vertex_descriptor> vs;
  for(const P3& p : soup.points) {
    vertex_descriptor v = add_vertex(tm);
    put(vpm, v, Point(p[0], p[1], p[2]));
    vs.push_back(v);
  }
  for(const Tri& t : soup.triangles) {
    std::array<vertex_descriptor, 3> f = {vs[t[0]], vs[t[1]], vs[t[2]]};
    if(CGAL::Euler::add_face(f, tm) == boost::graph_traits<Mesh>::null_face()) return false;
  }
  // drop vertices no face uses
  std::vector<vertex_descriptor> isolated;
  for(vertex_descriptor v : vertices(tm))
    if(halfedge(v, tm) == boost::graph_traits<Mesh>::null_halfedge()) isolated.push_back(v);
  for(vertex_descriptor v : isolated) remove_vertex(v, tm);
  return true;
}

// A (nx x ny)-cell grid over [0,1]^2 mapped by f, counter-clockwise in (u,v).
// Cells for which `hole(i, j)` is true are left out.
inline Soup grid(std::size_t nx, std::size_t ny, const std::function<P3(double, double)>& f,
                 const std::function<bool(std::size_t, std::size_t)>& hole = {})
{
  Soup s;
  for(std::size_t j = 0; j <= ny; ++j)
    for(std::size_t i = 0; i <= nx; ++i)
      s.points.push_back(f(double(i) / nx, double(j) / ny));
  auto id = [nx](std::size_t i, std::size_t j) { return j * (nx + 1) + i; };
  for(std::size_t j = 0; j < ny; ++j)
    for(std::size_t i = 0; i < nx; ++i) {
      if(hole && hole(i, j)) continue;
      // alternate diagonals so that no direction is preferred
      if((i + j) % 2 == 0) {
        s.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
        s.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
      } else {
        s.triangles.push_back({id(i, j), id(i + 1, j), id(i, j + 1)});
        s.triangles.push_back({id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
      }
    }
  return s;
}

// rectangular holes given as cell ranges [i0, i1) x [j0, j1)
inline std::function<bool(std::size_t, std::size_t)> holes(std::vector<std::array<std::size_t, 4>> boxes)
{
  return [boxes](std::size_t i, std::size_t j) {
    for(const auto& b : boxes)
      if(i >= b[0] && i < b[1] && j >= b[2] && j < b[3]) return true;
    return false;
  };
}

// a cylinder of radius r cut open along a ruling, spanning `angle` < 2 pi
inline std::function<P3(double, double)> cylinder(double r, double angle, double height)
{
  return [=](double u, double v) { return P3{r * std::cos(angle * u), r * std::sin(angle * u), height * v}; };
}

// a cone (apex excluded), radius from r0 to r1 along the height
inline std::function<P3(double, double)> cone(double r0, double r1, double angle, double height)
{
  return [=](double u, double v) {
    const double r = r0 + (r1 - r0) * v;
    return P3{r * std::cos(angle * u), r * std::sin(angle * u), height * v};
  };
}

inline std::function<P3(double, double)> bump(double amplitude)
{
  return [=](double u, double v) {
    return P3{u, v, amplitude * std::sin(pi * u) * std::sin(pi * v) + 0.3 * amplitude * u * u};
  };
}

// A polar patch: a centre vertex and `rings` rings of `sectors` vertices,
// mapped by f(rho in [0,1], phi).
inline Soup polar(std::size_t rings, std::size_t sectors, const std::function<P3(double, double)>& f)
{
  Soup s;
  s.points.push_back(f(0., 0.));
  for(std::size_t r = 1; r <= rings; ++r)
    for(std::size_t k = 0; k < sectors; ++k)
      s.points.push_back(f(double(r) / rings, 2 * pi * (k + 0.5 * (r % 2)) / sectors));
  auto id = [sectors](std::size_t r, std::size_t k) { return 1 + (r - 1) * sectors + k % sectors; };
  for(std::size_t k = 0; k < sectors; ++k) s.triangles.push_back({0, id(1, k), id(1, k + 1)});
  for(std::size_t r = 1; r < rings; ++r)
    for(std::size_t k = 0; k < sectors; ++k) {
      if(r % 2 == 1) {  // ring r shifted by half a sector relative to ring r+1
        s.triangles.push_back({id(r, k), id(r + 1, k + 1), id(r, k + 1)});
        s.triangles.push_back({id(r, k), id(r + 1, k), id(r + 1, k + 1)});
      } else {
        s.triangles.push_back({id(r, k), id(r + 1, k), id(r, k + 1)});
        s.triangles.push_back({id(r, k + 1), id(r + 1, k), id(r + 1, k + 1)});
      }
    }
  return s;
}

// sphere cap of unit radius and polar half-angle `beta` (beta > pi/2: wider than a hemisphere)
inline std::function<P3(double, double)> sphere_cap(double beta)
{
  return [=](double rho, double phi) {
    const double t = beta * rho;
    return P3{std::sin(t) * std::cos(phi), std::sin(t) * std::sin(phi), std::cos(t)};
  };
}

// a cap of an ellipsoid (x stretched by `ex`) whose border is not a circle of
// latitude: polar half-angle (b0 + b1 cos phi) pi
inline std::function<P3(double, double)> tilted_cap(double b0, double b1, double ex)
{
  return [=](double rho, double phi) {
    const double t = (b0 + b1 * std::cos(phi)) * pi * rho;
    return P3{ex * std::sin(t) * std::cos(phi), std::sin(t) * std::sin(phi), std::cos(t)};
  };
}

inline std::function<P3(double, double)> flat_disk(double radius)
{
  return [=](double rho, double phi) { return P3{radius * rho * std::cos(phi), radius * rho * std::sin(phi), 0.}; };
}

// A torus (radii 2 and 0.7) as an n x m grid; `open` leaves out one face, which
// makes a genus-1 patch with one border loop.
inline Soup torus(std::size_t n, std::size_t m, bool open = false)
{
  Soup s;
  for(std::size_t j = 0; j < m; ++j)
    for(std::size_t i = 0; i < n; ++i) {
      const double a = 2 * pi * i / n, b = 2 * pi * j / m;
      s.points.push_back({(2 + 0.7 * std::cos(b)) * std::cos(a), (2 + 0.7 * std::cos(b)) * std::sin(a), 0.7 * std::sin(b)});
    }
  for(std::size_t j = 0; j < m; ++j)
    for(std::size_t i = 0; i < n; ++i) {
      if(open && i == 0 && j == 0) continue;
      const std::size_t a = j * n + i, b = j * n + (i + 1) % n, c = ((j + 1) % m) * n + (i + 1) % n,
                        d = ((j + 1) % m) * n + i;
      s.triangles.push_back({a, b, c});
      s.triangles.push_back({a, c, d});
    }
  return s;
}

// Merges points that coincide (to 1e-9) and re-indexes the triangles.
inline Soup merge_coincident_points(const Soup& in)
{
  Soup out;
  std::map<std::array<long long, 3>, std::size_t> index;
  std::vector<std::size_t> remap(in.points.size());
  for(std::size_t i = 0; i < in.points.size(); ++i) {
    const P3& p = in.points[i];
    const std::array<long long, 3> key = {std::llround(p[0] * 1e9), std::llround(p[1] * 1e9), std::llround(p[2] * 1e9)};
    auto it = index.find(key);
    if(it == index.end()) {
      it = index.emplace(key, out.points.size()).first;
      out.points.push_back(p);
    }
    remap[i] = it->second;
  }
  for(const Tri& t : in.triangles) out.triangles.push_back({remap[t[0]], remap[t[1]], remap[t[2]]});
  return out;
}

// Cuts a soup open along the given edges (pairs of point indices): around every
// vertex, the faces are grouped into wedges separated by cut edges (or borders),
// and each wedge gets its own copy of the vertex.
inline Soup cut_open(const Soup& in, const std::set<std::pair<std::size_t, std::size_t>>& cut)
{
  auto is_cut = [&](std::size_t a, std::size_t b) { return cut.count({a, b}) || cut.count({b, a}); };
  const std::size_t nc = 3 * in.triangles.size();
  std::vector<std::size_t> parent(nc);
  for(std::size_t i = 0; i < nc; ++i) parent[i] = i;
  std::function<std::size_t(std::size_t)> find = [&](std::size_t x) {
    while(parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  // corners of the two faces of every uncut edge, at both of its vertices
  std::map<std::pair<std::size_t, std::size_t>, std::vector<std::pair<std::size_t, int>>> edge_faces;
  for(std::size_t f = 0; f < in.triangles.size(); ++f)
    for(int k = 0; k < 3; ++k) {
      const std::size_t a = in.triangles[f][k], b = in.triangles[f][(k + 1) % 3];
      edge_faces[{(std::min)(a, b), (std::max)(a, b)}].push_back({f, k});
    }
  for(const auto& e : edge_faces) {
    if(e.second.size() != 2 || is_cut(e.first.first, e.first.second)) continue;
    for(std::size_t endpoint : {e.first.first, e.first.second}) {
      std::size_t c[2];
      for(int s = 0; s < 2; ++s) {
        const auto& fk = e.second[s];
        for(int k = 0; k < 3; ++k)
          if(in.triangles[fk.first][k] == endpoint) c[s] = 3 * fk.first + k;
      }
      parent[find(c[0])] = find(c[1]);
    }
  }
  Soup out;
  std::map<std::size_t, std::size_t> copy_of_class;
  out.triangles.resize(in.triangles.size());
  for(std::size_t f = 0; f < in.triangles.size(); ++f)
    for(int k = 0; k < 3; ++k) {
      const std::size_t cls = find(3 * f + k);
      auto it = copy_of_class.find(cls);
      if(it == copy_of_class.end()) {
        it = copy_of_class.emplace(cls, out.points.size()).first;
        out.points.push_back(in.points[in.triangles[f][k]]);
      }
      out.triangles[f][k] = it->second;
    }
  return out;
}

// The surface of the unit cube, each side an n x n grid, opened along five
// edges forming a tree: three edges of the top square and two vertical edges.
inline Soup cube_opened_by_five_cuts(std::size_t n)
{
  Soup s;
  auto side = [&](P3 o, P3 du, P3 dv) {
    Soup g = grid(n, n, [=](double u, double v) {
      return P3{o[0] + u * du[0] + v * dv[0], o[1] + u * du[1] + v * dv[1], o[2] + u * du[2] + v * dv[2]};
    });
    const std::size_t off = s.points.size();
    for(const P3& p : g.points) s.points.push_back(p);
    for(const Tri& t : g.triangles) s.triangles.push_back({t[0] + off, t[1] + off, t[2] + off});
  };
  // outward normals: du x dv points out of the cube
  side({0, 0, 0}, {0, 1, 0}, {1, 0, 0});  // bottom, normal -z
  side({0, 0, 1}, {1, 0, 0}, {0, 1, 0});  // top, +z
  side({0, 0, 0}, {1, 0, 0}, {0, 0, 1});  // y = 0, normal -y
  side({0, 1, 0}, {0, 0, 1}, {1, 0, 0});  // y = 1, +y
  side({0, 0, 0}, {0, 0, 1}, {0, 1, 0});  // x = 0, -x
  side({1, 0, 0}, {0, 1, 0}, {0, 0, 1});  // x = 1, +x
  Soup closed = merge_coincident_points(s);
  // the cut tree: (0,0,1)-(1,0,1)-(1,1,1)-(0,1,1), (0,0,0)-(0,0,1), (1,1,0)-(1,1,1)
  const std::vector<std::pair<P3, P3>> tree = {{{0, 0, 1}, {1, 0, 1}}, {{1, 0, 1}, {1, 1, 1}}, {{1, 1, 1}, {0, 1, 1}},
                                               {{0, 0, 0}, {0, 0, 1}}, {{1, 1, 0}, {1, 1, 1}}};
  auto on_segment = [](const P3& p, const std::pair<P3, P3>& e) {
    double t = -1;
    for(int c = 0; c < 3; ++c) {
      const double d = e.second[c] - e.first[c];
      if(d != 0) t = (p[c] - e.first[c]) / d;
      else if(std::abs(p[c] - e.first[c]) > 1e-12) return false;
    }
    return t >= -1e-12 && t <= 1 + 1e-12;
  };
  std::set<std::pair<std::size_t, std::size_t>> cut;
  for(const Tri& t : closed.triangles)
    for(int k = 0; k < 3; ++k) {
      const std::size_t a = t[k], b = t[(k + 1) % 3];
      for(const auto& e : tree)
        if(on_segment(closed.points[a], e) && on_segment(closed.points[b], e)) cut.insert({a, b});
    }
  return cut_open(closed, cut);
}

// A patch grown on a real mesh as a segmentation would leave it: a ball of
// faces around a seed, whose border is then cleaned of one-face notches (an
// outside face sharing two edges with the patch joins it) and ears (a patch
// face with two border edges leaves it).
inline bool grow_disk_patch(const Surface_mesh& sm, Surface_mesh::Face_index seed, std::size_t max_faces, Surface_mesh& out)
{
  std::vector<Surface_mesh::Face_index> order{seed};
  std::set<Surface_mesh::Face_index> in{seed};
  for(std::size_t q = 0; q < order.size() && order.size() < max_faces; ++q)
    for(auto h : CGAL::halfedges_around_face(halfedge(order[q], sm), sm)) {
      auto o = opposite(h, sm);
      if(is_border(o, sm)) continue;
      if(in.insert(face(o, sm)).second) order.push_back(face(o, sm));
    }
  auto inside_neighbours = [&](Surface_mesh::Face_index f) {
    int k = 0;
    for(auto h : CGAL::halfedges_around_face(halfedge(f, sm), sm))
      if(!is_border(opposite(h, sm), sm) && in.count(face(opposite(h, sm), sm))) ++k;
    return k;
  };
  for(int round = 0; round < 10; ++round) {
    bool changed = false;
    for(auto f : faces(sm))
      if(!in.count(f) && inside_neighbours(f) >= 2) { in.insert(f); changed = true; }
    std::vector<Surface_mesh::Face_index> ears;
    for(auto f : in)
      if(inside_neighbours(f) <= 1) ears.push_back(f);
    for(auto f : ears) { in.erase(f); changed = true; }
    if(!changed) break;
  }
  std::vector<Surface_mesh::Face_index> patch(in.begin(), in.end());
  CGAL::Face_filtered_graph<Surface_mesh> fg(sm, patch);
  CGAL::copy_face_graph(fg, out);
  return true;
}

// applies p -> s R p + t with a random rotation R
inline void rigid_motion(Soup& s, double scale, unsigned seed)
{
  std::mt19937 gen(seed);
  std::normal_distribution<double> n;
  double q[4] = {n(gen), n(gen), n(gen), n(gen)};
  const double nq = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  for(double& x : q) x /= nq;
  const double a = q[0], b = q[1], c = q[2], d = q[3];
  const double R[3][3] = {{a * a + b * b - c * c - d * d, 2 * (b * c - a * d), 2 * (b * d + a * c)},
                          {2 * (b * c + a * d), a * a - b * b + c * c - d * d, 2 * (c * d - a * b)},
                          {2 * (b * d - a * c), 2 * (c * d + a * b), a * a - b * b - c * c + d * d}};
  const double t[3] = {n(gen), n(gen), n(gen)};
  for(P3& p : s.points) {
    P3 r{0, 0, 0};
    for(int i = 0; i < 3; ++i) r[i] = scale * (R[i][0] * p[0] + R[i][1] * p[1] + R[i][2] * p[2]) + t[i];
    p = r;
  }
}

} // namespace qd_test

#endif // CGAL_QD_TEST_MESH_GENERATORS_H
