// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#define BOOST_TEST_MODULE outputs
#include <boost/test/unit_test.hpp>

#include "mesh_generators.h"
#include "test_utils.h"

#include <CGAL_QD/IO/charts_and_atlas.h>
#include <CGAL_QD/IO/internal/label_placement.h>
#include <CGAL_QD/IO/patterns_svg.h>
#ifdef CGAL_QD_HAS_CAIRO
#include <CGAL_QD/IO/patterns_pdf.h>
#endif
#include <CGAL_QD/IO/segmentation_svg.h>
#include <CGAL_QD/IO/viewer_html.h>
#include <CGAL_QD/pack_charts.h>
#include <CGAL_QD/segment_quasi_developable.h>

#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Surface_mesh/IO/PLY.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>
#include <boost/property_tree/xml_parser.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace QD = CGAL_QD;
namespace tt = boost::test_tools;
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

namespace {

// what a pattern drew for one piece: the box around its lines and tabs, its
// page, the sizes of its labels, and the elements by kind
struct Drawn_piece
{
  std::size_t chart = 0, page = 0;
  double x0 = std::numeric_limits<double>::infinity(), y0 = x0, x1 = -x0, y1 = -x0;
  double largest_seam_label = 0, chart_label = 0;
  std::vector<QD::internal::Pattern_drawing::Text> seam_labels;  // as drawn
  QD::internal::Pattern_drawing::Text id;
  std::vector<std::array<QD::internal::Pattern_drawing::P2, 2>> cut_lines;
  std::vector<std::array<QD::internal::Pattern_drawing::P2, 2>> tab_lines;  // the outlines of its tabs
  void add(double x, double y)
  {
    x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
  }
};

struct Drawn_pattern
{
  std::vector<Drawn_piece> pieces;
  std::map<std::string, int> labels;  // seam label -> times drawn
  std::size_t cuts = 0, charts = 0, tabs = 0;
  double worst_length_error = 0;  // |printed length - scale * 3D length| over the cut lines
  double page_width = 0, page_height = 0;
};

// the group of every piece of a pattern: on its page, or, for a piece larger
// than a page, defined once and shown in parts
// (patterns_print_a_piece_larger_than_a_page_in_parts)
std::vector<const boost::property_tree::ptree*> piece_groups(const boost::property_tree::ptree& svg)
{
  std::vector<const boost::property_tree::ptree*> groups;
  for(const auto& child : svg) {
    if(child.first == "g" && child.second.get<std::string>("<xmlattr>.class") != "part" &&
       child.second.get<std::string>("<xmlattr>.class") != "check")
      groups.push_back(&child.second);
    if(child.first == "defs")
      for(const auto& def : child.second)
        if(def.first == "g") groups.push_back(&def.second);
  }
  return groups;
}

Drawn_pattern parse_pattern(std::istream& in, const Surface_mesh& tm, double scale, std::size_t pages)
{
  Drawn_pattern d;
  boost::property_tree::ptree tree;
  BOOST_REQUIRE_NO_THROW(boost::property_tree::read_xml(in, tree));
  const auto& svg = tree.get_child("svg");
  {
    std::istringstream box(svg.get<std::string>("<xmlattr>.viewBox"));
    double a, b, h;
    box >> a >> b >> d.page_width >> h;
    d.page_height = h / pages;
  }
  std::vector<Surface_mesh::Vertex_index> vs(vertices(tm).begin(), vertices(tm).end());
  for(const boost::property_tree::ptree* g : piece_groups(svg)) {
    const auto group = std::make_pair(std::string("g"), *g);
    BOOST_TEST(group.second.get<std::string>("<xmlattr>.class") == "piece");
    Drawn_piece piece;
    piece.chart = group.second.get<std::size_t>("<xmlattr>.data-chart");
    piece.page = group.second.get<std::size_t>("<xmlattr>.data-page");
    for(const auto& child : group.second) {
      const auto& node = child.second;
      const std::string cls = node.get<std::string>("<xmlattr>.class", "");
      // a text: centred at (x, y), turned by the angle of its rotate()
      auto text = [&]() {
        QD::internal::Pattern_drawing::Text t;
        t.at = {{node.get<double>("<xmlattr>.x"), node.get<double>("<xmlattr>.y")}};
        t.size = node.get<double>("<xmlattr>.font-size");
        t.text = node.data();
        const std::string turn = node.get<std::string>("<xmlattr>.transform", "");
        t.angle = turn.rfind("rotate(", 0) == 0 ? std::stod(turn.substr(7)) : 0.;
        return t;
      };
      if(child.first == "text" && cls == "seam") {
        ++d.labels[node.data()];
        piece.largest_seam_label = std::max(piece.largest_seam_label, node.get<double>("<xmlattr>.font-size"));
        piece.seam_labels.push_back(text());
      }
      if(child.first == "text" && cls == "chart") {
        ++d.charts;
        piece.chart_label = node.get<double>("<xmlattr>.font-size");
        piece.id = text();
      }
      if(child.first == "polygon" && cls == "tab") {
        ++d.tabs;
        std::istringstream pts(node.get<std::string>("<xmlattr>.points"));
        std::string xy;
        std::vector<QD::internal::Pattern_drawing::P2> outline;
        while(pts >> xy) {
          outline.push_back({{std::stod(xy.substr(0, xy.find(','))), std::stod(xy.substr(xy.find(',') + 1))}});
          piece.add(outline.back()[0], outline.back()[1]);
        }
        for(std::size_t i = 0; i + 1 < outline.size(); ++i) piece.tab_lines.push_back({{outline[i], outline[i + 1]}});
      }
      if(child.first == "line") {
        const double ax = node.get<double>("<xmlattr>.x1"), ay = node.get<double>("<xmlattr>.y1"),
                     bx = node.get<double>("<xmlattr>.x2"), by = node.get<double>("<xmlattr>.y2");
        piece.add(ax, ay);
        piece.add(bx, by);
        if(cls != "cut") continue;
        ++d.cuts;
        piece.cut_lines.push_back({{{{ax, ay}}, {{bx, by}}}});
        std::istringstream ids(node.get<std::string>("<xmlattr>.data-v"));
        std::size_t i, j;
        ids >> i >> j;
        const double l3 = std::sqrt(CGAL::squared_distance(tm.point(vs[i]), tm.point(vs[j])));
        d.worst_length_error = std::max(d.worst_length_error, std::abs(std::hypot(bx - ax, by - ay) - scale * l3));
      }
    }
    d.pieces.push_back(piece);
  }
  return d;
}

// every piece inside its page's margins, no two pieces' boxes overlapping, and
// labels smaller than the pieces
void expect_pieces_apart_within_margins(const Drawn_pattern& d, double margin)
{
  for(std::size_t a = 0; a < d.pieces.size(); ++a) {
    const Drawn_piece& p = d.pieces[a];
    const double top = p.page * d.page_height;
    BOOST_TEST(p.x0 >= margin - 1e-3);
    BOOST_TEST(p.x1 <= d.page_width - margin + 1e-3);
    BOOST_TEST(p.y0 - top >= margin - 1e-3, "piece " << p.chart << " reaches " << p.y0 - top << " from its page's top");
    BOOST_TEST(p.y1 - top <= d.page_height - margin + 1e-3);
    const double side = std::min(p.x1 - p.x0, p.y1 - p.y0);
    BOOST_TEST(p.chart_label <= side / 3 + 1e-3, "piece " << p.chart << " of side " << side);
    BOOST_TEST(p.largest_seam_label <= side / 4 + 1e-3, "piece " << p.chart << " of side " << side);
    for(std::size_t b = 0; b < a; ++b) {
      const Drawn_piece& q = d.pieces[b];
      const bool apart = p.page != q.page || p.x1 < q.x0 || q.x1 < p.x0 || p.y1 < q.y0 || q.y1 < p.y0;
      BOOST_TEST(apart, "pieces " << p.chart << " and " << q.chart << " overlap");
    }
  }
}

// whether a point is on a piece: a ray from it crosses the piece's cut lines
// an odd number of times
bool on_piece(const Drawn_piece& p, const QD::internal::Pattern_drawing::P2& x)
{
  bool inside = false;
  for(const auto& c : p.cut_lines)
    if((c[0][1] > x[1]) != (c[1][1] > x[1]) && c[0][0] + (x[1] - c[0][1]) * (c[1][0] - c[0][0]) / (c[1][1] - c[0][1]) > x[0])
      inside = !inside;
  return inside;
}

// every piece's number on the piece, or, with `outside` (the height of the
// texts of small pieces put outside them), beside it at that height, within
// `room` of the box of the piece and its tabs; no two seam labels of a piece
// overlapping, none on the piece's number, none crossing a cut line or the
// outline of a tab
void expect_labels_apart(const Drawn_pattern& d, double outside = 0, double room = 0)
{
  using QD::internal::convex_overlap;
  using QD::internal::text_box;
  for(const Drawn_piece& p : d.pieces) {
    const QD::internal::Segment_grid tabs(p.tab_lines, 1.);
    BOOST_TEST(!tabs.crosses(text_box(p.id)), "the number of piece " << p.chart << " crosses a tab");
    for(const auto& t : p.seam_labels)
      BOOST_TEST(!tabs.crosses(text_box(t)), "label " << t.text << " crosses a tab of piece " << p.chart);
    if(outside > 0 && !on_piece(p, p.id.at)) {
      BOOST_TEST(p.id.size == outside, tt::tolerance(1e-6));
      for(const auto& corner : text_box(p.id)) {  // off the piece's box, within its room
        const double reach = room + 1e-3;
        BOOST_TEST((corner[0] >= p.x0 - reach && corner[0] <= p.x1 + reach), "piece " << p.chart);
        BOOST_TEST((corner[1] >= p.y0 - reach && corner[1] <= p.y1 + reach), "piece " << p.chart);
      }
      const std::array<QD::internal::Pattern_drawing::P2, 4> box = {
          {{{p.x0, p.y0}}, {{p.x1, p.y0}}, {{p.x1, p.y1}}, {{p.x0, p.y1}}}};
      BOOST_TEST(!convex_overlap(text_box(p.id), box), "the number of piece " << p.chart << " is on its box");
    } else {
      BOOST_TEST(on_piece(p, p.id.at), "the number of piece " << p.chart << " is off the piece");
    }
    const QD::internal::Segment_grid cuts(p.cut_lines, 1.);
    for(std::size_t a = 0; a < p.seam_labels.size(); ++a) {
      const auto box = text_box(p.seam_labels[a]);
      BOOST_TEST(!convex_overlap(box, text_box(p.id)), "label " << p.seam_labels[a].text << " on piece " << p.chart);
      BOOST_TEST(!cuts.crosses(box), "label " << p.seam_labels[a].text << " crosses a cut line of piece " << p.chart);
      for(std::size_t b = 0; b < a; ++b)
        BOOST_TEST(!convex_overlap(box, text_box(p.seam_labels[b])),
                   "labels " << p.seam_labels[a].text << " and " << p.seam_labels[b].text << " overlap on piece "
                             << p.chart);
    }
  }
}

// the longest side of the bounding box
// the distance from p to the segment c (x1, y1, x2, y2)
double segment_distance(const std::array<double, 2>& p, const std::array<double, 4>& c)
{
  const double dx = c[2] - c[0], dy = c[3] - c[1], l2 = dx * dx + dy * dy;
  const double t = l2 > 0 ? std::clamp(((p[0] - c[0]) * dx + (p[1] - c[1]) * dy) / l2, 0., 1.) : 0.;
  return std::hypot(c[0] + t * dx - p[0], c[1] + t * dy - p[1]);
}

double extent(const Surface_mesh& tm)
{
  const CGAL::Bbox_3 b = CGAL::Polygon_mesh_processing::bbox(tm);
  return std::max({b.xmax() - b.xmin(), b.ymax() - b.ymin(), b.zmax() - b.zmin()});
}

} // namespace

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
    BOOST_TEST(pr.scale == 100.);
    BOOST_TEST(!pr.reduced_to_fit);
    const Drawn_pattern d = parse_pattern(ss, s.tm, options.scale, pr.number_of_pages);
    // printed edge lengths are the 3D lengths at the scale, to the SVG's 4 decimals
    BOOST_TEST(d.worst_length_error < 2e-4);
    BOOST_TEST(d.pieces.size() == s.result.number_of_charts);
    BOOST_TEST(d.cuts == pr.cut_edges);
    BOOST_TEST(d.charts == s.result.number_of_charts);
    BOOST_TEST(d.tabs == pr.tabs);
    BOOST_TEST(d.labels.size() == pr.seam_labels);
    for(const auto& l : d.labels) BOOST_TEST(l.second == 2, "label " << l.first << " appears " << l.second << " times");
    // every seam edge is cut on both sides, every mesh border edge on one
    std::size_t border = 0;
    for(auto h : halfedges(s.tm)) border += is_border(h, s.tm);
    BOOST_TEST(pr.cut_edges == 2 * s.result.seam_edges.size() + border);
    if(pr.oversized_charts == 0) expect_pieces_apart_within_margins(d, options.page_margin);
    expect_labels_apart(d);
    BOOST_TEST(pr.crowded_pieces.empty());
  }
}

