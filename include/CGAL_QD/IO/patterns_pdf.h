// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_IO_PATTERNS_PDF_H
#define CGAL_QD_IO_PATTERNS_PDF_H

/// \file IO/patterns_pdf.h
/// Printable sewing and folding patterns as PDF, one page per sheet, at true
/// scale, drawn with cairo. Including this header needs cairo (Debian's
/// `libcairo2-dev`; compile and link with `pkg-config --cflags --libs cairo`).

#include <CGAL_QD/Error_code.h>
#include <CGAL_QD/IO/internal/pattern_drawing.h>
#include <CGAL_QD/IO/pattern_options.h>

#include <CGAL/Named_function_parameters.h>

#include <cairo-pdf.h>
#include <cairo.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <ostream>
#include <vector>

namespace CGAL_QD {
namespace internal {

// cairo's output, into a stream
inline cairo_status_t write_to_stream(void* closure, const unsigned char* data, unsigned int length)
{
  std::ostream& out = *static_cast<std::ostream*>(closure);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(length));
  return out ? CAIRO_STATUS_SUCCESS : CAIRO_STATUS_WRITE_ERROR;
}

// `text` centred on its point (or starting there), turned by its angle
inline void show_centred_text(cairo_t* cr, const Pattern_drawing::Text& text)
{
  cairo_save(cr);
  cairo_translate(cr, text.at[0], text.at[1]);
  cairo_rotate(cr, text.angle * 3.141592653589793 / 180);
  cairo_set_font_size(cr, text.size);
  cairo_text_extents_t e;
  cairo_text_extents(cr, text.text.c_str(), &e);
  cairo_move_to(cr, text.centred ? -e.x_bearing - e.width / 2 : 0., -e.y_bearing - e.height / 2);
  cairo_show_text(cr, text.text.c_str());
  cairo_restore(cr);
}

// every line of `kind` of a piece, as one path
inline void stroke_lines(cairo_t* cr, const Pattern_drawing::Piece& piece, Pattern_drawing::Line_kind kind)
{
  bool any = false;
  for(const Pattern_drawing::Line& l : piece.lines)
    if(l.kind == kind) {
      cairo_move_to(cr, l.a[0], l.a[1]);
      cairo_line_to(cr, l.b[0], l.b[1]);
      any = true;
    }
  if(any) cairo_stroke(cr);
}

// everything drawn for one piece, in drawing units
template <class Drawing>
void draw_piece(cairo_t* cr, const typename Drawing::Piece& piece, const Drawing& d)
{
  const double line = piece.line_width;
  const double mountain[4] = {12 * line, 4 * line, 2 * line, 4 * line}, valley[2] = {8 * line, 4 * line};
  cairo_set_line_width(cr, 0.6 * line);
  for(const auto& t : piece.tabs) {
    cairo_move_to(cr, t[0][0], t[0][1]);
    for(int c = 1; c < 4; ++c) cairo_line_to(cr, t[c][0], t[c][1]);
    cairo_close_path(cr);
    cairo_set_source_rgb(cr, 0.933, 0.933, 0.933);
    cairo_fill_preserve(cr);
    cairo_set_source_rgb(cr, 0.467, 0.467, 0.467);
    cairo_stroke(cr);
  }
  cairo_set_line_width(cr, 0.8 * line);
  cairo_set_source_rgb(cr, 0.8, 0, 0);
  cairo_set_dash(cr, mountain, 4, 0);
  stroke_lines(cr, piece, Drawing::MOUNTAIN);
  cairo_set_source_rgb(cr, 0, 0, 0.8);
  cairo_set_dash(cr, valley, 2, 0);
  stroke_lines(cr, piece, Drawing::VALLEY);
  cairo_set_dash(cr, nullptr, 0, 0);
  cairo_set_line_width(cr, line);
  cairo_set_source_rgb(cr, 0, 0, 0);
  for(const auto& outline : piece.allowance) {  // the cut line, outside the stitch line
    for(std::size_t i = 0; i < outline.size(); ++i) (i ? cairo_line_to : cairo_move_to)(cr, outline[i][0], outline[i][1]);
    cairo_close_path(cr);
    cairo_stroke(cr);
  }
  if(d.seam_allowance > 0) {  // the stitch line, dashed
    const double stitch[2] = {6 * line, 3 * line};
    cairo_set_line_width(cr, 0.6 * line);
    cairo_set_dash(cr, stitch, 2, 0);
  }
  stroke_lines(cr, piece, Drawing::CUT);
  cairo_set_dash(cr, nullptr, 0, 0);
  cairo_set_line_width(cr, line);
  for(const auto& l : piece.notches) {
    cairo_move_to(cr, l.a[0], l.a[1]);
    cairo_line_to(cr, l.b[0], l.b[1]);
  }
  if(!piece.notches.empty()) cairo_stroke(cr);
  for(const auto& t : piece.notch_labels) show_centred_text(cr, t);
  for(const auto& t : piece.labels) show_centred_text(cr, t);
  // the diamonds where the parts of a piece larger than a page meet, dark grey
  cairo_set_source_rgb(cr, 0.35, 0.35, 0.35);
  for(const auto& m : piece.marks) {
    cairo_move_to(cr, m[0][0], m[0][1]);
    for(int c = 1; c < 4; ++c) cairo_line_to(cr, m[c][0], m[c][1]);
    cairo_close_path(cr);
    cairo_fill(cr);
  }
  for(const auto& t : piece.mark_labels) show_centred_text(cr, t);
  cairo_set_source_rgb(cr, 0.533, 0.533, 0.533);
  show_centred_text(cr, piece.id);
}

} // namespace internal

