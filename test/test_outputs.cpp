// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#define BOOST_TEST_MODULE outputs
#include <boost/test/unit_test.hpp>

#include "mesh_generators.h"
#include "test_utils.h"

#include <CGAL_QD/IO/charts_and_atlas.h>
#include <CGAL_QD/IO/patterns_svg.h>
#include <CGAL_QD/IO/segmentation_svg.h>
#include <CGAL_QD/pack_charts.h>
#include <CGAL_QD/segment_quasi_developable.h>

#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Surface_mesh/IO/PLY.h>

#include <boost/property_tree/ptree.hpp>
#include <boost/property_tree/xml_parser.hpp>

#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace QD = CGAL_QD;
using namespace qd_test;

namespace {

typedef std::map<Surface_mesh::Face_index, std::size_t> Chart_map;

struct Segmented
{
  Surface_mesh tm;
  Chart_map chart;
  QD::Segmentation_result<Surface_mesh> result;
};

// a torus (closed, genus 1) and, when CGAL's meshes are there, fandisk; with
// the paper's criterion, so that every border edge keeps its 3D length in the
// patterns (the default's pieces are checked in test_segmentation)
std::vector<Segmented> segmented_meshes()
{
  std::vector<Segmented> out(1);
  out[0].tm = make<Surface_mesh>(torus(48, 24));
#ifdef CGAL_QD_DEMO_MESH_DIR
  out.emplace_back();
  BOOST_REQUIRE(CGAL::IO::read_polygon_mesh(std::string(CGAL_QD_DEMO_MESH_DIR) + "/fandisk.off", out[1].tm));
#endif
  for(Segmented& s : out) {
    s.result = QD::segment_quasi_developable(
        s.tm, boost::make_assoc_property_map(s.chart),
        QD::parameters::chart_criterion(QD::Chart_criterion::LPFB_IP,
                                        QD::parameters::merge_order(QD::Merge_order::LONGEST_RELATIVE_CURVE_FIRST)));
    BOOST_REQUIRE(s.result);
  }
  return out;
}

const std::vector<Segmented>& meshes()
{
  static const std::vector<Segmented> m = segmented_meshes();
  return m;
}

} // namespace

BOOST_AUTO_TEST_CASE(atlas_charts_fit_the_unit_square_without_overlap)
{
  for(const Segmented& s : meshes()) {
    const QD::Atlas_result a = QD::pack_charts(s.tm, boost::make_assoc_property_map(s.chart), s.result.corner_uv);
    BOOST_REQUIRE(a);
    const std::size_t n = s.result.number_of_charts;
    BOOST_TEST(a.charts.size() == n);
    BOOST_TEST_MESSAGE(n << " charts packed, coverage " << a.coverage << ", scale " << a.scale);
    BOOST_TEST(a.coverage > 0.25);
    BOOST_TEST(a.coverage <= 1.0);
    // every UV in the unit square; per chart, the box of its UVs
    std::vector<std::array<double, 4>> box(n, {{1e300, 1e300, -1e300, -1e300}});
    std::size_t i = 0;
    for(auto f : faces(s.tm)) {
      const std::size_t k = s.chart.at(f);
      for(int c = 0; c < 3; ++c) {
        const auto& p = a.corner_uv[3 * i + c];
        BOOST_TEST((p[0] >= -1e-12 && p[0] <= 1 + 1e-12 && p[1] >= -1e-12 && p[1] <= 1 + 1e-12));
        box[k][0] = std::min(box[k][0], p[0]);
        box[k][1] = std::min(box[k][1], p[1]);
        box[k][2] = std::max(box[k][2], p[0]);
        box[k][3] = std::max(box[k][3], p[1]);
      }
      // a similarity of the chart's flattening: lengths times the common scale, orientation kept
      const auto& u = s.result.corner_uv;
      const auto& v = a.corner_uv;
      auto len = [](const std::array<double, 2>& x, const std::array<double, 2>& y) {
        return std::hypot(x[0] - y[0], x[1] - y[1]);
      };
      for(int c = 0; c < 3; ++c) {
        const double l0 = len(u[3 * i + c], u[3 * i + (c + 1) % 3]), l1 = len(v[3 * i + c], v[3 * i + (c + 1) % 3]);
        BOOST_TEST(std::abs(l1 - a.scale * l0) <= 1e-9 * (1e-12 + a.scale * l0));
      }
      auto signed_area = [](const std::array<double, 2>& x, const std::array<double, 2>& y, const std::array<double, 2>& z) {
        return (y[0] - x[0]) * (z[1] - x[1]) - (y[1] - x[1]) * (z[0] - x[0]);
      };
      BOOST_TEST(signed_area(u[3 * i], u[3 * i + 1], u[3 * i + 2]) * signed_area(v[3 * i], v[3 * i + 1], v[3 * i + 2]) > 0);
      ++i;
    }
    // the charts' boxes are disjoint: no chart overlaps another
    for(std::size_t p = 0; p < n; ++p)
      for(std::size_t q = p + 1; q < n; ++q) {
        const bool apart = box[p][2] <= box[q][0] || box[q][2] <= box[p][0] || box[p][3] <= box[q][1] ||
                           box[q][3] <= box[p][1];
        BOOST_TEST(apart, "charts " << p << " and " << q << " overlap in the atlas");
      }
  }
}