// Without a scale, the model is 200 mm at its largest, or less, to whole
// millimetres, when a piece would not fit on the page at that size; whatever
// the size of the mesh's coordinates
// Seam labels crowded along one side of a square piece, its number in the
// middle: at their curves' middles they would overlap; placed, no two overlap,
// none crosses the cut lines or sits on the number, and each stays beside its
// own curve
BOOST_AUTO_TEST_CASE(seam_labels_are_placed_apart_beside_their_curves)
{
  typedef QD::internal::Pattern_drawing::P2 P2;
  typedef QD::internal::Pattern_drawing::Text Text;
  using QD::internal::convex_overlap;
  using QD::internal::text_box;
  const double size = 3.5;
  // the square [0, 40]^2 on the page (y down); along its bottom, six curves
  // 4 long from x = 0 (two of them with their segments listed from the other
  // end), up its left side one 12 long, and its top one curve, the whole side
  std::vector<std::array<P2, 2>> square = {{{P2{{0., 40.}}, P2{{40., 40.}}}}, {{P2{{40., 40.}}, P2{{40., 0.}}}},
                                           {{P2{{40., 0.}}, P2{{0., 0.}}}}, {{P2{{0., 0.}}, P2{{0., 40.}}}}};
  std::vector<QD::internal::Seam_label_request> requests;
  for(int i = 0; i < 6; ++i) {
    QD::internal::Seam_label_request q;
    q.text = QD::internal::seam_label(std::size_t(26 + i));  // A1, B1, ...
    for(int k = 0; k < 4; ++k)  // the piece above: (dy, -dx) points up the page
      q.curve.push_back({{P2{{4. * i + k, 40.}}, P2{{4. * i + k + 1, 40.}}}});
    if(i % 3 == 1) std::reverse(q.curve.begin(), q.curve.end());  // in the other order along the curve
    requests.push_back(q);
  }
  {
    QD::internal::Seam_label_request q;
    q.text = "Q";
    for(int k = 0; k < 12; ++k)  // listed up the page, each segment down it: the piece to the right
      q.curve.push_back({{P2{{0., 39. - k}}, P2{{0., 40. - k}}}});
    requests.push_back(q);
    q.text = "R";
    q.curve = {{{P2{{40., 0.}}, P2{{0., 0.}}}}};  // piece below
    requests.push_back(q);
  }
  Text id;
  id.at = {{20., 20.}};
  id.size = 2 * size;
  id.text = "7";
  const QD::internal::Segment_grid cuts(square, size);
  const std::vector<Text> labels = QD::internal::place_seam_labels(requests, size, cuts, {id});
  BOOST_REQUIRE(labels.size() == requests.size());
  // at the middles of the bottom curves, the labels would overlap
  {
    Text a = labels[0], b = labels[1];
    a.at = {{2., 40. - 0.9 * size}};
    b.at = {{6., 40. - 0.9 * size}};
    a.size = b.size = size;
    a.angle = b.angle = 0;
    BOOST_TEST(convex_overlap(text_box(a), text_box(b)));
  }
  for(std::size_t r = 0; r < labels.size(); ++r) {
    const Text& t = labels[r];
    BOOST_TEST(t.text == requests[r].text);
    BOOST_TEST(t.size >= 0.5 * size - 1e-12);
    BOOST_TEST(t.size <= size + 1e-12);
    BOOST_TEST(!cuts.crosses(text_box(t)), "label " << t.text << " crosses the border");
    BOOST_TEST(!convex_overlap(text_box(t), text_box(id)), "label " << t.text << " on the piece's number");
    for(std::size_t s = 0; s < r; ++s)
      BOOST_TEST(!convex_overlap(text_box(t), text_box(labels[s])), "labels " << t.text << " and " << labels[s].text);
    // inside the square, beside its curve, turned along it
    BOOST_TEST(t.at[0] > 0.);
    BOOST_TEST(t.at[0] < 40.);
    BOOST_TEST(t.at[1] > 0.);
    BOOST_TEST(t.at[1] < 40.);
    double nearest = HUGE_VAL;
    for(const auto& s : requests[r].curve)
      nearest = std::min(nearest, segment_distance(t.at, {{s[0][0], s[0][1], s[1][0], s[1][1]}}));
    BOOST_TEST(nearest == 0.9 * t.size, tt::tolerance(1e-9));
    const bool side = requests[r].text == "Q";
    BOOST_TEST(std::abs(std::remainder(t.angle - (side ? 90. : 0.), 180.)) < 1e-9, t.text << " at " << t.angle);
  }
  // the bottom labels in the order of their curves
  for(std::size_t r = 1; r < 6; ++r) BOOST_TEST(labels[r].at[0] > labels[r - 1].at[0]);
  // the grid finds a border crossed whether its cells are small beside the
  // segments (each side then looked at by every query) or not
  Text across = id;
  across.at = {{40., 13.}};
  for(double cell : {0.5, 3.5, 100.}) {
    const QD::internal::Segment_grid grid(square, cell);
    BOOST_TEST(grid.crosses(text_box(across)));
    BOOST_TEST(!grid.crosses(text_box(id)));
    for(const Text& t : labels) BOOST_TEST(!grid.crosses(text_box(t)));
  }
}

// A piece's number goes where the piece is widest: on a U, inside the U at the
// centre of a largest inscribed circle, not in the gap between its arms where
// the centre of its box is
BOOST_AUTO_TEST_CASE(piece_number_goes_where_the_piece_is_widest)
{
  typedef QD::internal::Pattern_drawing::P2 P2;
  // the square [0, 30]^2 less [10, 20] x [0, 20] (y down: the gap opens at the top)
  const std::vector<P2> u = {P2{{0., 0.}},   P2{{10., 0.}},  P2{{10., 20.}}, P2{{20., 20.}},
                             P2{{20., 0.}},  P2{{30., 0.}},  P2{{30., 30.}}, P2{{0., 30.}}};
  std::vector<std::array<P2, 2>> border;
  for(std::size_t i = 0; i < u.size(); ++i) border.push_back({{u[i], u[(i + 1) % u.size()]}});
  const std::pair<P2, double> widest = QD::internal::farthest_inside(border);
  // within the U; its largest inscribed circles, in the two bottom corners,
  // touch two sides and the end of the gap: radius 10 / (1 + 1 / sqrt(2))
  const P2& p = widest.first;
  const bool in_u = p[0] > 0 && p[0] < 30 && p[1] > 0 && p[1] < 30 && !(p[0] > 10 && p[0] < 20 && p[1] < 20);
  BOOST_TEST(in_u, "at " << p[0] << ", " << p[1]);
  const double radius = 10. / (1. + 1. / std::sqrt(2.));
  BOOST_TEST(widest.second > 0.99 * radius);
  BOOST_TEST(widest.second <= radius + 1e-12);
  double nearest = HUGE_VAL;
  for(const auto& s : border) nearest = std::min(nearest, segment_distance(p, {{s[0][0], s[0][1], s[1][0], s[1][1]}}));
  BOOST_TEST(nearest == widest.second, tt::tolerance(1e-12));
  // a sliver with no area: the centre of its box
  const std::pair<P2, double> flat = QD::internal::farthest_inside({{{P2{{0., 0.}}, P2{{4., 0.}}}}, {{P2{{4., 0.}}, P2{{0., 0.}}}}});
  BOOST_TEST(flat.second == 0.);
  BOOST_TEST(flat.first[0] == 2.);
}

BOOST_AUTO_TEST_CASE(patterns_default_to_a_real_size)
{
  for(const Segmented& s : meshes())
    for(double factor : {1e-3, 1., 1e4}) {
      Surface_mesh tm = s.tm;
      for(auto v : vertices(tm)) tm.point(v) = CGAL::ORIGIN + factor * (tm.point(v) - CGAL::ORIGIN);
      std::vector<std::array<double, 2>> uv = s.result.corner_uv;
      for(auto& c : uv) c = {{factor * c[0], factor * c[1]}};
      std::map<Surface_mesh::Face_index, std::size_t> chart;
      {
        auto f = faces(s.tm).begin();
        for(auto g : faces(tm)) chart[g] = s.chart.at(*f++);
      }
      std::vector<Surface_mesh::Edge_index> seams(s.result.seam_edges.begin(), s.result.seam_edges.end());
      QD::IO::Pattern_options options;
      options.tabs = true;
      std::stringstream ss;
      const QD::IO::Pattern_result pr =
          QD::IO::write_patterns_SVG(ss, tm, boost::make_assoc_property_map(chart), uv, seams, options);
      BOOST_REQUIRE(pr);
      BOOST_TEST_MESSAGE("model " << pr.model_size << " mm at " << pr.scale << " mm per unit, "
                                  << pr.number_of_pages << " pages" << (pr.reduced_to_fit ? ", reduced to fit" : ""));
      BOOST_TEST(pr.scale * extent(tm) == pr.model_size, tt::tolerance(1e-12));
      if(pr.reduced_to_fit) {
        BOOST_TEST(pr.model_size < 200.);
        BOOST_TEST(pr.model_size == std::floor(pr.model_size + 1e-9), tt::tolerance(1e-9));  // whole millimetres
      } else {
        BOOST_TEST(pr.model_size == 200., tt::tolerance(1e-12));
      }
      BOOST_TEST(pr.oversized_charts == 0u);
      const Drawn_pattern d = parse_pattern(ss, tm, pr.scale, pr.number_of_pages);
      BOOST_TEST(d.worst_length_error < 2e-4);
      BOOST_TEST(d.pieces.size() == s.result.number_of_charts);
      expect_pieces_apart_within_margins(d, options.page_margin);
    }
}

// a model size or a unit given; a size too large for the page is reported
BOOST_AUTO_TEST_CASE(patterns_take_a_model_size_and_units)
{
  const Segmented& s = meshes().back();
  const auto chart = boost::make_assoc_property_map(const_cast<Chart_map&>(s.chart));
  QD::IO::Pattern_options options;
  options.model_size = 120;
  std::stringstream ss;
  QD::IO::Pattern_result pr = QD::IO::write_patterns_SVG(ss, s.tm, chart, s.result.corner_uv, s.result.seam_edges, options);
  BOOST_REQUIRE(pr);
  BOOST_TEST(pr.model_size == 120., tt::tolerance(1e-12));
  BOOST_TEST(!pr.reduced_to_fit);
  expect_pieces_apart_within_margins(parse_pattern(ss, s.tm, pr.scale, pr.number_of_pages), options.page_margin);

  options.model_size = 2000;  // two metres: some piece is larger than an A4 page, and said so
  ss.str("");
  pr = QD::IO::write_patterns_SVG(ss, s.tm, chart, s.result.corner_uv, s.result.seam_edges, options);
  BOOST_REQUIRE(pr);
  BOOST_TEST(pr.oversized_charts > 0u);
  BOOST_TEST(pr.part_pages >= 2 * pr.oversized_charts);  // each in parts, on pages of their own
  BOOST_TEST(pr.number_of_pages > pr.part_pages);

  // in inches, on a letter page: 200 mm is 7.87 in
  options = QD::IO::Pattern_options();
  options.units = "in";
  options.page_width = 8.5, options.page_height = 11, options.page_margin = 0.4, options.spacing = 0.25;
  ss.str("");
  pr = QD::IO::write_patterns_SVG(ss, s.tm, chart, s.result.corner_uv, s.result.seam_edges, options);
  BOOST_REQUIRE(pr);
  if(!pr.reduced_to_fit) BOOST_TEST(pr.model_size == 200 / 25.4, tt::tolerance(1e-12));
  BOOST_TEST(ss.str().find("width=\"8.5000in\"") != std::string::npos);
  expect_pieces_apart_within_margins(parse_pattern(ss, s.tm, pr.scale, pr.number_of_pages), options.page_margin);
}

// The scale check: on every page, in its bottom-left corner, a bar along the
// bottom margin and one up the left margin from the same corner, of the
// round length named beside them, with ticks into the page; within the
// margins, its text before the page number; shorter on a narrow page, none on
// a margin too thin or when not asked for
BOOST_AUTO_TEST_CASE(patterns_carry_a_scale_check_on_every_page)
{
  const Segmented& s = meshes().back();
  const auto chart = boost::make_assoc_property_map(const_cast<Chart_map&>(s.chart));
  auto check = [&](const QD::IO::Pattern_options& options, double length, const std::string& text) {
    BOOST_TEST_CONTEXT(options.units << ", " << options.page_width << " x " << options.page_height << ", margin "
                                     << options.page_margin) {
      std::stringstream ss;
      const QD::IO::Pattern_result pr =
          QD::IO::write_patterns_SVG(ss, s.tm, chart, s.result.corner_uv, s.result.seam_edges, options);
      BOOST_REQUIRE(pr);
      BOOST_TEST(pr.scale_check == length, tt::tolerance(1e-12));
      boost::property_tree::ptree tree;
      BOOST_REQUIRE_NO_THROW(boost::property_tree::read_xml(ss, tree));
      const double w = options.page_width, ph = options.page_height, m = options.page_margin;
      std::size_t groups = 0;
      for(const auto& child : tree.get_child("svg")) {
        if(child.first != "g" || child.second.get<std::string>("<xmlattr>.class") != "check") continue;
        const double top = ph * double(groups++);  // one group per page, in page order
        double horizontal = 0, vertical = 0, label_y = 0;
        std::size_t lines = 0;
        std::string label;
        for(const auto& node : child.second) {
          if(node.first == "text") {
            label = node.second.data();
            label_y = node.second.get<double>("<xmlattr>.y") - top;
            BOOST_TEST(node.second.get<double>("<xmlattr>.x") + 0.35 * text.size() * node.second.get<double>("<xmlattr>.font-size") < w / 2);
            continue;
          }
          if(node.first != "line") continue;
          ++lines;
          const double x1 = node.second.get<double>("<xmlattr>.x1"), y1 = node.second.get<double>("<xmlattr>.y1") - top,
                       x2 = node.second.get<double>("<xmlattr>.x2"), y2 = node.second.get<double>("<xmlattr>.y2") - top;
          // in the page's bottom or left margin
          for(const std::array<double, 2> p : {std::array<double, 2>{{x1, y1}}, std::array<double, 2>{{x2, y2}}}) {
            BOOST_TEST((p[0] >= 0 && p[0] <= w && p[1] >= 0 && p[1] <= ph));
            BOOST_TEST((p[0] <= m + 1e-9 || p[1] >= ph - m - 1e-9));
          }
          if(y1 == y2) horizontal = (std::max)(horizontal, std::abs(x2 - x1));
          if(x1 == x2) vertical = (std::max)(vertical, std::abs(y2 - y1));
        }
        BOOST_TEST(horizontal == length, tt::tolerance(1e-9));
        BOOST_TEST(vertical == length, tt::tolerance(1e-9));
        BOOST_TEST(lines >= 6u);  // two bars and ticks
        BOOST_TEST(label == text);
        BOOST_TEST(label_y == ph - 0.65 * m, tt::tolerance(1e-9));
      }
      BOOST_TEST(groups == (length > 0 ? pr.number_of_pages : 0u));
    }
  };
  QD::IO::Pattern_options options;
  check(options, 50, "50 mm at 100 %");
  options.units = "cm";
  options.page_width = 21, options.page_height = 29.7, options.page_margin = 1, options.spacing = 0.6;
  options.tab_width = 0.5;
  check(options, 5, "5 cm at 100 %");
  options = QD::IO::Pattern_options();
  options.units = "in";
  options.page_width = 8.5, options.page_height = 11, options.page_margin = 0.4, options.spacing = 0.25;
  check(options, 2, "2 in at 100 %");
  // a page 100 mm wide has room for 20 mm before its page number
  options = QD::IO::Pattern_options();
  options.page_width = 100, options.page_height = 150, options.model_size = 80;
  check(options, 20, "20 mm at 100 %");
  options = QD::IO::Pattern_options();
  options.page_margin = 3;
  check(options, 0, "");
  options = QD::IO::Pattern_options();
  options.scale_check = false;
  check(options, 0, "");
}

