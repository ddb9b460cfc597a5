// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#define BOOST_TEST_MODULE distortion
#include <boost/test/unit_test.hpp>
#include <boost/mpl/list.hpp>

#include "mesh_generators.h"
#include "test_utils.h"

#include <CGAL_QD/distortion.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <set>
#include <utility>
#include <vector>

namespace QD = CGAL_QD;
using namespace qd_test;

typedef boost::mpl::list<Surface_mesh, Polyhedron, Cartesian_surface_mesh> Mesh_types;

namespace {

// UVs from a function of the 3D point
template <class Mesh>
Uv_store<Mesh> map_uv(const Mesh& tm, const std::function<std::array<double, 2>(const P3&)>& f)
{
  Uv_store<Mesh> uv;
  for(auto v : vertices(tm)) {
    const auto q = f(p3(tm, v));
    uv.map[v] = typename Uv_store<Mesh>::Point_2(q[0], q[1]);
  }
  return uv;
}

// a flat grid in the plane z = 0 over [0,2] x [0,1]
Soup flat_grid() { return grid(10, 6, [](double u, double v) { return P3{2 * u, v, 0}; }); }

// the flat grid with a slit from its border inwards along y = 0.5, to x = 1
Soup flat_grid_with_slit()
{
  Soup s = flat_grid();
  std::set<std::pair<std::size_t, std::size_t>> slit;
  std::vector<std::size_t> on_line;
  for(std::size_t i = 0; i < s.points.size(); ++i)
    if(std::abs(s.points[i][1] - 0.5) < 1e-12 && s.points[i][0] < 1.0 + 1e-12) on_line.push_back(i);
  std::sort(on_line.begin(), on_line.end(), [&](std::size_t a, std::size_t b) { return s.points[a][0] < s.points[b][0]; });
  for(std::size_t k = 0; k + 1 < on_line.size(); ++k) slit.insert({on_line[k], on_line[k + 1]});
  BOOST_REQUIRE(slit.size() >= 4u);
  return cut_open(s, slit);
}

} // namespace

BOOST_AUTO_TEST_CASE_TEMPLATE(identity_map, Mesh, Mesh_types)
{
  const Mesh tm = make<Mesh>(flat_grid());
  const auto uv = map_uv(tm, [](const P3& p) { return std::array<double, 2>{p[0], p[1]}; });
  const auto r = QD::compute_distortion(tm, uv.pmap_const());
  BOOST_REQUIRE(r);
  BOOST_TEST(r.number_of_faces == num_faces(tm));
  BOOST_TEST(std::abs(r.area_3d - 2.0) < 1e-12);
  BOOST_TEST(r.area_distortion < 1e-12);
  BOOST_TEST(std::abs(r.l2_stretch - 1) < 1e-12);
  BOOST_TEST(std::abs(r.l2_stretch_normalized - 1) < 1e-12);
  BOOST_TEST(std::abs(r.linf_stretch - 1) < 1e-12);
  BOOST_TEST(r.angle_distortion < 1e-12);
  BOOST_TEST(r.boundary_length_error < 1e-14);
  BOOST_TEST(r.boundary_angle_error < 1e-12);
  BOOST_TEST(r.flipped_faces == 0u);
  BOOST_TEST(r.branch_vertices == 0u);
  BOOST_TEST(r.border_crossings.empty());
  BOOST_TEST(!r.overlap);
  BOOST_TEST(!QD::has_global_overlap(tm, uv.pmap_const()));
}

