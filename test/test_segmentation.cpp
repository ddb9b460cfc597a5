// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#define BOOST_TEST_MODULE segmentation
#include <boost/test/unit_test.hpp>
#include <boost/mpl/list.hpp>

#include "mesh_generators.h"
#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif
#include "resolution_series.h"
#include "test_utils.h"

#include <CGAL_QD/distortion.h>
#include <CGAL_QD/extract_chart.h>
#include <CGAL_QD/flatten_charts.h>
#include <CGAL_QD/flatten_patch.h>
#include <CGAL_QD/optimize_flattening.h>
#include <CGAL_QD/segmentation_measures.h>
#include <CGAL_QD/segment_quasi_developable.h>
#include <CGAL_QD/shorten_chart_cuts.h>
#include <CGAL_QD/smooth_chart_boundaries.h>
#include <CGAL_QD/smooth_chart_cuts.h>
#include <CGAL_QD/smooth_segmentation_seams.h>
#include <CGAL_QD/vsa_segmentation.h>
#include <CGAL_QD/boundary_refinement.h>
#include <CGAL_QD/internal/bucket_queue.h>
#include <CGAL_QD/internal/chart_border_curves.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Variational_shape_approximation.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <boost/property_map/function_property_map.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <random>
#include <limits>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <utility>
#include <vector>

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

// Each connected component is a shape of its own at step 1: fandisk with a
// stray triangle far away gets the charts it gets alone, and beside a copy of
// itself as many (the proxies are added over the whole mesh, so not in the
// same order). The scale of step 1 came from the bounding box of the whole
// mesh: a triangle 100 away left fandisk one chart (its area, 2.2, below the
// (0.07 D)^2 of a chart split further), and 8 pieces instead of 3.
BOOST_AUTO_TEST_CASE(each_component_is_segmented_at_its_own_scale)
{
  Surface_mesh fandisk;
  BOOST_REQUIRE(CGAL::IO::read_polygon_mesh(std::string(CGAL_QD_DEMO_MESH_DIR) + "/fandisk.off", fandisk));
  // `fandisk`, and a copy of it scaled by `scale` and moved by `shift`, or a triangle of side `side` at `shift`
  auto with = [&](double scale, double shift, double side) {
    Surface_mesh m = fandisk;
    if(side > 0) {
      const auto a = m.add_vertex(Surface_mesh::Point(shift, 0, 0));
      const auto b = m.add_vertex(Surface_mesh::Point(shift, side, 0));
      const auto c = m.add_vertex(Surface_mesh::Point(shift, 0, side));
      m.add_face(a, b, c);
      return m;
    }
    std::map<Surface_mesh::Vertex_index, Surface_mesh::Vertex_index> copy;
    for(auto v : vertices(fandisk)) {
      const auto p = fandisk.point(v);
      copy[v] = m.add_vertex(Surface_mesh::Point(p.x() * scale + shift, p.y() * scale, p.z() * scale));
    }
    for(auto f : faces(fandisk)) {
      std::vector<Surface_mesh::Vertex_index> vs;
      for(auto v : CGAL::vertices_around_face(halfedge(f, fandisk), fandisk)) vs.push_back(copy[v]);
      m.add_face(vs);
    }
    return m;
  };
  auto vsa_charts = [](const Surface_mesh& m, std::vector<std::size_t>& ids) {
    Chart_map<Surface_mesh> chart;
    const auto r = QD::segment_by_error_controlled_vsa(m, boost::make_assoc_property_map(chart));
    BOOST_REQUIRE(r);
    ids.clear();
    for(auto f : faces(m)) ids.push_back(chart.at(f));
    return r;
  };
  // the charts of the faces [first, first + n) relabelled in order of appearance
  auto partition = [](const std::vector<std::size_t>& ids, std::size_t first, std::size_t n) {
    std::map<std::size_t, std::size_t> label;
    std::vector<std::size_t> out;
    for(std::size_t i = first; i < first + n; ++i) out.push_back(label.emplace(ids[i], label.size()).first->second);
    return out;
  };
  const std::size_t nf = num_faces(fandisk);
  std::vector<std::size_t> alone_ids;
  const auto alone = vsa_charts(fandisk, alone_ids);
  const std::vector<std::size_t> alone_partition = partition(alone_ids, 0, nf);

  const Surface_mesh stray = with(1, 100, 1);
  std::vector<std::size_t> ids;
  const auto r = vsa_charts(stray, ids);
  BOOST_TEST(r.number_of_charts == alone.number_of_charts + 1);
  BOOST_TEST(partition(ids, 0, nf) == alone_partition);
  BOOST_TEST(r.smoothing_radius == alone.smoothing_radius);  // of the largest component, fandisk

  // beside a copy of itself, of the same size or 1024 times as large: each
  // copy gets the charts of fandisk alone, and step 1 adds to each the
  // proxies it adds alone (segmented at once, as CGAL's class segments, a
  // round's proxies went in proportion to the L2,1 errors, which grow with
  // the square of the size: the large copy took the small one's proxies, up
  // to the cap)
  for(const double scale : {1., 1024.}) {
    BOOST_TEST_CONTEXT("copy scaled by " << scale)
    {
      const Surface_mesh pair = with(scale, 100 * scale, 0);
      const auto rp = vsa_charts(pair, ids);
      BOOST_TEST(rp.number_of_charts == 2 * alone.number_of_charts);
      BOOST_TEST(partition(ids, 0, nf) == alone_partition);
      BOOST_TEST(partition(ids, nf, nf) == alone_partition);
      BOOST_TEST(rp.proxies_added == 2 * alone.proxies_added);
      BOOST_TEST(rp.tolerance_reached);
      BOOST_TEST(rp.min_chart_area == alone.min_chart_area * scale * scale, boost::test_tools::tolerance(1e-12));
    }
  }
  // a cap given is shared out over the components, in proportion to their own caps
  {
    Chart_map<Surface_mesh> chart;
    const auto capped = QD::segment_by_error_controlled_vsa(with(1024, 102400, 0), boost::make_assoc_property_map(chart),
                                                            CGAL::parameters::max_number_of_proxies(6));
    BOOST_REQUIRE(capped);
    BOOST_TEST(!capped.tolerance_reached);
    BOOST_TEST(capped.max_number_of_proxies == 6u);
    BOOST_TEST(capped.proxies_added == 4u);  // 3 proxies for each copy, one of them its first
  }

  // and the whole segmentation: fandisk's pieces and the triangle; twice
  // fandisk's pieces for fandisk beside a copy 1024 times as large; and with
  // a triangle 1e30 away, whose scale the segmentation takes for the whole
  // mesh: fandisk's charts then lie below 2^-64, and their trials and final
  // flattenings are scaled again, chart by chart (every ARAP trial failed
  // there: fandisk came out in 9 pieces, every one of them LPFB+IP's)
  Chart_map<Surface_mesh> c0, c1, c2, c3;
  const auto s0 = QD::segment_quasi_developable(fandisk, boost::make_assoc_property_map(c0),
                                                QD::parameters::final_flattening(false));
  const auto s1 = QD::segment_quasi_developable(stray, boost::make_assoc_property_map(c1),
                                                QD::parameters::final_flattening(false));
  const auto s2 = QD::segment_quasi_developable(with(1024, 102400, 0), boost::make_assoc_property_map(c2),
                                                QD::parameters::final_flattening(false));
  BOOST_REQUIRE(s0);
  BOOST_REQUIRE(s1);
  BOOST_REQUIRE(s2);
  BOOST_TEST(s1.number_of_charts == s0.number_of_charts + 1);
  BOOST_TEST(s2.number_of_charts == 2 * s0.number_of_charts);
  const auto s3 = QD::segment_quasi_developable(with(1, 1e30, 1e28), boost::make_assoc_property_map(c3),
                                                QD::parameters::final_flattening(false));
  BOOST_REQUIRE(s3);
  BOOST_TEST(s3.number_of_charts == s0.number_of_charts + 1);
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

// ===================================================================== steps 2 to 5

namespace {

// two planes meeting at a valley along x = 0: z = 0.8 |x|, x in [-1, 1], y in [0, 1]
Soup folded_sheet(std::size_t n)
{
  return grid(n, n, [](double u, double v) {
    const double x = 2 * u - 1;
    return P3{x, v, 0.8 * std::abs(x)};
  });
}

template <class Mesh>
std::array<double, 3> centroid(const Mesh& tm, typename boost::graph_traits<Mesh>::face_descriptor f)
{
  std::array<double, 3> c = {0, 0, 0};
  for(auto v : CGAL::vertices_around_face(halfedge(f, tm), tm))
    for(int k = 0; k < 3; ++k) c[k] += p3(tm, v)[k] / 3;
  return c;
}

template <class Mesh>
std::size_t count_border_loops(const Mesh& tm)
{
  std::set<typename boost::graph_traits<Mesh>::halfedge_descriptor> seen;
  std::size_t loops = 0;
  for(auto h : halfedges(tm))
    if(is_border(h, tm) && seen.insert(h).second) {
      ++loops;
      for(auto g : CGAL::halfedges_around_face(h, tm)) seen.insert(g);
    }
  return loops;
}

// The whole result, checked through the public API only: every face has one
// chart, charts are connected, and every chart, extracted with the seams as
// cuts, flattens by flatten_patch() within the thresholds and without overlap.
template <class Mesh>
void expect_valid_segmentation(const Mesh& tm, const Chart_map<Mesh>& chart,
                               const QD::Segmentation_result<Mesh>& r, double max_area = 10., double max_l2 = 2.,
                               double max_local = 2.5)
{
  typedef typename boost::graph_traits<Mesh>::edge_descriptor edge_descriptor;
  expect_valid_charts(tm, chart, r.number_of_charts);
  BOOST_TEST(r.charts.size() == r.number_of_charts);
  BOOST_TEST(r.number_of_charts <= r.charts_before_merging);  // merging never adds charts
  BOOST_TEST(r.charts_after_refinement == r.charts_after_vsa);  // the min cut never empties a chart
  BOOST_TEST(r.overlapping_charts == 0u);
  BOOST_TEST(r.rejected_charts == 0u);
  BOOST_TEST(r.max_area_distortion <= max_area);
  BOOST_TEST(r.max_l2_stretch <= max_l2);
  if(max_local > 0) BOOST_TEST(r.max_local_area_distortion <= max_local);
  std::map<edge_descriptor, bool> seam;
  double seam_length = 0;
  for(edge_descriptor e : r.seam_edges) {
    seam[e] = true;
    seam_length += std::sqrt(CGAL::to_double(CGAL::squared_distance(get(CGAL::vertex_point, tm, source(e, tm)),
                                                                      get(CGAL::vertex_point, tm, target(e, tm)))));
  }
  BOOST_TEST(std::abs(seam_length - r.seam_length) <= 1e-9 * (1 + seam_length));
  // every edge between two charts is a seam
  for(auto e : edges(tm)) {
    const auto h = halfedge(e, tm);
    if(!is_border_edge(h, tm) && chart.at(face(h, tm)) != chart.at(face(opposite(h, tm), tm)))
      BOOST_TEST(seam.count(e) == 1u);
  }
  auto fim = CGAL::get_initialized_face_index_map(tm);
  auto length3 = [&](auto h) {
    return std::sqrt(CGAL::to_double(
        CGAL::squared_distance(get(CGAL::vertex_point, tm, source(h, tm)), get(CGAL::vertex_point, tm, target(h, tm)))));
  };
  // the kept UVs, measured face by face: A(Omega), A_loc, no flipped face
  std::vector<double> area2(r.number_of_charts, 0.), area3(r.number_of_charts, 0.), local(r.number_of_charts, 0.);
  for(auto f : faces(tm)) {
    const std::size_t k = chart.at(f);
    const auto& a = r.corner_uv[3 * get(fim, f)];
    const auto& b = r.corner_uv[3 * get(fim, f) + 1];
    const auto& c = r.corner_uv[3 * get(fim, f) + 2];
    const double a2 = 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]));
    const auto h = halfedge(f, tm);
    const double a3 = std::sqrt(CGAL::to_double(CGAL::squared_area(get(CGAL::vertex_point, tm, source(h, tm)),
                                                                   get(CGAL::vertex_point, tm, target(h, tm)),
                                                                   get(CGAL::vertex_point, tm, target(next(h, tm), tm)))));
    BOOST_TEST(a2 > 0);
    area2[k] += a2;
    area3[k] += a3;
    local[k] += std::abs(a2 - a3);
  }
  // every piece's compactness 4 pi A / P^2 (P along its border and twice along its cuts), and their
  // area-weighted mean
  std::vector<double> perimeter(r.number_of_charts, 0.);
  for(auto h : halfedges(tm)) {
    if(is_border(h, tm)) continue;
    const auto o = opposite(h, tm);
    if(seam.count(edge(h, tm)) || is_border(o, tm) || chart.at(face(o, tm)) != chart.at(face(h, tm)))
      perimeter[chart.at(face(h, tm))] += length3(h);
  }
  double weighted = 0, total = 0;
  for(std::size_t k = 0; k < r.number_of_charts; ++k) {
    const double c = perimeter[k] > 0 ? 4 * pi * area3[k] / (perimeter[k] * perimeter[k]) : 0.;
    BOOST_TEST(std::abs(c - r.charts[k].compactness) <= 1e-9 * (1 + c));
    weighted += area3[k] * r.charts[k].compactness;
    total += area3[k];
  }
  BOOST_TEST(std::abs(weighted / total - r.compactness) <= 1e-9);
  for(std::size_t k = 0; k < r.number_of_charts; ++k) {
    const double A = 100 * std::abs(area2[k] - area3[k]) / area3[k], A_loc = 100 * local[k] / area3[k];
    BOOST_TEST(A <= max_area);
    BOOST_TEST(std::abs(A - r.charts[k].area_distortion) <= 1e-6 * (1 + A));
    BOOST_TEST(std::abs(A_loc - r.charts[k].local_area_distortion) <= 1e-6 * (1 + A_loc));
    if(max_local > 0) BOOST_TEST(A_loc <= max_local);
    BOOST_TEST(r.charts[k].l2_stretch <= max_l2);
    BOOST_TEST(!r.charts[k].overlap);
  }
  // every chart flattened by LPFB+IP is checked again from scratch
  for(std::size_t k = 0; k < r.number_of_charts; ++k) {
    if(r.charts[k].optimized) continue;
    Surface_mesh piece;
    const QD::Error_code ec = QD::extract_chart(
        tm, boost::make_assoc_property_map(chart), k, piece,
        CGAL::parameters::edge_is_constrained_map(boost::make_assoc_property_map(seam)));
    BOOST_REQUIRE(ec == QD::Error_code::OK);
    BOOST_TEST(num_faces(piece) == r.charts[k].number_of_faces);
    Uv_store<Surface_mesh> uv;
    const QD::Flattening_result f = QD::flatten_patch(piece, uv.pmap());
    BOOST_REQUIRE_MESSAGE(f, "chart " << k << ": " << QD::error_message(f.status));
    const auto d = QD::compute_distortion(piece, uv.pmap_const(), QD::parameters::overlap_tolerance(1e-9));
    BOOST_TEST(d.area_distortion <= max_area);
    BOOST_TEST(d.l2_stretch <= max_l2);
    BOOST_TEST(!d.overlap);
    BOOST_TEST(std::abs(d.area_distortion - r.charts[k].area_distortion) <= 1e-6 * (1 + d.area_distortion));
  }
  // on every seam edge and border edge of an LPFB+IP chart, the 2D length is
  // the 3D length; with matched seams, the two sides of a seam edge differ
  // only by the scaling of each side along its curve
  bool all_matched = true;
  for(std::size_t k = 0; k < r.number_of_charts; ++k) all_matched = all_matched && r.charts[k].lengths_matched;
  double worst = 0;
  for(auto f : faces(tm)) {
    if(r.charts[chart.at(f)].optimized) continue;
    int k = 0;
    for(auto h : CGAL::halfedges_around_face(halfedge(f, tm), tm)) {
      // corner k is target(h); the edge of next(h) runs from corner k to corner k + 1
      const auto g = next(h, tm);
      // (the associative map inserted false for every edge extract_chart() looked up)
      const auto it = seam.find(edge(g, tm));
      if((it != seam.end() && it->second) || is_border(opposite(g, tm), tm)) {
        const auto& a = r.corner_uv[3 * get(fim, f) + k];
        const auto& b = r.corner_uv[3 * get(fim, f) + (k + 1) % 3];
        const double l2d = std::hypot(a[0] - b[0], a[1] - b[1]);
        worst = (std::max)(worst, std::abs(l2d - length3(g)) / length3(g));
      }
      ++k;
    }
  }
  BOOST_TEST(worst < 1e-7);
  // every border edge at exactly its share of its seam's common length: the sides agree
  if(all_matched) BOOST_TEST(r.max_seam_length_mismatch <= 1e-6);
  // every curve that does not match, with how far apart its sides are
  BOOST_TEST(r.number_of_seam_curves - r.seam_curves_matched == r.unmatched_seams.size());
  BOOST_TEST(r.unmatched_seam_mismatch.size() == r.unmatched_seams.size());
  double worst_mismatch = 0;
  for(double m : r.unmatched_seam_mismatch) {
    BOOST_TEST(m > 0.005);
    worst_mismatch = (std::max)(worst_mismatch, m);
  }
  if(!r.unmatched_seams.empty()) BOOST_TEST(worst_mismatch == r.max_seam_length_mismatch);
  BOOST_TEST(r.seam_zigzag >= 1.);
  BOOST_TEST(r.compactness > 0.);
  BOOST_TEST(r.compactness <= 1.5);
}

Soup closed_tube(std::size_t n, std::size_t m)
{
  return merge_coincident_points(grid(n, m, cylinder(1.0, 2 * pi, 3.0)));
}

} // namespace

BOOST_AUTO_TEST_CASE(extract_chart_cuts_seams_slits_and_pinches)
{
  const Surface_mesh tm = make<Surface_mesh>(grid(6, 6, bump(0.2)));
  typedef Surface_mesh::Face_index F;
  typedef Surface_mesh::Vertex_index V;
  typedef Surface_mesh::Edge_index E;
  Chart_map<Surface_mesh> chart;
  for(F f : faces(tm)) chart[f] = centroid(tm, f)[0] < 0.5 ? 0 : 1;
  std::vector<std::pair<V, V>> v2v;
  std::vector<std::pair<F, F>> f2f;
  Surface_mesh out;
  BOOST_REQUIRE(QD::extract_chart(tm, boost::make_assoc_property_map(chart), 0, out,
                                  CGAL::parameters::vertex_to_vertex_output_iterator(std::back_inserter(v2v))
                                      .face_to_face_output_iterator(std::back_inserter(f2f))) == QD::Error_code::OK);
  std::set<V> used;
  std::size_t n0 = 0;
  for(F f : faces(tm))
    if(chart[f] == 0) {
      ++n0;
      for(V v : CGAL::vertices_around_face(halfedge(f, tm), tm)) used.insert(v);
    }
  BOOST_TEST(num_faces(out) == n0);
  BOOST_TEST(num_vertices(out) == used.size());
  BOOST_TEST(v2v.size() == num_vertices(out));
  BOOST_TEST(f2f.size() == n0);
  for(const auto& p : v2v) BOOST_TEST(p3(tm, p.first) == p3(out, p.second));
  BOOST_TEST(CGAL::is_valid_polygon_mesh(out));
  BOOST_TEST(count_border_loops(out) == 1u);

  // a slit: two interior edges a-b-c cut open; b is doubled and the slit is a second border loop
  Chart_map<Surface_mesh> all;
  for(F f : faces(tm)) all[f] = 7;
  std::map<E, bool> cut;
  V b;
  for(V v : vertices(tm))
    if(std::abs(p3(tm, v)[0] - 0.5) < 1e-9 && std::abs(p3(tm, v)[1] - 0.5) < 1e-9) b = v;
  std::size_t marked = 0;
  for(auto h : CGAL::halfedges_around_target(b, tm)) {
    const auto q = p3(tm, source(h, tm));
    if(std::abs(q[1] - 0.5) < 1e-9 && marked < 2) {  // the two edges along y = 0.5
      cut[edge(h, tm)] = true;
      ++marked;
    }
  }
  BOOST_REQUIRE(marked == 2u);
  BOOST_REQUIRE(QD::extract_chart(tm, boost::make_assoc_property_map(all), 7, out,
                                  CGAL::parameters::edge_is_constrained_map(boost::make_assoc_property_map(cut))) ==
                QD::Error_code::OK);
  BOOST_TEST(num_vertices(out) == num_vertices(tm) + 1);
  BOOST_TEST(count_border_loops(out) == 2u);
  Uv_store<Surface_mesh> uv;
  BOOST_TEST(bool(QD::flatten_patch(out, uv.pmap())));  // a disk with a hole: flattens

  // a chart touching itself at a vertex gives two vertices there
  Chart_map<Surface_mesh> pinch;
  std::vector<F> around;
  for(auto h : CGAL::halfedges_around_target(b, tm)) around.push_back(face(h, tm));
  for(F f : faces(tm)) pinch[f] = 1;
  pinch[around[0]] = pinch[around[3]] = 0;  // opposite faces of the fan of b share only b
  BOOST_REQUIRE(QD::extract_chart(tm, boost::make_assoc_property_map(pinch), 0, out) == QD::Error_code::OK);
  BOOST_TEST(num_faces(out) == 2u);
  BOOST_TEST(num_vertices(out) == 6u);
  BOOST_TEST((QD::extract_chart(tm, boost::make_assoc_property_map(pinch), 5, out) == QD::Error_code::EMPTY_MESH));
  BOOST_TEST(num_faces(out) == 0u);
}

BOOST_AUTO_TEST_CASE(min_cut_moves_a_zigzag_border_onto_the_crease)
{
  const Surface_mesh tm = make<Surface_mesh>(folded_sheet(40));
  typedef Surface_mesh::Face_index F;
  Chart_map<Surface_mesh> chart;
  auto truth = [&](F f) { return centroid(tm, f)[0] < 0 ? std::size_t(3) : std::size_t(8); };
  std::size_t wrong_before = 0, wrong_after = 0;
  for(F f : faces(tm)) {
    const auto c = centroid(tm, f);
    chart[f] = c[0] < 0.12 * std::sin(6 * pi * c[1]) ? 3 : 8;  // ids need not be 0..n-1
    wrong_before += chart[f] != truth(f);
  }
  // a single-face chart inside chart 8 must survive
  F lonely;
  for(F f : faces(tm)) {
    const auto c = centroid(tm, f);
    if(c[0] > 0.6 && c[0] < 0.7 && c[1] > 0.5 && c[1] < 0.55) lonely = f;
  }
  chart[lonely] = 5;
  const QD::Refinement_result r = QD::refine_chart_boundaries(tm, boost::make_assoc_property_map(chart));
  BOOST_REQUIRE(r);
  BOOST_TEST(r.number_of_charts == 3u);
  BOOST_TEST(r.border_cost_after < r.border_cost_before);
  BOOST_TEST(r.faces_moved > 0u);
  BOOST_TEST(chart[lonely] == 5u);
  for(F f : faces(tm))
    if(f != lonely) wrong_after += chart[f] != truth(f);
  BOOST_TEST_MESSAGE("zigzag: " << wrong_before << " faces off the crease before, " << wrong_after << " after");
  BOOST_TEST(wrong_before > 50u);
  BOOST_TEST(wrong_after == 0u);
  // only the given ids are used, and every chart is connected
  Chart_map<Surface_mesh> compact;
  for(F f : faces(tm)) {
    BOOST_TEST((chart[f] == 3u || chart[f] == 5u || chart[f] == 8u));
    compact[f] = chart[f] == 3 ? 0 : (chart[f] == 5 ? 1 : 2);
  }
  expect_valid_charts(tm, compact, 3);
}