// A piece larger than a page, in parts: every part on a page of its own,
// framed by the page's printable area, the windows of a piece side by side on
// one grid; every line of the piece in a window printed; two half diamonds
// numbered alike across every line where two printed parts meet
BOOST_AUTO_TEST_CASE(patterns_print_a_piece_larger_than_a_page_in_parts)
{
  const Segmented& s = meshes().back();
  const auto chart = boost::make_assoc_property_map(const_cast<Chart_map&>(s.chart));
  QD::IO::Pattern_options options;
  options.model_size = 1000;  // a metre: pieces larger than an A4 page
  std::stringstream ss;
  const QD::IO::Pattern_result pr =
      QD::IO::write_patterns_SVG(ss, s.tm, chart, s.result.corner_uv, s.result.seam_edges, options);
  BOOST_REQUIRE(pr);
  BOOST_REQUIRE(pr.oversized_charts > 0u);
  BOOST_TEST(pr.part_pages >= 2 * pr.oversized_charts);
  boost::property_tree::ptree tree;
  BOOST_REQUIRE_NO_THROW(boost::property_tree::read_xml(ss, tree));
  const auto& svg = tree.get_child("svg");
  const double w = options.page_width, h = options.page_height, m = options.page_margin;
  const double uw = w - 2 * m, uh = h - 2 * m;
  // the pieces defined once, with their lines and marks
  struct Defined
  {
    std::vector<std::array<double, 4>> lines;
    std::vector<std::array<double, 2>> marks;  // centres
    std::map<std::string, int> mark_labels;
  };
  std::map<std::size_t, Defined> defined;
  std::map<std::string, std::array<double, 4>> clips;
  for(const auto& child : svg) {
    if(child.first != "defs") continue;
    for(const auto& def : child.second) {
      if(def.first == "clipPath") {
        const auto& r = def.second.get_child("rect");
        clips[def.second.get<std::string>("<xmlattr>.id")] = {{r.get<double>("<xmlattr>.x"), r.get<double>("<xmlattr>.y"),
                                                                r.get<double>("<xmlattr>.width"),
                                                                r.get<double>("<xmlattr>.height")}};
        continue;
      }
      if(def.first != "g") continue;
      Defined& d = defined[def.second.get<std::size_t>("<xmlattr>.data-chart")];
      for(const auto& e : def.second) {
        const std::string cls = e.second.get<std::string>("<xmlattr>.class", "");
        if(e.first == "line")
          d.lines.push_back({{e.second.get<double>("<xmlattr>.x1"), e.second.get<double>("<xmlattr>.y1"),
                              e.second.get<double>("<xmlattr>.x2"), e.second.get<double>("<xmlattr>.y2")}});
        if(e.first == "polygon" && cls == "mark") {
          std::istringstream pts(e.second.get<std::string>("<xmlattr>.points"));
          std::array<double, 2> c{{0, 0}};
          std::string xy;
          for(int k = 0; k < 4 && pts >> xy; ++k)
            c[0] += std::stod(xy.substr(0, xy.find(','))) / 4, c[1] += std::stod(xy.substr(xy.find(',') + 1)) / 4;
          d.marks.push_back(c);
        }
        if(e.first == "text" && cls == "mark") ++d.mark_labels[e.second.data()];
      }
    }
  }
  BOOST_TEST(defined.size() == pr.oversized_charts);
  // the parts
  std::set<std::size_t> pages;
  std::map<std::size_t, std::vector<std::array<double, 4>>> windows;  // by chart: x, y, width, height
  std::size_t frames = 0;
  for(const auto& child : svg) {
    if(child.first == "rect" && child.second.get<std::string>("<xmlattr>.class") == "frame") ++frames;
    if(child.first != "g" || child.second.get<std::string>("<xmlattr>.class") != "part") continue;
    const auto& g = child.second;
    const std::size_t page = g.get<std::size_t>("<xmlattr>.data-page"), k = g.get<std::size_t>("<xmlattr>.data-chart");
    BOOST_TEST(pages.insert(page).second, "two parts on page " << page);
    BOOST_TEST(page < pr.number_of_pages);
    std::array<double, 4> window;
    std::istringstream(g.get<std::string>("<xmlattr>.data-window")) >> window[0] >> window[1] >> window[2] >> window[3];
    BOOST_TEST(window[2] == uw, tt::tolerance(1e-6));
    BOOST_TEST(window[3] == uh, tt::tolerance(1e-6));
    // the clip: the printable area of its page
    std::string clip = g.get<std::string>("<xmlattr>.clip-path");
    clip = clip.substr(5, clip.size() - 6);  // url(#...)
    BOOST_REQUIRE(clips.count(clip) == 1u);
    const std::array<double, 4>& c = clips[clip];
    BOOST_TEST(c[0] == m, tt::tolerance(1e-6));
    BOOST_TEST(c[1] == page * h + m, tt::tolerance(1e-6));
    BOOST_TEST(c[2] == uw, tt::tolerance(1e-6));
    BOOST_TEST(c[3] == uh, tt::tolerance(1e-6));
    // the piece moved so that its window is that area
    std::string use = g.get<std::string>("use.<xmlattr>.transform");
    double dx = 0, dy = 0;
    std::istringstream(use.substr(use.find('(') + 1)) >> dx >> dy;
    BOOST_TEST(window[0] + dx == m, tt::tolerance(1e-4));
    BOOST_TEST(window[1] + dy == page * h + m, tt::tolerance(1e-4));
    windows[k].push_back(window);
  }
  BOOST_TEST(pages.size() == pr.part_pages);
  BOOST_TEST(frames == pr.part_pages);
  for(const auto& entry : defined) {
    const std::vector<std::array<double, 4>>& ws = windows[entry.first];
    BOOST_REQUIRE(!ws.empty());
    // one grid of windows, the page's printable area each
    for(const auto& a : ws) {
      const double cx = (a[0] - ws.front()[0]) / uw, cy = (a[1] - ws.front()[1]) / uh;
      BOOST_TEST(std::abs(cx - std::round(cx)) < 1e-6);
      BOOST_TEST(std::abs(cy - std::round(cy)) < 1e-6);
    }
    auto inside = [&](double x, double y, double slack) {
      for(const auto& a : ws)
        if(x >= a[0] - slack && x <= a[0] + a[2] + slack && y >= a[1] - slack && y <= a[1] + a[3] + slack) return true;
      return false;
    };
    for(const auto& l : entry.second.lines) {
      BOOST_TEST(inside(l[0], l[1], 1e-3), "piece " << entry.first << ": a line at " << l[0] << ", " << l[1] << " is printed on no page");
      BOOST_TEST(inside(l[2], l[3], 1e-3));
    }
    // every mark on a line between two printed windows; every label twice
    BOOST_TEST(!entry.second.marks.empty());
    for(const auto& c : entry.second.marks) {
      std::size_t holding = 0;
      for(const auto& a : ws)
        if(c[0] >= a[0] - 1e-3 && c[0] <= a[0] + a[2] + 1e-3 && c[1] >= a[1] - 1e-3 && c[1] <= a[1] + a[3] + 1e-3) ++holding;
      BOOST_TEST(holding == 2u, "a mark of piece " << entry.first << " at " << c[0] << ", " << c[1] << " in " << holding << " windows");
    }
    BOOST_TEST(entry.second.mark_labels.size() == entry.second.marks.size());
    for(const auto& label : entry.second.mark_labels) BOOST_TEST(label.second == 2, label.first);
  }
}

// a piece 300 x 100 mm needs two parts on A4 whichever way it is turned; the
// grid of windows is placed so that neither is a sliver: each part holds at
// least 45 % of the outline (half of it where the line between them is in the
// middle), where the grid's first corner at the piece's leaves 152 mm of the
// 800 to one of them
BOOST_AUTO_TEST_CASE(patterns_print_no_sliver_of_a_piece_in_parts)
{
  Surface_mesh tm;
  const auto v0 = tm.add_vertex(Epick::Point_3(0, 0, 0)), v1 = tm.add_vertex(Epick::Point_3(3, 0, 0)),
             v2 = tm.add_vertex(Epick::Point_3(3, 1, 0)), v3 = tm.add_vertex(Epick::Point_3(0, 1, 0));
  tm.add_face(v0, v1, v2);
  tm.add_face(v0, v2, v3);
  Chart_map chart;
  std::vector<std::array<double, 2>> uv(6);
  for(auto f : faces(tm)) {
    chart[f] = 0;
    int c = 0;
    for(auto h : CGAL::halfedges_around_face(halfedge(f, tm), tm))
      uv[3 * std::size_t(f) + c++] = {{tm.point(target(h, tm)).x(), tm.point(target(h, tm)).y()}};
  }
  QD::IO::Pattern_options options;
  options.scale = 100;
  options.assembly_page = false;
  std::stringstream ss;
  const QD::IO::Pattern_result pr = QD::IO::write_patterns_SVG(
      ss, tm, boost::make_assoc_property_map(chart), uv, std::vector<Surface_mesh::Edge_index>(), options);
  BOOST_REQUIRE(pr);
  BOOST_TEST(pr.part_pages == 2u);
  boost::property_tree::ptree tree;
  BOOST_REQUIRE_NO_THROW(boost::property_tree::read_xml(ss, tree));
  std::vector<std::array<double, 4>> lines, windows;
  for(const auto& child : tree.get_child("svg")) {
    if(child.first == "defs")
      for(const auto& def : child.second)
        if(def.first == "g")
          for(const auto& e : def.second)
            if(e.first == "line" && e.second.get<std::string>("<xmlattr>.class", "") == "cut")
              lines.push_back({{e.second.get<double>("<xmlattr>.x1"), e.second.get<double>("<xmlattr>.y1"),
                                e.second.get<double>("<xmlattr>.x2"), e.second.get<double>("<xmlattr>.y2")}});
    if(child.first == "g" && child.second.get<std::string>("<xmlattr>.class") == "part") {
      std::array<double, 4> w;
      std::istringstream(child.second.get<std::string>("<xmlattr>.data-window")) >> w[0] >> w[1] >> w[2] >> w[3];
      windows.push_back(w);
    }
  }
  BOOST_REQUIRE(windows.size() == 2u);
  double outline = 0;
  for(const auto& l : lines) outline += std::hypot(l[2] - l[0], l[3] - l[1]);
  BOOST_TEST(outline == 800., tt::tolerance(1e-6));
  for(const auto& w : windows) {
    double held = 0;
    for(const auto& l : lines) {
      // the part of an axis-parallel line within the window
      const double x0 = std::max(std::min(l[0], l[2]), w[0]), x1 = std::min(std::max(l[0], l[2]), w[0] + w[2]);
      const double y0 = std::max(std::min(l[1], l[3]), w[1]), y1 = std::min(std::max(l[1], l[3]), w[1] + w[3]);
      if(x1 >= x0 && y1 >= y0) held += std::hypot(x1 - x0, y1 - y0);
    }
    BOOST_TEST_MESSAGE("a part holds " << held << " mm of the outline");
    BOOST_TEST(held >= 0.45 * outline);
  }
}

// the order in which to join the pieces: outward from the largest, every piece
// once, every seam sewn once, listed on a last page of its own
BOOST_AUTO_TEST_CASE(patterns_list_the_assembly_order)
{
  for(const Segmented& s : meshes()) {
    const auto chart = boost::make_assoc_property_map(const_cast<Chart_map&>(s.chart));
    QD::IO::Pattern_options options;
    options.scale = 100;
    std::stringstream ss;
    const QD::IO::Pattern_result pr =
        QD::IO::write_patterns_SVG(ss, s.tm, chart, s.result.corner_uv, s.result.seam_edges, options);
    BOOST_REQUIRE(pr);
    BOOST_REQUIRE(pr.assembly.size() == s.result.number_of_charts);
    std::vector<double> area(s.result.number_of_charts, 0.);
    for(auto f : faces(s.tm)) area[s.chart.at(f)] += CGAL::Polygon_mesh_processing::face_area(f, s.tm);
    const std::size_t largest = std::max_element(area.begin(), area.end()) - area.begin();
    BOOST_TEST(pr.assembly.front().piece == largest);
    BOOST_TEST(pr.assembly.front().onto == largest);
    std::set<std::size_t> joined;
    std::map<std::string, int> sewn;
    for(const QD::IO::Assembly_step& step : pr.assembly) {
      BOOST_TEST(joined.insert(step.piece).second);  // once
      if(step.onto != step.piece) BOOST_TEST(joined.count(step.onto) == 1u);  // onto a piece joined before
      for(const std::string& label : step.seams) ++sewn[label];
    }
    const Drawn_pattern d = parse_pattern(ss, s.tm, options.scale, pr.number_of_pages);
    BOOST_TEST(sewn.size() == d.labels.size());
    for(const auto& l : d.labels) BOOST_TEST(sewn[l.first] == 1, "seam " << l.first << " sewn " << sewn[l.first] << " times");
    // the list on the last page, where no piece is
    boost::property_tree::ptree tree;
    ss.clear();
    ss.seekg(0);
    boost::property_tree::read_xml(ss, tree);
    std::size_t lines = 0;
    for(const auto& node : tree.get_child("svg"))
      if(node.first == "text" && node.second.get<std::string>("<xmlattr>.class", "") == "assembly") {
        ++lines;
        BOOST_TEST(node.second.get<double>("<xmlattr>.y") > (pr.number_of_pages - 1) * d.page_height);
      }
    BOOST_TEST(lines > pr.assembly.size());  // a title and a line per step at least
    for(const Drawn_piece& piece : d.pieces) BOOST_TEST(piece.page + 1 < pr.number_of_pages);
    // without the page: the same pieces, one page fewer
    options.assembly_page = false;
    std::stringstream without;
    const QD::IO::Pattern_result pw =
        QD::IO::write_patterns_SVG(without, s.tm, chart, s.result.corner_uv, s.result.seam_edges, options);
    BOOST_TEST(pw.number_of_pages + 1 == pr.number_of_pages);
    BOOST_TEST(pr.assembly_pages == 1u);
    BOOST_TEST(pw.assembly_pages == 0u);
    BOOST_TEST(without.str().find("class=\"assembly\"") == std::string::npos);
  }
}

