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
#include <CGAL_QD/IO/internal/pattern_layout.h>
#include <CGAL_QD/pack_charts.h>
#include <CGAL_QD/segmentation_measures.h>

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
#include <limits>
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
/// millimetres per drawing unit for the units `write_patterns_SVG()` knows
/// (`mm`, `cm`, `in`, `pt`, `pc`, and `px`, the CSS pixel of 1/96 in); 0 for any other.
inline double millimetres_per_unit(const std::string& units)
{
  if(units == "mm") return 1;
  if(units == "cm") return 10;
  if(units == "in") return 25.4;
  if(units == "pt") return 25.4 / 72;
  if(units == "pc") return 25.4 / 6;
  if(units == "px") return 25.4 / 96;
  return 0;
}

/// \ingroup PkgCGAL_QDRef
/// options of `write_patterns_SVG()`. Every length is in drawing units
/// (`units`); the defaults are for millimetres.
struct Pattern_options
{
  /// drawing units per mesh unit; 0 (the default): chosen from `model_size`
  double scale = 0;
  /// with `scale` 0, the model's largest dimension (the longest side of its
  /// axis-aligned bounding box) on paper; 0 (the default): 200 mm, made smaller
  /// (to whole millimetres) where a piece would not fit on a page at that size
  double model_size = 0;
  /// the unit of the drawing, written into the SVG's width and height: `mm`, `cm`, `in`, `pt`, `pc` or `px`
  std::string units = "mm";
  /// the page (default A4 portrait in mm)
  double page_width = 210, page_height = 297;
  /// free border of every page, and space between pieces
  double page_margin = 10, spacing = 6;
  /// draw a glue tab on one side of every seam
  bool tabs = false;
  /// the width of the tabs
  double tab_width = 5;
  /// interior edges whose dihedral angle exceeds this (radians) are fold lines
  double fold_angle = 0.1745329251994330;  // 10 degrees
  /// the largest height of the label text (0: from the page size); a piece's
  /// labels are made smaller where the piece is small
  double font_size = 0;
};

/// \ingroup PkgCGAL_QDRef
/// what `write_patterns_SVG()` drew.
struct Pattern_result
{
  Error_code status = Error_code::OK;
  /// the scale used, in drawing units per mesh unit
  double scale = 0;
  /// the model's largest dimension (its longest bounding-box side) on paper, in drawing units
  double model_size = 0;
  /// whether the scale was chosen (`Pattern_options::scale` 0) and made smaller
  /// than the one of the default model size, so that every piece fits on a page
  bool reduced_to_fit = false;
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
/// - the scale is `options.scale`, or, when that is 0, the one that makes the
///   model's largest dimension `options.model_size` on paper, or, when that is
///   0 too, 200 mm, lowered to whole millimetres until every piece fits on a
///   page (`Pattern_result::scale`, `model_size` and `reduced_to_fit` tell);
/// - each chart is turned to its smallest enclosing rectangle and the charts,
///   tallest first, are packed page by page bottom-left on a skyline, each
///   either way up, on pages of `page_width` x `page_height` (stacked downwards
///   in one SVG, each page framed and numbered), what does not fit going on to
///   the next page, never within `page_margin` of a page's edge nor within
///   `spacing` (and the tabs) of each other; a chart larger than a page (at a
///   scale or a model size given) gets as many pages of its own as its height
///   needs and overflows their frames (print it tiled, or lower the scale);
/// - every piece is one group, `<g class="piece" data-chart="k" data-page="p">`,
///   holding all that is drawn for it;
/// - the layout shows the outer side of the surface (a chart is drawn as seen
///   from the side its face normals point to);
/// - cut lines (solid, class `cut`) on every border edge of a chart: a seam or a
///   border of the mesh. Each carries `data-v="i j"`, the indices of the edge's
///   vertices in `tm`;
/// - every seam curve (a chain of seam edges between the same two charts, or a
///   cut inside one chart, from junction to junction) has a label, drawn on
///   both sides of the seam, inside the piece, beside the middle of the curve,
///   so the pieces can be matched;
/// - with `tabs`, a glue tab outside one side of every seam edge;
/// - fold lines on interior edges whose dihedral angle exceeds `fold_angle`:
///   mountain folds (convex edges) dash-dotted in red, valley folds (concave)
///   dashed in blue;
/// - the chart id at the centre of the chart's box;
/// - labels at most `font_size` high and at most a quarter (seams) or a third
///   (chart ids) of the piece's smaller side; lines at most 0.25 mm wide and
///   at most 1/40 of the smallest piece's smaller side.
///
/// \param corner_uv 3 UVs per face by face index, in mesh units and with each chart's
///        border at its true length (`Segmentation_result::corner_uv`)
/// \param seam_edges the edges where the surface is cut (`Segmentation_result::seam_edges`)
/// \param np optional: `vertex_point_map`, `vertex_index_map`, `face_index_map`, `halfedge_index_map`
/// \returns a `Pattern_result`; `EMPTY_MESH` without faces, `INVALID_COORDINATES` if
///          `corner_uv` has the wrong size or a non-finite value, the mesh has a non-finite
///          or only one point, or the options are negative, not finite, too small for the margins
///          or of an unknown unit. Nothing is written then.
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
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef std::array<double, 2> P2;
  typedef CGAL::Exact_predicates_inexact_constructions_kernel K;

