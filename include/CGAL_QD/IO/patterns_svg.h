// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_IO_PATTERNS_SVG_H
#define CGAL_QD_IO_PATTERNS_SVG_H

/// \file IO/patterns_svg.h
/// Printable sewing and folding patterns: every chart of a segmentation at true
/// scale, laid out on pages, with cut lines, matching seam labels, optional
/// glue tabs and fold lines, as SVG.

#include <CGAL_QD/Error_code.h>
#include <CGAL_QD/IO/internal/pattern_drawing.h>
#include <CGAL_QD/IO/pattern_options.h>

#include <CGAL/Named_function_parameters.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <ostream>
#include <string>
#include <vector>

namespace CGAL_QD {
namespace internal {

inline std::string svg_number(double x)
{
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.4f", std::abs(x) < 5e-5 ? 0. : x);
  return buffer;
}

} // namespace internal

namespace IO {

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
///   scale or a model size given) is turned the way that needs the fewest
///   parts and printed in parts: its box cut into windows the size of a page's
///   printable area, each window that holds some of it on a page of its own,
///   within a grey frame (`<rect class="frame">`), with a caption in the top
///   margin (`<text class="caption">`); where two parts meet, two diamonds
///   numbered alike lie across the line between them, half on each page
///   (`<polygon class="mark">`), so that a person cuts one page along its
///   frame, lays the two edge to edge and matches the halves;
/// - every piece is one group, `<g class="piece" data-chart="k" data-page="p">`,
///   holding all that is drawn for it; a piece in parts is defined once in
///   `<defs>` (`id="piece-k"`) and shown by one group per part, `<g
///   class="part" data-chart="k" data-page="p" data-row="r" data-column="c"
///   data-window="x y w h">` (the window in the piece's coordinates), clipped
///   to the printable area of its page;
/// - the layout shows the outer side of the surface (a chart is drawn as seen
///   from the side its face normals point to);
/// - cut lines (solid, class `cut`) on every border edge of a chart: a seam or a
///   border of the mesh. Each carries `data-v="i j"`, the indices of the edge's
///   vertices in `tm`. Lines are 0.25 mm wide, and on a piece less than 10 mm
///   across a fortieth of its smaller side (a style of that piece's own);
/// - every seam curve (a chain of seam edges between the same two charts, or a
///   cut inside one chart, from junction to junction) has a label, drawn on
///   both sides of the seam, inside the piece beside the curve, as near its
///   middle as the label can be without overlapping another label, the chart
///   id or a notch number or crossing a cut line (smaller, down to half its
///   height, where it must), so the pieces can be matched. A piece too small
///   for labels of half the largest height gets them outside, beside their
///   curves, and its number beside its box, within the room the layout keeps
///   around the piece (on a tab or off the tabs; not with a seam allowance);
///   the pieces still too small for their labels at the scale are listed in
///   `Pattern_result::crowded_pieces`;
/// - with `tabs`, a glue tab outside one side of every seam edge;
/// - with `seam_allowance` (needs Clipper: `CGAL_QD_HAS_CLIPPER`; otherwise
///   `INVALID_ARGUMENT`), the outline of the points within that distance of the
///   piece (`<polygon class="allowance">`, round at convex corners) is the cut
///   line, and the piece's border the stitch line, dashed;
/// - with `notch_spacing`, notches: short marks from the cut line into the
///   piece (`<line class="notch" data-seam="A" data-n="1">`, with their
///   number), the same count on the two sides of every seam curve, at the same
///   fractions of each side's length, about `notch_spacing` apart;
/// - fold lines on interior edges whose dihedral angle exceeds `fold_angle`:
///   mountain folds (convex edges) dash-dotted in red, valley folds (concave)
///   dashed in blue; only where those edges make a line at least
///   `min_fold_length` long on the page, or a shorter one between the cut line
///   and other fold lines (see `Pattern_options::min_fold_length`);
/// - the chart id where the piece is widest (the point inside it farthest
///   from its cut lines), smaller where it would reach them (down to half),
///   or, where that is under half the largest label height, at that height
///   beside the piece's box, apart from its labels and off the tabs' outlines;
/// - unless `options.assembly_page` is false, a last page lists the order in
///   which to join the pieces (`Pattern_result::assembly`): outward from the
///   largest piece (by 3D area), each step the piece that shares the longest
///   seams with those joined before, and the labels of the seams it closes;
///   then the seams whose two sides differ by more than 0.5 % as drawn, each
///   with its two lengths, to be eased in (`Pattern_result::seams`);
/// - unless `options.scale_check` is false, two bars of 50 mm (2 in) in the
///   bottom-left corner of every page, in the margins, to measure the print;
/// - labels at most `font_size` high and at most a quarter (seams) or a third
///   (chart ids) of the piece's smaller side; lines 0.25 mm wide, and on a
///   piece less than 10 mm across a fortieth of its smaller side.
///
/// \param corner_uv 3 UVs per face by face index, in mesh units and with each chart's
///        border at its true length (`Segmentation_result::corner_uv`)
/// \param seam_edges the edges where the surface is cut (`Segmentation_result::seam_edges`)
/// \param np optional: `vertex_point_map`, `vertex_index_map`, `face_index_map`, `halfedge_index_map`
/// \returns a `Pattern_result`; `EMPTY_MESH` without faces, `INVALID_COORDINATES` if
///          `corner_uv` has the wrong size or a non-finite value, the mesh has a non-finite
///          or only one point, or the options are negative, not finite, too small for the margins
///          or of an unknown unit, or leave a piece no room within a page's margins (half the
///          `spacing`, the `tab_width` with `tabs` and the `seam_allowance` on each side), or
///          a `notch_spacing` under 1 mm. Nothing is written then. `CANNOT_WRITE` if the stream fails.
template <class TriangleMesh, class FaceChartMap, class EdgeRange,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
Pattern_result write_patterns_SVG(std::ostream& out, const TriangleMesh& tm, const FaceChartMap& face_chart,
                                  const std::vector<std::array<double, 2>>& corner_uv, const EdgeRange& seam_edges,
                                  const Pattern_options& options = Pattern_options(),
                                  const NamedParameters& np = CGAL::parameters::default_values())
{
  internal::Pattern_drawing d;
  Pattern_result result = internal::draw_pattern(tm, face_chart, corner_uv, seam_edges, options, np, d);
  if(!result) return result;
  const double w = d.page_width, ph = d.page_height, line = d.line_width, mm = d.millimetre;
  const bool any_parts = result.part_pages > 0;
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\""
      << (any_parts ? " xmlns:xlink=\"http://www.w3.org/1999/xlink\"" : "") << " width=\"" << internal::svg_number(w) << d.units
      << "\" height=\"" << internal::svg_number(ph * d.number_of_pages) << d.units
      << "\" viewBox=\"0 0 " << internal::svg_number(w) << ' '
      << internal::svg_number(ph * d.number_of_pages) << "\">\n"
      << "<desc>CGAL_QD pattern: " << result.number_of_charts << " pieces at " << result.scale << ' ' << d.units
      << " per mesh unit (the model " << result.model_size << ' ' << d.units
      << " at its largest); cut on solid lines, fold red dash-dot lines as mountains and blue dashed "
      << "lines as valleys, join equal labels.</desc>\n";
  auto n_ = [](double x) { return internal::svg_number(x); };
  // the lines' style at a width: with a seam allowance the piece's border is
  // the stitch line, dashed, and the allowance's outline the cut line
  auto line_rules = [&](const std::string& scope, double line) {
    std::string rules = d.seam_allowance > 0 ? scope + ".cut{stroke:#000;stroke-width:" + n_(0.6 * line) +
                                                   ";stroke-dasharray:" + n_(6 * line) + ' ' + n_(3 * line) +
                                                   ";fill:none}" + scope + ".allowance{stroke:#000;stroke-width:" +
                                                   n_(line) + ";fill:none}"
                                             : scope + ".cut{stroke:#000;stroke-width:" + n_(line) + ";fill:none}";
    rules += scope + ".mountain{stroke:#c00;stroke-width:" + n_(0.8 * line) + ";stroke-dasharray:" + n_(12 * line) +
             ' ' + n_(4 * line) + ' ' + n_(2 * line) + ' ' + n_(4 * line) + "}" + scope +
             ".valley{stroke:#00c;stroke-width:" + n_(0.8 * line) + ";stroke-dasharray:" + n_(8 * line) + ' ' +
             n_(4 * line) + "}" + scope + ".tab{fill:#eee;stroke:#777;stroke-width:" + n_(0.6 * line) + "}";
    if(result.notches > 0) rules += scope + ".notch{stroke:#000;stroke-width:" + n_(line) + "}";
    return rules;
  };
  out << "<style>" << line_rules("", line) << ".page{fill:none;stroke:#ccc;stroke-width:" << n_(0.3 * mm) << "}"
      << "text{font-family:sans-serif;text-anchor:middle;dominant-baseline:middle}"
      << (d.assembly.empty() ? "" : "text.assembly{text-anchor:start}")
      << (result.part_pages == 0 ? "" : ".frame{fill:none;stroke:#999;stroke-width:" + n_(0.5 * line) + "}.mark{fill:#595959}")
      << (d.check_lines.empty() ? "" : ".check{stroke:#666;stroke-width:" + n_(line) + "}text.check{fill:#666;stroke:none}");
  // the thinner lines of the pieces less than 10 mm across
  for(const internal::Pattern_drawing::Piece& piece : d.pieces)
    if(piece.line_width < line)
      out << line_rules(".piece[data-chart=\"" + std::to_string(piece.chart) + "\"] ", piece.line_width);
  out << "</style>\n";
  for(std::size_t p = 0; p < d.number_of_pages; ++p)
    out << "<rect class=\"page\" x=\"0\" y=\"" << n_(p * ph) << "\" width=\"" << n_(w) << "\" height=\"" << n_(ph)
        << "\"/>\n<text class=\"page\" x=\"" << n_(w / 2) << "\" y=\"" << n_(p * ph + ph - d.page_margin / 2)
        << "\" font-size=\"" << n_(d.page_number_size()) << "\">" << d.page_number(p) << "</text>\n";
  // the scale check of every page, in its bottom-left corner
  if(!d.check_lines.empty())
    for(std::size_t p = 0; p < d.number_of_pages; ++p) {
      out << "<g class=\"check\" data-length=\"" << n_(d.check_length) << "\">";
      for(const auto& l : d.check_lines)
        out << "<line x1=\"" << n_(l[0][0]) << "\" y1=\"" << n_(p * ph + l[0][1]) << "\" x2=\"" << n_(l[1][0])
            << "\" y2=\"" << n_(p * ph + l[1][1]) << "\"/>";
      out << "<text class=\"check\" x=\"" << n_(d.check_label.at[0]) << "\" y=\"" << n_(p * ph + d.check_label.at[1])
          << "\" font-size=\"" << n_(d.check_label.size) << "\">" << d.check_label.text << "</text></g>\n";
    }

  // a piece larger than a page is defined once and shown through the windows of its parts
  auto rect = [&](const std::array<double, 4>& r, const char* cls) {
    return std::string("<rect") + (*cls ? std::string(" class=\"") + cls + "\"" : std::string()) + " x=\"" + n_(r[0]) +
           "\" y=\"" + n_(r[1]) + "\" width=\"" + n_(r[2]) + "\" height=\"" + n_(r[3]) + "\"/>";
  };
  auto write_quad = [&](const std::array<std::array<double, 2>, 4>& q, const char* cls) {
    out << "<polygon class=\"" << cls << "\" points=\"" << n_(q[0][0]) << ',' << n_(q[0][1]) << ' ' << n_(q[1][0])
        << ',' << n_(q[1][1]) << ' ' << n_(q[2][0]) << ',' << n_(q[2][1]) << ' ' << n_(q[3][0]) << ','
        << n_(q[3][1]) << "\"/>\n";
  };
  auto write_piece = [&](const internal::Pattern_drawing::Piece& piece) {
    out << "<g class=\"piece\"";
    if(!piece.parts.empty()) out << " id=\"piece-" << piece.chart << "\"";
    out << " data-chart=\"" << piece.chart << "\" data-page=\"" << piece.page << "\">\n";
    for(const auto& t : piece.tabs) write_quad(t, "tab");
    for(const auto& outline : piece.allowance) {
      out << "<polygon class=\"allowance\" points=\"";
      for(std::size_t i = 0; i < outline.size(); ++i) out << (i ? " " : "") << n_(outline[i][0]) << ',' << n_(outline[i][1]);
      out << "\"/>\n";
    }
    for(const internal::Pattern_drawing::Line& l : piece.lines) {
      if(l.kind == internal::Pattern_drawing::CUT)
        out << "<line class=\"cut\" data-v=\"" << l.vertices[0] << ' ' << l.vertices[1] << "\"";
      else
        out << "<line class=\"" << (l.kind == internal::Pattern_drawing::VALLEY ? "valley" : "mountain") << '"';
      out << " x1=\"" << n_(l.a[0]) << "\" y1=\"" << n_(l.a[1]) << "\" x2=\"" << n_(l.b[0]) << "\" y2=\""
          << n_(l.b[1]) << "\"/>\n";
    }
    for(std::size_t i = 0; i < piece.notches.size(); ++i) {
      const internal::Pattern_drawing::Line& l = piece.notches[i];
      const internal::Pattern_drawing::Text& t = piece.notch_labels[i];
      out << "<line class=\"notch\" data-seam=\"" << internal::seam_label(l.vertices[0]) << "\" data-n=\""
          << l.vertices[1] << "\" x1=\"" << n_(l.a[0]) << "\" y1=\"" << n_(l.a[1]) << "\" x2=\"" << n_(l.b[0])
          << "\" y2=\"" << n_(l.b[1]) << "\"/>\n<text class=\"notch\" x=\"" << n_(t.at[0]) << "\" y=\""
          << n_(t.at[1]) << "\" font-size=\"" << n_(t.size) << "\">" << t.text << "</text>\n";
    }
    for(const internal::Pattern_drawing::Text& t : piece.labels)
      out << "<text class=\"seam\" x=\"" << n_(t.at[0]) << "\" y=\"" << n_(t.at[1]) << "\" font-size=\""
          << n_(t.size) << "\" transform=\"rotate(" << n_(t.angle) << ' ' << n_(t.at[0]) << ' ' << n_(t.at[1])
          << ")\">" << t.text << "</text>\n";
    for(const auto& m : piece.marks) write_quad(m, "mark");
    for(const internal::Pattern_drawing::Text& t : piece.mark_labels)
      out << "<text class=\"mark\" x=\"" << n_(t.at[0]) << "\" y=\"" << n_(t.at[1]) << "\" font-size=\""
          << n_(t.size) << "\">" << t.text << "</text>\n";
    out << "<text class=\"chart\" x=\"" << n_(piece.id.at[0]) << "\" y=\"" << n_(piece.id.at[1])
        << "\" font-size=\"" << n_(piece.id.size) << "\" fill=\"#888\">" << piece.id.text << "</text>\n</g>\n";
  };
  for(const internal::Pattern_drawing::Piece& piece : d.pieces)
    if(piece.parts.empty()) write_piece(piece);
  if(any_parts) {
    out << "<defs>\n";
    for(const internal::Pattern_drawing::Piece& piece : d.pieces) {
      if(piece.parts.empty()) continue;
      write_piece(piece);
      for(std::size_t i = 0; i < piece.parts.size(); ++i)
        out << "<clipPath id=\"part-" << piece.chart << '-' << i << "\">" << rect(piece.parts[i].on_page(), "")
            << "</clipPath>\n";
    }
    out << "</defs>\n";
    // every part: the piece moved by the part's shift, seen through its window on its page
    for(const internal::Pattern_drawing::Piece& piece : d.pieces)
      for(std::size_t i = 0; i < piece.parts.size(); ++i) {
        const internal::Pattern_part& part = piece.parts[i];
        out << "<g class=\"part\" data-chart=\"" << piece.chart << "\" data-page=\"" << part.page << "\" data-row=\""
            << part.row << "\" data-column=\"" << part.column << "\" data-window=\"" << n_(part.low[0]) << ' '
            << n_(part.low[1]) << ' ' << n_(part.size[0]) << ' ' << n_(part.size[1]) << "\" clip-path=\"url(#part-"
            << piece.chart << '-' << i << ")\"><use xlink:href=\"#piece-" << piece.chart
            << "\" transform=\"translate(" << n_(part.shift[0]) << ' ' << n_(part.shift[1]) << ")\"/></g>\n"
            << rect(part.on_page(), "frame") << "\n";
      }
    for(const internal::Pattern_drawing::Text& t : d.captions)
      out << "<text class=\"caption\" x=\"" << n_(t.at[0]) << "\" y=\"" << n_(t.at[1]) << "\" font-size=\""
          << n_(t.size) << "\">" << t.text << "</text>\n";
  }
  // the assembly order, on the last page
  for(const internal::Pattern_drawing::Text& t : d.assembly)
    out << "<text class=\"assembly\" x=\"" << n_(t.at[0]) << "\" y=\"" << n_(t.at[1]) << "\" font-size=\""
        << n_(t.size) << "\">" << t.text << "</text>\n";
  out << "</svg>\n";
  if(!out) result.status = Error_code::CANNOT_WRITE;
  return result;
}

} // namespace IO
} // namespace CGAL_QD

#endif // CGAL_QD_IO_PATTERNS_SVG_H