// A list too long for one page at half the largest label height goes on over
// more pages at that height, each with its title, every line within its
// page's margins; a pattern that would then take more than max_pages is
// refused. A 30 x 30 grid of squares, every triangle a piece: 1,800 steps.
BOOST_AUTO_TEST_CASE(patterns_list_a_long_assembly_over_several_pages)
{
  Surface_mesh tm;
  const int n = 30;
  std::vector<Surface_mesh::Vertex_index> v;
  for(int j = 0; j <= n; ++j)
    for(int i = 0; i <= n; ++i) v.push_back(tm.add_vertex(Epick::Point_3(i, j, 0)));
  for(int j = 0; j < n; ++j)
    for(int i = 0; i < n; ++i) {
      const auto a = v[j * (n + 1) + i], b = v[j * (n + 1) + i + 1], c = v[(j + 1) * (n + 1) + i + 1],
                 d = v[(j + 1) * (n + 1) + i];
      tm.add_face(a, b, c);
      tm.add_face(a, c, d);
    }
  Chart_map chart;
  std::vector<std::array<double, 2>> uv(3 * num_faces(tm));
  for(auto f : faces(tm)) {
    chart[f] = std::size_t(f);
    int c = 0;
    for(auto h : CGAL::halfedges_around_face(halfedge(f, tm), tm)) {
      const Epick::Point_3& p = tm.point(target(h, tm));
      uv[3 * std::size_t(f) + c++] = {{p.x(), p.y()}};
    }
  }
  std::vector<Surface_mesh::Edge_index> seams;
  for(auto e : edges(tm))
    if(!is_border(e, tm)) seams.push_back(e);
  QD::IO::Pattern_options options;
  std::stringstream ss;
  const QD::IO::Pattern_result pr =
      QD::IO::write_patterns_SVG(ss, tm, boost::make_assoc_property_map(chart), uv, seams, options);
  BOOST_REQUIRE(pr);
  BOOST_TEST(pr.assembly.size() == std::size_t(2 * n * n));
  BOOST_TEST_MESSAGE(pr.number_of_pages << " pages, " << pr.assembly_pages << " of them the assembly");
  BOOST_TEST(pr.assembly_pages > 1u);
  const std::size_t first = pr.number_of_pages - pr.assembly_pages;  // the first page of the list
  const double ph = options.page_height, m = options.page_margin, half_font = 0.5 * 210. / 60;
  boost::property_tree::ptree tree;
  BOOST_REQUIRE_NO_THROW(boost::property_tree::read_xml(ss, tree));
  std::vector<std::size_t> titles(pr.number_of_pages, 0), lines(pr.number_of_pages, 0);
  for(const auto& node : tree.get_child("svg")) {
    if(node.first != "text" || node.second.get<std::string>("<xmlattr>.class", "") != "assembly") continue;
    const double y = node.second.get<double>("<xmlattr>.y"), size = node.second.get<double>("<xmlattr>.font-size");
    const std::size_t page = static_cast<std::size_t>(y / ph);
    BOOST_REQUIRE(page < pr.number_of_pages);
    BOOST_TEST(page >= first);
    BOOST_TEST(size >= half_font * (1 - 1e-6));  // never smaller than half the largest label height
    BOOST_TEST((y - page * ph > m && (page + 1) * ph - y > m));
    const std::string text = node.second.data();
    if(text.rfind("Assembly", 0) == 0)
      ++titles[page];
    else
      ++lines[page];
  }
  std::size_t total = 0;
  for(std::size_t p = first; p < pr.number_of_pages; ++p) {
    BOOST_TEST(titles[p] == 1u);
    BOOST_TEST(lines[p] > 0u);
    total += lines[p];
  }
  BOOST_TEST(total >= pr.assembly.size());  // a line per step at least
  // a limit the list would pass: refused, with the pages it would take
  options.max_pages = pr.number_of_pages - 1;
  std::stringstream refused;
  const QD::IO::Pattern_result pm =
      QD::IO::write_patterns_SVG(refused, tm, boost::make_assoc_property_map(chart), uv, seams, options);
  BOOST_TEST((pm.status == QD::Error_code::INVALID_ARGUMENT));
  BOOST_TEST(pm.number_of_pages == pr.number_of_pages);
  BOOST_TEST(pm.assembly_pages == pr.assembly_pages);
  BOOST_TEST(refused.str().empty());
}

// Loose pieces too small to cut (the specks a scan leaves beside a model) are
// left off the pattern and out of the assembly, the others kept: the torus's
// pieces beside five loose triangles 1 mm across on the page and one 100 mm
// across. With the bound 0 every piece is drawn; a pattern of specks alone
// is drawn whole. The model's size leaves out the pieces left out.
BOOST_AUTO_TEST_CASE(patterns_leave_off_small_loose_pieces)
{
  const Segmented& s = meshes().front();
  Surface_mesh tm = s.tm;
  Chart_map chart = s.chart;
  std::vector<std::array<double, 2>> corner_uv = s.result.corner_uv;
  const std::size_t torus_pieces = s.result.number_of_charts;
  // a triangle in the plane z of side `side` with its corner at (x, 0), as a chart of its own
  auto add_loose_triangle = [&](Surface_mesh& m, Chart_map& c, std::vector<std::array<double, 2>>& uv, double x,
                                double side, double z = 10) {
    const auto a = m.add_vertex(Epick::Point_3(x, 0, z)), b = m.add_vertex(Epick::Point_3(x + side, 0, z)),
               d = m.add_vertex(Epick::Point_3(x, side, z));
    const auto f = m.add_face(a, b, d);
    BOOST_REQUIRE(f != Surface_mesh::null_face());
    c[f] = c.empty() ? 0 : std::max_element(c.begin(), c.end(), [](const auto& p, const auto& q) {
                             return p.second < q.second;
                           })->second + 1;
    BOOST_REQUIRE_EQUAL(uv.size(), 3 * std::size_t(f));
    auto h = halfedge(f, m);
    for(int k = 0; k < 3; ++k, h = next(h, m)) uv.push_back({{m.point(target(h, m)).x(), m.point(target(h, m)).y()}});
    return c[f];
  };
  std::vector<std::size_t> specks;
  for(int i = 0; i < 5; ++i) specks.push_back(add_loose_triangle(tm, chart, corner_uv, 5. + i, 0.01));
  const std::size_t large = add_loose_triangle(tm, chart, corner_uv, 12., 1.);
  const auto chart_map = boost::make_assoc_property_map(chart);

  QD::IO::Pattern_options options;
  options.scale = 100;  // the specks 1 mm, the large triangle 100 mm
  options.min_loose_piece_size = 2;
  std::stringstream ss;
  const QD::IO::Pattern_result pr =
      QD::IO::write_patterns_SVG(ss, tm, chart_map, corner_uv, s.result.seam_edges, options);
  BOOST_REQUIRE(pr);
  BOOST_TEST(pr.left_out_pieces == specks, boost::test_tools::per_element());
  BOOST_TEST(pr.number_of_charts == torus_pieces + 1);
  BOOST_TEST(pr.assembly.size() == torus_pieces + 1);
  std::set<std::size_t> in_assembly;
  for(const QD::IO::Assembly_step& step : pr.assembly) in_assembly.insert(step.piece);
  BOOST_TEST(in_assembly.count(large) == 1u);
  const Drawn_pattern d = parse_pattern(ss, tm, options.scale, pr.number_of_pages);
  std::set<std::size_t> drawn;
  for(const Drawn_piece& piece : d.pieces) drawn.insert(piece.chart);
  BOOST_TEST(drawn.size() == torus_pieces + 1);
  BOOST_TEST(drawn.count(large) == 1u);
  for(std::size_t k : specks) {
    BOOST_TEST(drawn.count(k) == 0u);
    BOOST_TEST(in_assembly.count(k) == 0u);
  }

  // the bound 0: every piece, each a step of the assembly
  options.min_loose_piece_size = 0;
  std::stringstream all;
  const QD::IO::Pattern_result pa = QD::IO::write_patterns_SVG(all, tm, chart_map, corner_uv, s.result.seam_edges, options);
  BOOST_REQUIRE(pa);
  BOOST_TEST(pa.left_out_pieces.empty());
  BOOST_TEST(pa.number_of_charts == torus_pieces + 6);
  BOOST_TEST(pa.assembly.size() == torus_pieces + 6);

  // specks alone: none is left out, since nothing would be drawn
  Surface_mesh dust;
  Chart_map dust_chart;
  std::vector<std::array<double, 2>> dust_uv;
  for(int i = 0; i < 3; ++i) add_loose_triangle(dust, dust_chart, dust_uv, i, 0.01);
  options.min_loose_piece_size = 2;
  std::stringstream ds;
  const QD::IO::Pattern_result pd = QD::IO::write_patterns_SVG(
      ds, dust, boost::make_assoc_property_map(dust_chart), dust_uv, std::vector<Surface_mesh::Edge_index>(), options);
  BOOST_REQUIRE(pd);
  BOOST_TEST(pd.left_out_pieces.empty());
  BOOST_TEST(pd.number_of_charts == 3u);

  // the model's size is that of the pieces drawn: the torus 200 mm long with
  // five specks far from it left out, and a triangle in its hole, shorter
  // than 2 mm at the scale of the whole mesh (4.3 mm per unit) but not at the
  // torus's (37 mm per unit), drawn
  Surface_mesh far = s.tm;
  Chart_map far_chart = s.chart;
  std::vector<std::array<double, 2>> far_uv = s.result.corner_uv;
  double low = std::numeric_limits<double>::infinity(), high = -low;
  for(auto v : vertices(s.tm)) low = (std::min)(low, s.tm.point(v).x()), high = (std::max)(high, s.tm.point(v).x());
  const double torus_extent = high - low;
  for(auto v : vertices(s.tm)) {  // x is the torus's longest side
    BOOST_REQUIRE(std::abs(s.tm.point(v).y()) <= torus_extent / 2);
    BOOST_REQUIRE(std::abs(s.tm.point(v).z()) <= torus_extent / 2);
  }
  std::vector<std::size_t> far_specks;
  for(int i = 0; i < 5; ++i) far_specks.push_back(add_loose_triangle(far, far_chart, far_uv, 40. + i, 0.01));
  const std::size_t in_hole = add_loose_triangle(far, far_chart, far_uv, 0., 0.1, 0.);
  QD::IO::Pattern_options sized;
  sized.model_size = 200;
  sized.min_loose_piece_size = 2;
  std::stringstream fs;
  const QD::IO::Pattern_result pf =
      QD::IO::write_patterns_SVG(fs, far, boost::make_assoc_property_map(far_chart), far_uv, s.result.seam_edges, sized);
  BOOST_REQUIRE(pf);
  BOOST_TEST(pf.left_out_pieces == far_specks, boost::test_tools::per_element());
  BOOST_TEST(pf.number_of_charts == torus_pieces + 1);
  BOOST_TEST(pf.model_size == 200., boost::test_tools::tolerance(1e-12));
  BOOST_TEST(pf.scale == 200. / torus_extent, boost::test_tools::tolerance(1e-12));
  const Drawn_pattern fd = parse_pattern(fs, far, pf.scale, pf.number_of_pages);
  std::set<std::size_t> far_drawn;
  for(const Drawn_piece& piece : fd.pieces) far_drawn.insert(piece.chart);
  BOOST_TEST(far_drawn.count(in_hole) == 1u);
  for(std::size_t k : far_specks) BOOST_TEST(far_drawn.count(k) == 0u);
  // without the bound, the model is the whole mesh
  sized.min_loose_piece_size = 0;
  std::stringstream fa;
  const QD::IO::Pattern_result pfa =
      QD::IO::write_patterns_SVG(fa, far, boost::make_assoc_property_map(far_chart), far_uv, s.result.seam_edges, sized);
  BOOST_REQUIRE(pfa);
  BOOST_TEST(pfa.left_out_pieces.empty());
  BOOST_TEST(pfa.scale == 200. / (44.01 - low), boost::test_tools::tolerance(1e-12));
}

// The torus at 5 mm: its pieces are too small for labels inside them that
// could be read (a quarter of a piece's smaller side, under half the font's
// height), so each label goes outside its piece, half the font's height,
// within the room the layout keeps around the piece, or the piece is named
// (Pattern_result::crowded_pieces), and so does its number; with tabs too,
// on a tab or off them; at 400 mm every label is inside and no piece is
// named. A piece less than 10 mm across gets lines of its own, a fortieth of
// its smaller side, while the others keep 0.25 mm, also beside a speck a few
// millimetres across
BOOST_AUTO_TEST_CASE(patterns_name_the_pieces_too_small_for_their_labels)
{
  const Segmented& s = meshes().front();
  // the torus with a triangle in its hole, a chart of its own
  Surface_mesh speck = s.tm;
  Chart_map speck_chart = s.chart;
  std::vector<std::array<double, 2>> speck_uv = s.result.corner_uv;
  std::size_t speck_id = 0;
  for(const auto& fc : s.chart) speck_id = (std::max)(speck_id, fc.second + 1);
  {
    const double side = 0.02;
    const auto a = speck.add_vertex(Epick::Point_3(0, 0, 0)), b = speck.add_vertex(Epick::Point_3(side, 0, 0)),
               c = speck.add_vertex(Epick::Point_3(0, side, 0));
    const auto f = speck.add_face(a, b, c);
    BOOST_REQUIRE(f != Surface_mesh::null_face());
    speck_chart[f] = speck_id;
    BOOST_REQUIRE_EQUAL(speck_uv.size(), 3 * std::size_t(f));
    auto h = halfedge(f, speck);
    for(int k = 0; k < 3; ++k, h = next(h, speck))
      speck_uv.push_back({{speck.point(target(h, speck)).x(), speck.point(target(h, speck)).y()}});
  }
  const double half_font = 0.5 * 210. / 60;  // A4, the default font size
  for(int run = 0; run < 4; ++run) {  // 5 mm, 400 mm, 400 mm with the speck, 5 mm with tabs
    const Surface_mesh& tm = run != 2 ? s.tm : speck;
    QD::IO::Pattern_options options;
    const bool small = run == 0 || run == 3;
    options.model_size = small ? 5. : 400.;
    options.tabs = run == 3;
    // how far outside its box (with its tabs) a text of a piece may go
    const double room = options.spacing / 2 + (options.tabs ? options.tab_width : 0);
    std::stringstream ss;
    const QD::IO::Pattern_result pr =
        run != 2 ? QD::IO::write_patterns_SVG(ss, tm, boost::make_assoc_property_map(s.chart), s.result.corner_uv,
                                              s.result.seam_edges, options)
                 : QD::IO::write_patterns_SVG(ss, tm, boost::make_assoc_property_map(speck_chart), speck_uv,
                                              s.result.seam_edges, options);
    BOOST_REQUIRE(pr);
    BOOST_TEST(pr.model_size == options.model_size, tt::tolerance(1e-12));
    BOOST_TEST(std::is_sorted(pr.crowded_pieces.begin(), pr.crowded_pieces.end()));
    BOOST_TEST(pr.font_size == 2 * half_font, tt::tolerance(1e-12));
    const std::string svg = ss.str();
    const std::string style = svg.substr(svg.find("<style>"), svg.find("</style>") - svg.find("<style>"));
    BOOST_TEST(style.rfind("<style>.cut{stroke:#000;stroke-width:0.2500;fill:none}", 0) == 0u);
    const Drawn_pattern d = parse_pattern(ss, tm, pr.scale, pr.number_of_pages);
    BOOST_TEST(d.pieces.size() == s.result.number_of_charts + (run == 2 ? 1 : 0));
    std::size_t with_labels = 0, thin = 0, outside = 0;
    for(const Drawn_piece& p : d.pieces) {
      const bool crowded = std::binary_search(pr.crowded_pieces.begin(), pr.crowded_pieces.end(), p.chart);
      for(const auto& t : p.seam_labels) {
        if(t.size < half_font * (1 - 1e-6))
          BOOST_TEST(crowded, "piece " << p.chart << " has a label under half the font's height");
        if(on_piece(p, t.at)) {
          BOOST_TEST((!small || crowded), "piece " << p.chart << " has a label inside at 5 mm");
          continue;
        }
        ++outside;
        BOOST_TEST(small, "a label of piece " << p.chart << " is outside at 400 mm");
        BOOST_TEST(t.size == half_font, tt::tolerance(1e-6));
        for(const auto& corner : QD::internal::text_box(t)) {  // within the piece's room
          const double reach = room + 1e-3;
          BOOST_TEST((corner[0] >= p.x0 - reach && corner[0] <= p.x1 + reach), "piece " << p.chart);
          BOOST_TEST((corner[1] >= p.y0 - reach && corner[1] <= p.y1 + reach), "piece " << p.chart);
        }
      }
      if(!small) BOOST_TEST(!crowded, "piece " << p.chart << " at 400 mm");
      with_labels += !p.seam_labels.empty();
      if(run == 3) continue;  // the box has the tabs
      // its own lines where it is less than 10 mm across
      const std::string scope = ".piece[data-chart=\"" + std::to_string(p.chart) + "\"] .cut{stroke:#000;stroke-width:";
      const std::size_t at = style.find(scope);
      const double side = (std::min)(p.x1 - p.x0, p.y1 - p.y0);
      if(side < 10 - 0.01) {
        BOOST_REQUIRE_MESSAGE(at != std::string::npos, "piece " << p.chart << " is " << side << " mm across");
        BOOST_TEST(40 * std::stod(style.substr(at + scope.size())) == side, tt::tolerance(0.01));
        ++thin;
      } else if(side > 10 + 0.01) {
        BOOST_TEST(at == std::string::npos, "piece " << p.chart << " is " << side << " mm across");
      }
    }
    BOOST_TEST(with_labels > 0u);
    if(small) BOOST_TEST(outside > pr.crowded_pieces.size());
    // the labels of the pieces not named lie apart, from those of other pieces too
    Drawn_pattern roomy = d;
    roomy.pieces.clear();
    for(const Drawn_piece& p : d.pieces)
      if(!std::binary_search(pr.crowded_pieces.begin(), pr.crowded_pieces.end(), p.chart)) roomy.pieces.push_back(p);
    expect_labels_apart(roomy, half_font, room);
    for(std::size_t a = 0; a < roomy.pieces.size(); ++a)
      for(std::size_t b = 0; b < a; ++b) {
        std::vector<QD::internal::Pattern_drawing::Text> sa = roomy.pieces[a].seam_labels,
                                                         sb = roomy.pieces[b].seam_labels;
        sa.push_back(roomy.pieces[a].id);
        sb.push_back(roomy.pieces[b].id);
        for(const auto& s : sa)
          for(const auto& t : sb)
            BOOST_TEST(!QD::internal::convex_overlap(QD::internal::text_box(s), QD::internal::text_box(t)),
                       "texts of pieces " << roomy.pieces[a].chart << " and " << roomy.pieces[b].chart);
      }
    // the numbers too: each at least half the font's height, unless its piece is named
    for(const Drawn_piece& p : d.pieces)
      if(p.id.size < half_font * (1 - 1e-6))
        BOOST_TEST(std::binary_search(pr.crowded_pieces.begin(), pr.crowded_pieces.end(), p.chart),
                   "the number of piece " << p.chart);
    if(run == 0) BOOST_TEST(thin == d.pieces.size());
    if(run == 1) BOOST_TEST(thin == 0u);
    if(run == 2) BOOST_TEST(thin == 1u);  // the speck alone
  }
}