// The refinement tells whether a chart is still connected after its pair's
// band was relabelled from the faces near the band where it can
// (internal::connected_near_band()); it may say nothing where the chart is
// connected, but never that a chart cut in two is connected.
BOOST_AUTO_TEST_CASE(connectivity_near_the_band_never_joins_a_chart_cut_in_two)
{
  // a flat 40 x 40 grid; chart 0 a U (two arms i < 10 and i >= 30 joined by
  // the rows j < 5), chart 1 the rest
  const std::size_t n = 40;
  const Surface_mesh tm = make<Surface_mesh>(grid(n, n, bump(0.)));
  typedef Surface_mesh::Face_index F;
  const auto fim = get(CGAL::face_index, tm);
  std::vector<F> face_of(num_faces(tm));
  for(F f : faces(tm)) face_of[get(fim, f)] = f;
  auto cell = [&](std::size_t f) { return std::array<std::size_t, 2>{{(f / 2) % n, (f / 2) / n}}; };
  std::vector<std::size_t> chart(num_faces(tm));
  for(std::size_t f = 0; f < chart.size(); ++f) {
    const auto c = cell(f);
    chart[f] = c[0] < 10 || c[0] >= 30 || c[1] < 5 ? 0 : 1;
  }
  std::vector<char> mark(chart.size(), 0);
  auto check = [&](const std::function<bool(std::size_t, std::size_t)>& in, std::size_t c) {
    std::vector<std::size_t> band;
    std::vector<char> is_in(chart.size(), 0);
    std::size_t outside = 0;
    for(std::size_t f = 0; f < chart.size(); ++f) {
      if(in(cell(f)[0], cell(f)[1])) {
        band.push_back(f);
        is_in[f] = 1;
      } else if(chart[f] == c) {
        ++outside;
      }
    }
    const bool near = QD::internal::connected_near_band(
        tm, fim, face_of, band, [&](std::size_t f) { return is_in[f] != 0; }, chart, c, outside, mark);
    BOOST_TEST(std::count(mark.begin(), mark.end(), 0) == std::ptrdiff_t(mark.size()));  // the scratch is left clean
    return near;
  };
  std::vector<F> all(face_of);
  auto connected = [&](std::size_t c) { return QD::internal::chart_is_connected(tm, fim, all, chart, c); };
  // a band across the left arm: the arm's faces above and below it meet through it
  const auto left_strip = [](std::size_t i, std::size_t j) { return i < 10 && j >= 20 && j < 25; };
  BOOST_TEST(connected(0));
  BOOST_TEST(check(left_strip, 0));
  // a band across the whole grid: the two arms meet far below it, which the
  // faces near the band do not show; chart 1 is cut in two
  const auto across = [](std::size_t, std::size_t j) { return j >= 20 && j < 25; };
  BOOST_TEST(!check(across, 0));
  BOOST_TEST(connected(0));
  for(std::size_t f = 0; f < chart.size(); ++f)
    if(across(cell(f)[0], cell(f)[1]) && chart[f] == 1) chart[f] = 0;
  BOOST_TEST(!connected(1));
  BOOST_TEST(!check(across, 1));
  for(std::size_t f = 0; f < chart.size(); ++f)
    if(across(cell(f)[0], cell(f)[1]) && cell(f)[0] >= 10 && cell(f)[0] < 30) chart[f] = 1;
  // the left strip given to chart 1: the top of the left arm is cut off
  for(std::size_t f = 0; f < chart.size(); ++f)
    if(left_strip(cell(f)[0], cell(f)[1])) chart[f] = 1;
  BOOST_TEST(!connected(0));
  BOOST_TEST(!check(left_strip, 0));
  // a chart wholly inside the band: nothing outside to reach
  for(std::size_t f = 0; f < chart.size(); ++f)
    chart[f] = cell(f)[0] >= 12 && cell(f)[0] < 16 && cell(f)[1] >= 12 && cell(f)[1] < 16 ? 2 : chart[f];
  const auto square = [](std::size_t i, std::size_t j) { return i >= 11 && i < 17 && j >= 11 && j < 17; };
  BOOST_TEST(check(square, 2));
  // and no face of the chart anywhere
  BOOST_TEST(!check(square, 7));
}

BOOST_AUTO_TEST_CASE(denoising_pulls_noisy_crease_vertices_onto_the_crease)
{
  Soup s = folded_sheet(20);
  unsigned seed = 12345;
  auto noise = [&]() {
    seed = seed * 1103515245u + 12345u;
    return ((seed >> 8) % 2001) / 1000.0 - 1.0;
  };
  std::vector<std::size_t> crease;
  for(std::size_t i = 0; i < s.points.size(); ++i)
    if(std::abs(s.points[i][0]) < 1e-12 && s.points[i][1] > 1e-9 && s.points[i][1] < 1 - 1e-9) {
      s.points[i][0] += 0.01 * noise();
      s.points[i][2] += 0.02 * noise();
      crease.push_back(i);
    }
  BOOST_REQUIRE(crease.size() > 10u);
  Surface_mesh tm = make<Surface_mesh>(s);
  Chart_map<Surface_mesh> chart;
  for(auto f : faces(tm)) chart[f] = centroid(tm, f)[0] < 0 ? 0 : 1;
  // distance of a point to the crease line x = 0, z = 0
  auto off_crease = [](const std::array<double, 3>& p) { return std::hypot(p[0], p[2]); };
  std::vector<Surface_mesh::Vertex_index> vs(vertices(tm).begin(), vertices(tm).end());
  double before = 0;
  for(std::size_t i : crease) before = (std::max)(before, off_crease(p3(tm, vs[i])));

  std::map<Surface_mesh::Vertex_index, Epick::Point_3> moved;
  const Surface_mesh copy = tm;
  const QD::Denoising_result r = QD::denoise_chart_boundaries(tm, boost::make_assoc_property_map(chart),
                                                              boost::make_assoc_property_map(moved),
                                                              QD::parameters::denoising_iterations(40));
  BOOST_REQUIRE(r);
  BOOST_TEST(r.number_of_border_vertices == crease.size() + 2);  // and the two ends on the mesh border
  for(auto v : vertices(tm)) BOOST_TEST(p3(tm, v) == p3(copy, v));  // the mesh did not change
  double after = 0;
  for(std::size_t i : crease) {
    const Epick::Point_3& p = moved.at(vs[i]);
    after = (std::max)(after, off_crease({p.x(), p.y(), p.z()}));
  }
  BOOST_TEST_MESSAGE("denoising: crease vertices at most " << before << " off the crease before, " << after
                                                           << " after, " << r.rejected_moves << " moves undone");
  BOOST_TEST(after < 0.25 * before);
  // into the mesh's own point map: the mesh changes
  BOOST_REQUIRE(bool(QD::denoise_chart_boundaries(tm, boost::make_assoc_property_map(chart), get(CGAL::vertex_point, tm),
                                                  QD::parameters::denoising_iterations(40))));
  for(std::size_t i : crease) BOOST_TEST(p3(tm, vs[i])[2] == moved.at(vs[i]).z());
}

BOOST_AUTO_TEST_CASE(tube_merges_into_very_few_charts)
{
  const Surface_mesh tm = make<Surface_mesh>(closed_tube(48, 12));
  Chart_map<Surface_mesh> chart;
  for(auto f : faces(tm)) {
    const auto c = centroid(tm, f);
    const double a = std::atan2(c[1], c[0]) + pi;
    chart[f] = std::min<std::size_t>(7, std::size_t(a / (2 * pi) * 8)) + (c[2] < 1.5 ? 0 : 8);
  }
  const auto r = QD::merge_charts_by_boundaries<CGAL::Sequential_tag>(tm, boost::make_assoc_property_map(chart));
  BOOST_REQUIRE(r);
  BOOST_TEST(r.charts_before == 16u);
  BOOST_TEST(r.charts_split == 0u);
  BOOST_TEST_MESSAGE("tube: 16 charts -> " << r.number_of_charts << " in " << r.trials << " trials");
  BOOST_TEST(r.number_of_charts <= 2u);
  BOOST_TEST(r.merges >= 14u);
  expect_valid_charts(tm, chart, r.number_of_charts);
}

BOOST_AUTO_TEST_CASE(compactness_ratio_keeps_a_sprawling_join_in_two_pieces)
{
  // two flat strips of unit cells (each cell in 8 triangles), 9 x 1 along x
  // from x = 1 and 1 x 10 along y, that meet along one unit edge: their
  // union, an L, flattens exactly but sprawls. Compactness 4 pi A / P^2: the
  // strips 4 pi 9 / 20^2 = 0.283 and 4 pi 10 / 22^2 = 0.260, the L 4 pi 19 /
  // 40^2 = 0.149, 0.575 times the less compact strip
  Soup s;
  std::map<std::pair<int, int>, std::size_t> index;  // lattice points in half units
  auto point = [&](int i, int j) {
    const auto it = index.find({i, j});
    if(it != index.end()) return it->second;
    s.points.push_back({0.5 * i, 0.5 * j, 0.});
    return index[{i, j}] = s.points.size() - 1;
  };
  std::vector<std::pair<int, int>> cells;
  for(int x = 1; x < 10; ++x) cells.push_back({x, 0});
  for(int y = 0; y < 10; ++y) cells.push_back({0, y});
  for(const auto& c : cells)
    for(int a = 0; a < 2; ++a)
      for(int b = 0; b < 2; ++b) {
        const int i = 2 * c.first + a, j = 2 * c.second + b;
        s.triangles.push_back({point(i, j), point(i + 1, j), point(i + 1, j + 1)});
        s.triangles.push_back({point(i, j), point(i + 1, j + 1), point(i, j + 1)});
      }
  const Surface_mesh tm = make<Surface_mesh>(s);
  Chart_map<Surface_mesh> strips;
  for(auto f : faces(tm)) {
    const auto c = centroid(tm, f);
    strips[f] = c[0] > 1 ? 0 : 1;
  }
  auto merged = [&](const double* ratio) {
    Chart_map<Surface_mesh> chart = strips;
    const auto r = ratio ? QD::merge_charts_by_boundaries<CGAL::Sequential_tag>(
                               tm, boost::make_assoc_property_map(chart), QD::parameters::compactness_ratio(*ratio))
                         : QD::merge_charts_by_boundaries<CGAL::Sequential_tag>(tm, boost::make_assoc_property_map(chart));
    BOOST_REQUIRE_MESSAGE(r, QD::error_message(r.status));
    BOOST_TEST(r.charts_before == 2u);
    expect_valid_charts(tm, chart, r.number_of_charts);
    return r;
  };
  const double zero = 0, half = 0.5, limit = 0.57, above = 0.58, strict = 0.9;
  // the paper's merging and ratios up to 0.575: one piece, after one trial
  for(const double* ratio : {&zero, &half, &limit}) {
    const auto r = merged(ratio);
    BOOST_TEST(r.number_of_charts == 1u);
    BOOST_TEST(r.trials == 1u);
  }
  // the default (0.6) and ratios above 0.575: two pieces, without a trial
  for(const double* ratio : {static_cast<const double*>(nullptr), &above, &strict}) {
    const auto r = merged(ratio);
    BOOST_TEST(r.number_of_charts == 2u);
    BOOST_TEST(r.trials == 0u);
  }
  // a ratio outside [0, 1], or a negative or NaN bound of the criterion:
  // INVALID_ARGUMENT from every step, nothing written
  auto refused = [&](const auto& np) {
    Chart_map<Surface_mesh> chart = strips;
    BOOST_TEST((QD::merge_charts_by_boundaries(tm, boost::make_assoc_property_map(chart), np).status ==
                QD::Error_code::INVALID_ARGUMENT));
    BOOST_TEST((chart == strips));
    Chart_map<Surface_mesh> untouched;
    BOOST_TEST((QD::segment_quasi_developable(tm, boost::make_assoc_property_map(untouched), np).status ==
                QD::Error_code::INVALID_ARGUMENT));
    BOOST_TEST(untouched.empty());
    BOOST_TEST((QD::flatten_charts(tm, boost::make_assoc_property_map(chart), np).status ==
                QD::Error_code::INVALID_ARGUMENT));
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for(const double bad : {-0.1, 1.5, nan}) refused(QD::parameters::compactness_ratio(bad));
  for(const double bad : {-0.1, nan}) {
    refused(QD::parameters::max_area_distortion(bad));
    refused(QD::parameters::max_l2_stretch(bad));
    refused(QD::parameters::max_local_area_distortion(bad));
  }
}

BOOST_AUTO_TEST_CASE_TEMPLATE(cube_unfolds_into_few_charts, Mesh, Mesh_types)
{
  const Mesh tm = make<Mesh>(closed_cube(4));
  Chart_map<Mesh> chart;
  const auto r = QD::segment_quasi_developable(tm, boost::make_assoc_property_map(chart));
  BOOST_REQUIRE_MESSAGE(r, QD::error_message(r.status));
  BOOST_TEST_MESSAGE("cube: " << r.charts_after_vsa << " VSA charts -> " << r.number_of_charts);
  BOOST_TEST(r.number_of_charts <= 2u);
  BOOST_TEST(r.max_area_distortion < 1e-6);  // the cube's net is exact
  expect_valid_segmentation(tm, chart, r);
}

BOOST_AUTO_TEST_CASE(closed_surfaces_of_any_topology_and_components)
{
  // two cubes and a torus in one mesh
  Soup s = closed_cube(4);
  const Soup t = torus(32, 16);
  const std::size_t off = s.points.size();
  for(P3 p : t.points) s.points.push_back({p[0] + 5, p[1], p[2]});
  for(Tri f : t.triangles) s.triangles.push_back({f[0] + off, f[1] + off, f[2] + off});
  const Soup u = closed_cube(3);
  const std::size_t off2 = s.points.size();
  for(P3 p : u.points) s.points.push_back({p[0], p[1] + 4, p[2]});
  for(Tri f : u.triangles) s.triangles.push_back({f[0] + off2, f[1] + off2, f[2] + off2});
  const Surface_mesh tm = make<Surface_mesh>(s);
  Chart_map<Surface_mesh> chart;
  const auto r = QD::segment_quasi_developable(tm, boost::make_assoc_property_map(chart));
  BOOST_REQUIRE_MESSAGE(r, QD::error_message(r.status));
  BOOST_TEST_MESSAGE("cubes and torus: " << r.charts_after_vsa << " -> " << r.charts_before_merging << " -> "
                                         << r.number_of_charts << " charts, " << r.merging.trials << " trials");
  expect_valid_segmentation(tm, chart, r);
}

// A small chart in the middle of a flat square, between a left and a right
// chart: shared out between them where both enlarged charts pass the trial,
// kept where one of them would fail (one neighbour alone would be a merge).
BOOST_AUTO_TEST_CASE(small_chart_shared_out_among_neighbours)
{
  const Surface_mesh tm = make<Surface_mesh>(grid(20, 20, [](double u, double v) { return P3{u, v, 0.}; }));
  const auto fim = get(boost::face_index, tm);
  const auto him = get(boost::halfedge_index, tm);
  const auto vim = get(boost::vertex_index, tm);
  const std::vector<QD::internal::Face_geometry> geo = QD::internal::face_geometry(tm, tm.points(), fim);
  std::vector<std::array<double, 3>> points;
  for(auto v : vertices(tm)) points.push_back({p3(tm, v)[0], p3(tm, v)[1], p3(tm, v)[2]});
  // 0: the left, 1: the right, 2: the square [0.4, 0.6]^2 (4 % of the area)
  std::vector<std::size_t> start(num_faces(tm));
  for(auto f : faces(tm)) {
    const auto& c = geo[fim[f]].centroid;
    start[fim[f]] = (c[0] > 0.4 && c[0] < 0.6 && c[1] > 0.4 && c[1] < 0.6) ? 2 : c[0] < 0.5 ? 0 : 1;
  }
  auto seams_of = [&](const std::vector<std::size_t>& chart) {
    std::vector<char> seam(num_halfedges(tm), 0);
    for(auto h : halfedges(tm))
      if(!is_border_edge(h, tm) && chart[fim[face(h, tm)]] != chart[fim[face(opposite(h, tm), tm)]]) seam[him[h]] = 1;
    return seam;
  };
  typedef boost::graph_traits<Surface_mesh>::face_descriptor face_descriptor;
  typedef boost::graph_traits<Surface_mesh>::halfedge_descriptor halfedge_descriptor;
  typedef std::function<bool(halfedge_descriptor)> Is_cut;
  auto share = [&](std::vector<std::size_t>& chart, std::size_t& n,
                   const std::function<bool(const std::vector<face_descriptor>&)>& accept) {
    std::vector<char> seam = seams_of(chart);
    const auto r = QD::internal::share_out_small_charts<CGAL::Sequential_tag>(
        tm, fim, him, vim, points, geo,
        [&](const std::vector<face_descriptor>& fs, const Is_cut&) { return accept(fs); }, chart, n, seam);
    BOOST_TEST((seam == seams_of(chart)));  // the seams are the borders between the charts
    return r;
  };

  // both neighbours accept: two charts, each with its half of the square
  std::vector<std::size_t> chart = start;
  std::size_t n = 3;
  auto r = share(chart, n, [](const std::vector<face_descriptor>&) { return true; });
  BOOST_TEST(r.first == 1u);
  BOOST_TEST(r.second == 2u);
  BOOST_REQUIRE(n == 2u);
  std::set<std::size_t> taken;
  for(auto f : faces(tm)) {
    // renumbered by smallest face index: the left chart (face 0 is at the origin) is 0
    const auto& c = geo[fim[f]].centroid;
    if(start[fim[f]] != 2) BOOST_TEST(chart[fim[f]] == start[fim[f]]);
    // each face of the square goes to the side it is nearer to
    if(start[fim[f]] == 2) {
      taken.insert(chart[fim[f]]);
      if(std::abs(c[0] - 0.5) > 0.03) BOOST_TEST(chart[fim[f]] == (c[0] < 0.5 ? 0u : 1u));
    }
  }
  BOOST_TEST(taken.size() == 2u);

  // the right chart fails once it takes a face of the square: kept as it was
  chart = start;
  n = 3;
  r = share(chart, n, [&](const std::vector<face_descriptor>& fs) {
    return std::none_of(fs.begin(), fs.end(), [&](face_descriptor f) {
      return start[fim[f]] == 2 && geo[fim[f]].centroid[0] > 0.5;
    });
  });
  BOOST_TEST(r.first == 0u);
  BOOST_TEST(r.second == 2u);
  BOOST_TEST(n == 3u);
  std::map<std::size_t, std::set<std::size_t>> renamed;  // each chart keeps its faces under one id
  for(std::size_t i = 0; i < chart.size(); ++i) renamed[start[i]].insert(chart[i]);
  BOOST_TEST(renamed.size() == 3u);
  for(const auto& x : renamed) BOOST_TEST(x.second.size() == 1u);

  // a chart above 5 % of the area is not tried
  for(auto f : faces(tm)) {
    const auto& c = geo[fim[f]].centroid;
    start[fim[f]] = (c[0] > 0.35 && c[0] < 0.65 && c[1] > 0.35 && c[1] < 0.65) ? 2 : c[0] < 0.5 ? 0 : 1;
  }
  chart = start;
  n = 3;
  r = share(chart, n, [](const std::vector<face_descriptor>&) { return true; });
  BOOST_TEST(r.second == 0u);
  BOOST_TEST(n == 3u);
}

BOOST_AUTO_TEST_CASE(deterministic_and_parallel_equals_sequential)
{
#ifdef CGAL_QD_DEMO_MESH_DIR
  Surface_mesh tm;
  BOOST_REQUIRE(CGAL::IO::read_polygon_mesh(std::string(CGAL_QD_DEMO_MESH_DIR) + "/elephant.off", tm));
#else
  const Surface_mesh tm = make<Surface_mesh>(torus(48, 24));
#endif
  Chart_map<Surface_mesh> a, b, c;
  const auto ra = QD::segment_quasi_developable<CGAL::Sequential_tag>(tm, boost::make_assoc_property_map(a));
  const auto rb = QD::segment_quasi_developable<CGAL::Sequential_tag>(tm, boost::make_assoc_property_map(b));
  // the progress callback is called on the calling thread only
  std::atomic<std::size_t> calls{0}, calls_elsewhere{0};
  const std::thread::id caller = std::this_thread::get_id();
  const auto rc = QD::segment_quasi_developable<CGAL::Parallel_if_available_tag>(
      tm, boost::make_assoc_property_map(c), CGAL::parameters::callback([&](const char*, double) {
        ++calls;
        if(std::this_thread::get_id() != caller) ++calls_elsewhere;
      }));
  BOOST_REQUIRE(ra);
  BOOST_TEST(calls.load() > 0u);
  BOOST_TEST(calls_elsewhere.load() == 0u);
  BOOST_TEST((a == b));
  BOOST_TEST((a == c));
  BOOST_TEST(ra.merging.trials == rb.merging.trials);
  BOOST_TEST(ra.number_of_charts == rc.number_of_charts);
  BOOST_TEST((ra.corner_uv == rc.corner_uv));
  BOOST_TEST((ra.seam_edges == rc.seam_edges));
#ifdef CGAL_LINKED_WITH_TBB
  BOOST_TEST_MESSAGE("parallel trials: " << ra.time_merge_ms << " ms sequential, " << rc.time_merge_ms << " ms parallel");
  // the same charts with TBB limited to 1, 2 and 8 threads
  for(std::size_t threads : {1, 2, 8}) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    Chart_map<Surface_mesh> d;
    const auto rd = QD::segment_quasi_developable<CGAL::Parallel_tag>(tm, boost::make_assoc_property_map(d));
    BOOST_REQUIRE(rd);
    BOOST_TEST((a == d), threads << " threads");
    BOOST_TEST((ra.corner_uv == rd.corner_uv), threads << " threads");
  }
#endif
  expect_valid_segmentation(tm, a, ra);
}

// A mesh with exact constructions (Epeck), as many CGAL users keep theirs: the
// library reads its points as doubles, so the segmentation, its flattening
// and its smoothed seams are those of the same mesh with Epick, face for face
BOOST_AUTO_TEST_CASE(exact_constructions_kernel_gives_the_same_segmentation)
{
  typedef CGAL::Exact_predicates_exact_constructions_kernel Epeck;
  typedef CGAL::Surface_mesh<Epeck::Point_3> Exact_mesh;
  const Soup soup = torus(32, 16);
  const Surface_mesh tm = make<Surface_mesh>(soup);
  const Exact_mesh em = make<Exact_mesh>(soup);
  BOOST_REQUIRE(num_faces(em) == num_faces(tm));
  Chart_map<Surface_mesh> chart;
  Chart_map<Exact_mesh> exact_chart;
  const auto r = QD::segment_quasi_developable(tm, boost::make_assoc_property_map(chart));
  const auto er = QD::segment_quasi_developable(em, boost::make_assoc_property_map(exact_chart));
  BOOST_REQUIRE(r);
  BOOST_REQUIRE(er);
  BOOST_TEST(er.number_of_charts == r.number_of_charts);
  BOOST_TEST(er.number_of_charts > 1u);
  // the faces are numbered alike in both meshes
  bool same = true;
  for(auto f : faces(tm)) same = same && exact_chart.at(Exact_mesh::Face_index(std::size_t(f))) == chart.at(f);
  BOOST_TEST(same);
  BOOST_TEST((er.corner_uv == r.corner_uv));
  expect_valid_segmentation(em, exact_chart, er);
  // the seams smoothed into a new mesh of each kernel
  Surface_mesh out;
  Exact_mesh exact_out;
  Chart_map<Surface_mesh> out_chart;
  Chart_map<Exact_mesh> exact_out_chart;
  const auto s = QD::smooth_segmentation_seams(tm, boost::make_assoc_property_map(chart), r, out,
                                                boost::make_assoc_property_map(out_chart));
  const auto es = QD::smooth_segmentation_seams(em, boost::make_assoc_property_map(exact_chart), er, exact_out,
                                                 boost::make_assoc_property_map(exact_out_chart));
  BOOST_REQUIRE(s);
  BOOST_REQUIRE(es);
  BOOST_TEST(es.kept == s.kept);
  BOOST_TEST(num_faces(exact_out) == num_faces(out));
  BOOST_TEST(es.smoothing.curves_smoothed == s.smoothing.curves_smoothed);
  BOOST_TEST(es.smoothing.zigzag_after == s.smoothing.zigzag_after);
}

BOOST_AUTO_TEST_CASE(steps_can_be_switched_and_thresholds_hold)
{
  const Surface_mesh tm = make<Surface_mesh>(grid(30, 30, bump(0.35)));
  for(double max_area : {0.02, 0.10}) {
    Chart_map<Surface_mesh> chart;
    std::vector<std::string> steps;
    const auto r = QD::segment_quasi_developable(
        tm, boost::make_assoc_property_map(chart),
        QD::parameters::max_area_distortion(
            max_area, QD::parameters::max_l2_stretch(
                          1.5, CGAL::parameters::callback([&](const char* step, double) { steps.push_back(step); }))));
    BOOST_REQUIRE(r);
    expect_valid_segmentation(tm, chart, r, 100 * max_area, 1.5);
    BOOST_TEST(steps.front() == "vsa");
    BOOST_TEST(std::count(steps.begin(), steps.end(), std::string("refine")) == 1);
    BOOST_TEST(steps.back() == "flatten");
  }
  // no merging: the charts are those of VSA and refinement, split only where beyond the thresholds
  Chart_map<Surface_mesh> chart;
  const auto r = QD::segment_quasi_developable(
      tm, boost::make_assoc_property_map(chart),
      QD::parameters::merge_charts(false, QD::parameters::refine_boundaries(false)));
  BOOST_REQUIRE(r);
  BOOST_TEST(r.merging.trials == 0u);
  BOOST_TEST(r.time_refine_ms == 0.);
  BOOST_TEST(r.number_of_charts == r.charts_before_merging);
  expect_valid_segmentation(tm, chart, r);

  // denoising on request: the caller's mesh keeps its points unless it passes a map
  std::map<Surface_mesh::Vertex_index, Epick::Point_3> denoised;
  Chart_map<Surface_mesh> dc;
  const auto rd = QD::segment_quasi_developable(
      tm, boost::make_assoc_property_map(dc),
      QD::parameters::denoise_boundaries(true, QD::parameters::denoised_point_map(boost::make_assoc_property_map(denoised))));
  BOOST_REQUIRE(rd);
  BOOST_TEST(rd.denoising.number_of_border_vertices > 0u);
  BOOST_TEST(denoised.size() == num_vertices(tm));
  for(auto v : vertices(tm))
    BOOST_TEST(std::abs(rd.points[v][2] - denoised.at(v).z()) == 0.);
}