BOOST_AUTO_TEST_CASE(uniform_scale_and_shear)
{
  const Surface_mesh tm = make<Surface_mesh>(flat_grid());
  for(double s : {0.5, 3.0}) {
    const auto uv = map_uv(tm, [s](const P3& p) { return std::array<double, 2>{s * p[0] + 1, s * p[1] - 2}; });
    const auto r = QD::compute_distortion(tm, uv.pmap_const());
    BOOST_TEST(std::abs(r.area_distortion - std::abs(s * s - 1) * 100) < 1e-9);
    BOOST_TEST(std::abs(r.l2_stretch - 1 / s) < 1e-12);  // the 2D -> 3D map shrinks by 1/s
    BOOST_TEST(std::abs(r.l2_stretch_normalized - 1) < 1e-12);
    BOOST_TEST(r.angle_distortion < 1e-12);
    // border edges: lengths l/10 and l/6 scaled by s; Pi_L = |s - 1| * mean length
    const double mean_length = (2 * 10 * 0.2 + 2 * 6 * (1. / 6)) / 32;
    BOOST_TEST(std::abs(r.boundary_length_error - std::abs(s - 1) * mean_length) < 1e-12);
    BOOST_TEST(r.boundary_angle_error < 1e-12);
    BOOST_TEST(std::abs(QD::area_distortion(tm, uv.pmap_const()) - r.area_distortion) < 1e-15);
    BOOST_TEST(std::abs(QD::l2_stretch(tm, uv.pmap_const()) - r.l2_stretch) < 1e-15);
    // a uniform scale changes every face alike: A_loc = A(Omega)
    BOOST_TEST(std::abs(r.local_area_distortion - std::abs(s * s - 1) * 100) < 1e-9);
    BOOST_TEST(std::abs(QD::local_area_distortion(tm, uv.pmap_const()) - r.local_area_distortion) < 1e-15);
  }
  // half of the grid grown by 2 in area, half shrunk by 2 (x scaled by 2 or by
  // 1/2 on either side of x = 1): the total area error cancels partly, A_loc
  // does not
  {
    const auto uv = map_uv(tm, [](const P3& p) {
      return std::array<double, 2>{p[0] <= 1 ? 2 * p[0] : 2 + 0.5 * (p[0] - 1), p[1]};
    });
    const auto r = QD::compute_distortion(tm, uv.pmap_const());
    double a3 = 0, a2 = 0, local = 0;  // by face, from the grid's cells left and right of x = 1
    for(auto f : faces(tm)) {
      const auto h = halfedge(f, tm);
      const P3 p = p3(tm, source(h, tm)), q = p3(tm, target(h, tm)), o = p3(tm, target(next(h, tm), tm));
      const double area = 0.5 * std::abs((q[0] - p[0]) * (o[1] - p[1]) - (o[0] - p[0]) * (q[1] - p[1]));
      const double scale = (p[0] + q[0] + o[0]) / 3 <= 1 ? 2. : 0.5;
      a3 += area;
      a2 += scale * area;
      local += std::abs(scale - 1) * area;
    }
    BOOST_TEST(std::abs(r.area_distortion - 100 * std::abs(a2 - a3) / a3) < 1e-9);
    BOOST_TEST(std::abs(r.local_area_distortion - 100 * local / a3) < 1e-9);
    BOOST_TEST(r.local_area_distortion > r.area_distortion);
  }
  // shear (x + k y, y): areas kept; the 2D -> 3D Jacobian [[1, -k], [0, 1]] gives
  // L2 = sqrt((2 + k^2) / 2) and Linf = its largest singular value
  const double k = 0.75;
  const auto uv = map_uv(tm, [k](const P3& p) { return std::array<double, 2>{p[0] + k * p[1], p[1]}; });
  const auto r = QD::compute_distortion(tm, uv.pmap_const());
  BOOST_TEST(r.area_distortion < 1e-12);
  BOOST_TEST(std::abs(r.l2_stretch - std::sqrt((2 + k * k) / 2)) < 1e-12);
  const double big = std::sqrt((2 + k * k + std::sqrt((2 + k * k) * (2 + k * k) - 4)) / 2);
  BOOST_TEST(std::abs(r.linf_stretch - big) < 1e-12);
  BOOST_TEST(r.angle_distortion > 0.05);
  BOOST_TEST(!r.overlap);
}

BOOST_AUTO_TEST_CASE_TEMPLATE(mirrored_layout_flips_every_face, Mesh, Mesh_types)
{
  const Mesh tm = make<Mesh>(flat_grid());
  const auto uv = map_uv(tm, [](const P3& p) { return std::array<double, 2>{p[0], -p[1]}; });
  const auto r = QD::compute_distortion(tm, uv.pmap_const());
  BOOST_TEST(r.flipped_faces == num_faces(tm));
  BOOST_TEST(QD::number_of_flipped_faces(tm, uv.pmap_const()) == num_faces(tm));
  BOOST_TEST(r.overlap);
  BOOST_TEST(r.area_distortion < 1e-12);  // unsigned areas
}

