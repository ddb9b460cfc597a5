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
#include <CGAL/boost/graph/helpers.h>

#include <array>
#include <cmath>
#include <functional>
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