BOOST_AUTO_TEST_CASE(atlas_rejects_bad_uvs)
{
  const Segmented& s = meshes().front();
  auto uv = s.result.corner_uv;
  uv.pop_back();
  BOOST_TEST((QD::pack_charts(s.tm, boost::make_assoc_property_map(s.chart), uv).status ==
              QD::Error_code::INVALID_COORDINATES));
  uv = s.result.corner_uv;
  uv[5][1] = std::numeric_limits<double>::quiet_NaN();
  BOOST_TEST((QD::pack_charts(s.tm, boost::make_assoc_property_map(s.chart), uv).status ==
              QD::Error_code::INVALID_COORDINATES));
  const Surface_mesh empty;
  Chart_map none;
  BOOST_TEST((QD::pack_charts(empty, boost::make_assoc_property_map(none), {}).status == QD::Error_code::EMPTY_MESH));
}

BOOST_AUTO_TEST_CASE(ply_with_charts_reloads_through_cgal)
{
  for(const Segmented& s : meshes()) {
    std::stringstream ss;
    BOOST_REQUIRE(QD::IO::write_PLY_with_charts(ss, s.tm, boost::make_assoc_property_map(s.chart)));
    Surface_mesh back;
    BOOST_REQUIRE(CGAL::IO::read_PLY(ss, back));
    BOOST_TEST(num_vertices(back) == num_vertices(s.tm));
    BOOST_TEST(num_faces(back) == num_faces(s.tm));
    const auto chart = back.property_map<Surface_mesh::Face_index, boost::int32_t>("f:chart");
    const auto color = back.property_map<Surface_mesh::Face_index, CGAL::IO::Color>("f:color");
    BOOST_REQUIRE(chart.second);
    BOOST_REQUIRE(color.second);
    auto fb = faces(back).begin();
    for(auto f : faces(s.tm)) {
      const std::size_t k = s.chart.at(f);
      BOOST_TEST(std::size_t(chart.first[*fb]) == k);
      const auto c = QD::IO::chart_color(k);
      BOOST_TEST((color.first[*fb].red() == c[0] && color.first[*fb].green() == c[1] && color.first[*fb].blue() == c[2]));
      // the same corners, in the same order
      auto v0 = CGAL::vertices_around_face(halfedge(f, s.tm), s.tm).begin();
      for(auto w : CGAL::vertices_around_face(halfedge(*fb, back), back)) {
        BOOST_TEST(p3(back, w) == p3(s.tm, *v0));
        ++v0;
      }
      ++fb;
    }
  }
  // chart colours are pairwise distinct over the first 64 ids
  std::set<std::array<unsigned char, 3>> colors;
  for(std::size_t k = 0; k < 64; ++k) colors.insert(QD::IO::chart_color(k));
  BOOST_TEST(colors.size() == 64u);
}