BOOST_AUTO_TEST_CASE(one_flipped_face_is_counted)
{
  const Surface_mesh tm = make<Surface_mesh>(flat_grid());
  auto uv = map_uv(tm, [](const P3& p) { return std::array<double, 2>{p[0], p[1]}; });
  // move the interior vertex (3,3) across its neighbours: its faces fold over
  auto v = *std::next(vertices(tm).begin(), 3 * 11 + 3);
  uv.map[v] = Uv_store<Surface_mesh>::Point_2(0.6 + 0.5, 0.5);
  const auto r = QD::compute_distortion(tm, uv.pmap_const());
  BOOST_TEST(r.flipped_faces > 0u);
  BOOST_TEST(r.flipped_faces < 6u);
  BOOST_TEST(r.overlap);
  BOOST_TEST(r.border_crossings.empty());
}

BOOST_AUTO_TEST_CASE(overlap_without_flip_is_detected)
{
  // a strip wound 1.25 times around a circle: every face keeps its orientation,
  // but the strip lies over itself
  const Surface_mesh tm = make<Surface_mesh>(grid(60, 2, [](double u, double v) { return P3{u, 0.1 * v, 0}; }));
  const auto uv = map_uv(tm, [](const P3& p) {
    const double a = 2.5 * pi * p[0], r = 1.0 - p[1];  // v grows inwards: orientation kept
    return std::array<double, 2>{r * std::cos(a), r * std::sin(a)};
  });
  const auto r = QD::compute_distortion(tm, uv.pmap_const());
  BOOST_TEST(r.flipped_faces == 0u);
  BOOST_TEST(!r.border_crossings.empty());
  BOOST_TEST(r.overlap);
  // every reported pair really crosses
  for(const auto& pr : r.border_crossings) BOOST_TEST((pr.first != pr.second));
  // a real crossing stays one with a tolerance
  BOOST_TEST(QD::compute_distortion(tm, uv.pmap_const(), QD::parameters::overlap_tolerance(1e-9)).overlap);
}

BOOST_AUTO_TEST_CASE(sides_of_a_slit_touch_within_the_tolerance)
{
  // the two sides of the slit lie on each other in the plane
  const Surface_mesh tm = make<Surface_mesh>(flat_grid_with_slit());
  const auto uv = map_uv(tm, [](const P3& p) { return std::array<double, 2>{p[0], p[1]}; });
  const auto exact = QD::compute_distortion(tm, uv.pmap_const());
  BOOST_TEST(exact.flipped_faces == 0u);
  BOOST_TEST(exact.overlap);  // exact tests: touching is crossing
  const auto tolerant = QD::compute_distortion(tm, uv.pmap_const(), QD::parameters::overlap_tolerance(1e-9));
  BOOST_TEST(tolerant.border_crossings.empty());
  BOOST_TEST(!tolerant.overlap);
  BOOST_TEST(!QD::has_global_overlap(tm, uv.pmap_const(), QD::parameters::overlap_tolerance(1e-9)));
  // pushing the lower side of the slit over the upper side is an overlap again
  auto folded = uv;
  for(auto v : vertices(tm)) {
    const P3 p = p3(tm, v);
    if(std::abs(p[1] - 0.5) > 1e-12 || p[0] > 1 - 1e-12) continue;
    bool below = false;
    for(auto f : CGAL::faces_around_target(halfedge(v, tm), tm))
      if(f != Surface_mesh::null_face())
        for(auto w : CGAL::vertices_around_face(halfedge(f, tm), tm)) below = below || p3(tm, w)[1] < 0.5 - 1e-12;
    if(below) folded.map[v] = Epick::Point_2(p[0], p[1] + 0.05 * (1 - p[0]));
  }
  BOOST_TEST(QD::compute_distortion(tm, folded.pmap_const(), QD::parameters::overlap_tolerance(1e-9)).overlap);
  // a face below the slit squashed onto it (zero area in 2D) is an overlap,
  // and the touch test must not hand the degenerate image to CGAL's exact
  // triangle test (a precondition violation with assertions on)
  auto squashed = uv;
  bool done = false;
  for(auto f : faces(tm)) {
    std::vector<Surface_mesh::Vertex_index> on, off;
    for(auto w : CGAL::vertices_around_face(halfedge(f, tm), tm))
      (std::abs(p3(tm, w)[1] - 0.5) < 1e-12 && p3(tm, w)[0] < 1 - 1e-12 ? on : off).push_back(w);
    if(on.size() != 2 || off.size() != 1 || p3(tm, off[0])[1] > 0.5) continue;
    const auto a = uv.at(on[0]), b = uv.at(on[1]);
    squashed.map[off[0]] = Epick::Point_2((a[0] + b[0]) / 2, (a[1] + b[1]) / 2);
    done = true;
    break;
  }
  BOOST_REQUIRE(done);
  QD::Distortion_report<Surface_mesh> r;
  BOOST_CHECK_NO_THROW(r = QD::compute_distortion(tm, squashed.pmap_const(), QD::parameters::overlap_tolerance(1e-9)));
  BOOST_TEST(r.flipped_faces >= 1u);
  BOOST_TEST(r.overlap);
}

