// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#define BOOST_TEST_MODULE vsa_segmentation
#include <boost/test/unit_test.hpp>
#include <boost/mpl/list.hpp>

#include "mesh_generators.h"
#include "test_utils.h"

#include <CGAL_QD/vsa_segmentation.h>

#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <map>
#include <set>

namespace QD = CGAL_QD;
using namespace qd_test;

typedef boost::mpl::list<Surface_mesh, Polyhedron> Mesh_types;

namespace {

template <class Mesh>
using Chart_map = std::map<typename boost::graph_traits<Mesh>::face_descriptor, std::size_t>;

// every face has a chart in [0, n), every chart is non-empty and connected
template <class Mesh>
void expect_valid_charts(const Mesh& tm, const Chart_map<Mesh>& chart, std::size_t n)
{
  BOOST_REQUIRE(chart.size() == num_faces(tm));
  std::vector<std::size_t> size(n, 0), reached(n, 0);
  for(const auto& fc : chart) {
    BOOST_REQUIRE(fc.second < n);
    ++size[fc.second];
  }
  for(std::size_t k = 0; k < n; ++k) BOOST_TEST(size[k] > 0u);
  std::set<typename boost::graph_traits<Mesh>::face_descriptor> seen;
  for(const auto& fc : chart) {
    if(reached[fc.second]) continue;  // BFS once per chart, from its first face
    std::vector<typename boost::graph_traits<Mesh>::face_descriptor> queue{fc.first};
    seen.insert(fc.first);
    for(std::size_t q = 0; q < queue.size(); ++q)
      for(auto h : CGAL::halfedges_around_face(halfedge(queue[q], tm), tm)) {
        auto o = opposite(h, tm);
        if(is_border(o, tm)) continue;
        auto g = face(o, tm);
        if(chart.at(g) == fc.second && seen.insert(g).second) queue.push_back(g);
      }
    reached[fc.second] = queue.size();
    BOOST_TEST(queue.size() == size[fc.second]);  // connected
  }
}

Soup closed_cube(std::size_t n)
{
  // the opened cube with every cut sewn back
  Soup s = cube_opened_by_five_cuts(n);
  return merge_coincident_points(s);
}

} // namespace

BOOST_AUTO_TEST_CASE_TEMPLATE(cube_gives_its_six_sides, Mesh, Mesh_types)
{
  const Mesh tm = make<Mesh>(closed_cube(6));
  Chart_map<Mesh> chart;
  const auto r = QD::segment_by_error_controlled_vsa(tm, boost::make_assoc_property_map(chart),
                                                     QD::parameters::vsa_tolerance(0.01));
  BOOST_REQUIRE_MESSAGE(r, QD::error_message(r.status));
  BOOST_TEST(r.number_of_charts == 6u);
  BOOST_TEST(r.tolerance_reached);
  BOOST_TEST(r.max_chart_error < 1e-12);
  expect_valid_charts(tm, chart, r.number_of_charts);
  // each side is one chart
  for(const auto& fc : chart) BOOST_TEST(std::abs(r.chart_area[fc.second] - 1.0) < 1e-9);
}

BOOST_AUTO_TEST_CASE(curved_tube_meets_the_tolerance_and_is_deterministic)
{
  const Surface_mesh tm = make<Surface_mesh>(grid(48, 12, cylinder(1.0, 1.9 * pi, 3.0)));
  for(double tol : {0.02, 0.1}) {
    Chart_map<Surface_mesh> a, b;
    const auto np = QD::parameters::vsa_tolerance(tol, CGAL::parameters::max_number_of_proxies(500));
    const auto ra = QD::segment_by_error_controlled_vsa(tm, boost::make_assoc_property_map(a), np);
    const auto rb = QD::segment_by_error_controlled_vsa(tm, boost::make_assoc_property_map(b), np);
    BOOST_REQUIRE(ra);
    BOOST_TEST(ra.tolerance_reached);
    BOOST_TEST(ra.max_chart_error <= tol);
    for(double e : ra.chart_error) BOOST_TEST(e <= tol);
    BOOST_TEST(ra.number_of_charts > 1u);
    expect_valid_charts(tm, a, ra.number_of_charts);
    BOOST_TEST((a == b));  // the same input gives the same output
    BOOST_TEST(ra.number_of_charts == rb.number_of_charts);
  }
}