BOOST_AUTO_TEST_CASE(obj_with_uv_keeps_every_corner)
{
  for(const Segmented& s : meshes()) {
    const QD::Atlas_result a = QD::pack_charts(s.tm, boost::make_assoc_property_map(s.chart), s.result.corner_uv);
    std::stringstream ss;
    BOOST_REQUIRE(QD::IO::write_OBJ_with_uv(ss, s.tm, a.corner_uv, "atlas.mtl", "atlas"));
    std::vector<std::array<double, 3>> v;
    std::vector<std::array<double, 2>> vt;
    std::vector<std::vector<std::pair<std::size_t, std::size_t>>> f;
    std::string line, mtllib, usemtl;
    while(std::getline(ss, line)) {
      std::istringstream ls(line);
      std::string tag;
      ls >> tag;
      if(tag == "v") {
        std::array<double, 3> p;
        ls >> p[0] >> p[1] >> p[2];
        v.push_back(p);
      } else if(tag == "vt") {
        std::array<double, 2> p;
        ls >> p[0] >> p[1];
        vt.push_back(p);
      } else if(tag == "f") {
        f.emplace_back();
        std::string c;
        while(ls >> c) {
          const std::size_t slash = c.find('/');
          f.back().emplace_back(std::stoul(c.substr(0, slash)), std::stoul(c.substr(slash + 1)));
        }
      } else if(tag == "mtllib") ls >> mtllib;
      else if(tag == "usemtl") ls >> usemtl;
    }
    BOOST_TEST(mtllib == "atlas.mtl");
    BOOST_TEST(usemtl == "atlas");
    BOOST_TEST(v.size() == num_vertices(s.tm));
    BOOST_TEST(f.size() == num_faces(s.tm));
    BOOST_TEST(vt.size() >= num_vertices(s.tm));  // seams add coordinates
    std::size_t i = 0;
    for(auto face : faces(s.tm)) {
      BOOST_REQUIRE(f[i].size() == 3u);
      int c = 0;
      for(auto h : CGAL::halfedges_around_face(halfedge(face, s.tm), s.tm)) {
        const auto& corner = f[i][c];
        BOOST_TEST(v[corner.first - 1] == p3(s.tm, target(h, s.tm)));
        BOOST_TEST(vt[corner.second - 1] == a.corner_uv[3 * i + c]);  // 17 digits: exact round trip
        ++c;
      }
      ++i;
    }
  }
  std::stringstream ss;
  const Segmented& s = meshes().front();
  BOOST_TEST(!QD::IO::write_OBJ_with_uv(ss, s.tm, std::vector<std::array<double, 2>>(3)));
  BOOST_TEST(ss.str().empty());
}

BOOST_AUTO_TEST_CASE(patterns_are_true_scale_with_matching_labels)
{
  for(const Segmented& s : meshes()) {
    QD::IO::Pattern_options options;
    options.scale = 100;  // drawing units per mesh unit
    options.tabs = true;
    std::stringstream ss;
    const QD::IO::Pattern_result pr = QD::IO::write_patterns_SVG(
        ss, s.tm, boost::make_assoc_property_map(s.chart), s.result.corner_uv, s.result.seam_edges, options);
    BOOST_REQUIRE(pr);
    BOOST_TEST_MESSAGE(pr.number_of_charts << " pieces on " << pr.number_of_pages << " pages, " << pr.seam_labels
                                           << " seam labels, " << pr.fold_lines << " fold lines, " << pr.tabs << " tabs");
    BOOST_TEST(pr.number_of_charts == s.result.number_of_charts);
    // well-formed XML, parsed by Boost.PropertyTree
    boost::property_tree::ptree tree;
    BOOST_REQUIRE_NO_THROW(boost::property_tree::read_xml(ss, tree));
    const auto& svg = tree.get_child("svg");
    std::map<std::string, int> labels;
    std::size_t cuts = 0, charts = 0, tabs = 0;
    std::vector<Surface_mesh::Vertex_index> vs(vertices(s.tm).begin(), vertices(s.tm).end());
    double worst = 0;
    for(const auto& child : svg) {
      const auto& node = child.second;
      const std::string cls = node.get<std::string>("<xmlattr>.class", "");
      if(child.first == "text" && cls == "seam") ++labels[node.data()];
      if(child.first == "text" && cls == "chart") ++charts;
      if(child.first == "polygon" && cls == "tab") ++tabs;
      if(child.first == "line" && cls == "cut") {
        ++cuts;
        std::istringstream ids(node.get<std::string>("<xmlattr>.data-v"));
        std::size_t i, j;
        ids >> i >> j;
        const double l3 = std::sqrt(CGAL::squared_distance(s.tm.point(vs[i]), s.tm.point(vs[j])));
        const double l2 = std::hypot(node.get<double>("<xmlattr>.x2") - node.get<double>("<xmlattr>.x1"),
                                     node.get<double>("<xmlattr>.y2") - node.get<double>("<xmlattr>.y1"));
        worst = std::max(worst, std::abs(l2 - options.scale * l3));
      }
    }
    // printed edge lengths are the 3D lengths at the scale, to the SVG's 4 decimals
    BOOST_TEST(worst < 2e-4);
    BOOST_TEST(cuts == pr.cut_edges);
    BOOST_TEST(charts == s.result.number_of_charts);
    BOOST_TEST(tabs == pr.tabs);
    BOOST_TEST(labels.size() == pr.seam_labels);
    for(const auto& l : labels) BOOST_TEST(l.second == 2, "label " << l.first << " appears " << l.second << " times");
    // every seam edge is cut on both sides, every mesh border edge on one
    std::size_t border = 0;
    for(auto h : halfedges(s.tm)) border += is_border(h, s.tm);
    BOOST_TEST(pr.cut_edges == 2 * s.result.seam_edges.size() + border);
  }
}