BOOST_AUTO_TEST_CASE(branch_vertex_is_detected)
{
  // a fan of 8 triangles whose 2D layout wraps twice around the centre
  Soup s;
  s.points.push_back({0, 0, 0});
  for(int k = 0; k < 8; ++k) s.points.push_back({std::cos(2 * pi * k / 8), std::sin(2 * pi * k / 8), 0});
  for(std::size_t k = 0; k < 8; ++k) s.triangles.push_back({0, 1 + k, 1 + (k + 1) % 8});
  const Surface_mesh tm = make<Surface_mesh>(s);
  Uv_store<Surface_mesh> uv;
  std::size_t k = 0;
  for(auto v : vertices(tm)) {
    if(k == 0) uv.map[v] = Uv_store<Surface_mesh>::Point_2(0, 0);
    else uv.map[v] = Uv_store<Surface_mesh>::Point_2(std::cos(4 * pi * (k - 1) / 8 + 0.1), std::sin(4 * pi * (k - 1) / 8 + 0.1));
    ++k;
  }
  const auto r = QD::compute_distortion(tm, uv.pmap_const());
  BOOST_TEST(r.flipped_faces == 0u);
  BOOST_TEST(r.branch_vertices == 1u);
  BOOST_TEST(r.overlap);
}

// The acceptance measures (no corner angles; branch vertices by the winding
// of the 1-ring) decide as compute_distortion() does: the same areas, stretch,
// flips, crossings and overlap, bit for bit
template <class Mesh, class UV>
void check_acceptance_measures(const Mesh& tm, const UV& uv, double tolerance)
{
  const auto np = QD::parameters::overlap_tolerance(tolerance);
  const auto full = QD::compute_distortion(tm, uv, np);
  const auto fast = QD::internal::acceptance_measures(tm, uv, np);
  BOOST_TEST((fast.status == full.status));
  BOOST_TEST(fast.number_of_faces == full.number_of_faces);
  BOOST_TEST(fast.area_distortion == full.area_distortion);
  BOOST_TEST(fast.local_area_distortion == full.local_area_distortion);
  BOOST_TEST(fast.l2_stretch == full.l2_stretch);
  BOOST_TEST(fast.linf_stretch == full.linf_stretch);
  BOOST_TEST(fast.boundary_length_error == full.boundary_length_error);
  BOOST_TEST(fast.flipped_faces == full.flipped_faces);
  BOOST_TEST(fast.border_crossings.size() == full.border_crossings.size());
  BOOST_TEST(fast.overlap == full.overlap);
  BOOST_TEST(QD::has_global_overlap(tm, uv, np) == full.overlap);
  if(full.flipped_faces == 0) BOOST_TEST(fast.branch_vertices == full.branch_vertices);
  BOOST_TEST(fast.angle_distortion == 0.);
  BOOST_TEST(fast.boundary_angle_error == 0.);
}

