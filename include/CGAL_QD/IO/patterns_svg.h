// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_IO_PATTERNS_SVG_H
#define CGAL_QD_IO_PATTERNS_SVG_H

/// \file IO/patterns_svg.h
/// Printable sewing and folding patterns: every chart of a segmentation at true
/// scale, laid out on pages, with cut lines, matching seam labels, optional
/// glue tabs and fold lines.

#include <CGAL_QD/Error_code.h>
#include <CGAL_QD/internal/charts.h>
#include <CGAL_QD/internal/validation.h>
#include <CGAL_QD/pack_charts.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <map>
#include <ostream>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace CGAL_QD {
namespace internal {

// seam label of index k: A..Z, then A1..Z1, ...
inline std::string seam_label(std::size_t k)
{
  std::string s(1, char('A' + k % 26));
  if(k >= 26) s += std::to_string(k / 26);
  return s;
}

inline std::string svg_number(double x)
{
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.4f", std::abs(x) < 5e-5 ? 0. : x);
  return buffer;
}

} // namespace internal

namespace IO {

/// \ingroup PkgCGAL_QDRef
/// options of `write_patterns_SVG()`.
struct Pattern_options
{
  /// drawing units per mesh unit: the pattern is printed at this scale
  double scale = 1;
  /// the unit of the drawing, written into the SVG's width and height (`mm`, `cm`, `in`, `px`)
  std::string units = "mm";
  /// the page, in drawing units (default A4 portrait in mm)
  double page_width = 210, page_height = 297;
  /// free border of every page, and space between charts, in drawing units
  double page_margin = 10, spacing = 6;
  /// draw a glue tab on one side of every seam
  bool tabs = false;
  /// the width of the tabs, in drawing units
  double tab_width = 5;
  /// interior edges whose dihedral angle exceeds this (radians) are fold lines
  double fold_angle = 0.1745329251994330;  // 10 degrees
  /// the height of the label text, in drawing units (0: from the page size)
  double font_size = 0;
};

/// \ingroup PkgCGAL_QDRef
/// what `write_patterns_SVG()` drew.
struct Pattern_result
{
  Error_code status = Error_code::OK;
  std::size_t number_of_pages = 0;
  std::size_t number_of_charts = 0;
  /// charts larger than a page (after turning them): each gets pages of its own and overflows their frames
  std::size_t oversized_charts = 0;
  std::size_t cut_edges = 0;    ///< edges on the charts' borders, each drawn once per side
  std::size_t seam_labels = 0;  ///< labels of seam curves, each drawn on both sides
  std::size_t fold_lines = 0;
  std::size_t tabs = 0;