// the two sides of every seam as drawn: with the paper's criterion every
// border edge keeps its 3D length, so every seam matches; one piece drawn 2 %
// larger leaves exactly its seams with the other pieces unmatched, 2 % apart,
// and the last page lists them
BOOST_AUTO_TEST_CASE(patterns_name_the_seams_whose_sides_differ)
{
  for(const Segmented& s : meshes()) {
    const auto chart = boost::make_assoc_property_map(const_cast<Chart_map&>(s.chart));
    QD::IO::Pattern_options options;
    options.scale = 100;
    std::stringstream ss;
    const QD::IO::Pattern_result pr =
        QD::IO::write_patterns_SVG(ss, s.tm, chart, s.result.corner_uv, s.result.seam_edges, options);
    BOOST_REQUIRE(pr);
    BOOST_REQUIRE(pr.seams.size() == pr.seam_labels);
    BOOST_REQUIRE(!pr.seams.empty());
    double drawn = 0;
    for(const QD::IO::Pattern_seam& seam : pr.seams) {
      BOOST_TEST(seam.matched, "seam " << seam.label << ": " << seam.sides[0] << " against " << seam.sides[1]);
      BOOST_TEST(seam.sides[0] == seam.sides[1], tt::tolerance(1e-6));
      drawn += seam.sides[0];
    }
    // the sides as drawn are the seams' 3D lengths at the scale
    BOOST_TEST(drawn == options.scale * s.result.seam_length, tt::tolerance(1e-6));
    BOOST_TEST(ss.str().find("Ease in") == std::string::npos);

    // the piece with the most seams drawn 2 % larger about its first corner
    std::map<std::size_t, std::size_t> seams_of;
    for(const QD::IO::Pattern_seam& seam : pr.seams)
      if(seam.pieces[0] != seam.pieces[1]) ++seams_of[seam.pieces[0]], ++seams_of[seam.pieces[1]];
    const std::size_t k =
        std::max_element(seams_of.begin(), seams_of.end(), [](const auto& a, const auto& b) { return a.second < b.second; })
            ->first;
    std::vector<std::array<double, 2>> uv = s.result.corner_uv;
    std::array<double, 2> origin{{0., 0.}};
    bool first = true;
    for(auto f : faces(s.tm)) {
      if(s.chart.at(f) != k) continue;
      for(int c = 0; c < 3; ++c) {
        std::array<double, 2>& p = uv[3 * std::size_t(f) + c];
        if(first) origin = p, first = false;
        p = {{origin[0] + 1.02 * (p[0] - origin[0]), origin[1] + 1.02 * (p[1] - origin[1])}};
      }
    }
    std::stringstream grown;
    const QD::IO::Pattern_result pg = QD::IO::write_patterns_SVG(grown, s.tm, chart, uv, s.result.seam_edges, options);
    BOOST_REQUIRE(pg);
    BOOST_REQUIRE(pg.seams.size() == pr.seams.size());
    std::size_t unmatched = 0;
    for(std::size_t i = 0; i < pg.seams.size(); ++i) {
      const QD::IO::Pattern_seam &before = pr.seams[i], &after = pg.seams[i];
      BOOST_TEST(after.label == before.label);
      BOOST_TEST((after.pieces == before.pieces));
      const bool one_side = (after.pieces[0] == k) != (after.pieces[1] == k);
      BOOST_TEST(after.matched == !one_side, "seam " << after.label);
      for(int side = 0; side < 2; ++side)
        BOOST_TEST(after.sides[side] == (after.pieces[side] == k ? 1.02 : 1.) * before.sides[side], tt::tolerance(1e-9));
      if(!one_side) continue;
      ++unmatched;
      // listed on the last page with its two lengths
      const std::string line = QD::IO::pattern_seam_text(after, options.units);
      BOOST_TEST(line.find(after.label + ": ") == 0u);
      BOOST_TEST(line.find("(2.0 %)") != std::string::npos, line);
      BOOST_TEST(grown.str().find(">" + line + "<") != std::string::npos, line);
    }
    BOOST_TEST(unmatched == seams_of[k]);
    BOOST_TEST(grown.str().find("Ease in the longer side") != std::string::npos);
  }
  // the line's lengths: three significant digits, one to three decimals
  QD::IO::Pattern_seam seam;
  seam.label = "G";
  seam.pieces = {{3, 5}};
  seam.sides = {{152.34, 139.06}};
  BOOST_TEST(QD::IO::pattern_seam_text(seam, "mm") == "G: 152.3 mm on piece 3, 139.1 mm on piece 5 (8.7 %)");
  seam.sides = {{1.0, 0.987}};
  BOOST_TEST(QD::IO::pattern_seam_text(seam, "in") == "G: 1.00 in on piece 3, 0.99 in on piece 5 (1.3 %)");
  seam.sides = {{0.05, 0.0498}};
  BOOST_TEST(QD::IO::pattern_seam_text(seam, "cm") == "G: 0.050 cm on piece 3, 0.050 cm on piece 5 (0.4 %)");
}

// two parts of a model, each built outward from its largest piece; a cut
// inside a piece is sewn when the piece is joined
BOOST_AUTO_TEST_CASE(assembly_order_follows_the_longest_seams)
{
  // pieces 0-1-2 in a row (1 the largest), 3-4 apart (4 the larger), 5 unused;
  // curve 3 is a cut inside piece 2
  const std::vector<double> area = {2, 5, 1, 0.5, 1.5, 9};
  const std::vector<bool> used = {true, true, true, true, true, false};
  const std::vector<std::pair<std::size_t, std::size_t>> charts = {{0, 1}, {1, 2}, {0, 1}, {2, 2}, {3, 4}, {0, 2}};
  const std::vector<double> length = {1, 3, 1.5, 0.5, 1, 0.2};
  const std::vector<QD::IO::Assembly_step> steps = QD::internal::assembly_order(area, used, charts, length);
  BOOST_REQUIRE(steps.size() == 5u);
  BOOST_TEST(steps[0].piece == 1u);
  BOOST_TEST(steps[1].piece == 2u);  // 3 shared with 1, more than 0's 2.5
  BOOST_TEST(steps[1].onto == 1u);
  BOOST_TEST((steps[1].seams == std::vector<std::string>{"B", "D"}));
  BOOST_TEST(steps[2].piece == 0u);
  BOOST_TEST((steps[2].seams == std::vector<std::string>{"A", "C", "F"}));
  BOOST_TEST(steps[3].piece == 4u);  // the other part, from its larger piece
  BOOST_TEST(steps[3].onto == 4u);
  BOOST_TEST(steps[4].piece == 3u);
  BOOST_TEST((steps[4].seams == std::vector<std::string>{"E"}));
}

// notches: the same count on the two sides of every seam curve, numbered from
// 1, each starting on a cut line of its piece
BOOST_AUTO_TEST_CASE(pattern_notches_match_on_both_sides_of_every_seam)
{
  for(const Segmented& s : meshes()) {
    const auto chart = boost::make_assoc_property_map(const_cast<Chart_map&>(s.chart));
    QD::IO::Pattern_options options;
    options.scale = 100;
    options.notch_spacing = 20;
    std::stringstream ss;
    const QD::IO::Pattern_result pr =
        QD::IO::write_patterns_SVG(ss, s.tm, chart, s.result.corner_uv, s.result.seam_edges, options);
    BOOST_REQUIRE(pr);
    boost::property_tree::ptree tree;
    boost::property_tree::read_xml(ss, tree);
    std::map<std::pair<std::string, int>, int> sides;  // (seam, number) -> notches drawn
    std::map<std::string, int> largest;                 // seam -> its largest notch number
    std::size_t notches = 0;
    for(const boost::property_tree::ptree* group : piece_groups(tree.get_child("svg"))) {
      std::vector<std::array<double, 4>> cuts;
      std::vector<std::array<double, 2>> starts;
      for(const auto& child : *group) {
        const auto& node = child.second;
        if(child.first != "line") continue;
        const std::array<double, 4> xy = {node.get<double>("<xmlattr>.x1"), node.get<double>("<xmlattr>.y1"),
                                          node.get<double>("<xmlattr>.x2"), node.get<double>("<xmlattr>.y2")};
        const std::string cls = node.get<std::string>("<xmlattr>.class");
        if(cls == "cut") cuts.push_back(xy);
        if(cls != "notch") continue;
        ++notches;
        const std::string seam = node.get<std::string>("<xmlattr>.data-seam");
        const int n = node.get<int>("<xmlattr>.data-n");
        ++sides[{seam, n}];
        largest[seam] = std::max(largest[seam], n);
        starts.push_back({xy[0], xy[1]});
      }
      for(const auto& p : starts) {
        double nearest = std::numeric_limits<double>::infinity();
        for(const auto& c : cuts) nearest = std::min(nearest, segment_distance(p, c));
        BOOST_TEST(nearest < 1e-3);
      }
    }
    BOOST_TEST(notches == pr.notches);
    BOOST_TEST(largest.size() == pr.seam_labels);  // every seam has notches
    for(const auto& l : largest)
      for(int n = 1; n <= l.second; ++n)
        BOOST_TEST(sides[std::make_pair(l.first, n)] == 2, "seam " << l.first << " notch " << n);
    BOOST_TEST_MESSAGE(pr.notches << " notches on " << largest.size() << " seams");
  }
}

namespace {

// a 0.25 wide strip of 80 x 20 cells, one piece laid out as it lies in the
// plane (its UVs are x and y), with its heights z
struct Strip
{
  Surface_mesh tm;
  Chart_map chart;
  std::vector<std::array<double, 2>> uv;
  explicit Strip(const std::function<double(double, double)>& z)
  {
    BOOST_REQUIRE(build(grid(80, 20, [&](double u, double v) { return P3{{u, 0.25 * v, z(u, v)}}; }), tm));
    uv.assign(3 * num_faces(tm), {{0, 0}});
    for(auto f : faces(tm)) {
      chart[f] = 0;
      int c = 0;
      for(auto h : CGAL::halfedges_around_face(halfedge(f, tm), tm))
        uv[3 * std::size_t(f) + c++] = {{tm.point(target(h, tm)).x(), tm.point(target(h, tm)).y()}};
    }
  }
  std::size_t fold_lines(double scale, double min_fold_length, double min_fold_share = 0) const
  {
    QD::IO::Pattern_options options;
    options.scale = scale;
    options.min_fold_length = min_fold_length;
    options.min_fold_share = min_fold_share;
    std::stringstream ss;
    const QD::IO::Pattern_result pr = QD::IO::write_patterns_SVG(
        ss, tm, boost::make_assoc_property_map(const_cast<Chart_map&>(chart)), uv,
        std::vector<Surface_mesh::Edge_index>(), options);
    BOOST_REQUIRE(pr);
    // the strip is 1 long: the model `scale` long on the page
    BOOST_TEST(pr.min_fold_length == (min_fold_length > 0 ? min_fold_length : min_fold_share * scale),
               tt::tolerance(1e-12));
    // as many dashed lines in the SVG
    std::size_t drawn = 0;
    for(const std::string kind : {"class=\"mountain\"", "class=\"valley\""})
      for(std::size_t at = ss.str().find(kind); at != std::string::npos; at = ss.str().find(kind, at + 1)) ++drawn;
    BOOST_TEST(drawn == pr.fold_lines);
    return pr.fold_lines;
  }
};

} // namespace