BOOST_AUTO_TEST_CASE_TEMPLATE(acceptance_measures_decide_as_compute_distortion, Mesh, Mesh_types)
{
  // a fan whose layout turns `turns` times around its centre, starting at
  // angle `start` (0: ring vertices on the ray the winding is counted on)
  auto fan = [](std::size_t n, int turns, double start, std::size_t& checked) {
    Soup s;
    s.points.push_back({0, 0, 0});
    for(std::size_t k = 0; k < n; ++k) s.points.push_back({std::cos(2 * pi * k / n), std::sin(2 * pi * k / n), 0});
    for(std::size_t k = 0; k < n; ++k) s.triangles.push_back({0, 1 + k, 1 + (k + 1) % n});
    const Mesh tm = make<Mesh>(s);
    const auto uv = map_uv(tm, [&](const P3& p) {
      if(p[0] == 0 && p[1] == 0) return std::array<double, 2>{0, 0};
      const double a = turns * std::atan2(p[1], p[0]) + start;
      return std::array<double, 2>{std::cos(a), std::sin(a)};
    });
    const auto full = QD::compute_distortion(tm, uv.pmap_const());
    BOOST_TEST(full.branch_vertices == (turns > 1 ? 1u : 0u));
    check_acceptance_measures(tm, uv.pmap_const(), 0.);
    check_acceptance_measures(tm, uv.pmap_const(), 1e-9);
    ++checked;
  };
  std::size_t checked = 0;
  for(int turns = 1; turns <= 3; ++turns)
    for(double start : {0., 0.1, -0.3}) fan(12, turns, start, checked);

  // a curved, cut-open surface under its identity-like map, a wavy map, a
  // map with one face folded over, a strip wound over itself
  Soup cut = flat_grid_with_slit();
  for(auto& p : cut.points) p[2] = 0.2 * std::sin(2 * p[0]) * p[1];
  const Mesh tm = make<Mesh>(cut);
  std::vector<Uv_store<Mesh>> maps;
  maps.push_back(map_uv(tm, [](const P3& p) { return std::array<double, 2>{p[0], p[1]}; }));
  maps.push_back(map_uv(tm, [](const P3& p) {
    return std::array<double, 2>{p[0] + 0.05 * std::sin(7 * p[1]), 1.1 * p[1] + 0.03 * std::cos(5 * p[0])};
  }));
  maps.push_back(maps[0]);
  {
    // the interior vertex nearest (1.5, 0.3) pushed across its ring: faces flip
    auto it = std::min_element(maps[2].map.begin(), maps[2].map.end(), [&](const auto& a, const auto& b) {
      auto d = [](const auto& q) { return std::hypot(CGAL::to_double(q.x()) - 1.5, CGAL::to_double(q.y()) - 0.3); };
      return d(a.second) < d(b.second);
    });
    it->second = typename Uv_store<Mesh>::Point_2(1.5, 0.55);
  }
  for(const auto& uv : maps) {
    check_acceptance_measures(tm, uv.pmap_const(), 0.);
    check_acceptance_measures(tm, uv.pmap_const(), 1e-9);
    ++checked;
  }
  BOOST_TEST(QD::compute_distortion(tm, maps[2].pmap_const()).flipped_faces > 0u);
  BOOST_TEST(!QD::compute_distortion(tm, maps[0].pmap_const(), QD::parameters::overlap_tolerance(1e-9)).overlap);
  const Mesh strip = make<Mesh>(grid(60, 2, [](double u, double v) { return P3{u, 0.1 * v, 0}; }));
  const auto wound = map_uv(strip, [](const P3& p) {
    const double a = 2.5 * pi * p[0], r = 1.0 - p[1];
    return std::array<double, 2>{r * std::cos(a), r * std::sin(a)};
  });
  check_acceptance_measures(strip, wound.pmap_const(), 1e-9);
  BOOST_TEST(checked == 12u);
}