BOOST_AUTO_TEST_CASE(every_merge_order_gives_valid_charts)
{
  const Surface_mesh tm = make<Surface_mesh>(torus(48, 24));
  for(QD::Merge_order order : {QD::Merge_order::LARGEST_AREA_FIRST, QD::Merge_order::SMALLEST_AREA_FIRST,
                               QD::Merge_order::LONGEST_RELATIVE_CURVE_FIRST}) {
    Chart_map<Surface_mesh> chart;
    const auto r = QD::segment_quasi_developable(tm, boost::make_assoc_property_map(chart),
                                                 QD::parameters::merge_order(order));
    BOOST_REQUIRE(r);
    BOOST_TEST_MESSAGE("torus, merge order " << int(order) << ": " << r.charts_before_merging << " -> "
                                             << r.number_of_charts << " charts, " << r.merging.trials << " trials");
    BOOST_TEST(r.number_of_charts < r.charts_before_merging);
    expect_valid_segmentation(tm, chart, r);
  }
}

BOOST_AUTO_TEST_CASE(segmentation_rejects_bad_input)
{
  Chart_map<Surface_mesh> chart;
  const Surface_mesh empty;
  BOOST_TEST((QD::segment_quasi_developable(empty, boost::make_assoc_property_map(chart)).status ==
              QD::Error_code::EMPTY_MESH));
  Soup s = grid(4, 4, bump(0.2));
  s.points[6][2] = std::numeric_limits<double>::quiet_NaN();
  const Surface_mesh bad = make<Surface_mesh>(s);
  BOOST_TEST((QD::segment_quasi_developable(bad, boost::make_assoc_property_map(chart)).status ==
              QD::Error_code::INVALID_COORDINATES));
  BOOST_TEST((QD::refine_chart_boundaries(bad, boost::make_assoc_property_map(chart)).status ==
              QD::Error_code::INVALID_COORDINATES));
  BOOST_TEST((QD::merge_charts_by_boundaries(bad, boost::make_assoc_property_map(chart)).status ==
              QD::Error_code::INVALID_COORDINATES));
  Surface_mesh quad;
  const auto v0 = quad.add_vertex(Epick::Point_3(0, 0, 0)), v1 = quad.add_vertex(Epick::Point_3(1, 0, 0)),
             v2 = quad.add_vertex(Epick::Point_3(1, 1, 0)), v3 = quad.add_vertex(Epick::Point_3(0, 1, 0));
  quad.add_face(v0, v1, v2, v3);
  BOOST_TEST((QD::segment_quasi_developable(quad, boost::make_assoc_property_map(chart)).status ==
              QD::Error_code::NOT_TRIANGLE_MESH));
  BOOST_TEST(chart.empty());
}

#ifdef CGAL_QD_DEMO_MESH_DIR
// bunny00: the merging leaves a small piece between larger ones (1,189 faces
// by the ear); the sharing gives it to its neighbours, and the segmentation
// stays valid, one piece fewer
BOOST_AUTO_TEST_CASE(bunny00_small_chart_shared_out)
{
  Surface_mesh tm;
  BOOST_REQUIRE(CGAL::IO::read_polygon_mesh(std::string(CGAL_QD_DEMO_MESH_DIR) + "/bunny00.off", tm));
  Chart_map<Surface_mesh> chart, kept;
  const auto r = QD::segment_quasi_developable(tm, boost::make_assoc_property_map(chart));
  const auto r0 = QD::segment_quasi_developable(tm, boost::make_assoc_property_map(kept),
                                                QD::parameters::share_out_small_charts(false));
  BOOST_REQUIRE(r);
  BOOST_REQUIRE(r0);
  BOOST_TEST_MESSAGE("bunny00: " << r0.number_of_charts << " pieces, " << r.number_of_charts << " with "
                                 << r.merging.charts_shared_out << " shared out in " << r.merging.sharing_trials
                                 << " trials");
  BOOST_TEST(r0.merging.charts_shared_out == 0u);
  BOOST_TEST(r0.merging.sharing_trials == 0u);
  BOOST_TEST(r.merging.charts_shared_out >= 1u);
  BOOST_TEST(r.number_of_charts + r.merging.charts_shared_out == r0.number_of_charts);
  BOOST_TEST(r.merging.sharing_trials >= 2 * r.merging.charts_shared_out);
  expect_valid_segmentation(tm, chart, r);
  BOOST_TEST(r.seam_length < r0.seam_length);
}

BOOST_AUTO_TEST_CASE(real_meshes_segment_within_the_thresholds)
{
  // the defaults (free-boundary ARAP trials, A_loc <= 2.5 %): fewer pieces than
  // the paper's criterion, which went from 16 VSA charts to 5 on fandisk
  // The two sides of at least 90 % of the seam curves match within 0.5 %
  // (elephant: 40 of 94 curves when each chart was fitted at once to the mean
  // of the two sides, 87 with the rounds that first pull the borders towards it).
  for(const auto& mesh : std::vector<std::pair<std::string, std::size_t>>{
          {"fandisk.off", 4}, {"cow.off", 24}, {"elephant.off", 20}}) {
    Surface_mesh tm;
    BOOST_REQUIRE(CGAL::IO::read_polygon_mesh(std::string(CGAL_QD_DEMO_MESH_DIR) + "/" + mesh.first, tm));
    Chart_map<Surface_mesh> chart;
    const auto r = QD::segment_quasi_developable(tm, boost::make_assoc_property_map(chart));
    BOOST_REQUIRE_MESSAGE(r, QD::error_message(r.status));
    BOOST_TEST_MESSAGE(mesh.first << ": " << r.charts_after_vsa << " VSA charts -> " << r.charts_before_merging
                                  << " -> " << r.number_of_charts << ", max A " << r.max_area_distortion
                                  << " %, max L2 " << r.max_l2_stretch << ", max A_loc " << r.max_local_area_distortion
                                  << " %, seams differ by " << 100 * r.max_seam_length_mismatch << " %, zigzag "
                                  << r.seam_zigzag << ", compactness " << r.compactness << ", "
                                  << r.seam_curves_matched << " of " << r.number_of_seam_curves
                                  << " seam curves matched, " << r.time_total_ms << " ms");
    BOOST_TEST(r.number_of_charts <= mesh.second);
    BOOST_TEST(10 * r.seam_curves_matched >= 9 * r.number_of_seam_curves);
    BOOST_TEST(r.number_of_charts < r.charts_before_merging);
    expect_valid_segmentation(tm, chart, r);
  }
  // the paper's criterion and merge order stay available: LPFB+IP everywhere,
  // every border edge at its 3D length
  Surface_mesh tm;
  BOOST_REQUIRE(CGAL::IO::read_polygon_mesh(std::string(CGAL_QD_DEMO_MESH_DIR) + "/fandisk.off", tm));
  Chart_map<Surface_mesh> chart;
  const auto r = QD::segment_quasi_developable(
      tm, boost::make_assoc_property_map(chart),
      QD::parameters::chart_criterion(QD::Chart_criterion::LPFB_IP,
                                      QD::parameters::merge_order(QD::Merge_order::LARGEST_AREA_FIRST)));
  BOOST_REQUIRE(r);
  BOOST_TEST_MESSAGE("fandisk, the paper's criterion: " << r.number_of_charts << " charts");
  BOOST_TEST(r.number_of_charts <= 6u);
  for(const auto& c : r.charts) BOOST_TEST(!c.optimized);
  BOOST_TEST(r.max_seam_length_mismatch < 1e-6);
  expect_valid_segmentation(tm, chart, r, 10., 2., 0.);
}
#endif

// ===================================================================== step 1 across resolutions
// The same shape at several resolutions (test/resolution_series.h) must give
// about the same number of VSA charts: step 1's stopping rule depends on the
// geometry, not on the number of faces.

#ifdef CGAL_QD_DEMO_MESH_DIR
namespace {

struct Series_row
{
  std::string mesh, resolution;
  std::size_t faces = 0;
  QD::Vsa_result vsa;
};

Series_row segment_at_resolution(const std::string& name, const Series_mesh& original, int level,
                                 const std::string& out_dir)
{
  Series_row row;
  row.mesh = name;
  row.resolution = resolution_name(level);
  const Series_mesh tm = at_resolution(original, level);
  row.faces = num_faces(tm);
  if(!out_dir.empty()) {
    const std::string suffix[] = {"quarter", "half", "1x", "sub1", "sub2"};
    const std::string file = out_dir + "/" + name + "_" + suffix[level + 2] + ".off";
    BOOST_TEST(CGAL::IO::write_polygon_mesh(file, tm, CGAL::parameters::stream_precision(17)));
  }
  Chart_map<Series_mesh> chart;
  row.vsa = QD::segment_by_error_controlled_vsa(tm, boost::make_assoc_property_map(chart));
  BOOST_REQUIRE_MESSAGE(row.vsa, name << " " << row.resolution << ": " << QD::error_message(row.vsa.status));
  expect_valid_charts(tm, chart, row.vsa.number_of_charts);
  BOOST_TEST_MESSAGE("| " << name << " | " << row.resolution << " | " << row.faces << " | "
                          << row.vsa.number_of_charts << " | " << (row.vsa.tolerance_reached ? "yes" : "no") << " | "
                          << row.vsa.max_chart_error << " | " << row.vsa.time_ms << " |");
  return row;
}

Series_mesh read_demo_mesh(const std::string& name)
{
  Series_mesh tm;
  BOOST_REQUIRE(CGAL::IO::read_polygon_mesh(std::string(CGAL_QD_DEMO_MESH_DIR) + "/" + name + ".off", tm));
  return tm;
}

// every count within 15 % of every other: largest <= 1.15 smallest
void expect_counts_within_15_percent(const std::vector<Series_row>& rows)
{
  std::size_t lo = rows.front().vsa.number_of_charts, hi = lo;
  for(const Series_row& r : rows) {
    lo = (std::min)(lo, r.vsa.number_of_charts);
    hi = (std::max)(hi, r.vsa.number_of_charts);
  }
  BOOST_TEST_MESSAGE(rows.front().mesh << ": VSA charts from " << lo << " to " << hi);
  BOOST_TEST(double(hi) <= 1.15 * double(lo));
}

} // namespace

BOOST_AUTO_TEST_CASE(vsa_chart_count_does_not_depend_on_the_resolution)
{
  // elephant: a quarter, a half, all of its 5,558 faces, subdivided once
  BOOST_TEST_MESSAGE("| mesh | resolution | faces | VSA charts | tolerance reached | max error | VSA ms |");
  const Series_mesh elephant = read_demo_mesh("elephant");
  std::vector<Series_row> rows;
  for(int level : {-2, -1, 0, 1}) rows.push_back(segment_at_resolution("elephant", elephant, level, ""));
  expect_counts_within_15_percent(rows);
}

// Step 1 runs its own Lloyd iteration (internal/normal_vsa.h) in place of
// CGAL's Variational_shape_approximation; it must take the same decisions:
// the same charts after every operation that step 1 uses, with the same
// errors, on meshes with planar parts (ties of the flooding on fandisk), with
// smoothed normals, and on a mesh of two components.
namespace {

// the L2,1 metric on given normals, as CGAL's class needs it
struct Given_normals_metric
{
  typedef Epick::Vector_3 Proxy;
  typedef boost::graph_traits<Surface_mesh>::face_descriptor face_descriptor;
  const std::vector<QD::internal::Face_geometry>* geo;

  double compute_error(face_descriptor f, const Surface_mesh&, const Proxy& px) const
  {
    const QD::internal::Face_geometry& d = (*geo)[f.idx()];
    const double x = d.normal[0] - px.x(), y = d.normal[1] - px.y(), z = d.normal[2] - px.z();
    return d.area * (x * x + y * y + z * z);
  }
  template <class FaceRange>
  Proxy fit_proxy(const FaceRange& range, const Surface_mesh&) const
  {
    double s[3] = {0., 0., 0.};
    for(face_descriptor f : range)
      for(int i = 0; i < 3; ++i) s[i] += (*geo)[f.idx()].area * (*geo)[f.idx()].normal[i];
    const double l = std::sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
    return l > 0 ? Proxy(s[0] / l, s[1] / l, s[2] / l) : Proxy(0., 0., 0.);
  }
};

// runs the two through the same operations; returns how many were compared.
// `copies` (1 or 0; -1: either): whether ours is expected to have met a tie
// of the flooding, and flooded with every copy of a queued face since, as
// CGAL's class does (otherwise it floods without the copies, which gives the
// same decisions only where no two entries tie): both ways are compared
std::size_t compare_with_cgal_vsa(const Surface_mesh& tm, const std::vector<QD::internal::Face_geometry>& geo,
                                  const std::string& name, int copies, bool parallel_fits = false)
{
  const auto fim = get(CGAL::face_index, tm);
  const Given_normals_metric metric{&geo};
  CGAL::Variational_shape_approximation<Surface_mesh, Surface_mesh::Property_map<Surface_mesh::Vertex_index, Epick::Point_3>,
                                        Given_normals_metric>
      cgal(tm, tm.points(), metric);
  QD::internal::Normal_vsa ours(geo, QD::internal::face_neighbours(tm, fim), QD::internal::faces_in_order(tm, fim));
  ours.fit_in_parallel(parallel_fits);
  cgal.initialize_seeds(CGAL::parameters::seeding_method(CGAL::Surface_mesh_approximation::INCREMENTAL)
                            .max_number_of_proxies(1)
                            .number_of_relaxations(3));
  ours.bootstrap();
  std::size_t compared = 0;
  auto same = [&](const std::string& step) {
    std::vector<std::size_t> theirs(num_faces(tm));
    cgal.proxy_map(boost::make_iterator_property_map(theirs.begin(), fim));
    BOOST_TEST(cgal.number_of_proxies() == ours.number_of_proxies(), name << ", " << step);
    BOOST_TEST((theirs == ours.proxy_of()), name << ", " << step << ": the faces' proxies differ");
    ++compared;
  };
  // after a relaxation, the charts' errors and areas from the proxies' fits
  // are those measured over the mesh, to the last bit
  auto same_chart_errors = [&](const std::string& step) {
    BOOST_TEST_REQUIRE(ours.fitted_to_charts(), name << ", " << step);
    const std::vector<std::size_t> chart = ours.proxy_of();
    std::vector<double> error, area, fitted_error, fitted_area;
    QD::internal::chart_errors(geo, QD::internal::faces_in_order(tm, fim), chart, ours.number_of_proxies(), error,
                               area);
    ours.chart_errors(fitted_error, fitted_area);
    BOOST_TEST((fitted_error == error), name << ", " << step << ": the charts' errors differ");
    BOOST_TEST((fitted_area == area), name << ", " << step << ": the charts' areas differ");
  };
  same("seeds");
  BOOST_TEST(!ours.fitted_to_charts(), name);  // fitted to the components, not in face order
  BOOST_TEST(cgal.run(3) == ours.run(3), name);
  same("first relaxation");
  same_chart_errors("first relaxation");
  for(int round = 0; round < 6; ++round) {
    const std::size_t add = round % 3 == 2 ? 1 : 2 + round;
    const std::size_t a = add == 1 ? cgal.add_to_furthest_proxies(1, 0) : cgal.add_proxies_error_diffusion(add);
    const std::size_t b = add == 1 ? ours.add_to_furthest_proxies(1, 0) : ours.add_proxies_error_diffusion(add);
    BOOST_TEST(a == b, name << ", round " << round);
    same("round " + std::to_string(round) + ", added");
    BOOST_TEST(!ours.fitted_to_charts(), name << ", round " << round);
    BOOST_TEST(cgal.run(3) == ours.run(3), name << ", round " << round);
    same("round " + std::to_string(round) + ", relaxed");
    same_chart_errors("round " + std::to_string(round) + ", relaxed");
  }
  if(copies >= 0) BOOST_TEST(ours.floods_with_copies() == (copies == 1), name);
  return compared;
}

} // namespace

BOOST_AUTO_TEST_CASE(vsa_iteration_takes_the_decisions_of_cgal_vsa)
{
  for(const char* name : {"fandisk", "elephant", "cow"}) {
    Surface_mesh tm;
    BOOST_REQUIRE(CGAL::IO::read_polygon_mesh(std::string(CGAL_QD_DEMO_MESH_DIR) + "/" + name + ".off", tm));
    const auto fim = get(CGAL::face_index, tm);
    const std::vector<QD::internal::Face_geometry> raw = QD::internal::face_geometry(tm, tm.points(), fim);
    // fandisk's planar parts give ties, and its floods fall back to every
    // copy; elephant's floods meet none
    const std::string n = name;
    BOOST_TEST(compare_with_cgal_vsa(tm, raw, name, n == "fandisk" ? 1 : n == "elephant" ? 0 : -1,
                                     n == "cow") == 14u);
    if(std::string(name) == "elephant")  // with the normals that step 1 uses, the proxies fitted in parallel
      compare_with_cgal_vsa(tm, QD::internal::smooth_face_normals(tm, fim, raw, 0.05, QD::internal::vsa_crease_cos),
                            "elephant, smoothed", 0, true);
  }
  // two components: one proxy each to start with
  Surface_mesh two;
  BOOST_REQUIRE(CGAL::IO::read_polygon_mesh(std::string(CGAL_QD_DEMO_MESH_DIR) + "/fandisk.off", two));
  Surface_mesh copy = two;
  for(auto v : vertices(copy)) copy.point(v) = copy.point(v) + Epick::Vector_3(10, 0, 0);
  CGAL::copy_face_graph(copy, two);
  const auto fim = get(CGAL::face_index, two);
  const std::vector<QD::internal::Face_geometry> geo = QD::internal::face_geometry(two, two.points(), fim);
  QD::internal::Normal_vsa ours(geo, QD::internal::face_neighbours(two, fim), QD::internal::faces_in_order(two, fim));
  ours.bootstrap();
  BOOST_TEST(ours.number_of_proxies() == 2u);
  compare_with_cgal_vsa(two, geo, "two fandisks", 1);
}

// The flood without copies takes its entries from a queue of buckets
// (internal/bucket_queue.h): it must give them in the order of a binary heap
// wherever the keys differ, say where two are the same, and hold keys beyond
// its range (zero, below and above the largest key it was told of).
BOOST_AUTO_TEST_CASE(bucket_queue_gives_the_order_of_a_binary_heap)
{
  struct Entry
  {
    double key;
    std::uint32_t id;
    bool operator<(const Entry& o) const { return key > o.key; }  // a min-heap
  };
  struct Key_of
  {
    double operator()(const Entry& e) const { return e.key; }
  };
  QD::internal::Bucket_queue<Entry, Key_of> queue;
  queue.set_largest_key(4.);
  std::vector<Entry> heap;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> exponent(-60., 3.), unit(0., 1.);
  std::uint32_t id = 0;
  std::size_t taken = 0;
  // pushes and pops interleaved, the keys spread over 63 octaves (some
  // below the queue's range, a few above the largest key), and zero once
  for(int round = 0; round < 2; ++round) {
    queue.clear();
    heap.clear();
    for(int step = 0; step < 20000; ++step) {
      if(heap.empty() || unit(rng) < 0.55) {
        const Entry e{step == 10 ? 0. : std::pow(2., exponent(rng)) * (1 + unit(rng)), id++};
        queue.push(e);
        heap.push_back(e);
        std::push_heap(heap.begin(), heap.end());
      } else {
        BOOST_REQUIRE(!queue.empty());
        BOOST_REQUIRE_EQUAL(queue.front().id, heap.front().id);
        BOOST_REQUIRE_EQUAL(queue.front().key, heap.front().key);
        queue.pop();
        std::pop_heap(heap.begin(), heap.end());
        heap.pop_back();
        ++taken;
      }
      BOOST_REQUIRE_EQUAL(queue.size(), heap.size());
    }
    // the first round is left half full: clear() empties it
  }
  while(!heap.empty()) {
    BOOST_REQUIRE_EQUAL(queue.front().id, heap.front().id);
    queue.pop();
    std::pop_heap(heap.begin(), heap.end());
    heap.pop_back();
    ++taken;
  }
  BOOST_TEST(queue.empty());
  BOOST_TEST(taken > 15000u);
  // equal keys: after one is taken, the front has the same key (which the
  // flood reads as a tie); then a smaller key comes first
  for(std::uint32_t i = 0; i < 3; ++i) queue.push(Entry{0.25, i});
  queue.push(Entry{0.5, 3});
  queue.pop();
  BOOST_TEST(queue.front().key == 0.25);
  queue.push(Entry{0.125, 4});
  BOOST_TEST(queue.front().id == 4u);
  queue.pop();
  queue.pop();
  BOOST_TEST(queue.front().key == 0.25);
  queue.pop();
  BOOST_TEST(queue.front().id == 3u);
  queue.pop();
  BOOST_TEST(queue.empty());
}

// On fine meshes step 1 averages the face normals over discs gathered from
// clusters of faces (internal/smooth_face_normals.h), where a disc holds
// thousands of faces. The clustered average must stay close to the face by
// face one, keep the creases of fandisk, and be the one chosen only when the
// discs hold many faces.
namespace {

struct Normal_deviation
{
  double mean = 0, largest = 0;  // area-weighted mean and largest angle, in degrees
  std::size_t different = 0;     // faces whose two normals are not the same
};

// the radius of step 1's normal smoothing: 0.03 times the diagonal of the
// bounding box of the face centroids
double step1_smoothing_radius(const std::vector<QD::internal::Face_geometry>& geo)
{
  std::array<double, 3> lo = geo.front().centroid, hi = lo;
  for(const auto& g : geo)
    for(int k = 0; k < 3; ++k) {
      lo[k] = (std::min)(lo[k], g.centroid[k]);
      hi[k] = (std::max)(hi[k], g.centroid[k]);
    }
  return QD::internal::vsa_smoothing_radius * std::sqrt(QD::internal::squared_distance3(lo, hi));
}

// how the smoothed normal of every face, clustered (always with `force`, else
// where the default rule chooses the clusters), differs from the face by face one
Normal_deviation clustered_normal_deviation(const Series_mesh& tm, bool force)
{
  const auto fim = get(CGAL::face_index, tm);
  const std::vector<QD::internal::Face_geometry> geo =
      QD::internal::face_geometry(tm, get(CGAL::vertex_point, tm), fim);
  const double radius = step1_smoothing_radius(geo);
  const auto exact = QD::internal::smooth_face_normals(tm, fim, geo, radius, QD::internal::vsa_crease_cos,
                                                       std::numeric_limits<double>::infinity());
  const auto clustered = force ? QD::internal::smooth_face_normals(tm, fim, geo, radius,
                                                                   QD::internal::vsa_crease_cos, 0.)
                               : QD::internal::smooth_face_normals(tm, fim, geo, radius,
                                                                   QD::internal::vsa_crease_cos);
  Normal_deviation d;
  double area = 0;
  for(std::size_t i = 0; i < geo.size(); ++i) {
    double dot = 0;
    for(int k = 0; k < 3; ++k) dot += exact[i].normal[k] * clustered[i].normal[k];
    const double angle = std::acos((std::min)(1., (std::max)(-1., dot))) * 180 / 3.14159265358979323846;
    d.mean += geo[i].area * angle;
    area += geo[i].area;
    d.largest = (std::max)(d.largest, angle);
    if(exact[i].normal != clustered[i].normal) ++d.different;
  }
  d.mean /= area;
  return d;
}

} // namespace