namespace IO {

/// \ingroup PkgCGAL_QDRef
/// writes the flattened charts as a printable PDF pattern at true scale: the
/// same pattern as `write_patterns_SVG()` (same scale, layout, cut lines, fold
/// lines, tabs and labels; see there), one PDF page per page of
/// `options.page_width` x `options.page_height`, so that a length of 100 mm on
/// the pattern prints as 100 mm with the printer's scaling off ("actual
/// size"). A piece larger than a page is printed in parts, each on a page of
/// its own within a grey frame, with half diamonds to join them (see
/// `write_patterns_SVG()`).
///
/// \param out the stream written to (binary)
/// \param tm the triangle mesh
/// \param face_chart the chart id of every face
/// \param corner_uv 3 UVs per face by face index, in mesh units and with each chart's
///        border at its true length (`Segmentation_result::corner_uv`)
/// \param seam_edges the edges where the surface is cut (`Segmentation_result::seam_edges`)
/// \param options the drawing options
/// \param np optional: `vertex_point_map`, `vertex_index_map`, `face_index_map`, `halfedge_index_map`
/// \returns a `Pattern_result`, with the statuses of `write_patterns_SVG()` on invalid input
///          (nothing is written then), and `CANNOT_WRITE` if cairo or the stream fails.
template <class TriangleMesh, class FaceChartMap, class EdgeRange,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
Pattern_result write_patterns_PDF(std::ostream& out, const TriangleMesh& tm, const FaceChartMap& face_chart,
                                  const std::vector<std::array<double, 2>>& corner_uv, const EdgeRange& seam_edges,
                                  const Pattern_options& options = Pattern_options(),
                                  const NamedParameters& np = CGAL::parameters::default_values())
{
  typedef internal::Pattern_drawing Drawing;
  Drawing d;
  Pattern_result result = internal::draw_pattern(tm, face_chart, corner_uv, seam_edges, options, np, d);
  if(!result) return result;
  const double points = 72 / 25.4 * millimetres_per_unit(d.units);  // per drawing unit
  const double w = d.page_width, ph = d.page_height, line = d.line_width;
  cairo_surface_t* surface =
      cairo_pdf_surface_create_for_stream(internal::write_to_stream, &out, w * points, ph * points);
  cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_TITLE, "CGAL_QD pattern");
  cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_CREATOR, "CGAL_QD");
  cairo_t* cr = cairo_create(surface);
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  for(std::size_t page = 0; page < d.number_of_pages; ++page) {
    cairo_save(cr);
    cairo_scale(cr, points, points);
    cairo_translate(cr, 0, -double(page) * ph);
    // the page number, light, in the bottom margin
    cairo_set_source_rgb(cr, 0.6, 0.6, 0.6);
    internal::show_centred_text(cr, {{{w / 2, page * ph + ph - d.page_margin / 2}},
                                     d.page_number_size(), 0., d.page_number(page)});
    // the scale check in the bottom-left corner, its bars ending where they
    // measure
    if(!d.check_lines.empty()) {
      cairo_set_source_rgb(cr, 0.4, 0.4, 0.4);
      cairo_set_line_width(cr, line);
      cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
      for(const auto& l : d.check_lines) {
        cairo_move_to(cr, l[0][0], page * ph + l[0][1]);
        cairo_line_to(cr, l[1][0], page * ph + l[1][1]);
      }
      cairo_stroke(cr);
      cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
      Drawing::Text label = d.check_label;
      label.at[1] += page * ph;
      internal::show_centred_text(cr, label);
    }
    for(const Drawing::Piece& piece : d.pieces) {
      if(piece.parts.empty()) {
        if(piece.page == page) internal::draw_piece(cr, piece, d);
        continue;
      }
      // a part of a piece larger than a page: its window, moved onto the page
      for(const internal::Pattern_part& part : piece.parts) {
        if(part.page != page) continue;
        const std::array<double, 4> frame = part.on_page();
        cairo_save(cr);
        cairo_rectangle(cr, frame[0], frame[1], frame[2], frame[3]);
        cairo_clip(cr);
        cairo_translate(cr, part.shift[0], part.shift[1]);
        internal::draw_piece(cr, piece, d);
        cairo_restore(cr);
        cairo_set_source_rgb(cr, 0.6, 0.6, 0.6);  // the frame, outside the clip
        cairo_set_line_width(cr, 0.5 * line);
        cairo_rectangle(cr, frame[0], frame[1], frame[2], frame[3]);
        cairo_stroke(cr);
      }
    }
    // the captions of the pages of parts
    cairo_set_source_rgb(cr, 0, 0, 0);
    for(const Drawing::Text& t : d.captions)
      if(t.at[1] >= page * ph && t.at[1] < (page + 1) * ph) internal::show_centred_text(cr, t);
    cairo_set_source_rgb(cr, 0, 0, 0);
    for(const Drawing::Text& t : d.assembly)
      if(t.at[1] >= page * ph && t.at[1] < (page + 1) * ph) internal::show_centred_text(cr, t);
    cairo_restore(cr);
    cairo_show_page(cr);
  }
  cairo_destroy(cr);
  cairo_surface_finish(surface);
  const bool ok = cairo_surface_status(surface) == CAIRO_STATUS_SUCCESS;
  cairo_surface_destroy(surface);
  if(!ok || !out) result.status = Error_code::CANNOT_WRITE;
  return result;
}

} // namespace IO
} // namespace CGAL_QD

#endif // CGAL_QD_IO_PATTERNS_PDF_H