BOOST_AUTO_TEST_CASE(several_components_and_a_handle)
{
  // two cubes, then a torus: the segmentation opens any topology
  Soup s = closed_cube(4);
  Soup t = closed_cube(4);
  const std::size_t off = s.points.size();
  for(P3 p : t.points) s.points.push_back({p[0] + 3, p[1], p[2]});
  for(Tri f : t.triangles) s.triangles.push_back({f[0] + off, f[1] + off, f[2] + off});
  const Surface_mesh two = make<Surface_mesh>(s);
  Chart_map<Surface_mesh> chart;
  const auto r = QD::segment_by_error_controlled_vsa(
      two, boost::make_assoc_property_map(chart),
      QD::parameters::vsa_tolerance(0.01, CGAL::parameters::max_number_of_proxies(100)));
  BOOST_REQUIRE(r);
  BOOST_TEST(r.number_of_charts == 12u);
  expect_valid_charts(two, chart, r.number_of_charts);

  const Surface_mesh tm = make<Surface_mesh>(torus(24, 12));
  Chart_map<Surface_mesh> tc;
  const auto rt = QD::segment_by_error_controlled_vsa(
      tm, boost::make_assoc_property_map(tc), QD::parameters::vsa_tolerance(0.1, CGAL::parameters::max_number_of_proxies(200)));
  BOOST_REQUIRE(rt);
  BOOST_TEST(rt.tolerance_reached);
  expect_valid_charts(tm, tc, rt.number_of_charts);
}

BOOST_AUTO_TEST_CASE(proxy_cap_is_reported)
{
  const Surface_mesh tm = make<Surface_mesh>(grid(48, 12, cylinder(1.0, 1.9 * pi, 3.0)));
  Chart_map<Surface_mesh> chart;
  const auto r = QD::segment_by_error_controlled_vsa(
      tm, boost::make_assoc_property_map(chart),
      QD::parameters::vsa_tolerance(1e-6, CGAL::parameters::max_number_of_proxies(4)));
  BOOST_REQUIRE(r);
  BOOST_TEST(!r.tolerance_reached);
  BOOST_TEST(r.number_of_charts <= 4u);
  expect_valid_charts(tm, chart, r.number_of_charts);
}

BOOST_AUTO_TEST_CASE(invalid_input_writes_nothing)
{
  Chart_map<Surface_mesh> chart;
  const Surface_mesh empty;
  BOOST_TEST((QD::segment_by_error_controlled_vsa(empty, boost::make_assoc_property_map(chart)).status ==
              QD::Error_code::EMPTY_MESH));
  Soup s = grid(4, 4, bump(0.2));
  s.points[6][0] = std::numeric_limits<double>::infinity();
  const Surface_mesh bad = make<Surface_mesh>(s);
  BOOST_TEST((QD::segment_by_error_controlled_vsa(bad, boost::make_assoc_property_map(chart)).status ==
              QD::Error_code::INVALID_COORDINATES));
  Soup d = grid(4, 4, [](double u, double v) { return P3{u, v, 0}; });
  d.points[6] = d.points[1];
  const Surface_mesh degenerate = make<Surface_mesh>(d);
  BOOST_TEST((QD::segment_by_error_controlled_vsa(degenerate, boost::make_assoc_property_map(chart)).status ==
              QD::Error_code::DEGENERATE_FACE));
  BOOST_TEST(chart.empty());
}

#ifdef CGAL_QD_DEMO_MESH_DIR
BOOST_AUTO_TEST_CASE(real_meshes)
{
  for(const char* name : {"fandisk.off", "bunny00.off"}) {
    Surface_mesh tm;
    BOOST_REQUIRE(CGAL::IO::read_polygon_mesh(std::string(CGAL_QD_DEMO_MESH_DIR) + "/" + name, tm));
    Chart_map<Surface_mesh> chart;
    const auto r = QD::segment_by_error_controlled_vsa(tm, boost::make_assoc_property_map(chart));
    BOOST_REQUIRE_MESSAGE(r, QD::error_message(r.status));
    BOOST_TEST_MESSAGE(name << ": " << num_faces(tm) << " faces, " << r.number_of_charts << " charts, max error "
                            << r.max_chart_error << ", " << r.time_ms << " ms");
    BOOST_TEST(r.tolerance_reached);
    BOOST_TEST(r.number_of_charts >= 10u);  // tens of charts, as in the paper
    BOOST_TEST(r.number_of_charts <= 100u);
    expect_valid_charts(tm, chart, r.number_of_charts);
  }
}
#endif