  Pattern_result result;
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, tm));
  const auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
  const auto fim = CGAL::get_initialized_face_index_map(tm, np);
  const auto him = CGAL::get_initialized_halfedge_index_map(tm, np);
  const std::size_t nf = static_cast<std::size_t>(num_faces(tm));
  if(nf == 0) {
    result.status = Error_code::EMPTY_MESH;
    return result;
  }
  const double mm_per_unit = millimetres_per_unit(options.units);
  auto finite_at_least = [](double x, double low) { return std::isfinite(x) && x >= low; };
  bool valid = corner_uv.size() == 3 * nf && mm_per_unit > 0 && finite_at_least(options.scale, 0) &&
               finite_at_least(options.model_size, 0) && finite_at_least(options.spacing, 0) &&
               finite_at_least(options.tab_width, 0) && finite_at_least(options.page_margin, 0) &&
               finite_at_least(options.font_size, 0) && std::isfinite(options.fold_angle) &&
               std::isfinite(options.page_width) && std::isfinite(options.page_height) &&
               options.page_width > 2 * options.page_margin && options.page_height > 2 * options.page_margin;
  for(std::size_t i = 0; valid && i < corner_uv.size(); ++i)
    valid = std::isfinite(corner_uv[i][0]) && std::isfinite(corner_uv[i][1]);
  // the model's largest dimension
  double extent = 0;
  if(valid) {
    std::array<double, 3> low, high;
    low.fill(std::numeric_limits<double>::infinity());
    high.fill(-std::numeric_limits<double>::infinity());
    for(auto v : vertices(tm)) {
      const std::array<double, 3> p = CGAL_QD::internal::point_of<TriangleMesh>(v, vpm);
      for(int c = 0; c < 3; ++c) low[c] = (std::min)(low[c], p[c]), high[c] = (std::max)(high[c], p[c]);
    }
    for(int c = 0; c < 3; ++c) extent = (std::max)(extent, high[c] - low[c]);
    valid = std::isfinite(extent) && extent > 0;
  }
  if(!valid) {
    result.status = Error_code::INVALID_COORDINATES;
    return result;
  }
  const double mm = 1 / mm_per_unit;  // drawing units per millimetre
  const double font = options.font_size > 0 ? options.font_size : std::min(options.page_width, options.page_height) / 60;

  std::vector<face_descriptor> face_of(nf);
  std::vector<std::size_t> chart(nf);
  std::size_t n = 0;
  for(face_descriptor f : faces(tm)) {
    face_of[get(fim, f)] = f;
    chart[get(fim, f)] = static_cast<std::size_t>(get(face_chart, f));
    n = (std::max)(n, chart[get(fim, f)] + 1);
  }
  std::vector<std::vector<std::size_t>> faces_of_chart(n);
  for(std::size_t i = 0; i < nf; ++i) faces_of_chart[chart[i]].push_back(i);
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

  // ---- the scale, and every chart in its rectangle packed on pages
  std::vector<internal::Rectangle> boxes(n);
  std::vector<bool> used(n, false);
  for(std::size_t k = 0; k < n; ++k) {
    if(faces_of_chart[k].empty()) continue;
    std::vector<K::Point_2> points;
    for(std::size_t i : faces_of_chart[k])
      for(int c = 0; c < 3; ++c) points.emplace_back(corner_uv[3 * i + c][0], corner_uv[3 * i + c][1]);
    boxes[k] = internal::min_area_rectangle(points);
    used[k] = true;
  }
  const double pad = options.spacing / 2 + (options.tabs ? options.tab_width : 0);
  if(options.scale > 0) {
    result.scale = options.scale;
  } else {
    const double size = options.model_size > 0 ? options.model_size : 200 * mm;
    result.scale = size / extent;
    if(options.model_size == 0) {
      const double fit = internal::largest_fitting_scale(boxes, options.page_width - 2 * options.page_margin,
                                                         options.page_height - 2 * options.page_margin, pad);
      if(fit < result.scale) {
        // whole millimetres, where that leaves at least one
        const double whole = std::floor(fit * extent * mm_per_unit);
        result.scale = whole >= 1 ? whole * mm / extent : fit;
        result.reduced_to_fit = true;
      }
    }
    if(!(std::isfinite(result.scale) && result.scale > 0)) {
      result.status = Error_code::INVALID_COORDINATES;
      return result;
    }
  }
  result.model_size = result.scale * extent;
  const internal::Page_layout layout =
      internal::lay_out_pieces(boxes, used, result.scale, options.page_width, options.page_height,
                               options.page_margin, pad);
  const std::vector<internal::Piece_placement>& place = layout.pieces;
  result.number_of_pages = layout.number_of_pages;
  result.number_of_charts = layout.order.size();
  result.oversized_charts = layout.oversized;
  // the drawing position of a corner: scaled, rotated, y pointing down (so the
  // chart is seen from its outer side), placed on its page
  auto to_page = [&](std::size_t c, const P2& uv) {
    const internal::Piece_placement& p = place[chart[c / 3]];
    const double co = std::cos(p.angle), si = std::sin(p.angle);
    const double rx = co * uv[0] - si * uv[1] - p.low[0], ry = si * uv[0] + co * uv[1] - p.low[1];
    const double h = p.size[1] - 2 * pad;
    return P2{{p.at[0] + pad + result.scale * rx,
               p.page * options.page_height + p.at[1] + pad + h - result.scale * ry}};
  };
  auto point_at = [&](std::size_t c) { return to_page(c, corner_uv[c]); };
  // sizes that follow the pieces: a piece's smaller side, the lines' width
  auto smaller_side = [&](std::size_t k) {
    return (std::max)(0., (std::min)(place[k].size[0], place[k].size[1]) - 2 * pad);
  };
  double line = 0.25 * mm;
  for(std::size_t k : layout.order) line = (std::min)(line, smaller_side(k) / 40);
  if(!(line > 0)) line = 0.25 * mm;  // only pieces without area

  // ---- seam curves: connected seam edges with the same pair of charts, in order along the curve
  std::vector<halfedge_descriptor> seam_halfedges;
  for(edge_descriptor e : seam)
    if(!is_border_edge(halfedge(e, tm), tm)) seam_halfedges.push_back(halfedge(e, tm));
  // a curve also ends where the two charts on its sides change
  auto pair_of = [&](halfedge_descriptor h) {
    const std::size_t a = chart[get(fim, face(h, tm))], b = chart[get(fim, face(opposite(h, tm), tm))];
    return std::make_pair((std::min)(a, b), (std::max)(a, b));
  };
  auto pair_changes = [&](vertex_descriptor v) {
    std::set<std::pair<std::size_t, std::size_t>> pairs;
    for(halfedge_descriptor h : CGAL::halfedges_around_target(v, tm))
      if(seam.count(edge(h, tm)) && !is_border_edge(h, tm)) pairs.insert(pair_of(h));
    return pairs.size() > 1;
  };
  std::vector<std::vector<halfedge_descriptor>> curves;
  for(auto& c : internal::seam_curves(tm, seam_halfedges, vim, him, pair_changes)) curves.push_back(std::move(c.halfedges));
  // the sides of every curve to label: the halfedge of the curve's middle edge (by 3D
  // length) and its opposite, each in the face whose chart it labels
  std::vector<std::vector<std::pair<halfedge_descriptor, std::size_t>>> labels_of_chart(n);
  for(std::size_t id = 0; id < curves.size(); ++id) {
    double total = 0;
    std::vector<double> lengths;
    for(halfedge_descriptor h : curves[id]) {
      lengths.push_back(CGAL_QD::internal::distance3(CGAL_QD::internal::point_of<TriangleMesh>(source(h, tm), vpm),
                                                     CGAL_QD::internal::point_of<TriangleMesh>(target(h, tm), vpm)));
      total += lengths.back();
    }
    std::size_t middle = 0;
    for(double run = lengths[0]; run < total / 2 && middle + 1 < lengths.size(); run += lengths[++middle]) {}
    for(halfedge_descriptor h : {curves[id][middle], opposite(curves[id][middle], tm)})
      labels_of_chart[chart[get(fim, face(h, tm))]].emplace_back(h, id);
  }
  result.seam_labels = curves.size();
  std::vector<std::vector<halfedge_descriptor>> tabs_of_chart(n);
  if(options.tabs)  // on the side of the halfedges stored in the curve
    for(const auto& c : curves)
      for(halfedge_descriptor h : c) tabs_of_chart[chart[get(fim, face(h, tm))]].push_back(h);

  // ---- the SVG
  const double w = options.page_width, ph = options.page_height;
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << internal::svg_number(w) << options.units
      << "\" height=\"" << internal::svg_number(ph * result.number_of_pages) << options.units
      << "\" viewBox=\"0 0 " << internal::svg_number(w) << ' '
      << internal::svg_number(ph * result.number_of_pages) << "\">\n"
      << "<desc>CGAL_QD pattern: " << result.number_of_charts << " pieces at " << result.scale << ' ' << options.units
      << " per mesh unit (the model " << result.model_size << ' ' << options.units
      << " at its largest); cut on solid lines, fold red dash-dot lines as mountains and blue dashed "
      << "lines as valleys, join equal labels.</desc>\n";
  auto n_ = [](double x) { return internal::svg_number(x); };
  out << "<style>.cut{stroke:#000;stroke-width:" << n_(line) << ";fill:none}.mountain{stroke:#c00;stroke-width:"
      << n_(0.8 * line) << ";stroke-dasharray:" << n_(12 * line) << ' ' << n_(4 * line) << ' ' << n_(2 * line) << ' '
      << n_(4 * line) << "}.valley{stroke:#00c;stroke-width:" << n_(0.8 * line) << ";stroke-dasharray:"
      << n_(8 * line) << ' ' << n_(4 * line) << "}.tab{fill:#eee;stroke:#777;stroke-width:" << n_(0.6 * line)
      << "}.page{fill:none;stroke:#ccc;stroke-width:" << n_(0.3 * mm) << "}"
      << "text{font-family:sans-serif;text-anchor:middle;dominant-baseline:middle}</style>\n";
  for(std::size_t p = 0; p < result.number_of_pages; ++p)
    out << "<rect class=\"page\" x=\"0\" y=\"" << n_(p * ph) << "\" width=\"" << n_(w) << "\" height=\"" << n_(ph)
        << "\"/>\n<text class=\"page\" x=\"" << n_(w / 2) << "\" y=\"" << n_(p * ph + ph - options.page_margin / 2)
        << "\" font-size=\"" << n_((std::min)(font * 0.8, 0.8 * options.page_margin)) << "\">page " << p + 1
        << " of " << result.number_of_pages << "</text>\n";

  std::vector<internal::Face_geometry> geo = internal::face_geometry(tm, vpm, fim);
  for(std::size_t k : layout.order) {
    const internal::Piece_placement& p = place[k];
    const double side = smaller_side(k);
    out << "<g class=\"piece\" data-chart=\"" << k << "\" data-page=\"" << p.page << "\">\n";
    // tabs first, under the piece
    for(halfedge_descriptor h : tabs_of_chart[k]) {
      const P2 a = point_at(corner(prev(h, tm))), b = point_at(corner(h));  // h runs from a to b
      const double dx = b[0] - a[0], dy = b[1] - a[1], l = std::hypot(dx, dy);
      if(!(l > 0)) continue;
      // the page shows the chart as in UV (y is flipped into SVG's downward axis), so the
      // face stays on the visual left of a -> b; (nx, ny) points there, and the tab goes the other way
      const double nx = dy / l, ny = -dx / l, tw = (std::min)(options.tab_width, 0.45 * l);
      const P2 c1{{a[0] + 0.25 * dx - nx * tw, a[1] + 0.25 * dy - ny * tw}},
          c2{{a[0] + 0.75 * dx - nx * tw, a[1] + 0.75 * dy - ny * tw}};
      out << "<polygon class=\"tab\" points=\"" << n_(a[0]) << ',' << n_(a[1]) << ' ' << n_(c1[0]) << ','
          << n_(c1[1]) << ' ' << n_(c2[0]) << ',' << n_(c2[1]) << ' ' << n_(b[0]) << ',' << n_(b[1]) << "\"/>\n";
      ++result.tabs;
    }
    // cut lines and fold lines
    for(std::size_t i : faces_of_chart[k]) {
      halfedge_descriptor h = halfedge(face_of[i], tm);
      for(int c = 0; c < 3; ++c, h = next(h, tm)) {
        // the edge of next(h) runs from corner c to corner c + 1
        const halfedge_descriptor g = next(h, tm);
        const P2 a = point_at(3 * i + c), b = point_at(3 * i + (c + 1) % 3);
        if(is_cut(g)) {
          out << "<line class=\"cut\" data-v=\"" << vertex_number[get(vim, source(g, tm))] << ' '
              << vertex_number[get(vim, target(g, tm))] << "\" x1=\"" << n_(a[0]) << "\" y1=\"" << n_(a[1])
              << "\" x2=\"" << n_(b[0]) << "\" y2=\"" << n_(b[1]) << "\"/>\n";
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
        out << "<line class=\"" << (above > 0 ? "valley" : "mountain") << "\" x1=\"" << n_(a[0]) << "\" y1=\""
            << n_(a[1]) << "\" x2=\"" << n_(b[0]) << "\" y2=\"" << n_(b[1]) << "\"/>\n";
        ++result.fold_lines;
      }
    }
    // seam labels inside the piece, beside the middle edge of their curve
    const double label = (std::min)(font, side / 4);
    for(const auto& hl : labels_of_chart[k]) {
      const halfedge_descriptor h = hl.first;
      const P2 a = point_at(corner(prev(h, tm))), b = point_at(corner(h));
      const double dx = b[0] - a[0], dy = b[1] - a[1], l = std::hypot(dx, dy);
      // towards the face, (dy, -dx) / l as for the tabs, by 0.9 label heights
      const double t = l > 0 ? 0.9 * label / l : 0.;
      const P2 at{{(a[0] + b[0]) / 2 + t * dy, (a[1] + b[1]) / 2 - t * dx}};
      const double angle = std::atan2(dy, dx) * 180 / 3.141592653589793;
      const double upright = angle > 90 || angle < -90 ? angle + 180 : angle;
      out << "<text class=\"seam\" x=\"" << n_(at[0]) << "\" y=\"" << n_(at[1]) << "\" font-size=\"" << n_(label)
          << "\" transform=\"rotate(" << n_(upright) << ' ' << n_(at[0]) << ' ' << n_(at[1]) << ")\">"
          << internal::seam_label(hl.second) << "</text>\n";
    }
    // the chart id at the centre of its box
    out << "<text class=\"chart\" x=\"" << n_(p.at[0] + p.size[0] / 2) << "\" y=\""
        << n_(p.page * ph + p.at[1] + p.size[1] / 2) << "\" font-size=\"" << n_((std::min)(1.5 * font, side / 3))
        << "\" fill=\"#888\">" << k << "</text>\n</g>\n";
  }
  out << "</svg>\n";
  if(!out) result.status = Error_code::INVALID_COORDINATES;
  return result;
}

} // namespace IO
} // namespace CGAL_QD

#endif // CGAL_QD_IO_PATTERNS_SVG_H