BOOST_AUTO_TEST_CASE(clustered_normal_smoothing_follows_the_face_by_face_one)
{
  // elephant subdivided once (22K faces) and fandisk, clusters forced
  const Normal_deviation elephant = clustered_normal_deviation(at_resolution(read_demo_mesh("elephant"), 1), true);
  BOOST_TEST_MESSAGE("elephant subdivided once: mean " << elephant.mean << " deg, largest " << elephant.largest
                                                       << ", " << elephant.different << " faces differ");
  BOOST_TEST(elephant.different > 0u);  // the clusters were used
  BOOST_TEST(elephant.mean < 1.);
  // fandisk: its creases bound the clusters as they bound the discs
  const Normal_deviation fandisk = clustered_normal_deviation(read_demo_mesh("fandisk"), true);
  BOOST_TEST_MESSAGE("fandisk: mean " << fandisk.mean << " deg, largest " << fandisk.largest);
  BOOST_TEST(fandisk.mean < 0.01);
  BOOST_TEST(fandisk.largest < 1.);
  // by default the coarse meshes keep the face by face average (about 25
  // faces per disc on elephant) ...
  BOOST_TEST(clustered_normal_deviation(read_demo_mesh("elephant"), false).different == 0u);
  // ... and a fine one takes the clusters (about 380 faces per disc)
  BOOST_TEST(clustered_normal_deviation(at_resolution(read_demo_mesh("elephant"), 2), false).different > 0u);
}

BOOST_AUTO_TEST_CASE(parallel_normal_smoothing_is_the_sequential_one)
{
  // elephant (face by face) and elephant subdivided once with clusters forced:
  // the discs summed in parallel give every normal to the last bit
  for(const bool clustered : {false, true}) {
    const Series_mesh tm = clustered ? at_resolution(read_demo_mesh("elephant"), 1) : read_demo_mesh("elephant");
    const auto fim = get(CGAL::face_index, tm);
    const std::vector<QD::internal::Face_geometry> geo =
        QD::internal::face_geometry(tm, get(CGAL::vertex_point, tm), fim);
    const double radius = step1_smoothing_radius(geo);
    const double cluster_above = clustered ? 0. : std::numeric_limits<double>::infinity();
    const auto sequential = QD::internal::smooth_face_normals<CGAL::Sequential_tag>(
        tm, fim, geo, radius, QD::internal::vsa_crease_cos, cluster_above);
    const auto parallel = QD::internal::smooth_face_normals<CGAL::Parallel_tag>(
        tm, fim, geo, radius, QD::internal::vsa_crease_cos, cluster_above);
    BOOST_REQUIRE(sequential.size() == geo.size());
    BOOST_REQUIRE(parallel.size() == geo.size());
    std::size_t smoothed = 0, same = 0;
    for(std::size_t i = 0; i < geo.size(); ++i) {
      if(sequential[i].normal != geo[i].normal) ++smoothed;
      if(sequential[i].normal == parallel[i].normal) ++same;
    }
    BOOST_TEST_MESSAGE((clustered ? "clusters: " : "faces: ") << smoothed << " of " << geo.size()
                                                               << " normals smoothed");
    BOOST_TEST(smoothed > geo.size() / 2);  // the smoothing did something
    BOOST_TEST(same == geo.size());
  }
}

BOOST_AUTO_TEST_CASE(face_by_face_normal_smoothing_is_the_flood_in_the_mesh_numbering)
{
  // the face by face discs are flooded on the faces renumbered along a Morton
  // curve: every normal must be the one of a flood in the mesh's own
  // numbering (the same faces summed in the same order), to the last bit
  for(const char* name : {"elephant", "fandisk"}) {
    const Series_mesh tm = read_demo_mesh(name);
    const auto fim = get(CGAL::face_index, tm);
    const std::vector<QD::internal::Face_geometry> geo =
        QD::internal::face_geometry(tm, get(CGAL::vertex_point, tm), fim);
    const double radius = 2 * step1_smoothing_radius(geo);  // about 100 faces a disc on elephant
    const auto smoothed = QD::internal::smooth_face_normals<CGAL::Parallel_tag>(
        tm, fim, geo, radius, QD::internal::vsa_crease_cos, std::numeric_limits<double>::infinity());
    const std::size_t none = std::size_t(-1);
    const auto next_to = QD::internal::smooth_neighbours(tm, fim, geo, QD::internal::vsa_crease_cos);
    std::vector<std::size_t> stamp(geo.size(), none), queue;
    std::size_t same = 0, changed = 0;
    for(std::size_t s = 0; s < geo.size(); ++s) {
      std::array<double, 3> sum = {0., 0., 0.};
      stamp[s] = s;
      queue.assign(1, s);
      for(std::size_t q = 0; q < queue.size(); ++q) {
        const std::size_t i = queue[q];
        for(int k = 0; k < 3; ++k) sum[k] += geo[i].area * geo[i].normal[k];
        for(std::size_t g : next_to[i]) {
          if(g == none || stamp[g] == s || QD::internal::squared_distance3(geo[s].centroid, geo[g].centroid) >
                                               radius * radius)
            continue;
          stamp[g] = s;
          queue.push_back(g);
        }
      }
      std::array<double, 3> expected = geo[s].normal;
      const double l = std::sqrt(sum[0] * sum[0] + sum[1] * sum[1] + sum[2] * sum[2]);
      if(queue.size() > 1 && l > 0)
        for(int k = 0; k < 3; ++k) expected[k] = sum[k] / l;
      if(smoothed[s].normal == expected) ++same;
      if(expected != geo[s].normal) ++changed;
    }
    BOOST_TEST_MESSAGE(name << ": " << changed << " of " << geo.size() << " normals smoothed");
    BOOST_TEST(changed > geo.size() / 2);
    BOOST_TEST(same == geo.size());
  }
}

BOOST_AUTO_TEST_CASE_TEMPLATE(wedges_from_the_corner_table_are_the_walked_ones, Mesh, Mesh_types)
{
  // a trial groups the corners of its faces into wedges from a table of the
  // mesh's corners: the same wedges, numbered the same, as walking the mesh,
  // for sets of faces with holes, pinched vertices and cuts inside
  typedef boost::graph_traits<Mesh> GT;
  Mesh tm;
  BOOST_REQUIRE(build(torus(24, 16), tm));
  const auto fim = CGAL::get_initialized_face_index_map(tm, CGAL::parameters::default_values());
  const auto him = CGAL::get_initialized_halfedge_index_map(tm, CGAL::parameters::default_values());
  const QD::internal::Corner_table<Mesh> table(tm, fim);
  std::vector<long> local(num_faces(tm), -1);
  std::size_t compared = 0, cut_open = 0;
  for(std::size_t modulus : {2, 3, 5, 1000}) {
    std::vector<typename GT::face_descriptor> set;
    for(auto f : faces(tm))
      if(get(fim, f) % modulus != 1) set.push_back(f);
    std::sort(set.begin(), set.end(), [&](auto x, auto y) { return get(fim, x) < get(fim, y); });
    std::fill(local.begin(), local.end(), -1);
    for(std::size_t i = 0; i < set.size(); ++i) local[get(fim, set[i])] = static_cast<long>(i);
    for(std::size_t cut_every : {7, 1000000}) {
      const auto is_cut = [&](typename GT::halfedge_descriptor h) {
        return (std::min)(get(him, h), get(him, opposite(h, tm))) % cut_every == 0;
      };
      QD::internal::Wedges<Mesh> walked, read;
      QD::internal::compute_wedges(tm, fim, set, local, is_cut, walked);
      QD::internal::compute_wedges(table, tm, fim, set, local, is_cut, read);
      BOOST_TEST(walked.wedge_of_corner == read.wedge_of_corner);
      BOOST_TEST((walked.vertex_of_wedge == read.vertex_of_wedge));
      if(walked.size() > num_vertices(tm)) ++cut_open;
      ++compared;
    }
  }
  BOOST_TEST(compared == 8u);
  BOOST_TEST(cut_open > 0u);  // some sets are cut open into more wedges than vertices
}

BOOST_AUTO_TEST_CASE(parallel_loops_run_every_task_once_dearest_first)
{
  // the segmentation's tasks go out from the dearest to the cheapest (ties in index order)
  BOOST_TEST((QD::internal::dearest_first(std::vector<std::size_t>{3, 1, 3, 7, 2}) ==
              std::vector<std::size_t>{3, 0, 2, 4, 1}));
  BOOST_TEST(QD::internal::dearest_first(std::vector<double>{}).empty());
  // every index run exactly once, whatever the number of tasks and threads
  for(std::size_t n : {0, 1, 2, 3, 7, 1000}) {
    std::vector<std::atomic<int>> runs(n);
    for(std::atomic<int>& r : runs) r = 0;
    QD::internal::for_each_index<CGAL::Parallel_tag>(n, [&](std::size_t i) { ++runs[i]; });
    std::size_t once = 0;
    for(const std::atomic<int>& r : runs) once += r.load() == 1 ? 1 : 0;
    BOOST_TEST(once == n, n << " tasks");
  }
#ifdef CGAL_LINKED_WITH_TBB
  // with one thread, in the order given
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
  std::vector<std::size_t> order;
  QD::internal::for_each_index<CGAL::Parallel_tag>(5, [&](std::size_t i) { order.push_back(i); });
  BOOST_TEST((order == std::vector<std::size_t>{0, 1, 2, 3, 4}));
#endif
}

// The full series of doc/segmentation_results.md, too slow for every run:
// elephant and bunny00 from a quarter of their faces to subdivided twice
// (89K and 1.2M faces). Run it by name:
//   test_segmentation --run_test=vsa_resolution_series --log_level=message [-- OUT_DIR]
// With OUT_DIR, every version of the meshes is written there as OFF.
BOOST_AUTO_TEST_CASE(vsa_resolution_series, *boost::unit_test::disabled())
{
  const auto& suite = boost::unit_test::framework::master_test_suite();
  const std::string out_dir = suite.argc > 1 ? suite.argv[1] : "";
  BOOST_TEST_MESSAGE("| mesh | resolution | faces | VSA charts | tolerance reached | max error | VSA ms |");
  for(const auto& series : std::vector<std::pair<std::string, std::vector<int>>>{{"elephant", {-2, -1, 0, 1, 2}},
                                                                                 {"bunny00", {-2, -1, 0, 1, 2}}}) {
    const Series_mesh original = read_demo_mesh(series.first);
    std::vector<Series_row> rows;
    for(int level : series.second) rows.push_back(segment_at_resolution(series.first, original, level, out_dir));
    expect_counts_within_15_percent(rows);
  }
}
#endif

// ===================================================================== seam zigzag and compactness
// segmentation_measures.h on analytic cases