BOOST_AUTO_TEST_CASE(patterns_reject_bad_options)
{
  const Segmented& s = meshes().front();
  std::stringstream ss;
  QD::IO::Pattern_options bad;
  bad.scale = 0;
  BOOST_TEST((QD::IO::write_patterns_SVG(ss, s.tm, boost::make_assoc_property_map(s.chart), s.result.corner_uv,
                                         s.result.seam_edges, bad)
                  .status == QD::Error_code::INVALID_COORDINATES));
  bad = QD::IO::Pattern_options();
  bad.page_width = 15;  // narrower than its margins
  BOOST_TEST((QD::IO::write_patterns_SVG(ss, s.tm, boost::make_assoc_property_map(s.chart), s.result.corner_uv,
                                         s.result.seam_edges, bad)
                  .status == QD::Error_code::INVALID_COORDINATES));
  BOOST_TEST(ss.str().empty());
}

BOOST_AUTO_TEST_CASE(segmentation_picture_draws_every_face_and_seam)
{
  for(const Segmented& s : meshes()) {
    std::stringstream ss;
    BOOST_REQUIRE((QD::IO::write_segmentation_SVG(ss, s.tm, boost::make_assoc_property_map(s.chart),
                                                  s.result.seam_edges) == QD::Error_code::OK));
    boost::property_tree::ptree tree;
    BOOST_REQUIRE_NO_THROW(boost::property_tree::read_xml(ss, tree));
    std::size_t polygons = 0, lines = 0;
    std::set<std::string> fills;
    for(const auto& child : tree.get_child("svg.g")) {
      if(child.first == "polygon") {
        ++polygons;
        fills.insert(child.second.get<std::string>("<xmlattr>.fill"));
        // every point inside the picture
        std::istringstream pts(child.second.get<std::string>("<xmlattr>.points"));
        std::string xy;
        while(pts >> xy) {
          const double x = std::stod(xy.substr(0, xy.find(','))), y = std::stod(xy.substr(xy.find(',') + 1));
          BOOST_TEST((x >= 0 && x <= 800 && y >= 0 && y <= 800));
        }
      }
      if(child.first == "line") ++lines;
    }
    BOOST_TEST(polygons == num_faces(s.tm));
    BOOST_TEST(lines == 2 * s.result.seam_edges.size());  // a seam edge is drawn with each of its faces
    BOOST_TEST(fills.size() > s.result.number_of_charts);  // shaded chart colours
  }
  std::stringstream ss;
  const Surface_mesh empty;
  Chart_map none;
  BOOST_TEST((QD::IO::write_segmentation_SVG(ss, empty, boost::make_assoc_property_map(none),
                                             std::vector<Surface_mesh::Edge_index>()) == QD::Error_code::EMPTY_MESH));
}