// fold lines are creases, not the small bends of a finely sampled surface: a
// straight crease across the strip (its 20 edges bend by 17 degrees) is drawn
// whole, 25 mm long, and at 7.5 mm too, since it runs from the cut line to the
// cut line; of a strip whose heights are noise (edges bending by up to tens of
// degrees, 1.25 mm long on the page) only a few chains that happen to line up
// are drawn, the same at every size with the default share of the model's
// size; with `min_fold_length` and `min_fold_share` 0 every edge beyond the
// fold angle is drawn
BOOST_AUTO_TEST_CASE(pattern_fold_lines_follow_creases_not_the_sampling)
{
  const Strip crease([](double u, double) { return 0.15 * std::abs(u - 0.5); });
  BOOST_TEST(crease.fold_lines(100, 10) == 20u);
  BOOST_TEST(crease.fold_lines(30, 10) == 20u);
  BOOST_TEST(crease.fold_lines(100, 0) == 20u);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> height(0, 0.004);
  const Strip noise([&](double, double) { return height(random); });
  const std::size_t every = noise.fold_lines(100, 0), drawn = noise.fold_lines(100, 9);
  const QD::IO::Pattern_options defaults;
  BOOST_TEST(defaults.min_fold_length == 0.);
  BOOST_TEST(defaults.min_fold_share == 0.05);
  // a share of the model's size (the strip is 1 long): 9 mm at 200 mm, the
  // same lines at 50 and 800 mm (not a whole number of the grid's edges,
  // whose lines are whole numbers of them long)
  const std::size_t at_200 = noise.fold_lines(200, 0, 0.045);
  BOOST_TEST(at_200 == noise.fold_lines(200, 9));
  BOOST_TEST(at_200 == noise.fold_lines(50, 0, 0.045));
  BOOST_TEST(at_200 == noise.fold_lines(800, 0, 0.045));
  BOOST_TEST(at_200 < noise.fold_lines(800, 9));
  BOOST_TEST_MESSAGE("noise: " << drawn << " of " << every << " bending edges drawn as fold lines");
  BOOST_TEST(every > 1000u);
  BOOST_TEST(drawn * 10 < every);
  // the same noise at 2 mm per mesh unit: every line is shorter than 9 mm, and
  // only those between the cut line and other lines are drawn
  const std::size_t small = noise.fold_lines(2, 9);
  BOOST_TEST_MESSAGE("at 2 mm per mesh unit: " << small);
  BOOST_TEST(small * 10 < every);
}

#ifdef CGAL_QD_HAS_CLIPPER
// the seam allowance: every point of its outline is the allowance away from
// the piece's border (the stitch line), and every point of the border at least
// that far inside the outline; the pieces, allowance included, apart
BOOST_AUTO_TEST_CASE(pattern_seam_allowance_is_its_width_from_the_stitch_line)
{
  for(const Segmented& s : meshes()) {
    const auto chart = boost::make_assoc_property_map(const_cast<Chart_map&>(s.chart));
    QD::IO::Pattern_options options;
    options.seam_allowance = 6;
    std::stringstream ss;
    const QD::IO::Pattern_result pr =
        QD::IO::write_patterns_SVG(ss, s.tm, chart, s.result.corner_uv, s.result.seam_edges, options);
    BOOST_REQUIRE(pr);
    boost::property_tree::ptree tree;
    boost::property_tree::read_xml(ss, tree);
    typedef std::array<double, 4> Segment;
    std::size_t outlines = 0;
    double nearest_low = 1e30, nearest_high = 0, inside = 1e30;
    std::vector<std::array<double, 4>> boxes;  // of every piece's outer outline
    BOOST_TEST(pr.oversized_charts == 0u);  // every piece on one page: the boxes below are comparable
    for(const boost::property_tree::ptree* group : piece_groups(tree.get_child("svg"))) {
      std::vector<Segment> stitch, cut;
      std::vector<std::array<double, 2>> outline_points;
      for(const auto& child : *group) {
        const auto& node = child.second;
        const std::string cls = node.get<std::string>("<xmlattr>.class", "");
        if(child.first == "line" && cls == "cut")
          stitch.push_back({node.get<double>("<xmlattr>.x1"), node.get<double>("<xmlattr>.y1"),
                            node.get<double>("<xmlattr>.x2"), node.get<double>("<xmlattr>.y2")});
        if(child.first != "polygon" || cls != "allowance") continue;
        ++outlines;
        std::istringstream pts(node.get<std::string>("<xmlattr>.points"));
        std::vector<std::array<double, 2>> ring;
        std::string xy;
        while(pts >> xy) ring.push_back({std::stod(xy.substr(0, xy.find(','))), std::stod(xy.substr(xy.find(',') + 1))});
        for(std::size_t i = 0; i < ring.size(); ++i) {
          const auto& a = ring[i];
          const auto& b = ring[(i + 1) % ring.size()];
          cut.push_back({a[0], a[1], b[0], b[1]});
        }
        outline_points.insert(outline_points.end(), ring.begin(), ring.end());
      }
      BOOST_REQUIRE(!stitch.empty());
      BOOST_REQUIRE(!outline_points.empty());
      for(const auto& p : outline_points) {
        double d = 1e30;
        for(const Segment& c : stitch) d = std::min(d, segment_distance(p, c));
        nearest_low = std::min(nearest_low, d), nearest_high = std::max(nearest_high, d);
      }
      for(const Segment& c : stitch)
        for(const Segment& e : cut) inside = std::min(inside, segment_distance({c[0], c[1]}, e));
      std::array<double, 4> box = {1e30, 1e30, -1e30, -1e30};
      for(const auto& p : outline_points)
        box = {std::min(box[0], p[0]), std::min(box[1], p[1]), std::max(box[2], p[0]), std::max(box[3], p[1])};
      boxes.push_back(box);
    }
    BOOST_TEST_MESSAGE(outlines << " outlines; their points " << nearest_low << " to " << nearest_high
                                << " mm from the stitch lines, which are at least " << inside << " mm inside");
    BOOST_TEST(outlines >= pr.number_of_charts);
    // 6 mm, within the SVG's 4 decimals and Clipper's 0.1 micrometre grid and 6 micrometre arcs
    BOOST_TEST(nearest_low > 6 - 0.01);
    BOOST_TEST(nearest_high < 6 + 0.01);
    BOOST_TEST(inside > 6 - 0.01);
    // the allowance is in the layout: the outlines' boxes of pieces on the same page do not meet
    for(std::size_t i = 0; i < boxes.size(); ++i)
      for(std::size_t j = i + 1; j < boxes.size(); ++j) {
        const bool apart = boxes[i][2] <= boxes[j][0] || boxes[j][2] <= boxes[i][0] || boxes[i][3] <= boxes[j][1] ||
                           boxes[j][3] <= boxes[i][1];
        BOOST_TEST(apart, "the allowances of pieces " << i << " and " << j << " meet");
      }
  }
}
#endif // CGAL_QD_HAS_CLIPPER

BOOST_AUTO_TEST_CASE(patterns_reject_bad_options)
{
  const Segmented& s = meshes().front();
  std::stringstream ss;
  auto expect_refused = [&](const QD::IO::Pattern_options& bad) {
    BOOST_TEST((QD::IO::write_patterns_SVG(ss, s.tm, boost::make_assoc_property_map(s.chart), s.result.corner_uv,
                                           s.result.seam_edges, bad)
                    .status == QD::Error_code::INVALID_COORDINATES));
  };
  QD::IO::Pattern_options bad;
  bad.scale = -1;
  expect_refused(bad);
  bad.scale = std::numeric_limits<double>::quiet_NaN();
  expect_refused(bad);
  bad = QD::IO::Pattern_options();
  bad.model_size = std::numeric_limits<double>::infinity();
  expect_refused(bad);
  bad = QD::IO::Pattern_options();
  bad.page_width = 15;  // narrower than its margins
  expect_refused(bad);
  // tabs that leave a piece no room between the margins (190 mm on A4): 3 mm
  // of spacing and the tab on each side; with the scale given too
  bad = QD::IO::Pattern_options();
  bad.tabs = true;
  bad.tab_width = 92;
  expect_refused(bad);
  bad.scale = 10;
  expect_refused(bad);
  // a model under a millimetre: refused, with its size
  bad = QD::IO::Pattern_options();
  bad.scale = 1e-300;
  const QD::IO::Pattern_result tiny = QD::IO::write_patterns_SVG(
      ss, s.tm, boost::make_assoc_property_map(s.chart), s.result.corner_uv, s.result.seam_edges, bad);
  BOOST_TEST((tiny.status == QD::Error_code::INVALID_ARGUMENT));
  BOOST_TEST((tiny.model_size > 0 && tiny.model_size < 1e-290));
  bad.scale = 0;
  bad.model_size = 0.999;
  BOOST_TEST((QD::IO::write_patterns_SVG(ss, s.tm, boost::make_assoc_property_map(s.chart), s.result.corner_uv,
                                         s.result.seam_edges, bad)
                  .status == QD::Error_code::INVALID_ARGUMENT));
  bad.model_size = 1;
  std::stringstream drawn;
  BOOST_TEST(bool(QD::IO::write_patterns_SVG(drawn, s.tm, boost::make_assoc_property_map(s.chart), s.result.corner_uv,
                                             s.result.seam_edges, bad)));
  bad = QD::IO::Pattern_options();
  bad.tabs = true;
  bad.scale = 10;
  bad.tab_width = 91.9;  // room for a piece 0.2 mm wide
  drawn.str("");
  BOOST_TEST(bool(QD::IO::write_patterns_SVG(drawn, s.tm, boost::make_assoc_property_map(s.chart), s.result.corner_uv,
                                             s.result.seam_edges, bad)));
  bad = QD::IO::Pattern_options();
  bad.units = "furlong";
  expect_refused(bad);
  bad = QD::IO::Pattern_options();
  bad.notch_spacing = -5;
  expect_refused(bad);
  bad.notch_spacing = 0.999;  // under a millimetre
  expect_refused(bad);
  bad.notch_spacing = 1e-300;
  expect_refused(bad);
  bad = QD::IO::Pattern_options();
  bad.seam_allowance = std::numeric_limits<double>::quiet_NaN();
  expect_refused(bad);
  bad = QD::IO::Pattern_options();
  bad.min_fold_length = -1;
  expect_refused(bad);
  bad.min_fold_length = std::numeric_limits<double>::infinity();
  expect_refused(bad);
  bad = QD::IO::Pattern_options();
  bad.min_loose_piece_size = -1;
  expect_refused(bad);
  bad.min_loose_piece_size = std::numeric_limits<double>::quiet_NaN();
  expect_refused(bad);
  bad = QD::IO::Pattern_options();
  bad.min_fold_share = -0.1;
  expect_refused(bad);
  bad.min_fold_share = std::numeric_limits<double>::quiet_NaN();
  expect_refused(bad);
  // a model a kilometre long, or a scale near the largest double: more pages
  // than `max_pages`, refused before anything is drawn
  for(double scale : {0., 1e300}) {
    bad = QD::IO::Pattern_options();
    bad.model_size = scale > 0 ? 0. : 1e6;
    bad.scale = scale;
    const QD::IO::Pattern_result pr = QD::IO::write_patterns_SVG(
        ss, s.tm, boost::make_assoc_property_map(s.chart), s.result.corner_uv, s.result.seam_edges, bad);
    BOOST_TEST((pr.status == QD::Error_code::INVALID_ARGUMENT));
    BOOST_TEST(pr.number_of_pages >= bad.max_pages);
  }
  bad = QD::IO::Pattern_options();
  bad.max_pages = 0;
  BOOST_TEST((QD::IO::write_patterns_SVG(ss, s.tm, boost::make_assoc_property_map(s.chart), s.result.corner_uv,
                                         s.result.seam_edges, bad)
                  .status == QD::Error_code::INVALID_ARGUMENT));
  BOOST_TEST(ss.str().empty());
}

#ifdef CGAL_QD_HAS_CAIRO
namespace {

// the pages of a PDF file as cairo writes it (its object dictionaries are not
// compressed): every page's MediaBox, in points
std::vector<std::array<double, 4>> pdf_pages(const std::string& pdf)
{
  std::vector<std::array<double, 4>> pages;
  for(std::size_t at = pdf.find("/Type /Page"); at != std::string::npos; at = pdf.find("/Type /Page", at + 1)) {
    if(pdf.compare(at, 12, "/Type /Pages") == 0) continue;
    const std::size_t open = pdf.rfind("<<", at), box = pdf.find("/MediaBox", open);
    BOOST_REQUIRE(open != std::string::npos && box != std::string::npos);
    std::istringstream in(pdf.substr(pdf.find('[', box) + 1));
    std::array<double, 4> b;
    BOOST_REQUIRE(in >> b[0] >> b[1] >> b[2] >> b[3]);
    pages.push_back(b);
  }
  return pages;
}

} // namespace

// the PDF has the SVG's pieces and a page per sheet of the page size
BOOST_AUTO_TEST_CASE(pdf_patterns_have_a_page_per_sheet_of_the_page_size)
{
  for(const Segmented& s : meshes()) {
    const auto chart = boost::make_assoc_property_map(const_cast<Chart_map&>(s.chart));
    for(const std::string units : {"mm", "in"}) {
      QD::IO::Pattern_options options;
      options.tabs = true;
      if(units == "in") {
        options.units = "in";
        options.page_width = 8.5, options.page_height = 11, options.page_margin = 0.4, options.spacing = 0.25;
        options.tab_width = 0.2;
      }
      std::stringstream svg, pdf;
      const QD::IO::Pattern_result a =
          QD::IO::write_patterns_SVG(svg, s.tm, chart, s.result.corner_uv, s.result.seam_edges, options);
      const QD::IO::Pattern_result b =
          QD::IO::write_patterns_PDF(pdf, s.tm, chart, s.result.corner_uv, s.result.seam_edges, options);
      BOOST_REQUIRE(a);
      BOOST_REQUIRE(b);
      BOOST_TEST(b.scale == a.scale);
      BOOST_TEST(b.number_of_pages == a.number_of_pages);
      BOOST_TEST(b.cut_edges == a.cut_edges);
      BOOST_TEST(b.tabs == a.tabs);
      BOOST_TEST(b.fold_lines == a.fold_lines);
      BOOST_TEST(b.seam_labels == a.seam_labels);
      const std::string file = pdf.str();
      BOOST_TEST(file.compare(0, 5, "%PDF-") == 0);
      const std::vector<std::array<double, 4>> pages = pdf_pages(file);
      BOOST_TEST(pages.size() == b.number_of_pages);
      // A4 is 595.28 x 841.89 points, letter 612 x 792
      const double width = units == "mm" ? 210 / 25.4 * 72 : 612, height = units == "mm" ? 297 / 25.4 * 72 : 792;
      for(const auto& box : pages) {
        BOOST_TEST(box[0] == 0.);
        BOOST_TEST(box[1] == 0.);
        BOOST_TEST(box[2] == width, tt::tolerance(1e-5));
        BOOST_TEST(box[3] == height, tt::tolerance(1e-5));
      }
      BOOST_TEST_MESSAGE(pages.size() << " PDF pages of " << units << ", " << file.size() << " bytes");
    }
  }
}