BOOST_AUTO_TEST_CASE(curved_surface_measures)
{
  // a cylinder patch mapped by its exact development: no distortion at all
  const double R = 1.3, A = 1.4 * pi;
  const Surface_mesh tm = make<Surface_mesh>(grid(30, 8, cylinder(R, A, 2.0)));
  const auto uv = map_uv(tm, [R](const P3& p) { return std::array<double, 2>{R * std::atan2(p[1], p[0]), p[2]}; });
  // atan2 jumps at pi: the patch spans [0, 1.4 pi], so unwrap
  Uv_store<Surface_mesh> fixed;
  for(auto& kv : uv.map) {
    double x = CGAL::to_double(kv.second.x());
    if(x < -1e-12) x += 2 * pi * R;
    fixed.map[kv.first] = Uv_store<Surface_mesh>::Point_2(x, kv.second.y());
  }
  const auto r = QD::compute_distortion(tm, fixed.pmap_const());
  BOOST_TEST(r.area_distortion < 1.0);  // chords vs arcs: the development is of the polyhedron
  BOOST_TEST(!r.overlap);
  // the measures of the polyhedral development (from unrolled rulings) are exact:
  // rebuild the UVs from chord lengths
  Uv_store<Surface_mesh> exact;
  const double chord = 2 * R * std::sin(A / 30 / 2);
  std::size_t idx = 0;
  for(auto v : vertices(tm)) {
    exact.map[v] = Uv_store<Surface_mesh>::Point_2(chord * double(idx % 31), 2.0 * double(idx / 31) / 8);
    ++idx;
  }
  const auto e = QD::compute_distortion(tm, exact.pmap_const());
  BOOST_TEST(e.area_distortion < 1e-10);
  BOOST_TEST(std::abs(e.l2_stretch - 1) < 1e-10);
  BOOST_TEST(e.boundary_length_error < 1e-12);
  BOOST_TEST(e.boundary_angle_error < 1e-10);
  BOOST_TEST(e.angle_distortion < 1e-10);
}

BOOST_AUTO_TEST_CASE(invalid_input)
{
  const Surface_mesh empty;
  Uv_store<Surface_mesh> none;
  BOOST_TEST((QD::compute_distortion(empty, none.pmap_const()).status == QD::Error_code::EMPTY_MESH));
  BOOST_TEST(std::isinf(QD::area_distortion(empty, none.pmap_const())));
  BOOST_TEST(QD::has_global_overlap(empty, none.pmap_const()));

  const Surface_mesh tm = make<Surface_mesh>(flat_grid());
  auto uv = map_uv(tm, [](const P3& p) { return std::array<double, 2>{p[0], p[1]}; });
  uv.map[*vertices(tm).begin()] = Uv_store<Surface_mesh>::Point_2(std::nan(""), 0);
  const auto r = QD::compute_distortion(tm, uv.pmap_const());
  BOOST_TEST((r.status == QD::Error_code::INVALID_COORDINATES));
  BOOST_TEST(std::isinf(QD::l2_stretch(tm, uv.pmap_const())));
  BOOST_TEST(QD::number_of_flipped_faces(tm, uv.pmap_const()) == num_faces(tm));

  // a degenerate UV triangle: infinite stretch, never NaN
  auto flat = map_uv(tm, [](const P3& p) { return std::array<double, 2>{p[0], 0.0 * p[1]}; });
  const auto d = QD::compute_distortion(tm, flat.pmap_const());
  BOOST_REQUIRE(d);
  BOOST_TEST(std::isinf(d.l2_stretch));
  BOOST_TEST(!std::isnan(d.area_distortion));
  BOOST_TEST(d.overlap);
}

BOOST_AUTO_TEST_CASE(paper_normalisation_of_a_scaled_map)
{
  // a map scaled by 3 and shifted: the similarity brings the longest border edge
  // back to its 3D length, and with it every length of this uniform map
  const Surface_mesh tm = make<Surface_mesh>(flat_grid());
  auto uv = map_uv(tm, [](const P3& p) { return std::array<double, 2>{3 * p[0] + 5, 3 * p[1] - 1}; });
  BOOST_TEST(QD::compute_distortion(tm, uv.pmap_const()).area_distortion > 100);
  QD::normalize_by_longest_border_edge(tm, uv.pmap());
  const auto r = QD::compute_distortion(tm, uv.pmap_const());
  BOOST_TEST(r.area_distortion < 1e-10);
  BOOST_TEST(std::abs(r.l2_stretch - 1) < 1e-12);
  BOOST_TEST(r.boundary_length_error < 1e-12);
  // no border: nothing happens
  Soup s;
  s.points = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  s.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  const Surface_mesh closed = make<Surface_mesh>(s);
  auto cuv = map_uv(closed, [](const P3& p) { return std::array<double, 2>{p[0], p[1]}; });
  const auto before = cuv.map;
  QD::normalize_by_longest_border_edge(closed, cuv.pmap());
  BOOST_TEST((before == cuv.map));
}