  explicit operator bool() const { return status == Error_code::OK; }
};


/// \ingroup PkgCGAL_QDRef
/// writes the flattened charts as a printable SVG pattern at true scale:
///
/// \param out the stream written to
/// \param tm the triangle mesh
/// \param face_chart the chart id of every face
/// \param options the drawing options
/// - each chart is turned to its smallest enclosing rectangle and the charts are
///   placed in rows on pages of `page_width` x `page_height` (stacked downwards
///   in one SVG, each page framed and numbered), turned by 90 degrees when that
///   makes them fit; a chart larger than a page gets as many pages of its own as
///   its height needs and overflows their frames (print it tiled, or lower `scale`);
/// - the layout shows the outer side of the surface (a chart is drawn as seen
///   from the side its face normals point to);
/// - cut lines (solid, class `cut`) on every border edge of a chart: a seam or a
///   border of the mesh. Each carries `data-v="i j"`, the indices of the edge's
///   vertices in `tm`;
/// - every seam curve (a chain of seam edges between the same two charts, or a
///   cut inside one chart, from junction to junction) has a label, drawn on
///   both sides of the seam, so the pieces can be matched;
/// - with `tabs`, a glue tab outside one side of every seam edge;
/// - fold lines on interior edges whose dihedral angle exceeds `fold_angle`:
///   mountain folds (convex edges) dash-dotted in red, valley folds (concave)
///   dashed in blue;
/// - the chart id at the chart's centre.
///
/// \param corner_uv 3 UVs per face by face index, in mesh units and with each chart's
///        border at its true length (`Segmentation_result::corner_uv`)
/// \param seam_edges the edges where the surface is cut (`Segmentation_result::seam_edges`)
/// \param np optional: `vertex_point_map`, `vertex_index_map`, `face_index_map`
/// \returns a `Pattern_result`; `EMPTY_MESH` without faces, `INVALID_COORDINATES` if
///          `corner_uv` has the wrong size or a non-finite value, or the options are not positive.
template <class TriangleMesh, class FaceChartMap, class EdgeRange,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
Pattern_result write_patterns_SVG(std::ostream& out, const TriangleMesh& tm, const FaceChartMap& face_chart,
                                  const std::vector<std::array<double, 2>>& corner_uv, const EdgeRange& seam_edges,
                                  const Pattern_options& options = Pattern_options(),
                                  const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;
  typedef typename GT::edge_descriptor edge_descriptor;
  typedef std::array<double, 2> P2;
  typedef CGAL::Exact_predicates_inexact_constructions_kernel K;

  Pattern_result result;
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, tm));
  const auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
  const auto fim = CGAL::get_initialized_face_index_map(tm, np);
  const std::size_t nf = static_cast<std::size_t>(num_faces(tm));
  if(nf == 0) {
    result.status = Error_code::EMPTY_MESH;
    return result;
  }
  bool valid = corner_uv.size() == 3 * nf && options.scale > 0 && options.page_width > 2 * options.page_margin &&
               options.page_height > 2 * options.page_margin && options.spacing >= 0 && options.tab_width >= 0;
  for(std::size_t i = 0; valid && i < corner_uv.size(); ++i)
    valid = std::isfinite(corner_uv[i][0]) && std::isfinite(corner_uv[i][1]);
  if(!valid) {
    result.status = Error_code::INVALID_COORDINATES;
    return result;
  }
  const double font = options.font_size > 0 ? options.font_size : std::min(options.page_width, options.page_height) / 60;

  std::vector<face_descriptor> face_of(nf);
  std::vector<std::size_t> chart(nf);
  std::size_t n = 0;
  for(face_descriptor f : faces(tm)) {
    face_of[get(fim, f)] = f;
    chart[get(fim, f)] = static_cast<std::size_t>(get(face_chart, f));
    n = (std::max)(n, chart[get(fim, f)] + 1);
  }
  std::vector<std::size_t> vertex_number(num_vertices(tm));
  {
    std::size_t k = 0;
    for(auto v : vertices(tm)) vertex_number[get(vim, v)] = k++;
  }
  // corner of halfedge h in its face: the target of the k-th halfedge from halfedge(f)
  auto corner = [&](halfedge_descriptor h) {
    const face_descriptor f = face(h, tm);
    const halfedge_descriptor h0 = halfedge(f, tm);
    return 3 * get(fim, f) + (h == h0 ? 0 : (h == next(h0, tm) ? 1 : 2));
  };
  std::set<edge_descriptor> seam(seam_edges.begin(), seam_edges.end());
  auto is_cut = [&](halfedge_descriptor h) {  // h is a halfedge of a face
    return is_border(opposite(h, tm), tm) || seam.count(edge(h, tm)) > 0;
  };

  // ---- layout: every chart in its rectangle, at scale, placed in rows on pages
  std::vector<std::vector<K::Point_2>> points(n);
  for(std::size_t i = 0; i < nf; ++i)
    for(int k = 0; k < 3; ++k) points[chart[i]].emplace_back(corner_uv[3 * i + k][0], corner_uv[3 * i + k][1]);
  struct Placement { double angle = 0; P2 low{{0, 0}}, size{{0, 0}}, at{{0, 0}}; std::size_t page = 0; bool used = false; };
  std::vector<Placement> place(n);
  const double usable_w = options.page_width - 2 * options.page_margin,
               usable_h = options.page_height - 2 * options.page_margin;
  const double pad = options.spacing / 2 + (options.tabs ? options.tab_width : 0);
  std::vector<std::size_t> order;
  for(std::size_t k = 0; k < n; ++k) {
    if(points[k].empty()) continue;
    const internal::Rectangle r = internal::min_area_rectangle(points[k]);
    Placement& p = place[k];
    p.used = true;
    p.angle = r.angle;
    p.low = r.low;
    p.size = {{r.size[0] * options.scale + 2 * pad, r.size[1] * options.scale + 2 * pad}};
    // lay it flat, or upright if it fits only so
    const bool fits = p.size[0] <= usable_w && p.size[1] <= usable_h;
    const bool fits_turned = p.size[1] <= usable_w && p.size[0] <= usable_h;
    if((!fits && fits_turned) || (!fits && !fits_turned && p.size[0] > p.size[1] && usable_h > usable_w)) {
      p.angle += 1.5707963267948966;
      // turning (x, y) -> (-y, x) maps [lx, lx + w] x [ly, ly + h] to [-ly - h, -ly] x [lx, lx + w]
      p.low = {{-r.low[1] - r.size[1], r.low[0]}};
      std::swap(p.size[0], p.size[1]);
    }
    if(p.size[0] > usable_w || p.size[1] > usable_h) ++result.oversized_charts;
    order.push_back(k);
  }
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return place[a].size[1] > place[b].size[1]; });
  std::size_t page = 0;
  double x = 0, y = 0, row = 0;
  bool page_used = false;
  std::size_t last_page = 0;
  for(std::size_t k : order) {
    Placement& p = place[k];
    if(p.size[0] > usable_w || p.size[1] > usable_h) {
      // a piece larger than a page: on pages of its own, as many as its height needs
      if(page_used) ++page;
      p.page = page;
      p.at = {{options.page_margin, options.page_margin}};
      const std::size_t span = static_cast<std::size_t>(std::ceil((p.size[1] + 2 * options.page_margin) / options.page_height));
      last_page = page + span - 1;
      page += span;
      x = y = row = 0;
      page_used = false;
      continue;
    }
    if(page_used && x + p.size[0] > usable_w) {  // next row
      x = 0;
      y += row;
      row = 0;
    }
    if(page_used && y + p.size[1] > usable_h) {  // next page
      ++page;
      x = y = row = 0;
    }
    p.page = page;
    p.at = {{options.page_margin + x, options.page_margin + y}};
    x += p.size[0];
    row = (std::max)(row, p.size[1]);
    page_used = true;
    last_page = page;
  }
  result.number_of_pages = last_page + 1;
  result.number_of_charts = order.size();
  // the drawing position of a corner: scaled, rotated, y pointing down (so the
  // chart is seen from its outer side), placed on its page
  auto to_page = [&](std::size_t c, const P2& uv) {
    const Placement& p = place[chart[c / 3]];
    const double co = std::cos(p.angle), si = std::sin(p.angle);
    const double rx = co * uv[0] - si * uv[1] - p.low[0], ry = si * uv[0] + co * uv[1] - p.low[1];
    const double h = p.size[1] - 2 * pad;
    return P2{{p.at[0] + pad + options.scale * rx,
               p.page * options.page_height + p.at[1] + pad + h - options.scale * ry}};
  };
  auto point_at = [&](std::size_t c) { return to_page(c, corner_uv[c]); };

  // ---- seam curves: connected seam edges with the same pair of charts
  std::map<edge_descriptor, std::size_t> curve_of;
  std::vector<std::vector<halfedge_descriptor>> curves;
  {
    std::vector<halfedge_descriptor> todo;
    for(edge_descriptor e : seam) {
      const halfedge_descriptor h = halfedge(e, tm);
      if(is_border(h, tm) || is_border(opposite(h, tm), tm)) continue;
      todo.push_back(h);
    }
    auto pair_of = [&](halfedge_descriptor h) {
      const std::size_t a = chart[get(fim, face(h, tm))], b = chart[get(fim, face(opposite(h, tm), tm))];
      return std::make_pair((std::min)(a, b), (std::max)(a, b));
    };
    // a curve runs through vertices with two seam edges only, so every curve is a
    // simple chain between junctions or ends, and its two sides are two runs of border
    std::vector<std::size_t> degree(num_vertices(tm), 0);
    for(halfedge_descriptor h : todo) {
      ++degree[get(vim, source(h, tm))];
      ++degree[get(vim, target(h, tm))];
    }
    for(halfedge_descriptor h : todo) {
      if(curve_of.count(edge(h, tm))) continue;
      const std::size_t id = curves.size();
      curves.emplace_back(1, h);
      curve_of[edge(h, tm)] = id;
      for(std::size_t q = 0; q < curves[id].size(); ++q)
        for(halfedge_descriptor end : {curves[id][q], opposite(curves[id][q], tm)}) {
          if(degree[get(vim, target(end, tm))] != 2) continue;
          for(halfedge_descriptor g : CGAL::halfedges_around_target(end, tm)) {
            const edge_descriptor e = edge(g, tm);
            if(!seam.count(e) || curve_of.count(e) || is_border(g, tm) || is_border(opposite(g, tm), tm)) continue;
            if(pair_of(g) != pair_of(curves[id][q])) continue;
            curve_of[e] = id;
            curves[id].push_back(g);
          }
        }
    }
  }

  // ---- the SVG
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << internal::svg_number(options.page_width)
      << options.units << "\" height=\"" << internal::svg_number(options.page_height * result.number_of_pages)
      << options.units << "\" viewBox=\"0 0 " << internal::svg_number(options.page_width) << ' '
      << internal::svg_number(options.page_height * result.number_of_pages) << "\">\n"
      << "<desc>CGAL_QD pattern: " << result.number_of_charts << " pieces at " << options.scale << ' '
      << options.units << " per mesh unit; cut on solid lines, fold red dash-dot lines as mountains and blue dashed "
      << "lines as valleys, join equal labels.</desc>\n"
      << "<style>.cut{stroke:#000;stroke-width:0.25;fill:none}.mountain{stroke:#c00;stroke-width:0.2;"
      << "stroke-dasharray:3 1 0.5 1}.valley{stroke:#00c;stroke-width:0.2;stroke-dasharray:2 1}"
      << ".tab{fill:#eee;stroke:#777;stroke-width:0.15}.page{fill:none;stroke:#ccc;stroke-width:0.3}"
      << "text{font-family:sans-serif;text-anchor:middle;dominant-baseline:middle}</style>\n";
  for(std::size_t p = 0; p < result.number_of_pages; ++p)
    out << "<rect class=\"page\" x=\"0\" y=\"" << internal::svg_number(p * options.page_height) << "\" width=\""
        << internal::svg_number(options.page_width) << "\" height=\"" << internal::svg_number(options.page_height)
        << "\"/>\n<text x=\"" << internal::svg_number(options.page_width / 2) << "\" y=\""
        << internal::svg_number(p * options.page_height + options.page_height - options.page_margin / 2)
        << "\" font-size=\"" << internal::svg_number(font * 0.8) << "\">page " << p + 1 << " of "
        << result.number_of_pages << "</text>\n";

  // tabs first, under the pieces: on the side of the halfedge stored in the curve
  if(options.tabs)
    for(const auto& c : curves)
      for(halfedge_descriptor h : c) {
        const P2 a = point_at(corner(prev(h, tm))), b = point_at(corner(h));  // h runs from a to b
        const double dx = b[0] - a[0], dy = b[1] - a[1], l = std::hypot(dx, dy);
        if(!(l > 0)) continue;
        // the page shows the chart as in UV (y is flipped into SVG's downward axis), so the
        // face stays on the visual left of a -> b; (nx, ny) points there, and the tab goes the other way
        const double nx = dy / l, ny = -dx / l, w = (std::min)(options.tab_width, 0.45 * l);
        const P2 c1{{a[0] + 0.25 * dx - nx * w, a[1] + 0.25 * dy - ny * w}},
            c2{{a[0] + 0.75 * dx - nx * w, a[1] + 0.75 * dy - ny * w}};
        out << "<polygon class=\"tab\" points=\"" << internal::svg_number(a[0]) << ',' << internal::svg_number(a[1])
            << ' ' << internal::svg_number(c1[0]) << ',' << internal::svg_number(c1[1]) << ' '
            << internal::svg_number(c2[0]) << ',' << internal::svg_number(c2[1]) << ' ' << internal::svg_number(b[0])
            << ',' << internal::svg_number(b[1]) << "\"/>\n";
        ++result.tabs;
      }

  // cut lines and fold lines
  std::vector<internal::Face_geometry> geo = internal::face_geometry(tm, vpm, fim);
  for(std::size_t i = 0; i < nf; ++i) {
    halfedge_descriptor h = halfedge(face_of[i], tm);
    for(int k = 0; k < 3; ++k, h = next(h, tm)) {
      // the edge of next(h) runs from corner k to corner k + 1
      const halfedge_descriptor g = next(h, tm);
      const P2 a = point_at(3 * i + k), b = point_at(3 * i + (k + 1) % 3);
      if(is_cut(g)) {
        out << "<line class=\"cut\" data-v=\"" << vertex_number[get(vim, source(g, tm))] << ' '
            << vertex_number[get(vim, target(g, tm))] << "\" x1=\"" << internal::svg_number(a[0]) << "\" y1=\""
            << internal::svg_number(a[1]) << "\" x2=\"" << internal::svg_number(b[0]) << "\" y2=\""
            << internal::svg_number(b[1]) << "\"/>\n";
        ++result.cut_edges;
        continue;
      }
      // an interior edge: draw it once, from the face with the smaller index
      const std::size_t j = get(fim, face(opposite(g, tm), tm));
      if(j < i) continue;
      const internal::Face_geometry &fa = geo[i], &fb = geo[j];
      const double cosine = fa.normal[0] * fb.normal[0] + fa.normal[1] * fb.normal[1] + fa.normal[2] * fb.normal[2];
      if(std::acos((std::max)(-1., (std::min)(1., cosine))) <= options.fold_angle) continue;
      const double above = (fb.centroid[0] - fa.centroid[0]) * fa.normal[0] +
                           (fb.centroid[1] - fa.centroid[1]) * fa.normal[1] +
                           (fb.centroid[2] - fa.centroid[2]) * fa.normal[2];
      out << "<line class=\"" << (above > 0 ? "valley" : "mountain") << "\" x1=\"" << internal::svg_number(a[0])
          << "\" y1=\"" << internal::svg_number(a[1]) << "\" x2=\"" << internal::svg_number(b[0]) << "\" y2=\""
          << internal::svg_number(b[1]) << "\"/>\n";
      ++result.fold_lines;
    }
  }

  // seam labels, on both sides of the longest edge of each curve, inside the faces
  for(std::size_t id = 0; id < curves.size(); ++id) {
    halfedge_descriptor longest = curves[id].front();
    double best = -1;
    for(halfedge_descriptor h : curves[id]) {
      const double l = CGAL_QD::internal::distance3(CGAL_QD::internal::point_of<TriangleMesh>(source(h, tm), vpm),
                                                   CGAL_QD::internal::point_of<TriangleMesh>(target(h, tm), vpm));
      if(l > best) best = l, longest = h;
    }
    for(halfedge_descriptor h : {longest, opposite(longest, tm)}) {
      const P2 a = point_at(corner(prev(h, tm))), b = point_at(corner(h)), c = point_at(corner(next(h, tm)));
      const P2 m{{(a[0] + b[0]) / 2, (a[1] + b[1]) / 2}};
      // toward the opposite corner, at most 1.2 font heights
      const double dx = c[0] - m[0], dy = c[1] - m[1], l = std::hypot(dx, dy);
      const double t = l > 0 ? (std::min)(0.45, 1.2 * font / l) : 0.;
      const double angle = std::atan2(b[1] - a[1], b[0] - a[0]) * 180 / 3.141592653589793;
      const double upright = angle > 90 || angle < -90 ? angle + 180 : angle;
      out << "<text class=\"seam\" x=\"" << internal::svg_number(m[0] + t * dx) << "\" y=\""
          << internal::svg_number(m[1] + t * dy) << "\" font-size=\"" << internal::svg_number(font)
          << "\" transform=\"rotate(" << internal::svg_number(upright) << ' ' << internal::svg_number(m[0] + t * dx)
          << ' ' << internal::svg_number(m[1] + t * dy) << ")\">" << internal::seam_label(id) << "</text>\n";
    }
    ++result.seam_labels;
  }

  // chart ids at the centre of each chart's box
  for(std::size_t k : order) {
    const Placement& p = place[k];
    out << "<text class=\"chart\" x=\"" << internal::svg_number(p.at[0] + p.size[0] / 2) << "\" y=\""
        << internal::svg_number(p.page * options.page_height + p.at[1] + p.size[1] / 2) << "\" font-size=\""
        << internal::svg_number(1.5 * font) << "\" fill=\"#888\">" << k << "</text>\n";
  }
  out << "</svg>\n";
  if(!out) result.status = Error_code::INVALID_COORDINATES;
  return result;
}

} // namespace IO
} // namespace CGAL_QD

#endif // CGAL_QD_IO_PATTERNS_SVG_H