BOOST_AUTO_TEST_CASE(pdf_patterns_refuse_bad_input_and_say_when_they_cannot_write)
{
  const Segmented& s = meshes().front();
  const auto chart = boost::make_assoc_property_map(const_cast<Chart_map&>(s.chart));
  QD::IO::Pattern_options bad;
  bad.units = "furlong";
  std::stringstream ss;
  BOOST_TEST((QD::IO::write_patterns_PDF(ss, s.tm, chart, s.result.corner_uv, s.result.seam_edges, bad).status ==
              QD::Error_code::INVALID_COORDINATES));
  BOOST_TEST(ss.str().empty());
  std::ofstream closed;  // no file: every write fails
  BOOST_TEST((QD::IO::write_patterns_PDF(closed, s.tm, chart, s.result.corner_uv, s.result.seam_edges).status ==
              QD::Error_code::CANNOT_WRITE));
  BOOST_TEST((QD::IO::write_patterns_SVG(closed, s.tm, chart, s.result.corner_uv, s.result.seam_edges).status ==
              QD::Error_code::CANNOT_WRITE));
}

// the grey pixels of a binary PGM file (as pdftoppm -gray writes it), row by row
std::vector<unsigned char> read_pgm(const std::filesystem::path& file, int& width, int& height)
{
  std::ifstream pgm(file, std::ios::binary);
  std::string magic;
  int max = 0;
  BOOST_REQUIRE(pgm >> magic >> width >> height >> max);
  pgm.get();
  BOOST_REQUIRE(magic == "P5");
  std::vector<unsigned char> pixels(std::size_t(width) * height);
  BOOST_REQUIRE(pgm.read(reinterpret_cast<char*>(pixels.data()), std::streamsize(pixels.size())));
  return pixels;
}

// a 1 x 1 square in one chart, its UVs its x and y
Surface_mesh unit_square(Chart_map& chart, std::vector<std::array<double, 2>>& uv)
{
  Surface_mesh tm;
  const auto v0 = tm.add_vertex(Epick::Point_3(0, 0, 0)), v1 = tm.add_vertex(Epick::Point_3(1, 0, 0)),
             v2 = tm.add_vertex(Epick::Point_3(1, 1, 0)), v3 = tm.add_vertex(Epick::Point_3(0, 1, 0));
  tm.add_face(v0, v1, v2);
  tm.add_face(v0, v2, v3);
  uv.assign(6, {{0, 0}});
  for(auto f : faces(tm)) {
    chart[f] = 0;
    int c = 0;
    for(auto h : CGAL::halfedges_around_face(halfedge(f, tm), tm)) {
      const Epick::Point_3& p = tm.point(target(h, tm));
      uv[3 * std::size_t(f) + c++] = {{p.x(), p.y()}};
    }
  }
  return tm;
}

// the box of the pixels darker than 80 (the black cut lines, not the grey
// page numbers, chart ids, frames and marks): left, right, top, bottom
std::array<int, 4> dark_box(const std::vector<unsigned char>& pixels, int width, int height)
{
  std::array<int, 4> box = {width, -1, height, -1};
  for(int y = 0; y < height; ++y)
    for(int x = 0; x < width; ++x)
      if(pixels[std::size_t(y) * width + x] < 80)
        box = {std::min(box[0], x), std::max(box[1], x), std::min(box[2], y), std::max(box[3], y)};
  return box;
}

// `options`' pattern of the chart of `tm` as a PDF in a fresh temporary
// directory `name`, printed by poppler at `dpi` (gray, DIR/square-N.pgm; the
// first page only, or every page); an empty path where pdftoppm is not installed
std::filesystem::path print_pattern(const Surface_mesh& tm, Chart_map& chart, const std::vector<std::array<double, 2>>& uv,
                                    const QD::IO::Pattern_options& options, int dpi, const std::string& name,
                                    bool every_page)
{
  if(std::system("pdftoppm -v > /dev/null 2>&1") != 0) {
    BOOST_TEST_MESSAGE("pdftoppm (poppler-utils) is not installed: the printed pattern is not checked");
    return {};
  }
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  {
    std::ofstream out(dir / "square.pdf", std::ios::binary);
    BOOST_REQUIRE(QD::IO::write_patterns_PDF(out, tm, boost::make_assoc_property_map(chart), uv,
                                             std::vector<Surface_mesh::Edge_index>(), options));
  }
  const std::string command = "pdftoppm -gray -r " + std::to_string(dpi) + (every_page ? "" : " -f 1 -l 1") + " '" +
                              (dir / "square.pdf").string() + "' '" + (dir / "square").string() + "'";
  BOOST_REQUIRE(std::system(command.c_str()) == 0);
  return dir;
}

// A 1 x 1 square at 100 mm per unit, printed to pixels by poppler at 254 dpi
// (10 pixels per millimetre): its cut lines span 100 mm
BOOST_AUTO_TEST_CASE(pdf_pattern_prints_at_true_scale)
{
  Chart_map chart;
  std::vector<std::array<double, 2>> uv;
  const Surface_mesh tm = unit_square(chart, uv);
  QD::IO::Pattern_options options;
  options.scale = 100;
  const std::filesystem::path dir = print_pattern(tm, chart, uv, options, 254, "cgal_qd_pdf_scale", false);
  if(dir.empty()) return;
  int width = 0, height = 0;
  const std::vector<unsigned char> pixels = read_pgm(dir / "square-1.pgm", width, height);
  // the page: 210 x 297 mm
  BOOST_TEST(std::abs(width - 2100) <= 1);
  BOOST_TEST(std::abs(height - 2970) <= 1);
  // the cut lines are black; the page number and the chart id are grey
  const auto [left, right, top, bottom] = dark_box(pixels, width, height);
  BOOST_TEST_MESSAGE("the square prints " << (right - left + 1) / 10. << " x " << (bottom - top + 1) / 10.
                                           << " mm, lines included");
  // 100 mm and the 0.25 mm line: 1002.5 pixels, within 0.3 mm
  BOOST_TEST(std::abs(right - left + 1 - 1002.5) <= 3);
  BOOST_TEST(std::abs(bottom - top + 1 - 1002.5) <= 3);
  // the scale check's bars, grey (100 to 140), in the margins of the
  // bottom-left corner: 50 mm and their 0.25 mm ticks at the ends
  int first = height, last = -1, longest = 0;
  for(int y = 0; y < height; ++y)
    for(int x = 0, run = 0; x < width; ++x) {
      const bool grey = pixels[std::size_t(y) * width + x] < 140;
      if(grey && x < 100) first = std::min(first, y), last = std::max(last, y);
      run = grey ? run + 1 : 0;
      if(y >= 2870) longest = std::max(longest, run);
    }
  BOOST_TEST_MESSAGE("the scale check prints " << longest / 10. << " x " << (last - first + 1) / 10. << " mm");
  BOOST_TEST(std::abs(longest - 502.5) <= 3);
  BOOST_TEST(std::abs(last - first + 1 - 502.5) <= 3);
  std::filesystem::remove_all(dir);
}

// The same square at 400 mm per unit, larger than an A4 page: printed by
// poppler at 127 dpi (5 pixels per millimetre), its parts' printable areas
// laid side by side as their rows and columns say give the square, 400 mm
// wide and high; nothing is printed in a part's margins but its caption
BOOST_AUTO_TEST_CASE(pdf_parts_of_a_large_piece_join_at_true_scale)
{
  Chart_map chart;
  std::vector<std::array<double, 2>> uv;
  const Surface_mesh tm = unit_square(chart, uv);
  QD::IO::Pattern_options options;
  options.scale = 400;
  std::stringstream svg;
  const QD::IO::Pattern_result pr = QD::IO::write_patterns_SVG(svg, tm, boost::make_assoc_property_map(chart), uv,
                                                               std::vector<Surface_mesh::Edge_index>(), options);
  BOOST_REQUIRE(pr);
  BOOST_TEST(pr.oversized_charts == 1u);
  BOOST_TEST(pr.part_pages == 6u);  // 406 x 406 mm with the spacing: 3 columns and 2 rows of 190 x 277 mm
  BOOST_REQUIRE(pr.number_of_pages < 10u);  // pdftoppm numbers them with one digit
  const std::filesystem::path dir = print_pattern(tm, chart, uv, options, 127, "cgal_qd_pdf_parts", true);
  if(dir.empty()) return;
  boost::property_tree::ptree tree;
  BOOST_REQUIRE_NO_THROW(boost::property_tree::read_xml(svg, tree));
  const int margin = 50, uw = 950, uh = 1385;  // 10 mm, 190 mm, 277 mm
  const int columns = 3, rows = 2;
  std::vector<unsigned char> whole(std::size_t(columns * uw) * (rows * uh), 255);
  std::size_t parts = 0;
  for(const auto& child : tree.get_child("svg")) {
    if(child.first != "g" || child.second.get<std::string>("<xmlattr>.class") != "part") continue;
    const int page = child.second.get<int>("<xmlattr>.data-page"), row = child.second.get<int>("<xmlattr>.data-row"),
              column = child.second.get<int>("<xmlattr>.data-column");
    BOOST_REQUIRE(row < rows);
    BOOST_REQUIRE(column < columns);
    int width = 0, height = 0;
    const std::vector<unsigned char> pixels =
        read_pgm(dir / ("square-" + std::to_string(page + 1) + ".pgm"), width, height);
    BOOST_REQUIRE(std::abs(width - 1050) <= 1);  // 210 x 297 mm
    BOOST_REQUIRE(std::abs(height - 1485) <= 1);
    std::size_t in_margins = 0;
    for(int y = 0; y < height; ++y)
      for(int x = 0; x < width; ++x) {
        const unsigned char v = pixels[std::size_t(y) * width + x];
        const bool in_window = x >= margin && x < margin + uw && y >= margin && y < margin + uh;
        if(in_window)
          whole[std::size_t(row * uh + y - margin) * (columns * uw) + column * uw + x - margin] = v;
        else if(v < 80 && y >= margin)  // the caption is in the top margin
          ++in_margins;
      }
    BOOST_TEST(in_margins == 0u, "page " << page + 1 << " prints " << in_margins << " dark pixels in its margins");
    ++parts;
  }
  BOOST_TEST(parts == 6u);
  // the cut lines are black; the marks, frames, page numbers and chart id are grey
  const auto [left, right, top, bottom] = dark_box(whole, columns * uw, rows * uh);
  BOOST_TEST_MESSAGE("the parts join into a square of " << (right - left + 1) / 5. << " x " << (bottom - top + 1) / 5.
                                                         << " mm, lines included");
  // 400 mm and the 0.25 mm line: 2001.25 pixels, within 0.6 mm
  BOOST_TEST(std::abs(right - left + 1 - 2001.25) <= 3);
  BOOST_TEST(std::abs(bottom - top + 1 - 2001.25) <= 3);
  std::filesystem::remove_all(dir);
}
#endif // CGAL_QD_HAS_CAIRO

namespace {

// the polygons and seam lines of a segmentation picture, and the fills of the polygons
struct Picture
{
  std::size_t polygons = 0, lines = 0, turned_towards = 0, turned_away = 0;
  std::multiset<std::string> fills;
};

template <class EdgeRange>
Picture picture(const Surface_mesh& tm, const Chart_map& chart, const EdgeRange& seams)
{
  std::stringstream ss;
  BOOST_REQUIRE((QD::IO::write_segmentation_SVG(ss, tm, boost::make_assoc_property_map(chart), seams) ==
                 QD::Error_code::OK));
  boost::property_tree::ptree tree;
  BOOST_REQUIRE_NO_THROW(boost::property_tree::read_xml(ss, tree));
  Picture p;
  for(const auto& child : tree.get_child("svg.g")) {
    if(child.first == "polygon") {
      ++p.polygons;
      p.fills.insert(child.second.get<std::string>("<xmlattr>.fill"));
      // every point inside the picture
      std::istringstream pts(child.second.get<std::string>("<xmlattr>.points"));
      std::string xy;
      std::vector<std::array<double, 2>> c;
      while(pts >> xy) {
        const double x = std::stod(xy.substr(0, xy.find(','))), y = std::stod(xy.substr(xy.find(',') + 1));
        BOOST_TEST((x >= 0 && x <= 800 && y >= 0 && y <= 800));
        c.push_back({x, y});
      }
      // turned towards the viewer: clockwise on the page, whose y axis points
      // down (a little slack for the rounding of the coordinates)
      double area = 0;
      for(std::size_t k = 0; k < c.size(); ++k)
        area += c[k][0] * c[(k + 1) % c.size()][1] - c[(k + 1) % c.size()][0] * c[k][1];
      if(area > 0.1) ++p.turned_away;
      if(area < -0.1) ++p.turned_towards;
    }
    if(child.first == "line") ++p.lines;
  }
  return p;
}

} // namespace

// A closed surface is drawn without the faces turned away from the viewer
// (the faces turned towards it cover them), whichever way its faces are
// oriented; a surface with a border is drawn whole
BOOST_AUTO_TEST_CASE(segmentation_picture_draws_the_faces_that_can_be_seen_and_their_seams)
{
  for(const Segmented& s : meshes()) {
    const Picture p = picture(s.tm, s.chart, s.result.seam_edges);
    BOOST_TEST_MESSAGE(p.polygons << " of " << num_faces(s.tm) << " faces drawn, " << p.lines << " seam lines");
    // a closed surface: about half of its faces turned towards the viewer
    BOOST_TEST(p.polygons < 0.7 * double(num_faces(s.tm)));
    BOOST_TEST(p.polygons > 0.3 * double(num_faces(s.tm)));
    BOOST_TEST(p.turned_away == 0u);
    // a seam edge is drawn with each of its faces that is drawn
    BOOST_TEST(p.lines < 2 * s.result.seam_edges.size());
    BOOST_TEST(p.lines > s.result.seam_edges.size() / 2);
    std::set<std::string> shades(p.fills.begin(), p.fills.end());
    BOOST_TEST(shades.size() > s.result.number_of_charts);  // shaded chart colours
    // inside out: the same faces drawn in the same shades
    Surface_mesh inverted = s.tm;
    CGAL::Polygon_mesh_processing::reverse_face_orientations(inverted);
    Chart_map inverted_chart;
    for(auto f : faces(inverted)) inverted_chart[f] = s.chart.at(f);
    std::vector<Surface_mesh::Edge_index> inverted_seams(s.result.seam_edges.begin(), s.result.seam_edges.end());
    const Picture q = picture(inverted, inverted_chart, inverted_seams);
    BOOST_TEST(q.polygons == p.polygons);
    BOOST_TEST(q.lines == p.lines);
    BOOST_TEST((q.fills == p.fills));
    BOOST_TEST(q.turned_away == p.turned_towards);  // their orientation on the page is reversed too
    BOOST_TEST(q.turned_towards == 0u);
  }
  // a tube open at both ends: every face drawn, its inside through the ends
  const Surface_mesh tube = make<Surface_mesh>(grid(24, 8, cylinder(1.0, 1.9 * 3.14159265358979, 2.0)));
  Chart_map tube_chart;
  for(auto f : faces(tube)) tube_chart[f] = static_cast<std::size_t>(f) % 2;
  const Picture t = picture(tube, tube_chart, std::vector<Surface_mesh::Edge_index>());
  BOOST_TEST(t.polygons == num_faces(tube));
  BOOST_TEST(t.turned_away > 0u);
  std::stringstream ss;
  const Surface_mesh empty;
  Chart_map none;
  BOOST_TEST((QD::IO::write_segmentation_SVG(ss, empty, boost::make_assoc_property_map(none),
                                             std::vector<Surface_mesh::Edge_index>()) == QD::Error_code::EMPTY_MESH));
}