namespace seam_measures_tests {
namespace tt = boost::test_tools;
BOOST_AUTO_TEST_SUITE(seam_measures)

namespace {

template <class Mesh>
using Face_map = std::map<typename boost::graph_traits<Mesh>::face_descriptor, std::size_t>;
template <class Mesh>
using Edge_set = std::set<typename boost::graph_traits<Mesh>::edge_descriptor>;

// the vertices of a mesh built from a soup, in the order of the soup's points
template <class Mesh>
std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor> vertex_list(const Mesh& tm)
{
  return {vertices(tm).begin(), vertices(tm).end()};
}

// the edges between consecutive grid points (i, j) of a (nx x ny)-cell grid
template <class Mesh>
std::vector<typename boost::graph_traits<Mesh>::edge_descriptor> grid_path(
    const Mesh& tm, std::size_t nx, const std::vector<std::pair<std::size_t, std::size_t>>& points)
{
  const auto vs = vertex_list(tm);
  std::vector<typename boost::graph_traits<Mesh>::edge_descriptor> path;
  for(std::size_t k = 0; k + 1 < points.size(); ++k) {
    const auto a = vs[points[k].second * (nx + 1) + points[k].first];
    const auto b = vs[points[k + 1].second * (nx + 1) + points[k + 1].first];
    const auto h = halfedge(a, b, tm);
    BOOST_REQUIRE(h.second);
    path.push_back(edge(h.first, tm));
  }
  return path;
}

std::vector<std::pair<std::size_t, std::size_t>> straight(std::size_t i0, std::size_t j0, std::size_t i1,
                                                          std::size_t j1)
{
  std::vector<std::pair<std::size_t, std::size_t>> p;
  const std::size_t n = (std::max)(i1 > i0 ? i1 - i0 : i0 - i1, j1 > j0 ? j1 - j0 : j0 - j1);
  for(std::size_t k = 0; k <= n; ++k)
    p.push_back({i0 + (i1 > i0 ? k : 0) - (i1 < i0 ? k : 0), j0 + (j1 > j0 ? k : 0) - (j1 < j0 ? k : 0)});
  return p;
}

// (i0, j0), (i0 + 1, j0), (i0 + 1, j0 + 1), (i0 + 2, j0 + 1), ...: `steps` steps
std::vector<std::pair<std::size_t, std::size_t>> staircase(std::size_t i0, std::size_t j0, std::size_t steps)
{
  std::vector<std::pair<std::size_t, std::size_t>> p{{i0, j0}};
  for(std::size_t k = 0; k < steps; ++k) {
    p.push_back({i0 + k + 1, j0 + k});
    p.push_back({i0 + k + 1, j0 + k + 1});
  }
  return p;
}

Soup flat_grid(std::size_t nx, std::size_t ny, double sx = 1, double sy = 1)
{
  return grid(nx, ny, [=](double u, double v) { return P3{sx * u, sy * v, 0.}; });
}

} // namespace

// ===================================================================== seam zigzag

BOOST_AUTO_TEST_CASE_TEMPLATE(straight_seam_has_no_zigzag, Mesh, Mesh_types)
{
  const Mesh tm = make<Mesh>(flat_grid(12, 12));
  const auto seams = grid_path(tm, 12, straight(0, 5, 12, 5));
  const QD::Seam_zigzag z = QD::seam_zigzag(tm, seams);
  BOOST_TEST(z.number_of_curves == 1u);
  BOOST_TEST(z.length == 1.0, tt::tolerance(1e-12));
  BOOST_TEST(z.zigzag == 1.0, tt::tolerance(1e-12));
  BOOST_TEST(z.curve_zigzag.at(0) == 1.0, tt::tolerance(1e-12));
  BOOST_TEST(!z.curve_is_closed.at(0));
  // repeated edges are ignored
  std::vector<typename boost::graph_traits<Mesh>::edge_descriptor> twice = seams;
  twice.insert(twice.end(), seams.begin(), seams.end());
  BOOST_TEST(QD::seam_zigzag(tm, twice).length == 1.0, tt::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE_TEMPLATE(staircase_seam_zigzags, Mesh, Mesh_types)
{
  const Mesh tm = make<Mesh>(flat_grid(12, 12));
  const QD::Seam_zigzag z = QD::seam_zigzag(tm, grid_path(tm, 12, staircase(0, 0, 12)));
  BOOST_TEST(z.number_of_curves == 1u);
  BOOST_TEST(z.length == 2.0, tt::tolerance(1e-12));
  BOOST_TEST(z.zigzag > 1.1);
  BOOST_TEST(z.zigzag < std::sqrt(2.) + 1e-9);  // the smoothed curve is no shorter than the diagonal
  // no smoothing round: no zigzag measured
  BOOST_TEST(QD::seam_zigzag(tm, grid_path(tm, 12, staircase(0, 0, 12)), CGAL::parameters::number_of_iterations(0))
                 .zigzag == 1.0);
  // more rounds straighten more
  BOOST_TEST(QD::seam_zigzag(tm, grid_path(tm, 12, staircase(0, 0, 12)), CGAL::parameters::number_of_iterations(60))
                 .zigzag > z.zigzag);
}

BOOST_AUTO_TEST_CASE_TEMPLATE(closed_loop_shrinks_like_a_regular_polygon, Mesh, Mesh_types)
{
  // ring 3 of a polar patch is a regular 32-gon: smoothing scales it by
  // lambda = 1 - (1 - cos(2 pi / 32)) / 2 per round
  const std::size_t rings = 5, sectors = 32;
  const Mesh tm = make<Mesh>(polar(rings, sectors, flat_disk(1.)));
  const auto vs = vertex_list(tm);
  std::vector<typename boost::graph_traits<Mesh>::edge_descriptor> loop;
  const std::size_t r = 3;
  for(std::size_t k = 0; k < sectors; ++k) {
    const auto h = halfedge(vs[1 + (r - 1) * sectors + k], vs[1 + (r - 1) * sectors + (k + 1) % sectors], tm);
    BOOST_REQUIRE(h.second);
    loop.push_back(edge(h.first, tm));
  }
  const QD::Seam_zigzag z = QD::seam_zigzag(tm, loop);
  BOOST_TEST(z.number_of_curves == 1u);
  BOOST_TEST(z.curve_is_closed.at(0));
  const double lambda = 1 - 0.5 * (1 - std::cos(2 * pi / sectors));
  BOOST_TEST(z.zigzag == 1 / std::pow(lambda, 20), tt::tolerance(1e-9));
  BOOST_TEST(QD::seam_zigzag(tm, loop, CGAL::parameters::number_of_iterations(5)).zigzag == 1 / std::pow(lambda, 5),
             tt::tolerance(1e-9));
}

BOOST_AUTO_TEST_CASE_TEMPLATE(junctions_end_curves, Mesh, Mesh_types)
{
  const Mesh tm = make<Mesh>(flat_grid(12, 12));
  // a cross: four straight arms meeting at (6, 6), plus a staircase from (6, 6)
  // would make it five; first the cross alone
  std::vector<typename boost::graph_traits<Mesh>::edge_descriptor> seams;
  for(const auto& path : {straight(0, 6, 12, 6), straight(6, 0, 6, 12)}) {
    const auto p = grid_path(tm, 12, path);
    seams.insert(seams.end(), p.begin(), p.end());
  }
  QD::Seam_zigzag z = QD::seam_zigzag(tm, seams);
  BOOST_TEST(z.number_of_curves == 4u);
  for(double l : z.curve_length) BOOST_TEST(l == 0.5, tt::tolerance(1e-12));
  BOOST_TEST(z.zigzag == 1.0, tt::tolerance(1e-12));
  // a T: the staircase branch is its own curve, the straight ones keep Z = 1
  seams = grid_path(tm, 12, straight(0, 3, 12, 3));
  for(const auto& path : {straight(4, 3, 4, 4), staircase(4, 4, 5)}) {
    const auto p = grid_path(tm, 12, path);
    seams.insert(seams.end(), p.begin(), p.end());
  }
  z = QD::seam_zigzag(tm, seams);
  BOOST_REQUIRE(z.number_of_curves == 3u);
  std::size_t zigzagging = 0;
  for(std::size_t c = 0; c < 3; ++c) {
    if(z.curve_zigzag[c] > 1.1) {
      ++zigzagging;
      BOOST_TEST(z.curve_length[c] == 11. / 12, tt::tolerance(1e-12));
    }
    else
      BOOST_TEST(z.curve_zigzag[c] == 1.0, tt::tolerance(1e-12));
  }
  BOOST_TEST(zigzagging == 1u);
  BOOST_TEST(z.zigzag == z.length / z.smoothed_length);
  BOOST_TEST(z.zigzag > 1.0);
  // no seams: no curve, Z = 1
  z = QD::seam_zigzag(tm, std::vector<typename boost::graph_traits<Mesh>::edge_descriptor>());
  BOOST_TEST(z.number_of_curves == 0u);
  BOOST_TEST(z.zigzag == 1.0);
}

// ===================================================================== chart compactness

BOOST_AUTO_TEST_CASE_TEMPLATE(flat_disk_is_compact, Mesh, Mesh_types)
{
  const Mesh tm = make<Mesh>(polar(8, 64, flat_disk(2.)));
  Face_map<Mesh> chart;
  for(auto f : faces(tm)) chart[f] = 7;
  const QD::Chart_compactness c = QD::chart_compactness(tm, boost::make_assoc_property_map(chart));
  BOOST_REQUIRE(c.number_of_charts == 1u);
  BOOST_TEST(c.chart_id.at(0) == 7u);
  BOOST_TEST(c.area.at(0) == 4 * pi, tt::tolerance(0.01));
  BOOST_TEST(c.perimeter.at(0) == 4 * pi, tt::tolerance(0.01));
  BOOST_TEST(c.chart_compactness.at(0) == 1.0, tt::tolerance(0.02));
  BOOST_TEST(c.chart_compactness.at(0) <= 1.0);  // a flat polygon never beats a disk
  BOOST_TEST(c.compactness == c.chart_compactness.at(0));
}

BOOST_AUTO_TEST_CASE_TEMPLATE(strip_is_not_compact, Mesh, Mesh_types)
{
  const Mesh tm = make<Mesh>(flat_grid(40, 4, 10., 1.));
  Face_map<Mesh> chart;
  for(auto f : faces(tm)) chart[f] = 0;
  const QD::Chart_compactness c = QD::chart_compactness(tm, boost::make_assoc_property_map(chart));
  BOOST_REQUIRE(c.number_of_charts == 1u);
  BOOST_TEST(c.area.at(0) == 10.0, tt::tolerance(1e-12));
  BOOST_TEST(c.perimeter.at(0) == 22.0, tt::tolerance(1e-12));
  BOOST_TEST(c.compactness == 4 * pi * 10 / (22. * 22.), tt::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE_TEMPLATE(borders_between_charts_and_slits, Mesh, Mesh_types)
{
  // a 2 x 1 rectangle: the left square is chart 0, the right one chart 1
  const std::size_t n = 8;
  const Mesh tm = make<Mesh>(flat_grid(2 * n, n, 2., 1.));
  Face_map<Mesh> chart;
  for(auto f : faces(tm)) {
    double x = 0;
    for(auto v : vertices_around_face(halfedge(f, tm), tm)) x += p3(tm, v)[0] / 3;
    chart[f] = x < 1 ? 0 : 1;
  }
  QD::Chart_compactness c = QD::chart_compactness(tm, boost::make_assoc_property_map(chart));
  BOOST_REQUIRE(c.number_of_charts == 2u);
  for(std::size_t k = 0; k < 2; ++k) {
    BOOST_TEST(c.area[k] == 1.0, tt::tolerance(1e-12));
    BOOST_TEST(c.perimeter[k] == 4.0, tt::tolerance(1e-12));  // the shared side counts for both
    BOOST_TEST(c.chart_compactness[k] == pi / 4, tt::tolerance(1e-12));
  }
  BOOST_TEST(c.compactness == pi / 4, tt::tolerance(1e-12));

  // a slit inside chart 0, from the middle of its bottom side to its centre,
  // counts twice; constraining the border between the charts changes nothing
  Edge_set<Mesh> cut;
  for(auto e : grid_path(tm, 2 * n, straight(n / 2, 0, n / 2, n / 2))) cut.insert(e);
  for(auto e : grid_path(tm, 2 * n, straight(n, 0, n, n))) cut.insert(e);
  const auto constrained = boost::make_function_property_map<typename boost::graph_traits<Mesh>::edge_descriptor>(
      [&](typename boost::graph_traits<Mesh>::edge_descriptor e) { return cut.count(e) > 0; });
  c = QD::chart_compactness(tm, boost::make_assoc_property_map(chart),
                            CGAL::parameters::edge_is_constrained_map(constrained));
  BOOST_TEST(c.perimeter[0] == 5.0, tt::tolerance(1e-12));
  BOOST_TEST(c.perimeter[1] == 4.0, tt::tolerance(1e-12));
  BOOST_TEST(c.chart_compactness[0] == 4 * pi / 25, tt::tolerance(1e-12));
  BOOST_TEST(c.compactness == (4 * pi / 25 + pi / 4) / 2, tt::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE_TEMPLATE(border_curves_are_the_connected_chains_between_two_charts, Mesh, Mesh_types)
{
  // a 3 x 1 rectangle: chart 0 on both outer thirds, the middle third cut in
  // chart 1 below y = 1/2 and chart 2 above. Charts 0 and 1 meet along two
  // separate segments (x = 1 and x = 2, below the middle), as do 0 and 2
  // above it; 1 and 2 along y = 1/2.
  typedef typename boost::graph_traits<Mesh>::halfedge_descriptor halfedge_descriptor;
  const std::size_t n = 8;
  const Mesh tm = make<Mesh>(flat_grid(3 * n, n, 3., 1.));
  Face_map<Mesh> chart;
  for(auto f : faces(tm)) {
    double c[2] = {0., 0.};
    for(auto v : vertices_around_face(halfedge(f, tm), tm))
      for(int k = 0; k < 2; ++k) c[k] += p3(tm, v)[k] / 3;
    chart[f] = c[0] < 1 || c[0] > 2 ? 0 : c[1] < 0.5 ? 1 : 2;
  }
  const auto him = CGAL::get_initialized_halfedge_index_map(tm, CGAL::parameters::default_values());
  auto chart_of = [&](halfedge_descriptor h) { return chart.at(face(h, tm)); };
  auto length = [&](halfedge_descriptor h) {
    const P3 p = p3(tm, source(h, tm)), q = p3(tm, target(h, tm));
    return std::hypot(q[0] - p[0], q[1] - p[1]);
  };
  std::vector<long> curve_of;
  const auto curves = QD::internal::chart_border_curves(tm, him, chart_of, length, curve_of);
  BOOST_REQUIRE(curves.size() == 5u);
  std::map<std::pair<std::size_t, std::size_t>, std::vector<double>> by_pair;  // the lengths of the pair's curves
  std::size_t on_curves = 0;
  for(std::size_t c = 0; c < curves.size(); ++c) {
    BOOST_TEST(curves[c].a < curves[c].b);
    double sum = 0;
    std::set<std::size_t> xs;  // the x of every edge's vertices, times n
    for(halfedge_descriptor h : curves[c].halfedges) {
      BOOST_TEST(chart_of(h) == curves[c].a);
      BOOST_TEST(chart_of(opposite(h, tm)) == curves[c].b);
      BOOST_TEST(curve_of[get(him, h)] == long(c));
      BOOST_TEST(curve_of[get(him, opposite(h, tm))] == long(c));
      sum += length(h);
      for(auto v : {source(h, tm), target(h, tm)}) xs.insert(std::size_t(std::lround(p3(tm, v)[0] * n)));
    }
    BOOST_TEST(curves[c].length == sum, tt::tolerance(1e-12));
    on_curves += 2 * curves[c].halfedges.size();
    by_pair[{curves[c].a, curves[c].b}].push_back(curves[c].length);
    if(curves[c].b != 2 || curves[c].a != 1) BOOST_TEST(xs.size() == 1u);  // one of the vertical segments
  }
  BOOST_TEST(by_pair.size() == 3u);
  for(const auto& pair : {std::make_pair(std::size_t(0), std::size_t(1)), std::make_pair(std::size_t(0), std::size_t(2))}) {
    BOOST_REQUIRE(by_pair[pair].size() == 2u);
    for(double l : by_pair[pair]) BOOST_TEST(l == 0.5, tt::tolerance(1e-12));
  }
  BOOST_REQUIRE(by_pair[std::make_pair(std::size_t(1), std::size_t(2))].size() == 1u);
  BOOST_TEST(by_pair[std::make_pair(std::size_t(1), std::size_t(2))][0] == 1.0, tt::tolerance(1e-12));
  // every other halfedge is on no curve
  std::size_t marked = 0;
  for(long c : curve_of) marked += c >= 0 ? 1 : 0;
  BOOST_TEST(marked == on_curves);
  BOOST_TEST(on_curves == 2 * (4 * (n / 2) + n));
}


// ===================================================================== smooth borders, flatten given charts

namespace {

// a flat unit square cut by the staircase from (0, 0) to (1, 1): chart 1 below it, chart 0 above
template <class Mesh>
Face_map<Mesh> staircase_charts(const Mesh& tm, std::size_t n)
{
  Face_map<Mesh> chart;
  for(auto f : faces(tm)) {
    double c[2] = {0., 0.};
    for(auto v : vertices_around_face(halfedge(f, tm), tm))
      for(int k = 0; k < 2; ++k) c[k] += p3(tm, v)[k] / 3;
    chart[f] = std::floor(c[0] * n) > std::floor(c[1] * n) ? 1 : 0;
  }
  return chart;
}

template <class Mesh>
std::vector<typename boost::graph_traits<Mesh>::edge_descriptor> chart_borders(const Mesh& tm,
                                                                               const Face_map<Mesh>& chart)
{
  std::vector<typename boost::graph_traits<Mesh>::edge_descriptor> out;
  for(auto e : edges(tm)) {
    const auto h = halfedge(e, tm);
    if(!is_border_edge(h, tm) && chart.at(face(h, tm)) != chart.at(face(opposite(h, tm), tm))) out.push_back(e);
  }
  return out;
}

template <class Mesh>
double chart_area(const Mesh& tm, const Face_map<Mesh>& chart, std::size_t k)
{
  double a = 0;
  for(auto f : faces(tm))
    if(chart.at(f) == k) {
      const auto h = halfedge(f, tm);
      const P3 p = p3(tm, source(h, tm)), q = p3(tm, target(h, tm)), r = p3(tm, target(next(h, tm), tm));
      a += 0.5 * std::abs((q[0] - p[0]) * (r[1] - p[1]) - (r[0] - p[0]) * (q[1] - p[1]));
    }
  return a;
}

} // namespace

BOOST_AUTO_TEST_CASE_TEMPLATE(staircase_border_is_cut_smooth_through_the_triangles, Mesh, Mesh_types)
{
  const std::size_t n = 12;
  Mesh tm = make<Mesh>(flat_grid(n, n));
  Face_map<Mesh> chart = staircase_charts(tm, n);
  const double before = QD::seam_zigzag(tm, chart_borders(tm, chart)).zigzag;
  BOOST_REQUIRE(before > 1.1);
  const std::size_t faces_before = num_faces(tm);
  const QD::Boundary_smoothing_result r = QD::smooth_chart_boundaries(tm, boost::make_assoc_property_map(chart));
  BOOST_REQUIRE(r);
  BOOST_TEST(r.number_of_curves == 1u);
  BOOST_TEST(r.curves_smoothed == 1u);
  BOOST_TEST(r.zigzag_before == before, tt::tolerance(1e-12));
  BOOST_TEST(r.zigzag_after < 1.02);
  BOOST_TEST(r.vertices_added > 0u);
  BOOST_TEST(num_faces(tm) == faces_before + r.faces_added);
  BOOST_TEST(CGAL::is_valid_polygon_mesh(tm));
  BOOST_TEST(CGAL::is_triangle_mesh(tm));
  // the border measured on the refined mesh; it moved by less than the band
  BOOST_TEST(QD::seam_zigzag(tm, chart_borders(tm, chart)).zigzag == r.zigzag_after, tt::tolerance(1e-12));
  BOOST_TEST(r.max_border_move < 3.5 / n);
  // every face has a chart, both charts are connected and keep the same area
  expect_valid_charts(tm, chart, 2);
  BOOST_TEST(chart_area(tm, chart, 0) + chart_area(tm, chart, 1) == 1.0, tt::tolerance(1e-12));
  // the staircase gave chart 0 78 of the 144 cells; the smooth curve runs along the staircase's middle
  BOOST_TEST(std::abs(chart_area(tm, chart, 0) - 78. / 144) < 0.5 / n);
  // every new face is a real triangle
  for(auto f : faces(tm)) {
    const auto h = halfedge(f, tm);
    const P3 p = p3(tm, source(h, tm)), q = p3(tm, target(h, tm)), s = p3(tm, target(next(h, tm), tm));
    BOOST_TEST(std::abs((q[0] - p[0]) * (s[1] - p[1]) - (s[0] - p[0]) * (q[1] - p[1])) > 1e-6 / (n * n));
  }
  // the two flat charts flatten without distortion, and the seam's sides match
  const QD::Chart_flattening_result<Mesh> f = QD::flatten_charts(tm, boost::make_assoc_property_map(chart));
  BOOST_REQUIRE(f);
  BOOST_TEST(f.number_of_charts == 2u);
  BOOST_TEST(f.rejected_charts == 0u);
  BOOST_TEST(f.max_area_distortion < 1e-6);
  BOOST_TEST(f.max_seam_length_mismatch < 1e-6);
  BOOST_TEST(f.seam_zigzag == r.zigzag_after, tt::tolerance(1e-12));
  BOOST_TEST(f.corner_uv.size() == 3 * num_faces(tm));
}

// With CGAL::Parallel_tag the smoothing computes phi, the charts' topology
// and the move of every curve on several threads: the same mesh, charts and
// counts as one thread, on elephant's charts of step 1 (many curves)
BOOST_AUTO_TEST_CASE(parallel_border_smoothing_is_the_sequential_one)
{
  Surface_mesh one;
  BOOST_REQUIRE(CGAL::IO::read_polygon_mesh(std::string(CGAL_QD_DEMO_MESH_DIR) + "/elephant.off", one));
  auto chart_one = one.add_property_map<Surface_mesh::Face_index, std::size_t>("f:chart", 0).first;
  BOOST_REQUIRE(QD::segment_by_error_controlled_vsa(one, chart_one));
  Surface_mesh two = one;
  auto chart_two = two.property_map<Surface_mesh::Face_index, std::size_t>("f:chart").first;
  const QD::Boundary_smoothing_result a = QD::smooth_chart_boundaries<CGAL::Sequential_tag>(one, chart_one);
  const QD::Boundary_smoothing_result b = QD::smooth_chart_boundaries<CGAL::Parallel_tag>(two, chart_two);
  BOOST_REQUIRE(a);
  BOOST_REQUIRE(b);
  BOOST_TEST(a.curves_smoothed > 10u);
  BOOST_TEST(a.curves_smoothed == b.curves_smoothed);
  BOOST_TEST(a.curves_failed == b.curves_failed);
  BOOST_TEST(a.max_border_move == b.max_border_move);
  BOOST_TEST(a.zigzag_after == b.zigzag_after);
  BOOST_REQUIRE(num_vertices(one) == num_vertices(two));
  BOOST_REQUIRE(num_faces(one) == num_faces(two));
  std::size_t different = 0;
  for(auto v : vertices(one)) different += one.point(v) == two.point(v) ? 0 : 1;
  for(auto f : faces(one)) different += chart_one[f] == chart_two[f] ? 0 : 1;
  BOOST_TEST(different == 0u);
}

BOOST_AUTO_TEST_CASE_TEMPLATE(constrained_and_smooth_borders_stay, Mesh, Mesh_types)
{
  const std::size_t n = 12;
  Mesh tm = make<Mesh>(flat_grid(n, n));
  Face_map<Mesh> chart = staircase_charts(tm, n);
  // the constrained map is written to (the halves of a split constrained edge stay constrained)
  std::map<typename boost::graph_traits<Mesh>::edge_descriptor, bool> kept;
  for(auto e : edges(tm)) kept[e] = false;
  for(auto e : chart_borders(tm, chart)) kept[e] = true;
  const auto constrained = boost::make_assoc_property_map(kept);
  const std::size_t faces_before = num_faces(tm);
  QD::Boundary_smoothing_result r = QD::smooth_chart_boundaries(tm, boost::make_assoc_property_map(chart),
                                                                CGAL::parameters::edge_is_constrained_map(constrained));
  BOOST_REQUIRE(r);
  BOOST_TEST(r.curves_smoothed == 0u);
  BOOST_TEST(r.vertices_added == 0u);
  BOOST_TEST(num_faces(tm) == faces_before);
  // a straight border is left as it is
  Mesh flat = make<Mesh>(flat_grid(n, n));
  Face_map<Mesh> halves;
  for(auto f : faces(flat)) {
    double x = 0;
    for(auto v : vertices_around_face(halfedge(f, flat), flat)) x += p3(flat, v)[0] / 3;
    halves[f] = x < 0.5 ? 0 : 1;
  }
  r = QD::smooth_chart_boundaries(flat, boost::make_assoc_property_map(halves));
  BOOST_REQUIRE(r);
  BOOST_TEST(r.curves_already_smooth == 1u);
  BOOST_TEST(num_faces(flat) == faces_before);
}

BOOST_AUTO_TEST_CASE_TEMPLATE(chart_in_two_parts_of_different_topology_is_smoothed_on_both, Mesh, Mesh_types)
{
  // chart 0 in two parts along the diagonal, each with a staircase border to
  // chart 1 between them; the upper-left part holds chart 2 as an island, so
  // it is a ring while the lower-right part is a disc. The smoothing measures
  // a chart's topology once only where it holds the chart whole: both
  // staircases are smoothed, whichever part comes first.
  const std::size_t n = 24;
  Mesh tm = make<Mesh>(flat_grid(n, n));
  Face_map<Mesh> chart;
  for(auto f : faces(tm)) {
    double c[2] = {0., 0.};
    for(auto v : vertices_around_face(halfedge(f, tm), tm))
      for(int k = 0; k < 2; ++k) c[k] += p3(tm, v)[k] / 3;
    const double d = std::floor(c[0] * n) - std::floor(c[1] * n);
    chart[f] = std::abs(d) <= 3 ? 1 : 0;
    if(c[0] > 0.1 && c[0] < 0.25 && c[1] > 0.7 && c[1] < 0.85) chart[f] = 2;
  }
  auto zigzag_between = [&](std::size_t a, std::size_t b) {
    std::vector<typename boost::graph_traits<Mesh>::edge_descriptor> between;
    for(auto e : chart_borders(tm, chart)) {
      const auto h = halfedge(e, tm);
      const std::set<std::size_t> sides = {chart.at(face(h, tm)), chart.at(face(opposite(h, tm), tm))};
      if(sides == std::set<std::size_t>{a, b}) between.push_back(e);
    }
    return QD::seam_zigzag(tm, between).zigzag;
  };
  BOOST_REQUIRE(zigzag_between(0, 1) > 1.1);
  const QD::Boundary_smoothing_result r = QD::smooth_chart_boundaries(tm, boost::make_assoc_property_map(chart));
  BOOST_REQUIRE(r);
  BOOST_TEST(r.number_of_curves >= 3u);
  BOOST_TEST(r.curves_failed == 0u);
  BOOST_TEST(r.curves_smoothed == r.number_of_curves);
  BOOST_TEST(zigzag_between(0, 1) < 1.03);
  BOOST_TEST(CGAL::is_valid_polygon_mesh(tm));
  // the island is still one chart inside the ring, and chart 1 still one strip
  for(std::size_t k : {1u, 2u}) {
    std::set<typename boost::graph_traits<Mesh>::face_descriptor> part;
    std::vector<typename boost::graph_traits<Mesh>::face_descriptor> queue;
    std::size_t total = 0;
    for(auto f : faces(tm))
      if(chart.at(f) == k && total++ == 0) queue.push_back(f), part.insert(f);
    for(std::size_t q = 0; q < queue.size(); ++q)
      for(auto h : CGAL::halfedges_around_face(halfedge(queue[q], tm), tm)) {
        const auto o = opposite(h, tm);
        if(!is_border(o, tm) && chart.at(face(o, tm)) == k && part.insert(face(o, tm)).second)
          queue.push_back(face(o, tm));
      }
    BOOST_TEST(part.size() == total);
  }
}

BOOST_AUTO_TEST_CASE_TEMPLATE(staircase_cut_inside_a_chart_is_cut_smooth, Mesh, Mesh_types)
{
  // one chart with a staircase slit from a corner of the grid to its middle
  const std::size_t n = 12;
  Mesh tm = make<Mesh>(flat_grid(n, n));
  const Face_map<Mesh> stairs = staircase_charts(tm, n);
  Face_map<Mesh> chart;
  for(auto f : faces(tm)) chart[f] = 7;
  typedef typename boost::graph_traits<Mesh>::edge_descriptor edge_descriptor;
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  std::map<edge_descriptor, bool> cut;
  for(auto e : edges(tm)) cut[e] = false;
  for(auto e : chart_borders(tm, stairs)) {
    const P3 p = p3(tm, source(halfedge(e, tm), tm)), q = p3(tm, target(halfedge(e, tm), tm));
    if(p[0] + p[1] < 1.0 + 1e-9 && q[0] + q[1] < 1.0 + 1e-9) cut[e] = true;
  }
  auto cut_edges = [&]() {
    std::vector<edge_descriptor> out;
    for(const auto& ec : cut)
      if(ec.second) out.push_back(ec.first);
    return out;
  };
  // the free end of the slit, and its other end on the mesh border
  auto ends = [&]() {
    std::map<vertex_descriptor, int> degree;
    for(auto e : cut_edges()) {
      ++degree[source(halfedge(e, tm), tm)];
      ++degree[target(halfedge(e, tm), tm)];
    }
    std::vector<P3> out;
    for(const auto& vd : degree) {
      BOOST_TEST((vd.second == 1 || vd.second == 2));
      if(vd.second == 1) out.push_back(p3(tm, vd.first));
    }
    std::sort(out.begin(), out.end());
    return out;
  };
  const std::vector<P3> ends_before = ends();
  BOOST_REQUIRE(ends_before.size() == 2u);
  const double before = QD::seam_zigzag(tm, cut_edges()).zigzag;
  BOOST_REQUIRE(before > 1.1);
  const std::size_t faces_before = num_faces(tm);
  const QD::Boundary_smoothing_result r =
      QD::smooth_chart_cuts(tm, boost::make_assoc_property_map(chart), boost::make_assoc_property_map(cut));
  BOOST_REQUIRE(r);
  BOOST_TEST(r.number_of_curves == 1u);
  BOOST_TEST(r.curves_smoothed == 1u);
  BOOST_TEST(r.zigzag_before == before, tt::tolerance(1e-12));
  BOOST_TEST(r.zigzag_after < 1.03);
  BOOST_TEST(QD::seam_zigzag(tm, cut_edges()).zigzag == r.zigzag_after, tt::tolerance(1e-12));
  BOOST_TEST(num_faces(tm) == faces_before + r.faces_added);
  BOOST_TEST(r.max_border_move < 3.5 / n);
  BOOST_TEST(CGAL::is_valid_polygon_mesh(tm));
  BOOST_TEST(CGAL::is_triangle_mesh(tm));
  // the slit keeps its ends, is one chain of edges, and every face keeps its chart
  BOOST_TEST(ends() == ends_before);
  for(auto f : faces(tm)) BOOST_TEST(chart[f] == 7u);
  // the chart with its slit flattens without distortion, and the slit's two sides match
  const QD::Chart_flattening_result<Mesh> f = QD::flatten_charts(
      tm, boost::make_assoc_property_map(chart),
      CGAL::parameters::edge_is_constrained_map(boost::make_assoc_property_map(cut)));
  BOOST_REQUIRE(f);
  BOOST_TEST(f.number_of_charts == 1u);
  BOOST_TEST(f.rejected_charts == 0u);
  BOOST_TEST(f.max_area_distortion < 1e-6);
  BOOST_TEST(f.max_seam_length_mismatch < 1e-6);
  BOOST_TEST(f.seam_zigzag == r.zigzag_after, tt::tolerance(1e-12));
  // a second call leaves the smooth slit alone
  const QD::Boundary_smoothing_result again =
      QD::smooth_chart_cuts(tm, boost::make_assoc_property_map(chart), boost::make_assoc_property_map(cut));
  BOOST_REQUIRE(again);
  BOOST_TEST(again.curves_smoothed == 0u);
  BOOST_TEST(num_faces(tm) == faces_before + r.faces_added);
}

BOOST_AUTO_TEST_CASE(smoothing_and_flattening_reject_bad_input)
{
  Surface_mesh empty;
  Face_map<Surface_mesh> chart;
  BOOST_TEST(QD::smooth_chart_boundaries(empty, boost::make_assoc_property_map(chart)).status ==
             QD::Error_code::EMPTY_MESH);
  BOOST_TEST(QD::flatten_charts(empty, boost::make_assoc_property_map(chart)).status == QD::Error_code::EMPTY_MESH);
  std::map<Surface_mesh::Edge_index, bool> cut;
  BOOST_TEST(QD::smooth_chart_cuts(empty, boost::make_assoc_property_map(chart), boost::make_assoc_property_map(cut))
                 .status == QD::Error_code::EMPTY_MESH);
  // a quadrangle
  Surface_mesh quad;
  const auto q0 = quad.add_vertex(Surface_mesh::Point(0, 0, 0)), q1 = quad.add_vertex(Surface_mesh::Point(1, 0, 0)),
             q2 = quad.add_vertex(Surface_mesh::Point(1, 1, 0)), q3 = quad.add_vertex(Surface_mesh::Point(0, 1, 0));
  chart[quad.add_face(q0, q1, q2, q3)] = 0;
  BOOST_TEST(QD::smooth_chart_boundaries(quad, boost::make_assoc_property_map(chart)).status ==
             QD::Error_code::NOT_TRIANGLE_MESH);
  BOOST_TEST(QD::smooth_chart_cuts(quad, boost::make_assoc_property_map(chart), boost::make_assoc_property_map(cut))
                 .status == QD::Error_code::NOT_TRIANGLE_MESH);
  BOOST_TEST(num_faces(quad) == 1u);
  chart.clear();
  Surface_mesh bad = make<Surface_mesh>(flat_grid(4, 4));
  const auto v = *vertices(bad).begin();
  bad.point(v) = Surface_mesh::Point(std::nan(""), 0, 0);
  for(auto f : faces(bad)) chart[f] = 0;
  const std::size_t nf = num_faces(bad);
  BOOST_TEST(QD::smooth_chart_boundaries(bad, boost::make_assoc_property_map(chart)).status ==
             QD::Error_code::INVALID_COORDINATES);
  BOOST_TEST(num_faces(bad) == nf);  // nothing changed
  // cuts in the invalid mesh: refused, and left as they were
  for(auto e : edges(bad)) cut[e] = false;
  std::size_t cuts_before = 0;
  for(auto e : edges(bad))
    if(!is_border_edge(halfedge(e, bad), bad) && cuts_before < 3) {
      cut[e] = true;
      ++cuts_before;
    }
  BOOST_TEST(QD::smooth_chart_cuts(bad, boost::make_assoc_property_map(chart), boost::make_assoc_property_map(cut))
                 .status == QD::Error_code::INVALID_COORDINATES);
  BOOST_TEST(num_faces(bad) == nf);
  BOOST_TEST(std::count_if(cut.begin(), cut.end(), [](const auto& c) { return c.second; }) == long(cuts_before));
  BOOST_TEST(QD::flatten_charts(bad, boost::make_assoc_property_map(chart)).status ==
             QD::Error_code::INVALID_COORDINATES);
}

BOOST_AUTO_TEST_CASE(flatten_charts_repeats_the_segmentation_s_last_step)
{
  // the charts of a segmentation, flattened again, give the same measures
  const Surface_mesh tm = make<Surface_mesh>(grid(48, 12, cylinder(1.0, 1.9 * pi, 3.0)));
  Face_map<Surface_mesh> chart;
  const QD::Segmentation_result<Surface_mesh> s = QD::segment_quasi_developable(tm, boost::make_assoc_property_map(chart));
  BOOST_REQUIRE(s);
  Edge_set<Surface_mesh> cuts;
  for(auto e : s.seam_edges) {
    const auto h = halfedge(e, tm);
    if(chart.at(face(h, tm)) == chart.at(face(opposite(h, tm), tm))) cuts.insert(e);
  }
  const auto constrained = boost::make_function_property_map<Surface_mesh::Edge_index>(
      [&](Surface_mesh::Edge_index e) { return cuts.count(e) > 0; });
  const QD::Chart_flattening_result<Surface_mesh> f =
      QD::flatten_charts(tm, boost::make_assoc_property_map(chart), CGAL::parameters::edge_is_constrained_map(constrained));
  BOOST_REQUIRE(f);
  BOOST_TEST(f.number_of_charts == s.number_of_charts);
  BOOST_TEST(f.rejected_charts == 0u);
  BOOST_TEST(f.seam_edges.size() == s.seam_edges.size());
  BOOST_TEST(f.seam_length == s.seam_length, tt::tolerance(1e-9));
  BOOST_TEST(f.max_area_distortion == s.max_area_distortion, tt::tolerance(1e-9));
  BOOST_TEST(f.max_local_area_distortion == s.max_local_area_distortion, tt::tolerance(1e-9));
  BOOST_TEST(f.max_seam_length_mismatch == s.max_seam_length_mismatch, tt::tolerance(1e-9));
  BOOST_TEST(f.number_of_seam_curves == s.number_of_seam_curves);
  BOOST_TEST(f.seam_curves_matched == s.seam_curves_matched);
  BOOST_TEST(f.number_of_seam_curves - f.seam_curves_matched == f.unmatched_seams.size());
  BOOST_TEST(f.unmatched_seam_mismatch.size() == s.unmatched_seam_mismatch.size());
  BOOST_TEST(f.compactness == s.compactness, tt::tolerance(1e-12));
}

// The seam smoothing flattens every chart again at each try; the charts that
// a try leaves as they were are looked up in a cache (internal/flattening_cache.h)
// keyed by the chart cut open, the fit's targets and start, and the thresholds.
BOOST_AUTO_TEST_CASE(cached_flattenings_are_the_flattenings)
{
  const std::size_t n = 24;
  Surface_mesh tm = make<Surface_mesh>(grid(n, n, bump(0.3)));
  Face_map<Surface_mesh> chart;
  for(auto f : faces(tm)) {
    double x = 0;
    for(auto v : vertices_around_face(halfedge(f, tm), tm)) x += tm.point(v).x() / 3;
    chart[f] = static_cast<std::size_t>((std::min)(3., std::floor(4 * x)));
  }
  const auto chart_map = boost::make_assoc_property_map(chart);
  auto same = [](const QD::Chart_flattening_result<Surface_mesh>& a, const QD::Chart_flattening_result<Surface_mesh>& b) {
    BOOST_REQUIRE(a.charts.size() == b.charts.size());
    for(std::size_t k = 0; k < a.charts.size(); ++k) {
      BOOST_TEST(a.charts[k].accepted == b.charts[k].accepted);
      BOOST_TEST(a.charts[k].local_area_distortion == b.charts[k].local_area_distortion);
      BOOST_TEST(a.charts[k].lengths_matched == b.charts[k].lengths_matched);
    }
    BOOST_TEST(a.corner_uv == b.corner_uv);  // to the last bit
    BOOST_TEST(a.seam_curves_matched == b.seam_curves_matched);
  };
  QD::internal::Flattening_cache<QD::Chart_report> cache;
  const auto plain = QD::flatten_charts<CGAL::Sequential_tag>(tm, chart_map);
  BOOST_REQUIRE(plain);
  BOOST_REQUIRE(plain.number_of_charts == 4u);
  cache.next_generation();
  const auto first = QD::internal::flatten_charts_impl<CGAL::Sequential_tag>(tm, chart_map, CGAL::parameters::default_values(), &cache);
  same(plain, first);
  BOOST_TEST(cache.hits() == 0u);
  const std::size_t stored = cache.size();
  BOOST_TEST(stored >= 4u);  // the free flattenings and the fits
  // the same mesh again: every flattening is found
  cache.next_generation();
  const auto again = QD::internal::flatten_charts_impl<CGAL::Sequential_tag>(tm, chart_map, CGAL::parameters::default_values(), &cache);
  same(plain, again);
  BOOST_TEST(cache.hits() == stored);
  BOOST_TEST(cache.size() == stored);
  // one vertex of the last chart moved: that chart is flattened again, the
  // first is found, and the result is the uncached one of the moved mesh
  for(auto v : vertices(tm)) {
    const auto& p = tm.point(v);
    if(std::abs(p.x() - 21. / 24) < 1e-9 && std::abs(p.y() - 0.5) < 1e-9) {
      tm.point(v) = Surface_mesh::Point(p.x(), p.y(), p.z() + 0.01);
      break;
    }
  }
  const auto moved_plain = QD::flatten_charts<CGAL::Sequential_tag>(tm, chart_map);
  cache.next_generation();
  const auto moved = QD::internal::flatten_charts_impl<CGAL::Sequential_tag>(tm, chart_map, CGAL::parameters::default_values(), &cache);
  same(moved_plain, moved);
  BOOST_TEST(moved.corner_uv != plain.corner_uv);
  BOOST_TEST(cache.hits() > stored);
  BOOST_TEST(cache.hits() < 2 * stored);
}

BOOST_AUTO_TEST_CASE(rejected_trial_reports_its_optimised_map)
{
  // a merging trial that rejects a chart after optimising its flattening
  // reports the optimised map, the one it judged, not LPFB+IP's; a trial that
  // gives its optimisation up says after how many iterations
  auto trial = [](const Surface_mesh& tm, double max_local_area_distortion) {
    const auto fim = CGAL::get_initialized_face_index_map(tm);
    const auto vim = CGAL::get_initialized_vertex_index_map(tm);
    const std::vector<std::array<double, 3>> points = QD::internal::points_by_index(tm, get(CGAL::vertex_point, tm), vim);
    QD::internal::Merge_thresholds thresholds;
    thresholds.max_local_area_distortion = max_local_area_distortion;
    const QD::internal::Chart_evaluator<Surface_mesh, decltype(fim), decltype(vim)> evaluator(tm, fim, vim, points,
                                                                                              thresholds);
    const std::vector<Surface_mesh::Face_index> fs(faces(tm).begin(), faces(tm).end());
    return evaluator.evaluate(fs, [](Surface_mesh::Halfedge_index) { return false; });
  };
  // a cap that LPFB+IP flattens beyond A_loc 2.5 % and ARAP within it
  const Surface_mesh cap = make<Surface_mesh>(polar(8, 32, sphere_cap(0.6)));
  const QD::Chart_report passed = trial(cap, 0.025);
  BOOST_TEST(passed.accepted);
  BOOST_TEST(passed.optimized);
  BOOST_TEST(passed.given_up_after == 0u);
  BOOST_REQUIRE(passed.local_area_distortion > 0.5);
  // the same trial with the bound just below the A_loc of its optimised map
  const QD::Chart_report rejected = trial(cap, passed.local_area_distortion / 101.);
  BOOST_TEST(!rejected.accepted);
  BOOST_TEST(rejected.status == QD::Error_code::OK);
  BOOST_TEST(rejected.optimized);
  BOOST_TEST(rejected.given_up_after == 0u);
  BOOST_TEST(rejected.local_area_distortion == passed.local_area_distortion);  // the same map
  BOOST_TEST(rejected.area_distortion == passed.area_distortion);
  BOOST_TEST(rejected.l2_stretch == passed.l2_stretch);
  BOOST_TEST(!rejected.overlap);
  // a hemisphere: far beyond the bound after the first 5 iterations
  const QD::Chart_report hopeless = trial(make<Surface_mesh>(polar(8, 32, sphere_cap(0.5 * CGAL_PI))), 0.025);
  BOOST_TEST(!hopeless.accepted);
  BOOST_TEST(hopeless.optimized);
  BOOST_TEST(hopeless.given_up_after == 5u);
  BOOST_TEST(hopeless.local_area_distortion > 2.5 * std::pow(30. / 5., 0.6));
  BOOST_TEST(hopeless.area_distortion > 0.);
  BOOST_TEST(hopeless.l2_stretch == 0.);  // not measured
}

BOOST_AUTO_TEST_CASE(final_flattening_starts_from_the_remembered_trial)
{
  // a final flattening of a chart that a trial accepted starts from that
  // trial's LPFB+IP and optimisation (internal/trial_memory.h) and gives the
  // flattening made from scratch, to the last bit; rejected trials are not
  // remembered, and neither are charts cut open differently
  auto check = [](const Surface_mesh& tm, bool optimized_in_trial) {
    const auto fim = CGAL::get_initialized_face_index_map(tm);
    const auto vim = CGAL::get_initialized_vertex_index_map(tm);
    typedef QD::internal::Chart_evaluator<Surface_mesh, decltype(fim), decltype(vim)> Evaluator;
    const std::vector<std::array<double, 3>> points = QD::internal::points_by_index(tm, get(CGAL::vertex_point, tm), vim);
    QD::internal::Merge_thresholds thresholds, trial_thresholds;
    trial_thresholds.max_local_area_distortion *= 0.95;  // as the merging tries a chart
    Evaluator trials(tm, fim, vim, points, trial_thresholds), final(tm, fim, vim, points, thresholds),
        fresh(tm, fim, vim, points, thresholds);
    const auto memory = std::make_shared<QD::internal::Trial_memory>();
    trials.set_trial_memory(memory);
    final.set_trial_memory(memory);
    const std::vector<Surface_mesh::Face_index> fs(faces(tm).begin(), faces(tm).end());
    const auto no_cut = [](Surface_mesh::Halfedge_index) { return false; };
    const QD::Chart_report trial = trials.evaluate(fs, no_cut);
    BOOST_REQUIRE(trial.accepted);
    BOOST_TEST(trial.optimized == optimized_in_trial);
    BOOST_TEST(memory->size() == 1u);
    std::vector<std::array<double, 2>> resumed_uv, fresh_uv;
    const QD::Chart_report resumed = final.evaluate(fs, no_cut, &resumed_uv);
    const QD::Chart_report made = fresh.evaluate(fs, no_cut, &fresh_uv);
    BOOST_TEST(memory->hits() == 1u);
    BOOST_TEST(resumed.accepted == made.accepted);
    BOOST_TEST(resumed.optimized == made.optimized);
    BOOST_TEST(resumed.number_of_border_loops == made.number_of_border_loops);
    BOOST_TEST(resumed.area_distortion == made.area_distortion);
    BOOST_TEST(resumed.l2_stretch == made.l2_stretch);
    BOOST_TEST(resumed.local_area_distortion == made.local_area_distortion);
    BOOST_REQUIRE(resumed_uv.size() == 3 * fs.size());
    BOOST_TEST((resumed_uv == fresh_uv));
    // the same chart cut along an edge from its border inwards, which splits
    // the wedge of its border vertex: not the remembered trial
    Surface_mesh::Halfedge_index cut;
    for(auto h : halfedges(tm))
      if(!is_border_edge(h, tm) && is_border(target(h, tm), tm) && !is_border(source(h, tm), tm)) cut = h;
    BOOST_REQUIRE(cut != Surface_mesh::null_halfedge());
    const auto one_cut = [&](Surface_mesh::Halfedge_index h) { return h == cut || h == opposite(cut, tm); };
    std::vector<std::array<double, 2>> cut_uv;
    final.evaluate(fs, one_cut, &cut_uv);
    BOOST_TEST(memory->hits() == 1u);
  };
  // a cap that LPFB+IP flattens beyond A_loc 2.5 % and the trial's
  // optimisation within it; the final flattening goes on from its 30
  // iterations
  check(make<Surface_mesh>(polar(8, 32, sphere_cap(0.6))), true);
  // a flat disk, which LPFB+IP flattens within the thresholds: the trial runs
  // no optimisation, and the final flattening runs it from LPFB+IP's map
  check(make<Surface_mesh>(polar(6, 24, flat_disk(1.))), false);
  // a trial rejected is not remembered
  const Surface_mesh hemisphere = make<Surface_mesh>(polar(8, 32, sphere_cap(0.5 * CGAL_PI)));
  const auto fim = CGAL::get_initialized_face_index_map(hemisphere);
  const auto vim = CGAL::get_initialized_vertex_index_map(hemisphere);
  const std::vector<std::array<double, 3>> points =
      QD::internal::points_by_index(hemisphere, get(CGAL::vertex_point, hemisphere), vim);
  QD::internal::Chart_evaluator<Surface_mesh, decltype(fim), decltype(vim)> evaluator(
      hemisphere, fim, vim, points, QD::internal::Merge_thresholds());
  evaluator.set_trial_memory(std::make_shared<QD::internal::Trial_memory>());
  const std::vector<Surface_mesh::Face_index> fs(faces(hemisphere).begin(), faces(hemisphere).end());
  BOOST_TEST(!evaluator.evaluate(fs, [](Surface_mesh::Halfedge_index) { return false; }).accepted);
  BOOST_TEST(evaluator.trial_memory()->size() == 0u);
#ifdef CGAL_QD_DEMO_MESH_DIR
  // the final flattening of a segmentation, whose charts start from their
  // last trials (most of which stop at their 30 iterations and go on from
  // there), is the flattening of the same charts made from scratch
  Surface_mesh elephant;
  BOOST_REQUIRE(CGAL::IO::read_polygon_mesh(std::string(CGAL_QD_DEMO_MESH_DIR) + "/elephant.off", elephant));
  Face_map<Surface_mesh> chart;
  const QD::Segmentation_result<Surface_mesh> seg =
      QD::segment_quasi_developable(elephant, boost::make_assoc_property_map(chart));
  BOOST_REQUIRE(seg);
  // the same charts and seams flattened from scratch, as the segmentation's
  // last step does (the seams in the same order: it sets the order in which
  // the lengths along the two sides of each seam curve are summed)
  const auto efim = CGAL::get_initialized_face_index_map(elephant);
  const auto evim = CGAL::get_initialized_vertex_index_map(elephant);
  const auto ehim = CGAL::get_initialized_halfedge_index_map(elephant);
  std::vector<std::size_t> chart_of(num_faces(elephant));
  for(auto f : faces(elephant)) chart_of[get(efim, f)] = chart.at(f);
  QD::Chart_flattening_result<Surface_mesh> again;
  again.points = QD::internal::points_by_index(elephant, get(CGAL::vertex_point, elephant), evim);
  QD::internal::flatten_final_charts<CGAL::Sequential_tag>(
      elephant, get(CGAL::vertex_point, elephant), efim, evim, ehim, chart_of, seg.number_of_charts, seg.seam_edges,
      QD::internal::Merge_thresholds(), std::function<void(const char*, double)>(), again);
  BOOST_REQUIRE(again);
  BOOST_TEST(again.number_of_charts == seg.number_of_charts);
  BOOST_TEST((again.corner_uv == seg.corner_uv));
  BOOST_TEST(again.seam_curves_matched == seg.seam_curves_matched);
  for(std::size_t k = 0; k < seg.charts.size() && k < again.charts.size(); ++k) {
    BOOST_TEST(again.charts[k].accepted == seg.charts[k].accepted);
    BOOST_TEST(again.charts[k].local_area_distortion == seg.charts[k].local_area_distortion);
  }
#endif
}

BOOST_AUTO_TEST_CASE(flatten_charts_keeps_the_flattening_nearest_the_thresholds)
{
  // a chart that no flattening brings within the thresholds keeps the one
  // nearest them, and reports its measures: here an optimised map, far
  // nearer than LPFB+IP's
  Surface_mesh cap = make<Surface_mesh>(polar(8, 32, sphere_cap(0.6)));
  Face_map<Surface_mesh> chart;
  for(auto f : faces(cap)) chart[f] = 0;
  auto flatten = [&](double max_local_area_distortion) {
    return QD::flatten_charts(cap, boost::make_assoc_property_map(chart),
                              QD::parameters::max_local_area_distortion(max_local_area_distortion));
  };
  const QD::Chart_flattening_result<Surface_mesh> passed = flatten(0.025);
  BOOST_REQUIRE(passed);
  BOOST_REQUIRE(passed.charts[0].accepted);
  BOOST_REQUIRE(passed.charts[0].optimized);
  const double best = passed.charts[0].local_area_distortion;
  BOOST_REQUIRE(best > 0.5);
  const QD::Chart_flattening_result<Surface_mesh> paper = QD::flatten_charts(
      cap, boost::make_assoc_property_map(chart), QD::parameters::chart_criterion(QD::Chart_criterion::LPFB_IP));
  BOOST_REQUIRE(paper);
  BOOST_REQUIRE(paper.charts[0].local_area_distortion > 2.5);  // LPFB+IP's map
  // the bound just below the A_loc of the accepted map: every map is rejected
  const QD::Chart_flattening_result<Surface_mesh> rejected = flatten(best / 101.);
  BOOST_REQUIRE(rejected);
  BOOST_TEST(rejected.rejected_charts == 1u);
  const QD::Chart_report& r = rejected.charts[0];
  BOOST_TEST(!r.accepted);
  BOOST_TEST(r.optimized);
  BOOST_TEST(!r.overlap);
  // the optimisation from the same start, without the fit to the seam
  // lengths (factors of one here) that the accepted map had
  BOOST_TEST(r.local_area_distortion < 1.001 * best);
  BOOST_TEST(r.local_area_distortion < paper.charts[0].local_area_distortion / 2.);
  // the corners' UVs are the map measured
  const auto fim = CGAL::get_initialized_face_index_map(cap);
  auto uv = cap.add_property_map<Surface_mesh::Vertex_index, Epick::Point_2>("v:uv").first;
  for(auto f : faces(cap)) {
    std::size_t k = 0;
    for(auto h : CGAL::halfedges_around_face(halfedge(f, cap), cap)) {
      const std::array<double, 2>& p = rejected.corner_uv[3 * get(fim, f) + k++];
      put(uv, target(h, cap), Epick::Point_2(p[0], p[1]));
    }
  }
  const auto d = QD::compute_distortion(cap, uv);
  BOOST_REQUIRE(d);
  BOOST_TEST(std::abs(d.local_area_distortion - r.local_area_distortion) <= 1e-9 * r.local_area_distortion);
  BOOST_TEST(std::abs(d.area_distortion - r.area_distortion) <= 1e-9 * (1. + r.area_distortion));
  BOOST_TEST(!d.overlap);
}

BOOST_AUTO_TEST_CASE(flatten_charts_gives_both_sides_of_a_seam_the_same_length)
{
  // a curved patch in two charts: the free flattenings give the two sides of
  // the seam different lengths; the final fit gives every border edge exactly
  // its share of the common length
  const std::size_t n = 16;
  const Surface_mesh tm = make<Surface_mesh>(grid(n, n, bump(0.3)));
  Face_map<Surface_mesh> chart;
  for(auto f : faces(tm)) {
    double x = 0;
    for(auto v : vertices_around_face(halfedge(f, tm), tm)) x += tm.point(v).x() / 3;
    chart[f] = x < 0.5 ? 0 : 1;
  }
  const QD::Chart_flattening_result<Surface_mesh> f = QD::flatten_charts(tm, boost::make_assoc_property_map(chart));
  BOOST_REQUIRE(f);
  BOOST_REQUIRE(f.number_of_charts == 2u);
  BOOST_TEST(f.rejected_charts == 0u);
  BOOST_TEST(f.seam_edges.size() == n);
  for(const QD::Chart_report& c : f.charts) {
    BOOST_TEST(c.optimized);
    BOOST_TEST(c.lengths_matched);
    BOOST_TEST(c.local_area_distortion <= 2.5);
  }
  BOOST_TEST(f.max_seam_length_mismatch <= 1e-6);
  BOOST_TEST(f.number_of_seam_curves == 1u);
  BOOST_TEST(f.seam_curves_matched == 1u);
  BOOST_TEST(f.unmatched_seams.empty());
  for(const QD::Chart_report& c : f.charts) BOOST_TEST(c.seams_matched);
  // measured again from the corner UVs: the seam's two sides, edge by edge
  const auto fim = get(CGAL::face_index, tm);
  auto uv_length = [&](Surface_mesh::Halfedge_index h) {
    const auto g = halfedge(face(h, tm), tm);
    const int k = g == h ? 0 : next(g, tm) == h ? 1 : 2;
    const auto& a = f.corner_uv[3 * get(fim, face(h, tm)) + k];
    const auto& b = f.corner_uv[3 * get(fim, face(h, tm)) + (k + 2) % 3];
    return std::hypot(a[0] - b[0], a[1] - b[1]);
  };
  double side[2] = {0, 0}, length3 = 0, worst_edge = 0;
  for(auto e : f.seam_edges) {
    const auto h = halfedge(e, tm);
    const auto h0 = chart.at(face(h, tm)) == 0 ? h : opposite(h, tm);
    const double l0 = uv_length(h0), l1 = uv_length(opposite(h0, tm));
    side[0] += l0;
    side[1] += l1;
    length3 += std::sqrt(CGAL::squared_distance(tm.point(source(h, tm)), tm.point(target(h, tm))));
    worst_edge = (std::max)(worst_edge, std::abs(l0 - l1) / (std::max)(l0, l1));
  }
  BOOST_TEST(std::abs(side[0] - side[1]) <= 1e-6 * side[0]);
  // each side is scaled along itself, so single edges may differ a little
  BOOST_TEST(worst_edge < 0.05);
  // the free boundary gives the seam a length of its own, near the 3D one
  BOOST_TEST(std::abs(side[0] - length3) <= 0.05 * length3);
}

BOOST_AUTO_TEST_CASE(flatten_charts_starts_the_optimisation_again_where_lpfb_ip_folds)
{
  // a chart whose LPFB+IP folds so that the optimisation started from it
  // stays outside the thresholds; started again (from LSCM), it is accepted
  Surface_mesh tm;
  BOOST_REQUIRE(CGAL::IO::read_polygon_mesh(std::string(CGAL_QD_TEST_DATA_DIR) + "/camel_chart_folded_start.off", tm));
  BOOST_REQUIRE(num_faces(tm) == 712u);
  auto uv = tm.add_property_map<Surface_mesh::Vertex_index, Epick::Point_2>("v:uv").first;
  BOOST_REQUIRE(QD::flatten_patch(tm, uv));
  BOOST_REQUIRE(QD::optimize_flattening(tm, uv, QD::parameters::arap_border(QD::Arap_border::FREE,
                                                                          CGAL::parameters::number_of_iterations(100))));
  const auto first = QD::compute_distortion(tm, uv, QD::parameters::overlap_tolerance(1e-9));
  BOOST_REQUIRE(first);
  BOOST_TEST((first.overlap || first.local_area_distortion > 2.5));
  Face_map<Surface_mesh> chart;
  for(auto f : faces(tm)) chart[f] = 0;
  const QD::Chart_flattening_result<Surface_mesh> f = QD::flatten_charts(tm, boost::make_assoc_property_map(chart));
  BOOST_REQUIRE(f);
  BOOST_TEST(f.rejected_charts == 0u);
  BOOST_TEST(f.charts[0].accepted);
  BOOST_TEST(f.charts[0].optimized);
  BOOST_TEST(!f.charts[0].overlap);
  BOOST_TEST(f.charts[0].local_area_distortion <= 2.5);
  BOOST_TEST(f.charts[0].area_distortion <= 10.);
  BOOST_TEST(f.charts[0].l2_stretch <= 2.0);
}

#ifdef CGAL_QD_DEMO_MESH_DIR
// the seams of elephant's segmentation, smoothed by the library: the refined
// mesh comes out with its charts and a flattening that belongs to it
// The faces of `out` that the corners' UVs of `f` turn over, and the ratio
// of their 2D area to their 3D area.
template <class Mesh>
std::pair<std::size_t, double> turned_faces_and_area_ratio(const Mesh& out, const QD::Chart_flattening_result<Mesh>& f)
{
  const auto fim = CGAL::get_initialized_face_index_map(out);
  double area2 = 0, area3 = 0;
  std::size_t turned = 0;
  for(auto fd : faces(out)) {
    const std::size_t i = get(fim, fd);
    const auto &a = f.corner_uv[3 * i], &b = f.corner_uv[3 * i + 1], &c = f.corner_uv[3 * i + 2];
    const double signed_area = 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
    turned += signed_area <= 0;
    area2 += std::abs(signed_area);
    area3 += CGAL::Polygon_mesh_processing::face_area(fd, out);
  }
  return {turned, area2 / area3};
}

// The charts `out_chart` of `out` flattened again with the cuts of `f` (its
// seams with one chart on both sides).
template <class Mesh>
QD::Chart_flattening_result<Mesh> flatten_again(const Mesh& out, const Face_map<Mesh>& out_chart,
                                                const QD::Chart_flattening_result<Mesh>& f)
{
  Edge_set<Mesh> cuts;
  for(auto e : f.seam_edges) {
    const auto h = halfedge(e, out);
    if(out_chart.at(face(h, out)) == out_chart.at(face(opposite(h, out), out))) cuts.insert(e);
  }
  const auto constrained = boost::make_function_property_map<typename boost::graph_traits<Mesh>::edge_descriptor>(
      [&](typename boost::graph_traits<Mesh>::edge_descriptor e) { return cuts.count(e) > 0; });
  Face_map<Mesh> charts = out_chart;
  return QD::flatten_charts(out, boost::make_assoc_property_map(charts),
                            CGAL::parameters::edge_is_constrained_map(constrained));
}

BOOST_AUTO_TEST_CASE_TEMPLATE(segmentation_seams_are_smoothed_into_a_new_mesh, Mesh, Mesh_types)
{
  Mesh tm;
  BOOST_REQUIRE(CGAL::IO::read_polygon_mesh(std::string(CGAL_QD_DEMO_MESH_DIR) + "/elephant.off", tm));
  const std::size_t input_faces = num_faces(tm);
  Face_map<Mesh> chart;
  const QD::Segmentation_result<Mesh> seg = QD::segment_quasi_developable(tm, boost::make_assoc_property_map(chart));
  BOOST_REQUIRE(seg);
  BOOST_REQUIRE(seg.number_of_charts > 1u);

  Mesh out;
  Face_map<Mesh> out_chart;
  const QD::Seam_smoothing_result<Mesh> s =
      QD::smooth_segmentation_seams(tm, boost::make_assoc_property_map(chart), seg, out,
                                    boost::make_assoc_property_map(out_chart));
  BOOST_REQUIRE(s);
  BOOST_TEST_MESSAGE(s.smoothing.curves_smoothed << " of " << s.number_of_curves << " curves smoothed in "
                                                 << s.tries << " tries, zigzag " << seg.seam_zigzag << " -> "
                                                 << s.flattening.seam_zigzag);
  BOOST_REQUIRE(s.kept);
  BOOST_TEST(num_faces(tm) == input_faces);  // the input stays as it was
  BOOST_TEST(num_faces(out) > input_faces);  // refined along the new curves
  BOOST_TEST(CGAL::is_valid_polygon_mesh(out));
  BOOST_TEST(CGAL::is_triangle_mesh(out));
  const QD::Chart_flattening_result<Mesh>& f = s.flattening;
  BOOST_TEST(f.number_of_charts == seg.number_of_charts);
  BOOST_TEST(f.number_of_faces == num_faces(out));
  BOOST_TEST(f.rejected_charts == 0u);
  BOOST_TEST(f.seam_zigzag < seg.seam_zigzag - 0.02);
  BOOST_TEST(s.smoothing.curves_smoothed > 0u);
  BOOST_TEST(s.tries >= 1u);
  // no seam stops matching: the seams of a try are judged once its every
  // chart is accepted, not along a chart that a try pushed beyond the
  // thresholds (judged there, one seam of elephant ended unmatched)
  BOOST_TEST(f.number_of_seam_curves == seg.number_of_seam_curves);
  BOOST_TEST(f.seam_curves_matched >= seg.seam_curves_matched);
  std::vector<std::size_t> charts(f.number_of_charts, 0);
  for(auto fd : faces(out)) {
    BOOST_REQUIRE(out_chart.count(fd) == 1u);
    BOOST_REQUIRE(out_chart.at(fd) < f.number_of_charts);
    ++charts[out_chart.at(fd)];
  }
  for(std::size_t c : charts) BOOST_TEST(c > 0u);
  // the UVs follow the faces of `out`: no corner swapped (no face turned over),
  // the 2D areas those of the 3D faces up to the charts' area distortion
  BOOST_REQUIRE(f.corner_uv.size() == 3 * num_faces(out));
  const std::pair<std::size_t, double> turned = turned_faces_and_area_ratio(out, f);
  BOOST_TEST(turned.first == 0u);
  BOOST_TEST(std::abs(turned.second - 1) <= f.max_area_distortion / 100 + 1e-9);
  // the seams are edges of `out`: between two charts, or cuts inside one; the
  // charts flattened again with those cuts are accepted, with the same seams
  std::size_t borders = 0, between = 0;
  for(auto e : f.seam_edges) {
    const auto h = halfedge(e, out);
    BOOST_REQUIRE(!is_border_edge(h, out));
    if(out_chart.at(face(h, out)) != out_chart.at(face(opposite(h, out), out))) ++borders;
  }
  for(auto e : edges(out)) {
    const auto h = halfedge(e, out);
    between += !is_border_edge(h, out) && out_chart.at(face(h, out)) != out_chart.at(face(opposite(h, out), out));
  }
  BOOST_TEST(borders == between);
  const QD::Chart_flattening_result<Mesh> again = flatten_again(out, out_chart, f);
  BOOST_REQUIRE(again);
  BOOST_TEST(again.rejected_charts == 0u);
  BOOST_TEST(again.number_of_seam_curves == f.number_of_seam_curves);
  BOOST_TEST(again.seam_length == f.seam_length, tt::tolerance(1e-9));
  BOOST_TEST(again.seam_zigzag == f.seam_zigzag, tt::tolerance(1e-9));

  // an output that is not empty, or a segmentation of another mesh: refused, nothing written
  const std::size_t out_faces = num_faces(out);
  Face_map<Mesh> other_chart;
  BOOST_TEST(QD::smooth_segmentation_seams(tm, boost::make_assoc_property_map(chart), seg, out,
                                           boost::make_assoc_property_map(other_chart))
                 .status == QD::Error_code::INVALID_ARGUMENT);
  BOOST_TEST(num_faces(out) == out_faces);
  Mesh empty_out;
  QD::Chart_flattening_result<Mesh> foreign = seg;
  foreign.number_of_faces += 1;
  BOOST_TEST(QD::smooth_segmentation_seams(tm, boost::make_assoc_property_map(chart), foreign, empty_out,
                                           boost::make_assoc_property_map(other_chart))
                 .status == QD::Error_code::INVALID_ARGUMENT);
  BOOST_TEST(num_faces(empty_out) == 0u);
  BOOST_TEST(other_chart.empty());
  // an area preservation outside [0, 1]: refused by every step, nothing written
  BOOST_TEST(QD::smooth_segmentation_seams(tm, boost::make_assoc_property_map(chart), seg, empty_out,
                                           boost::make_assoc_property_map(other_chart),
                                           QD::parameters::area_preservation(1.5))
                 .status == QD::Error_code::INVALID_ARGUMENT);
  BOOST_TEST(num_faces(empty_out) == 0u);
  BOOST_TEST(QD::flatten_charts(tm, boost::make_assoc_property_map(chart), QD::parameters::area_preservation(-1.))
                 .status == QD::Error_code::INVALID_ARGUMENT);
  Face_map<Mesh> untouched;
  BOOST_TEST(QD::segment_quasi_developable(tm, boost::make_assoc_property_map(untouched),
                                           QD::parameters::area_preservation(std::nan("")))
                 .status == QD::Error_code::INVALID_ARGUMENT);
  BOOST_TEST(untouched.empty());
  Face_map<Mesh> merged = chart;
  BOOST_TEST(QD::merge_charts_by_boundaries(tm, boost::make_assoc_property_map(merged),
                                            QD::parameters::area_preservation(2.))
                 .status == QD::Error_code::INVALID_ARGUMENT);
  BOOST_TEST((merged == chart));
}

// The try kept is not held as a copy while later tries are made: it is made
// again from its smoothing levels at the end. On mannequin-devil the try kept
// is not the last one; the mesh made again must be the one flattened, or the
// corners' UVs would not follow its faces.
BOOST_AUTO_TEST_CASE(seam_smoothing_makes_the_try_kept_again_after_later_tries)
{
  Surface_mesh tm;
  BOOST_REQUIRE(CGAL::IO::read_polygon_mesh(std::string(CGAL_QD_DEMO_MESH_DIR) + "/mannequin-devil.off", tm));
  Face_map<Surface_mesh> chart;
  const QD::Segmentation_result<Surface_mesh> seg =
      QD::segment_quasi_developable(tm, boost::make_assoc_property_map(chart));
  BOOST_REQUIRE(seg);
  Surface_mesh out;
  Face_map<Surface_mesh> out_chart;
  const QD::Seam_smoothing_result<Surface_mesh> s = QD::smooth_segmentation_seams(
      tm, boost::make_assoc_property_map(chart), seg, out, boost::make_assoc_property_map(out_chart));
  BOOST_REQUIRE(s);
  BOOST_REQUIRE(s.kept);
  BOOST_TEST(s.tries >= 2u);
  const QD::Chart_flattening_result<Surface_mesh>& f = s.flattening;
  BOOST_REQUIRE(f.corner_uv.size() == 3 * num_faces(out));
  BOOST_TEST(num_faces(out) == num_faces(tm) + s.smoothing.faces_added);
  BOOST_TEST(f.rejected_charts == 0u);
  const std::pair<std::size_t, double> turned = turned_faces_and_area_ratio(out, f);
  BOOST_TEST(turned.first == 0u);
  BOOST_TEST(std::abs(turned.second - 1) <= f.max_area_distortion / 100 + 1e-9);
  // flattened again, the charts of `out` give the seams the smoothing reported
  const QD::Chart_flattening_result<Surface_mesh> again = flatten_again(out, out_chart, f);
  BOOST_REQUIRE(again);
  BOOST_TEST(again.number_of_seam_curves == f.number_of_seam_curves);
  BOOST_TEST(again.seam_length == f.seam_length, tt::tolerance(1e-9));
  BOOST_TEST(again.seam_zigzag == f.seam_zigzag, tt::tolerance(1e-9));

  // The same segmentation without its flattening: the same charts and seams;
  // the smoothing flattens the charts as they are where it needs them (on
  // mannequin-devil a try with every chart accepted leaves seams unmatched,
  // which are compared with the input's) and keeps the same try, bit for bit.
  Face_map<Surface_mesh> lazy_chart;
  const QD::Segmentation_result<Surface_mesh> lazy = QD::segment_quasi_developable(
      tm, boost::make_assoc_property_map(lazy_chart), QD::parameters::final_flattening(false));
  BOOST_REQUIRE(lazy);
  BOOST_TEST(!lazy.flattened);
  BOOST_TEST(seg.flattened);
  BOOST_TEST((lazy_chart == chart));
  BOOST_TEST(lazy.number_of_charts == seg.number_of_charts);
  BOOST_TEST((lazy.seam_edges == seg.seam_edges));
  BOOST_TEST(lazy.seam_length == seg.seam_length);
  BOOST_TEST(lazy.charts.empty());
  BOOST_TEST(lazy.corner_uv.empty());
  Surface_mesh lazy_out;
  Face_map<Surface_mesh> lazy_out_chart;
  const QD::Seam_smoothing_result<Surface_mesh> ls = QD::smooth_segmentation_seams(
      tm, boost::make_assoc_property_map(lazy_chart), lazy, lazy_out, boost::make_assoc_property_map(lazy_out_chart));
  BOOST_REQUIRE(ls);
  BOOST_REQUIRE(ls.kept);
  BOOST_TEST(ls.tries == s.tries);
  BOOST_TEST(num_faces(lazy_out) == num_faces(out));
  BOOST_TEST((ls.flattening.corner_uv == f.corner_uv));
  BOOST_TEST(ls.flattening.seam_curves_matched == f.seam_curves_matched);
  BOOST_TEST(ls.flattening.seam_zigzag == f.seam_zigzag);
  // made because a try left seams unmatched, and then the input's flattening
  BOOST_REQUIRE(ls.input_flattening.flattened);
  BOOST_TEST(!s.input_flattening.flattened);  // not made from a flattened segmentation
  BOOST_TEST((ls.input_flattening.corner_uv == seg.corner_uv));
  BOOST_TEST((ls.input_flattening.unmatched_seams == seg.unmatched_seams));
  BOOST_TEST(ls.input_flattening.max_seam_length_mismatch == seg.max_seam_length_mismatch);
  BOOST_TEST(ls.input_flattening.rejected_charts == seg.rejected_charts);
}

// A segmentation without its flattening that the smoothing cannot improve
// (a single chart, no seam): the smoothing returns the flattening that the
// segmentation would have made, and keeps nothing.
BOOST_AUTO_TEST_CASE(seam_smoothing_flattens_an_unflattened_segmentation_it_does_not_smooth)
{
  Surface_mesh tm;
  BOOST_REQUIRE(qd_test::build(qd_test::polar(12, 48, qd_test::flat_disk(1.)), tm));
  Face_map<Surface_mesh> chart, lazy_chart;
  const QD::Segmentation_result<Surface_mesh> seg =
      QD::segment_quasi_developable(tm, boost::make_assoc_property_map(chart));
  const QD::Segmentation_result<Surface_mesh> lazy = QD::segment_quasi_developable(
      tm, boost::make_assoc_property_map(lazy_chart), QD::parameters::final_flattening(false));
  BOOST_REQUIRE(seg);
  BOOST_REQUIRE(lazy);
  BOOST_REQUIRE(seg.number_of_charts == 1u);
  BOOST_TEST(!lazy.flattened);
  Surface_mesh out;
  Face_map<Surface_mesh> out_chart;
  const QD::Seam_smoothing_result<Surface_mesh> s = QD::smooth_segmentation_seams(
      tm, boost::make_assoc_property_map(lazy_chart), lazy, out, boost::make_assoc_property_map(out_chart));
  BOOST_REQUIRE(s);
  BOOST_TEST(!s.kept);
  BOOST_TEST(num_faces(out) == 0u);
  BOOST_REQUIRE(s.input_flattening.flattened);
  BOOST_TEST(s.input_flattening.number_of_charts == 1u);
  BOOST_TEST((s.input_flattening.corner_uv == seg.corner_uv));
  BOOST_TEST(s.input_flattening.max_local_area_distortion == seg.max_local_area_distortion);
  BOOST_TEST(s.input_flattening.rejected_charts == 0u);
  // chart ids that are not those of the segmentation: refused
  Face_map<Surface_mesh> wrong = lazy_chart;
  wrong.begin()->second = 7;
  Surface_mesh out2;
  BOOST_TEST(QD::smooth_segmentation_seams(tm, boost::make_assoc_property_map(wrong), lazy, out2,
                                           boost::make_assoc_property_map(out_chart))
                 .status == QD::Error_code::INVALID_ARGUMENT);
  BOOST_TEST(num_faces(out2) == 0u);
}
#endif

namespace {

// a polar patch in one chart with a dart along the edges from its border
// (ring `rings`, sector 0) to its centre; returns the dart's length
double dart_to_the_centre(const Surface_mesh& tm, std::size_t rings, std::size_t sectors,
                          std::map<Surface_mesh::Edge_index, bool>& cut)
{
  // polar(): vertex 0 is the centre, vertex 1 + (r - 1) * sectors + k the k-th of ring r
  double length = 0;
  for(auto e : edges(tm)) cut[e] = false;
  for(std::size_t r = 0; r < rings; ++r) {
    const Surface_mesh::Vertex_index a(r == 0 ? 0 : 1 + (r - 1) * sectors), b(1 + r * sectors);
    const auto h = halfedge(a, b, tm);
    BOOST_REQUIRE(h.second);
    cut[edge(h.first, tm)] = true;
    length += std::sqrt(CGAL::squared_distance(tm.point(a), tm.point(b)));
  }
  return length;
}

// the polar patch in one chart with that dart, flattened
QD::Chart_flattening_result<Surface_mesh> one_chart_with_a_dart(const Surface_mesh& tm, std::size_t rings,
                                                                std::size_t sectors, Face_map<Surface_mesh>& chart,
                                                                double& dart)
{
  for(auto f : faces(tm)) chart[f] = 0;
  std::map<Surface_mesh::Edge_index, bool> cut;
  dart = dart_to_the_centre(tm, rings, sectors, cut);
  const auto f = QD::flatten_charts(tm, boost::make_assoc_property_map(chart),
                                    CGAL::parameters::edge_is_constrained_map(boost::make_assoc_property_map(cut)));
  BOOST_REQUIRE(f);
  return f;
}

} // namespace

BOOST_AUTO_TEST_CASE(needless_cuts_are_closed_and_needed_ones_kept)
{
  const std::size_t rings = 8, sectors = 32;
  // a flat disk needs no dart: closed whole, and the disk flattens exactly
  {
    const Surface_mesh tm = make<Surface_mesh>(polar(rings, sectors, flat_disk(1.)));
    Face_map<Surface_mesh> chart;
    double dart = 0;
    const auto f = one_chart_with_a_dart(tm, rings, sectors, chart, dart);
    BOOST_REQUIRE(f.seam_edges.size() == rings);
    const auto s = QD::shorten_chart_cuts(tm, boost::make_assoc_property_map(chart), f);
    BOOST_REQUIRE(s);
    BOOST_TEST(s.kept);
    BOOST_TEST(s.cut_curves == 1u);
    BOOST_TEST(s.cuts_passing_trials == 1u);
    BOOST_TEST(s.cuts_shortened == 1u);
    BOOST_TEST(s.cuts_closed == 1u);
    BOOST_TEST(s.trials == 2u);  // closed whole at the first trial, tried beside the half
    BOOST_TEST(s.flattenings == 1u);
    BOOST_TEST(s.cut_length == dart, tt::tolerance(1e-12));
    BOOST_TEST(s.cut_length_closed == dart, tt::tolerance(1e-12));
    BOOST_TEST(s.flattening.seam_edges.empty());
    BOOST_TEST(s.flattening.rejected_charts == 0u);
    BOOST_TEST(s.flattening.max_area_distortion < 1e-6);
    BOOST_TEST(s.flattening.compactness > f.compactness);
  }
  // a cone of half-angle 30 degrees: its apex has half its angle missing, so
  // the dart must reach it; every trial, from the whole dart down to its last
  // edge at the apex, is tried and fails
  {
    const double a = CGAL_PI / 6;
    const Surface_mesh tm = make<Surface_mesh>(polar(rings, sectors, [=](double rho, double phi) {
      return P3{rho * std::sin(a) * std::cos(phi), rho * std::sin(a) * std::sin(phi), -rho * std::cos(a)};
    }));
    Face_map<Surface_mesh> chart;
    double dart = 0;
    const auto f = one_chart_with_a_dart(tm, rings, sectors, chart, dart);
    BOOST_REQUIRE(f.rejected_charts == 0u);  // the cone with its dart develops exactly
    BOOST_TEST(f.max_area_distortion < 1e-6);
    const auto s = QD::shorten_chart_cuts(tm, boost::make_assoc_property_map(chart), f);
    BOOST_REQUIRE(s);
    BOOST_TEST(!s.kept);
    BOOST_TEST(s.cut_curves == 1u);
    BOOST_TEST(s.cuts_passing_trials == 0u);
    BOOST_TEST(s.cuts_shortened == 0u);
    BOOST_TEST(s.trials == 4u);  // 8 edges, 4, 2, 1 (two at a time)
    BOOST_TEST(s.flattenings == 0u);  // nothing to flatten again
    BOOST_TEST(s.cut_length == dart, tt::tolerance(1e-12));
    BOOST_TEST(s.cut_length_closed == 0.);
    BOOST_TEST(s.flattening.charts.empty());
  }
  // two disks apart, the first with the dart: the second, neither shortened
  // nor next to a chart shortened, keeps its flattening exactly
  {
    Soup soup = polar(rings, sectors, flat_disk(1.));
    const Soup other = polar(rings, sectors, [](double rho, double phi) {
      return P3{3. + rho * std::cos(phi), rho * std::sin(phi), 0.2 * rho * rho};
    });
    const std::size_t offset = soup.points.size(), first_faces = soup.triangles.size();
    soup.points.insert(soup.points.end(), other.points.begin(), other.points.end());
    for(Tri t : other.triangles) soup.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
    const Surface_mesh tm = make<Surface_mesh>(soup);
    Face_map<Surface_mesh> chart;
    for(auto g : faces(tm)) chart[g] = std::size_t(g) < first_faces ? 0 : 1;
    std::map<Surface_mesh::Edge_index, bool> cut;
    dart_to_the_centre(tm, rings, sectors, cut);
    auto f = QD::flatten_charts(tm, boost::make_assoc_property_map(chart),
                                CGAL::parameters::edge_is_constrained_map(boost::make_assoc_property_map(cut)));
    BOOST_REQUIRE(f);
    BOOST_REQUIRE(f.number_of_charts == 2u);
    // the second disk's flattening moved, as a flattening of its own would not be
    for(std::size_t c = 3 * first_faces; c < f.corner_uv.size(); ++c) {
      f.corner_uv[c][0] += 5.;
      f.corner_uv[c][1] += 7.;
    }
    const auto s = QD::shorten_chart_cuts(tm, boost::make_assoc_property_map(chart), f);
    BOOST_REQUIRE(s);
    BOOST_TEST(s.kept);
    BOOST_TEST(s.cuts_closed == 1u);
    BOOST_TEST(s.flattening.seam_edges.empty());
    BOOST_TEST(s.flattening.rejected_charts == 0u);
    std::size_t same = 0;
    for(std::size_t c = 3 * first_faces; c < f.corner_uv.size(); ++c) same += s.flattening.corner_uv[c] == f.corner_uv[c];
    BOOST_TEST(same == f.corner_uv.size() - 3 * first_faces);
    BOOST_TEST(s.flattening.charts[1].local_area_distortion == f.charts[1].local_area_distortion);
  }
}

BOOST_AUTO_TEST_CASE(a_trial_given_a_flattening_starts_from_it)
{
  // the trials of shorten_chart_cuts() start from the chart's flattening,
  // each wedge at the mean of its corners, instead of LPFB+IP
  const std::size_t rings = 8, sectors = 32;
  auto check = [&](const Surface_mesh& tm, bool flat) {
    Face_map<Surface_mesh> chart;
    double dart = 0;
    const auto f = one_chart_with_a_dart(tm, rings, sectors, chart, dart);
    BOOST_REQUIRE(f.rejected_charts == 0u);
    const auto fim = CGAL::get_initialized_face_index_map(tm);
    const auto vim = CGAL::get_initialized_vertex_index_map(tm);
    const std::vector<std::array<double, 3>> points =
        QD::internal::points_by_index(tm, get(CGAL::vertex_point, tm), vim);
    const std::vector<Surface_mesh::Face_index> fs(faces(tm).begin(), faces(tm).end());
    // the flattening turned by a quarter and moved: a start LPFB+IP would not give
    std::vector<std::array<double, 2>> start(3 * fs.size());
    for(std::size_t i = 0; i < fs.size(); ++i)
      for(std::size_t j = 0; j < 3; ++j) {
        const std::array<double, 2>& p = f.corner_uv[3 * get(fim, fs[i]) + j];
        start[3 * i + j] = {5. - p[1], 2. + p[0]};
      }
    const auto no_cut = [](Surface_mesh::Halfedge_index) { return false; };
    for(QD::Chart_criterion criterion : {QD::Chart_criterion::LPFB_IP_THEN_ARAP, QD::Chart_criterion::LPFB_IP}) {
      QD::internal::Merge_thresholds thresholds;
      thresholds.criterion = criterion;
      const QD::internal::Chart_evaluator<Surface_mesh, decltype(fim), decltype(vim)> evaluator(tm, fim, vim, points,
                                                                                                thresholds);
      std::vector<std::array<double, 2>> uv;
      const QD::Chart_report rep = evaluator.evaluate(fs, no_cut, &uv, nullptr, &start);
      BOOST_REQUIRE(rep.status == QD::Error_code::OK);
      const bool paper = criterion == QD::Chart_criterion::LPFB_IP;
      if(flat) {
        // the dart of a flat disk is closed in its flattening: the start is an
        // isometry, accepted and kept, where the paper's criterion flattens
        // the disk by LPFB+IP as ever
        BOOST_TEST(rep.accepted);
        double farthest = 0;
        for(std::size_t c = 0; c < uv.size(); ++c)
          farthest = (std::max)(farthest, std::hypot(uv[c][0] - start[c][0], uv[c][1] - start[c][1]));
        if(paper) {
          BOOST_TEST(farthest > 1.);
        } else {
          BOOST_TEST(farthest < 1e-9);
        }
      } else if(!paper) {
        // a cap whose dart is open in its flattening: the wedges of its two
        // sides start halfway between them, and the optimisation brings the
        // chart without the dart within the thresholds
        BOOST_TEST(rep.accepted);
        BOOST_TEST(rep.optimized);
        BOOST_TEST(rep.local_area_distortion < 2.5);
        BOOST_TEST(evaluator.evaluate(fs, no_cut, nullptr, nullptr, &start).accepted);
      }
    }
  };
  check(make<Surface_mesh>(polar(rings, sectors, flat_disk(1.))), true);
  check(make<Surface_mesh>(polar(rings, sectors, sphere_cap(0.6))), false);
}

BOOST_AUTO_TEST_CASE(fandisk_darts_are_shortened_from_their_loose_ends)
{
  Surface_mesh tm;
  BOOST_REQUIRE(CGAL::IO::read_polygon_mesh(std::string(CGAL_QD_DEMO_MESH_DIR) + "/fandisk.off", tm));
  Face_map<Surface_mesh> chart;
  const auto r = QD::segment_quasi_developable(tm, boost::make_assoc_property_map(chart));
  BOOST_REQUIRE(r);
  BOOST_REQUIRE(r.rejected_charts == 0u);
  const auto s = QD::shorten_chart_cuts(tm, boost::make_assoc_property_map(chart), r);
  BOOST_REQUIRE(s);
  BOOST_TEST_MESSAGE("fandisk: " << s.cuts_shortened << " of " << s.cut_curves << " cuts shortened, "
                                 << s.cut_length_closed << " of " << s.cut_length << " closed in " << s.trials
                                 << " trials; seams " << r.seam_length << " -> " << s.flattening.seam_length
                                 << ", compactness " << r.compactness << " -> " << s.flattening.compactness);
  BOOST_TEST(s.kept);
  BOOST_TEST(s.cut_curves >= 2u);
  BOOST_TEST(s.cuts_shortened >= 1u);
  // a tenth of the cuts at least: fandisk's pieces keep long darts that they do not need whole
  BOOST_TEST(s.cut_length_closed > 0.1 * s.cut_length);
  BOOST_TEST(s.cut_length_closed < s.cut_length);
  const auto& f = s.flattening;
  BOOST_TEST(f.number_of_charts == r.number_of_charts);
  BOOST_TEST(f.rejected_charts == 0u);
  BOOST_TEST(f.overlapping_charts == 0u);
  BOOST_TEST(f.max_local_area_distortion <= 2.5);
  BOOST_TEST(f.number_of_seam_curves - f.seam_curves_matched <= r.number_of_seam_curves - r.seam_curves_matched);
  BOOST_TEST(f.seam_length == r.seam_length - s.cut_length_closed, tt::tolerance(1e-9));
  BOOST_TEST(f.compactness > r.compactness);
  // the cuts left are a subset of those before, and no border between two charts went
  const std::set<Surface_mesh::Edge_index> before(r.seam_edges.begin(), r.seam_edges.end());
  for(auto e : f.seam_edges) BOOST_TEST(before.count(e) == 1u);
  for(auto e : r.seam_edges) {
    const auto h = halfedge(e, tm);
    if(chart.at(face(h, tm)) != chart.at(face(opposite(h, tm), tm)))
      BOOST_TEST(std::count(f.seam_edges.begin(), f.seam_edges.end(), e) == 1);
  }
  // on one thread: the same trials, cuts and flattening
  const auto one = QD::shorten_chart_cuts<CGAL::Sequential_tag>(tm, boost::make_assoc_property_map(chart), r);
  BOOST_REQUIRE(one);
  BOOST_TEST(one.trials == s.trials);
  BOOST_TEST(one.cuts_shortened == s.cuts_shortened);
  BOOST_TEST(one.cut_length_closed == s.cut_length_closed);
  BOOST_TEST((one.flattening.seam_edges == f.seam_edges));
  BOOST_TEST((one.flattening.corner_uv == f.corner_uv));
}

// Coordinates beyond [2^-64, 2^64] (segment_mesh's seams were left unsmoothed
// there, and a refused smoothing once emptied its result): the seam smoothing
// and the cut shortening work on the points scaled by a power of two, as the
// segmentation does, so fandisk at 2^100 and 2^-100 gives what it gives at 1,
// the points, UVs and lengths multiplied by the scale, to the last bit
BOOST_AUTO_TEST_CASE(seams_smoothed_and_cuts_shortened_in_any_finite_range)
{
  Surface_mesh input;
  BOOST_REQUIRE(CGAL::IO::read_polygon_mesh(std::string(CGAL_QD_DEMO_MESH_DIR) + "/fandisk.off", input));
  struct Run
  {
    Surface_mesh tm, out;
    Face_map<Surface_mesh> chart, out_chart;
    QD::Segmentation_result<Surface_mesh> seg;
    QD::Seam_smoothing_result<Surface_mesh> smoothing;
    QD::Cut_shortening_result<Surface_mesh> shortening;
  };
  auto run = [&](double scale) {
    auto r = std::make_unique<Run>();
    r->tm = input;
    for(auto v : vertices(r->tm)) {
      const auto p = r->tm.point(v);
      r->tm.point(v) = Surface_mesh::Point(p.x() * scale, p.y() * scale, p.z() * scale);
    }
    r->seg = QD::segment_quasi_developable(r->tm, boost::make_assoc_property_map(r->chart),
                                           QD::parameters::final_flattening(false));
    BOOST_REQUIRE(r->seg);
    r->smoothing = QD::smooth_segmentation_seams(r->tm, boost::make_assoc_property_map(r->chart), r->seg, r->out,
                                                 boost::make_assoc_property_map(r->out_chart));
    BOOST_REQUIRE_MESSAGE(r->smoothing, QD::error_message(r->smoothing.status));
    BOOST_REQUIRE(r->smoothing.kept);
    r->shortening = QD::shorten_chart_cuts(r->out, boost::make_assoc_property_map(r->out_chart),
                                           r->smoothing.flattening);
    BOOST_REQUIRE_MESSAGE(r->shortening, QD::error_message(r->shortening.status));
    return r;
  };
  const auto base = run(1.);
  BOOST_TEST(base->smoothing.smoothing.curves_smoothed > 0u);
  BOOST_TEST(base->shortening.kept);
  for(const double scale : {0x1p100, 0x1p-100}) {
    BOOST_TEST_CONTEXT("scale " << scale)
    {
      const auto r = run(scale);
      BOOST_TEST(r->chart == base->chart);
      // the smoothed mesh, its charts and flattening
      const auto &s = r->smoothing, &s0 = base->smoothing;
      BOOST_TEST(s.tries == s0.tries);
      BOOST_TEST(s.smoothing.curves_smoothed == s0.smoothing.curves_smoothed);
      BOOST_TEST(s.smoothing.max_border_move == s0.smoothing.max_border_move * scale);
      BOOST_REQUIRE(num_vertices(r->out) == num_vertices(base->out));
      BOOST_REQUIRE(num_faces(r->out) == num_faces(base->out));
      bool same_points = true;
      for(auto v : vertices(r->out)) {
        const auto p = r->out.point(v), p0 = base->out.point(v);
        same_points = same_points && p.x() == p0.x() * scale && p.y() == p0.y() * scale && p.z() == p0.z() * scale;
      }
      BOOST_TEST(same_points);
      BOOST_TEST(r->out_chart == base->out_chart);
      auto scaled_uv = [scale](std::vector<std::array<double, 2>> uv) {
        for(auto& x : uv) x = {{x[0] * scale, x[1] * scale}};
        return uv;
      };
      BOOST_TEST((s.flattening.corner_uv == scaled_uv(s0.flattening.corner_uv)));
      BOOST_TEST(s.flattening.seam_length == s0.flattening.seam_length * scale);
      BOOST_TEST(s.flattening.seam_zigzag == s0.flattening.seam_zigzag);
      BOOST_TEST(s.flattening.seam_curves_matched == s0.flattening.seam_curves_matched);
      BOOST_TEST(s.flattening.points.size() == num_vertices(r->out));
      BOOST_TEST(s.flattening.points.back()[0] == s0.flattening.points.back()[0] * scale);
      BOOST_TEST(!s.input_flattening.flattened);  // every seam of the first try matched
      // the cuts shortened on the smoothed mesh
      const auto &c = r->shortening, &c0 = base->shortening;
      BOOST_TEST(c.kept == c0.kept);
      BOOST_TEST(c.trials == c0.trials);
      BOOST_TEST(c.cuts_shortened == c0.cuts_shortened);
      BOOST_TEST(c.cut_length == c0.cut_length * scale);
      BOOST_TEST(c.cut_length_closed == c0.cut_length_closed * scale);
      BOOST_TEST((c.flattening.seam_edges == c0.flattening.seam_edges));
      BOOST_TEST((c.flattening.corner_uv == scaled_uv(c0.flattening.corner_uv)));
      BOOST_TEST(c.flattening.seam_length == c0.flattening.seam_length * scale);
      BOOST_TEST(c.flattening.points.back()[2] == c0.flattening.points.back()[2] * scale);
    }
  }
  // a smoothing refused leaves nothing flattened in its result (segment_mesh
  // took such an empty flattening for the charts and lost them)
  Surface_mesh not_empty = input;
  const auto refused = QD::smooth_segmentation_seams(base->tm, boost::make_assoc_property_map(base->chart), base->seg,
                                                     not_empty, boost::make_assoc_property_map(base->out_chart));
  BOOST_TEST((refused.status == QD::Error_code::INVALID_ARGUMENT));
  BOOST_TEST(!refused.kept);
  BOOST_TEST(!refused.input_flattening.flattened);
  BOOST_TEST(!refused.flattening.flattened);
}

// elephant at a quarter of its faces (written with 17 digits and read back),
// segmented and its seams smoothed as segment_mesh does: the first
// flattening after the trials leaves seams unmatched that matched before, so
// the cuts of the pieces along them go back and the pieces are flattened
// again; what is kept has every piece within the thresholds, no more seams
// unmatched than before, and the cuts that did not go back
BOOST_AUTO_TEST_CASE(failing_pieces_get_their_cuts_back)
{
  // through an OFF file, as segment_mesh reads it (which numbers its halfedges anew)
  std::stringstream off;
  BOOST_REQUIRE(CGAL::IO::write_OFF(off, at_resolution(read_demo_mesh("elephant"), -2),
                                    CGAL::parameters::stream_precision(17)));
  Series_mesh tm;
  BOOST_REQUIRE(CGAL::IO::read_OFF(off, tm));
  Chart_map<Series_mesh> chart;
  const auto r = QD::segment_quasi_developable(tm, boost::make_assoc_property_map(chart),
                                               QD::parameters::final_flattening(false));
  BOOST_REQUIRE(r);
  Series_mesh out;
  Chart_map<Series_mesh> out_chart;
  const auto smoothed = QD::smooth_segmentation_seams(tm, boost::make_assoc_property_map(chart), r, out,
                                                      boost::make_assoc_property_map(out_chart));
  BOOST_REQUIRE(smoothed);
  BOOST_REQUIRE(smoothed.kept);
  const auto& seg = smoothed.flattening;
  BOOST_REQUIRE(seg.rejected_charts == 0u);
  const auto s = QD::shorten_chart_cuts(out, boost::make_assoc_property_map(out_chart), seg);
  BOOST_REQUIRE(s);
  BOOST_TEST_MESSAGE("elephant at a quarter: " << num_faces(tm) << " faces, " << r.number_of_charts << " charts, "
                                               << smoothed.smoothing.curves_smoothed << " curves smoothed in "
                                               << smoothed.tries << " tries; " << s.cut_curves << " cuts, "
                                               << s.cuts_passing_trials << " pass their trials, " << s.cuts_shortened
                                               << " kept after " << s.flattenings << " flattenings");
  BOOST_TEST(s.flattenings >= 2u);
  BOOST_TEST(s.kept);
  BOOST_TEST(s.cuts_shortened >= 1u);
  BOOST_TEST(s.cuts_shortened < s.cuts_passing_trials);
  const auto& f = s.flattening;
  BOOST_TEST(f.rejected_charts == 0u);
  BOOST_TEST(f.overlapping_charts == 0u);
  BOOST_TEST(f.number_of_seam_curves - f.seam_curves_matched <= seg.number_of_seam_curves - seg.seam_curves_matched);
  BOOST_TEST(f.seam_length == seg.seam_length - s.cut_length_closed, tt::tolerance(1e-9));
  // the seams left are the input's but for the edges closed
  const std::set<Series_mesh::Edge_index> before(seg.seam_edges.begin(), seg.seam_edges.end());
  for(auto e : f.seam_edges) BOOST_TEST(before.count(e) == 1u);
  BOOST_TEST(f.seam_edges.size() < seg.seam_edges.size());
  // on one thread: the same
  const auto one = QD::shorten_chart_cuts<CGAL::Sequential_tag>(out, boost::make_assoc_property_map(out_chart), seg);
  BOOST_REQUIRE(one);
  BOOST_TEST(one.flattenings == s.flattenings);
  BOOST_TEST(one.cuts_shortened == s.cuts_shortened);
  BOOST_TEST((one.flattening.seam_edges == f.seam_edges));
  BOOST_TEST((one.flattening.corner_uv == f.corner_uv));
}

BOOST_AUTO_TEST_CASE(cut_shortening_rejects_bad_input)
{
  Surface_mesh tm = make<Surface_mesh>(polar(4, 16, flat_disk(1.)));
  Face_map<Surface_mesh> chart;
  for(auto f : faces(tm)) chart[f] = 0;
  const auto f = QD::flatten_charts(tm, boost::make_assoc_property_map(chart));
  BOOST_REQUIRE(f);
  // without cuts: nothing to do
  const auto none = QD::shorten_chart_cuts(tm, boost::make_assoc_property_map(chart), f);
  BOOST_REQUIRE(none);
  BOOST_TEST(!none.kept);
  BOOST_TEST(none.cut_curves == 0u);
  BOOST_TEST(none.trials == 0u);
  // a segmentation of another mesh, one not flattened, a chart id out of range, a bad threshold
  const Surface_mesh other = make<Surface_mesh>(polar(5, 16, flat_disk(1.)));
  Face_map<Surface_mesh> other_chart;
  for(auto g : faces(other)) other_chart[g] = 0;
  BOOST_TEST(QD::shorten_chart_cuts(other, boost::make_assoc_property_map(other_chart), f).status ==
             QD::Error_code::INVALID_ARGUMENT);
  QD::Chart_flattening_result<Surface_mesh> unflattened = f;
  unflattened.flattened = false;
  BOOST_TEST(QD::shorten_chart_cuts(tm, boost::make_assoc_property_map(chart), unflattened).status ==
             QD::Error_code::INVALID_ARGUMENT);
  QD::Chart_flattening_result<Surface_mesh> without_uv = f;
  without_uv.corner_uv.clear();
  BOOST_TEST(QD::shorten_chart_cuts(tm, boost::make_assoc_property_map(chart), without_uv).status ==
             QD::Error_code::INVALID_ARGUMENT);
  Face_map<Surface_mesh> beyond = chart;
  beyond[*faces(tm).begin()] = 1;
  BOOST_TEST(QD::shorten_chart_cuts(tm, boost::make_assoc_property_map(beyond), f).status ==
             QD::Error_code::INVALID_ARGUMENT);
  BOOST_TEST(QD::shorten_chart_cuts(tm, boost::make_assoc_property_map(chart), f,
                                    QD::parameters::area_preservation(2.))
                 .status == QD::Error_code::INVALID_ARGUMENT);
  BOOST_TEST(QD::shorten_chart_cuts(tm, boost::make_assoc_property_map(chart), f,
                                    QD::parameters::max_local_area_distortion(-0.01))
                 .status == QD::Error_code::INVALID_ARGUMENT);
  BOOST_TEST(QD::shorten_chart_cuts(tm, boost::make_assoc_property_map(chart), f,
                                    QD::parameters::max_l2_stretch(std::nan("")))
                 .status == QD::Error_code::INVALID_ARGUMENT);
  // invalid coordinates
  tm.point(*vertices(tm).begin()) = Surface_mesh::Point(std::nan(""), 0, 0);
  BOOST_TEST(QD::shorten_chart_cuts(tm, boost::make_assoc_property_map(chart), f).status ==
             QD::Error_code::INVALID_COORDINATES);
  Surface_mesh empty;
  Face_map<Surface_mesh> no_chart;
  BOOST_TEST(QD::shorten_chart_cuts(empty, boost::make_assoc_property_map(no_chart), f).status ==
             QD::Error_code::EMPTY_MESH);
}

BOOST_AUTO_TEST_SUITE_END()
} // namespace seam_measures_tests

// ===================================================================== a trial's mesh in one pass
// internal/add_triangles.h builds the chart of a trial in one pass: it must
// give the mesh that add_face() gives face after face (the same edges, faces,
// next halfedges and border), and refuse what is not a manifold oriented
// surface, which the evaluator then hands to add_face().

#include <CGAL_QD/internal/add_triangles.h>
#include <CGAL/boost/graph/helpers.h>

namespace {

// the mesh's vertices alone
Surface_mesh vertices_of(const std::vector<Epick::Point_3>& points)
{
  Surface_mesh out;
  for(const Epick::Point_3& p : points) out.add_vertex(p);
  return out;
}

void expect_same_as_add_face(const std::vector<Epick::Point_3>& points, const std::vector<std::size_t>& corners,
                             const std::string& name)
{
  typedef Surface_mesh::Vertex_index V;
  Surface_mesh fast = vertices_of(points), slow = vertices_of(points);
  BOOST_REQUIRE_MESSAGE(QD::internal::add_triangles(fast, corners), name);
  for(std::size_t i = 0; i + 2 < corners.size(); i += 3)
    BOOST_REQUIRE(slow.add_face(V(Surface_mesh::size_type(corners[i])), V(Surface_mesh::size_type(corners[i + 1])),
                                V(Surface_mesh::size_type(corners[i + 2]))) != Surface_mesh::null_face());
  // (a vertex of no face makes both invalid: the grid with holes has one)
  BOOST_TEST(CGAL::is_valid_polygon_mesh(fast) == CGAL::is_valid_polygon_mesh(slow), name);
  BOOST_TEST(fast.number_of_halfedges() == slow.number_of_halfedges(), name);
  BOOST_TEST(fast.number_of_faces() == slow.number_of_faces(), name);
  std::size_t differ = 0;
  for(auto h : slow.halfedges())
    if(fast.target(h) != slow.target(h) || fast.face(h) != slow.face(h) || fast.next(h) != slow.next(h)) ++differ;
  for(auto f : slow.faces())
    if(fast.halfedge(f) != slow.halfedge(f)) ++differ;
  for(auto v : slow.vertices()) {
    // an incoming halfedge; on the border, the one border halfedge that comes in
    if(slow.halfedge(v) == Surface_mesh::null_halfedge()) {  // no face
      if(fast.halfedge(v) != Surface_mesh::null_halfedge()) ++differ;
      continue;
    }
    const bool border = bool(is_border(v, slow));
    if(fast.target(fast.halfedge(v)) != v || is_border(fast.halfedge(v), fast) != border) ++differ;
    if(border && fast.halfedge(v) != slow.halfedge(v)) ++differ;
  }
  BOOST_TEST(differ == 0u, name << ": " << differ << " differences");
}

} // namespace

BOOST_AUTO_TEST_CASE(add_triangles_builds_what_add_face_builds)
{
  using namespace qd_test;
  const std::vector<std::pair<std::string, Soup>> soups = {
      {"disk", polar(6, 24, sphere_cap(0.8))},
      {"grid with two holes", grid(12, 9, bump(0.2), holes({{{2, 4, 2, 4}}, {{7, 10, 3, 6}}}))},
      {"open torus", torus(16, 8, true)},
      {"closed torus", torus(16, 8)}};
  for(const auto& s : soups) {
    std::vector<Epick::Point_3> points;
    for(const auto& p : s.second.points) points.emplace_back(p[0], p[1], p[2]);
    std::vector<std::size_t> corners;
    for(const auto& t : s.second.triangles) corners.insert(corners.end(), t.begin(), t.end());
    expect_same_as_add_face(points, corners, s.first);
  }
#ifdef CGAL_QD_DEMO_MESH_DIR
  Surface_mesh fandisk;
  BOOST_REQUIRE(CGAL::IO::read_polygon_mesh(std::string(CGAL_QD_DEMO_MESH_DIR) + "/fandisk.off", fandisk));
  std::vector<Epick::Point_3> points;
  for(auto v : fandisk.vertices()) points.push_back(fandisk.point(v));
  std::vector<std::size_t> corners;
  for(auto f : fandisk.faces())
    for(auto v : CGAL::vertices_around_face(fandisk.halfedge(f), fandisk)) corners.push_back(v.idx());
  expect_same_as_add_face(points, corners, "fandisk");
#endif
}

BOOST_AUTO_TEST_CASE(add_triangles_refuses_what_is_not_a_manifold_surface)
{
  std::vector<Epick::Point_3> points;
  for(int i = 0; i < 6; ++i) points.emplace_back(std::cos(i), std::sin(i), 0.1 * i);
  const std::vector<std::pair<std::string, std::vector<std::size_t>>> cases = {
      {"an edge used twice in one direction", {0, 1, 2, 0, 1, 3}},
      {"an edge of three faces", {0, 1, 2, 1, 0, 3, 0, 1, 4}},
      {"two fans at a vertex (bow tie)", {0, 1, 2, 0, 3, 4}},
      {"a closed fan and an open one at a vertex", {0, 1, 2, 0, 2, 3, 0, 3, 1, 0, 4, 5}},
      {"a repeated vertex", {0, 0, 1}},
      {"a vertex index out of range", {0, 1, 6}}};
  for(const auto& c : cases) {
    Surface_mesh sm = vertices_of(points);
    BOOST_TEST(!QD::internal::add_triangles(sm, c.second), c.first);
  }
}

// ============================================ a chart cut open, and its measures
// internal/chart_mesh.h builds the mesh of a chart cut open from its wedges
// and judges a flattening of it against the thresholds, as every trial, fit
// and final flattening of the segmentation does.

#include <CGAL_QD/internal/chart_mesh.h>

BOOST_AUTO_TEST_CASE(chart_mesh_is_built_and_measured_against_the_thresholds)
{
  using namespace qd_test;
  namespace tt = boost::test_tools;
  typedef QD::internal::Chart_mesh Chart_mesh;
  typedef Chart_mesh::Vertex_index V;
  // a flat 1 x 0.75 rectangle of 8 x 6 cells
  Surface_mesh src;
  BOOST_REQUIRE(build(grid(8, 6, [](double x, double y) { return P3{{x, 0.75 * y, 0.}}; }), src));
  std::vector<std::array<double, 3>> points;
  QD::internal::Wedges<Surface_mesh> wedges;  // one wedge per vertex: nothing is cut
  for(auto v : src.vertices()) {
    points.push_back({src.point(v).x(), src.point(v).y(), src.point(v).z()});
    wedges.vertex_of_wedge.push_back(v);
  }
  for(auto f : src.faces())
    for(auto v : CGAL::vertices_around_face(src.halfedge(f), src)) wedges.wedge_of_corner.push_back(v.idx());
  const std::size_t nf = src.number_of_faces();
  Chart_mesh sm;
  double area = -1;
  BOOST_REQUIRE(QD::internal::build_chart_mesh(wedges, nf, get(CGAL::vertex_index, src), points, sm, area) ==
                QD::Error_code::OK);
  BOOST_TEST(sm.number_of_faces() == nf);
  BOOST_TEST(sm.number_of_vertices() == src.number_of_vertices());
  BOOST_TEST(CGAL::is_valid_polygon_mesh(sm));
  BOOST_TEST(area == 0.75, tt::tolerance(1e-12));
  BOOST_TEST(QD::internal::number_of_border_loops(sm) == 1u);

  // the rectangle as it is: accepted, with no distortion
  auto uv = sm.add_property_map<V, Epick::Point_2>("v:uv", Epick::Point_2(0, 0)).first;
  for(V v : sm.vertices()) put(uv, v, Epick::Point_2(sm.point(v).x(), sm.point(v).y()));
  const QD::internal::Merge_thresholds defaults;
  QD::Chart_report rep;
  BOOST_REQUIRE(QD::internal::measure_chart_flattening(sm, uv, defaults, rep));
  BOOST_TEST(rep.accepted);
  BOOST_TEST(rep.area_distortion < 1e-9);
  BOOST_TEST(rep.l2_stretch == 1.0, tt::tolerance(1e-9));
  BOOST_TEST(rep.local_area_distortion < 1e-9);
  BOOST_TEST(!rep.overlap);
  BOOST_TEST(rep.max_border_length_error < 1e-12);

  // the same rectangle with its columns moved along x: the same total area
  // (A(Omega) 0), but each triangle's area changed by up to 31 %, so A_loc is
  // far beyond 2.5 %; the paper's criterion, which does not look at A_loc,
  // accepts it
  for(V v : sm.vertices()) {
    const double x = sm.point(v).x();
    put(uv, v, Epick::Point_2(x + 0.05 * std::sin(2 * CGAL_PI * x), sm.point(v).y()));
  }
  BOOST_REQUIRE(QD::internal::measure_chart_flattening(sm, uv, defaults, rep));
  BOOST_TEST(rep.area_distortion < 1e-9);
  BOOST_TEST(rep.local_area_distortion > 10.);
  BOOST_TEST(rep.l2_stretch < 2.);
  BOOST_TEST(!rep.overlap);
  BOOST_TEST(!rep.accepted);
  BOOST_TEST(rep.max_border_length_error > 0.1);  // the border edges along x changed length
  QD::internal::Merge_thresholds paper = defaults;
  paper.criterion = QD::Chart_criterion::LPFB_IP;
  BOOST_REQUIRE(QD::internal::measure_chart_flattening(sm, uv, paper, rep));
  BOOST_TEST(rep.accepted);

  // twice the size: A(Omega) 300 %
  for(V v : sm.vertices()) put(uv, v, Epick::Point_2(2 * sm.point(v).x(), 2 * sm.point(v).y()));
  BOOST_REQUIRE(QD::internal::measure_chart_flattening(sm, uv, paper, rep));
  BOOST_TEST(rep.area_distortion == 300., tt::tolerance(1e-9));
  BOOST_TEST(!rep.accepted);

  // wedges that make no manifold surface: an edge used twice in one direction
  QD::internal::Wedges<Surface_mesh> bad;
  bad.vertex_of_wedge.assign(wedges.vertex_of_wedge.begin(), wedges.vertex_of_wedge.begin() + 4);
  bad.wedge_of_corner = {0, 1, 2, 0, 1, 3};
  Chart_mesh broken;
  double unset = -1;
  BOOST_TEST(QD::internal::build_chart_mesh(bad, 2, get(CGAL::vertex_index, src), points, broken, unset) ==
             QD::Error_code::NON_MANIFOLD);

  // which of two rejected flattenings is nearer the thresholds: one without
  // an overlap before one with; then the smaller largest ratio to a bound
  QD::Chart_report crossing, stretched, spread;
  crossing.overlap = true;
  stretched.l2_stretch = 3.;          // 1.5 times its bound
  spread.local_area_distortion = 3.;  // 1.2 times its bound
  BOOST_TEST(QD::internal::nearer_thresholds(stretched, crossing, defaults));
  BOOST_TEST(!QD::internal::nearer_thresholds(crossing, stretched, defaults));
  BOOST_TEST(QD::internal::nearer_thresholds(spread, stretched, defaults));
  BOOST_TEST(!QD::internal::nearer_thresholds(stretched, spread, defaults));
}