BOOST_AUTO_TEST_CASE(chart_palette_tells_neighbouring_charts_apart)
{
  // a torus cut into 12 x 6 blocks (72 charts, 4 neighbours each), and the segmented meshes
  std::vector<std::pair<const Surface_mesh*, Chart_map>> cases;
  static const Surface_mesh blocks = make<Surface_mesh>(torus(48, 24));
  Chart_map block_chart;
  std::size_t k = 0;
  for(auto f : faces(blocks)) {
    const std::size_t grid = k / 2, i = grid % 48, j = grid / 48;  // two triangles per grid square
    block_chart[f] = (j / 4) * 12 + i / 4;
    ++k;
  }
  cases.emplace_back(&blocks, block_chart);
  for(const Segmented& s : meshes()) cases.emplace_back(&s.tm, s.chart);
  for(const auto& c : cases) {
    const auto palette = QD::IO::chart_palette(*c.first, boost::make_assoc_property_map(c.second));
    std::size_t n = 0;
    for(const auto& fc : c.second) n = (std::max)(n, fc.second + 1);
    BOOST_REQUIRE(palette.size() == n);
    std::set<std::array<unsigned char, 3>> used(palette.begin(), palette.end());
    BOOST_TEST(used.size() == (std::min)(n, QD::IO::palette_colors().size()));  // every colour is used
    std::size_t pairs = 0;
    for(auto h : halfedges(*c.first)) {
      if(is_border_edge(h, *c.first)) continue;
      const std::size_t a = c.second.at(face(h, *c.first)), b = c.second.at(face(opposite(h, *c.first), *c.first));
      if(a == b) continue;
      ++pairs;
      // neighbours differ clearly
      BOOST_TEST(QD::internal::color_distance2(palette[a], palette[b]) >= 120. * 120.);
    }
    BOOST_TEST(pairs > 0u);
    // the same charts give the same colours
    BOOST_TEST((QD::IO::chart_palette(*c.first, boost::make_assoc_property_map(c.second)) == palette));
  }
}

BOOST_AUTO_TEST_CASE(segmentation_picture_is_seen_from_where_most_charts_show)
{
  // a box whose bottom (y = 0) is cut into 3 x 3 charts and the rest is one:
  // from above (the default direction) only the one chart shows
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<std::size_t, 3>> triangles;
  std::vector<std::size_t> chart;
  const std::size_t n = 6;
  for(int axis = 0; axis < 3; ++axis)
    for(int side = 0; side < 2; ++side) {
      const std::size_t first = points.size();
      for(std::size_t j = 0; j <= n; ++j)
        for(std::size_t i = 0; i <= n; ++i) {
          std::array<double, 3> p;
          p[axis] = side;
          p[(axis + 1) % 3] = double(i) / n;
          p[(axis + 2) % 3] = double(j) / n;
          points.push_back(p);
        }
      for(std::size_t j = 0; j < n; ++j)
        for(std::size_t i = 0; i < n; ++i) {
          const std::size_t a = first + j * (n + 1) + i;
          const std::size_t id = axis == 1 && side == 0 ? 1 + (j / 2) * 3 + i / 2 : 0;
          triangles.push_back({{a, a + 1, a + n + 2}});
          triangles.push_back({{a, a + n + 2, a + n + 1}});
          chart.insert(chart.end(), 2, id);
        }
    }
  const QD::internal::View_angles from_above;
  auto seen = [&](const QD::internal::View_angles& v) {
    std::size_t count = 0;
    for(std::size_t p : QD::internal::visible_chart_pixels(points, triangles, chart, 10, v, 160)) count += p >= 3;
    return count;
  };
  BOOST_TEST(seen(from_above) == 1u);
  const QD::internal::View_angles chosen = QD::internal::view_showing_most_charts(points, triangles, chart, 10, from_above);
  BOOST_TEST(chosen.elevation < 0);  // from below
  BOOST_TEST(seen(chosen) >= 10u);
  // the picture follows: the bottom's nine charts in their palette colours among the faces drawn last
  Surface_mesh box;
  std::vector<Surface_mesh::Vertex_index> vs;
  for(const auto& p : points) vs.push_back(box.add_vertex(Epick::Point_3(p[0], p[1], p[2])));
  Chart_map box_chart;
  for(std::size_t t = 0; t < triangles.size(); ++t)
    box_chart[box.add_face(vs[triangles[t][0]], vs[triangles[t][1]], vs[triangles[t][2]])] = chart[t];
  std::stringstream ss;
  BOOST_REQUIRE((QD::IO::write_segmentation_SVG(ss, box, boost::make_assoc_property_map(box_chart),
                                                std::vector<Surface_mesh::Edge_index>()) == QD::Error_code::OK));
  QD::IO::Picture_options fixed;
  fixed.choose_view = false;
  std::stringstream fixed_ss;
  BOOST_REQUIRE((QD::IO::write_segmentation_SVG(fixed_ss, box, boost::make_assoc_property_map(box_chart),
                                                std::vector<Surface_mesh::Edge_index>(), fixed) == QD::Error_code::OK));
  BOOST_TEST(ss.str() != fixed_ss.str());
}

namespace {

std::vector<unsigned char> from_base64(const std::string& text)
{
  std::vector<unsigned char> out;
  unsigned value = 0;
  int bits = 0;
  for(char c : text) {
    const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    const char* at = c ? std::strchr(table, c) : nullptr;
    if(!at) continue;  // '=' padding
    value = (value << 6) | unsigned(at - table);
    bits += 6;
    if(bits >= 8) {
      bits -= 8;
      out.push_back(static_cast<unsigned char>((value >> bits) & 255));
    }
  }
  return out;
}

template <class T>
std::vector<T> typed(const std::string& text)
{
  const std::vector<unsigned char> bytes = from_base64(text);
  std::vector<T> v(bytes.size() / sizeof(T));
  std::memcpy(v.data(), bytes.data(), v.size() * sizeof(T));
  return v;
}

} // namespace

BOOST_AUTO_TEST_CASE(viewer_page_holds_the_mesh_and_its_pieces_at_true_scale)
{
  QD::IO::Viewer_options options;
  options.three_js = "var THREE = {};";  // the page's structure is checked here, the drawing in a browser
  options.three_js_license = "licence";
  for(const Segmented& s : meshes()) {
    std::stringstream ss;
    BOOST_REQUIRE((QD::IO::write_viewer_HTML(ss, s.tm, boost::make_assoc_property_map(s.chart), s.result, options) ==
                   QD::Error_code::OK));
    const std::string page = ss.str();
    BOOST_TEST(page.find(options.three_js) != std::string::npos);
    BOOST_TEST(page.find("licence") != std::string::npos);
    const std::string open = "<script type=\"application/json\" id=\"qd-data\">";
    const std::size_t from = page.find(open) + open.size(), to = page.find("</script>", from);
    BOOST_REQUIRE(from != std::string::npos + open.size());
    std::stringstream json(page.substr(from, to - from));
    boost::property_tree::ptree data;
    BOOST_REQUIRE_NO_THROW(boost::property_tree::read_json(json, data));
    const std::size_t nf = num_faces(s.tm), n = s.result.number_of_charts;
    BOOST_TEST(data.get_child("charts").size() == n);
    BOOST_TEST(data.get_child("palette").size() == n);
    // the seams as labelled on the pattern
    std::stringstream svg;
    const QD::IO::Pattern_result pattern = QD::IO::write_patterns_SVG(svg, s.tm, boost::make_assoc_property_map(s.chart),
                                                                      s.result.corner_uv, s.result.seam_edges);
    BOOST_TEST(data.get_child("seams").size() == pattern.seam_labels);
    // the mesh: every face with its vertices and chart, the points in a unit box
    const auto positions = typed<float>(data.get<std::string>("positions"));
    const auto triangles = typed<std::uint32_t>(data.get<std::string>("triangles"));
    const auto face_chart = typed<std::uint32_t>(data.get<std::string>("face_chart"));
    const auto flat = typed<float>(data.get<std::string>("flat"));
    BOOST_REQUIRE(positions.size() == 3 * num_vertices(s.tm));
    BOOST_REQUIRE(triangles.size() == 3 * nf);
    BOOST_REQUIRE(face_chart.size() == nf);
    BOOST_REQUIRE(flat.size() == 6 * nf);
    for(float x : positions) BOOST_TEST((x >= -0.5f && x <= 0.5f));
    const double extent = data.get<double>("extent");
    std::vector<double> area_2d(n, 0.), area_page(n, 0.);
    for(auto f : faces(s.tm)) {
      const std::size_t i = f.idx(), k = s.chart.at(f);
      BOOST_TEST(face_chart[i] == k);
      std::size_t c = 0;
      for(auto h : CGAL::halfedges_around_face(halfedge(f, s.tm), s.tm)) BOOST_TEST(triangles[3 * i + c++] == target(h, s.tm).idx());
      const auto& u = s.result.corner_uv;
      area_2d[k] += std::abs((u[3 * i + 1][0] - u[3 * i][0]) * (u[3 * i + 2][1] - u[3 * i][1]) -
                             (u[3 * i + 2][0] - u[3 * i][0]) * (u[3 * i + 1][1] - u[3 * i][1])) / 2;
      const float* q = &flat[6 * i];
      area_page[k] += std::abs((q[2] - q[0]) * (q[5] - q[1]) - (q[4] - q[0]) * (q[3] - q[1])) / 2 * extent * extent;
    }
    // true scale: every piece keeps the area of its flattening
    for(std::size_t k = 0; k < n; ++k) BOOST_TEST(area_page[k] == area_2d[k], tt::tolerance(1e-4));
    // the two sides of every seam: their flat lengths are those of the flattening
    double total = 0, sides = 0;
    for(const auto& seam : data.get_child("seams")) {
      total += seam.second.get<double>("length");
      for(const auto& side : seam.second.get_child("sides")) sides += side.second.get_value<double>();
    }
    BOOST_TEST(total == s.result.seam_length, tt::tolerance(1e-9));
    BOOST_TEST(sides == 2 * s.result.seam_length, tt::tolerance(0.05));  // LPFB keeps border lengths
  }
}

BOOST_AUTO_TEST_CASE(viewer_page_refuses_bad_input_and_writes_nothing)
{
  const Segmented& s = meshes().front();
  const auto chart = boost::make_assoc_property_map(s.chart);
  QD::IO::Viewer_options options;
  options.three_js = "var THREE = {};";
  auto write = [&](const Surface_mesh& tm, const QD::Chart_flattening_result<Surface_mesh>& f,
                   const QD::IO::Viewer_options& o, std::string& out) {
    std::stringstream ss;
    Chart_map none;
    const QD::Error_code code = &tm == &s.tm ? QD::IO::write_viewer_HTML(ss, tm, chart, f, o)
                                             : QD::IO::write_viewer_HTML(ss, tm, boost::make_assoc_property_map(none), f, o);
    out = ss.str();
    return code;
  };
  std::string out;
  QD::IO::Viewer_options no_three = options;
  no_three.three_js.clear();
  BOOST_TEST((write(s.tm, s.result, no_three, out) == QD::Error_code::INVALID_ARGUMENT));
  BOOST_TEST(out.empty());
  QD::IO::Viewer_options closing = options;
  closing.three_js = "var a = '</script>';";
  BOOST_TEST((write(s.tm, s.result, closing, out) == QD::Error_code::INVALID_ARGUMENT));
  BOOST_TEST(out.empty());
  closing = options;
  closing.three_js_license = "MIT -->";
  BOOST_TEST((write(s.tm, s.result, closing, out) == QD::Error_code::INVALID_ARGUMENT));
  BOOST_TEST(out.empty());
  QD::Chart_flattening_result<Surface_mesh> short_uv = s.result;
  short_uv.corner_uv.pop_back();
  BOOST_TEST((write(s.tm, short_uv, options, out) == QD::Error_code::INVALID_COORDINATES));
  BOOST_TEST(out.empty());
  QD::Chart_flattening_result<Surface_mesh> nan_uv = s.result;
  nan_uv.corner_uv[5][1] = std::numeric_limits<double>::quiet_NaN();
  BOOST_TEST((write(s.tm, nan_uv, options, out) == QD::Error_code::INVALID_COORDINATES));
  BOOST_TEST(out.empty());
  const Surface_mesh empty;
  BOOST_TEST((write(empty, QD::Chart_flattening_result<Surface_mesh>(), options, out) == QD::Error_code::EMPTY_MESH));
  BOOST_TEST(out.empty());
  Surface_mesh quad;
  quad.add_face(quad.add_vertex(Epick::Point_3(0, 0, 0)), quad.add_vertex(Epick::Point_3(1, 0, 0)), quad.add_vertex(Epick::Point_3(1, 1, 0)),
                quad.add_vertex(Epick::Point_3(0, 1, 0)));
  QD::Chart_flattening_result<Surface_mesh> quad_uv;
  quad_uv.corner_uv.assign(3, {{0., 0.}});
  BOOST_TEST((write(quad, quad_uv, options, out) == QD::Error_code::NOT_TRIANGLE_MESH));
  BOOST_TEST(out.empty());
  // a stream that fails
  std::ofstream closed;
  BOOST_TEST((QD::IO::write_viewer_HTML(closed, s.tm, chart, s.result, options) == QD::Error_code::CANNOT_WRITE));
  // huge coordinates: the page's points stay finite, in the unit box
  Surface_mesh huge = s.tm;
  for(auto v : vertices(huge)) {
    const Epick::Point_3 p = huge.point(v);
    huge.point(v) = Epick::Point_3(p.x() * 1e200, p.y() * 1e200, p.z() * 1e200);
  }
  Chart_map huge_chart;
  auto fh = faces(huge).begin();
  for(auto f : faces(s.tm)) huge_chart[*fh++] = s.chart.at(f);
  std::stringstream ss;
  BOOST_REQUIRE((QD::IO::write_viewer_HTML(ss, huge, boost::make_assoc_property_map(huge_chart), s.result, options) ==
                 QD::Error_code::OK));
  const std::string page = ss.str();
  const std::string key = "\"positions\":\"";
  const std::size_t at = page.find(key) + key.size();
  for(float x : typed<float>(page.substr(at, page.find('"', at) - at))) BOOST_TEST((std::isfinite(x) && std::abs(x) <= 0.5f));
}
