// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_IO_INTERNAL_PATTERN_PIECES_H
#define CGAL_QD_IO_INTERNAL_PATTERN_PIECES_H

// What a printed pattern shows, before it is written in a file format: for
// every piece its glue tabs, cut and fold lines, notches, seam labels and id,
// in drawing units on pages stacked downwards (page p spans y in [p h, (p + 1) h]),
// y pointing down. internal/pattern_drawing.h computes it; IO/patterns_svg.h
// and IO/patterns_pdf.h write it.

#include <CGAL_QD/IO/internal/pattern_tiles.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL_QD {
namespace internal {

struct Pattern_drawing
{
  typedef std::array<double, 2> P2;
  enum Line_kind { CUT, MOUNTAIN, VALLEY, NOTCH };
  struct Line
  {
    Line_kind kind;
    P2 a, b;
    std::array<std::size_t, 2> vertices;  // of a cut: the numbers of its vertices in the mesh
  };
  struct Text
  {
    P2 at;         // its centre
    double size;   // its height
    double angle;  // in degrees, clockwise on the page
    std::string text;
    bool centred = true;  // or starting at `at`, centred in height
  };
  struct Piece
  {
    std::size_t chart = 0, page = 0;
    std::vector<std::array<P2, 4>> tabs;  // drawn under the piece
    std::vector<Line> lines;              // cut and fold lines
    std::vector<Text> labels;             // of the seam curves
    std::vector<Line> notches;            // from the cut line into the piece; `vertices` (seam, number)
    std::vector<Text> notch_labels;       // their numbers
    std::vector<std::vector<P2>> allowance;  // the outlines of the seam allowance: the cut lines then
    Text id;                              // the chart id, where the piece is widest
    double line_width = 0;                // of its cut lines, the other lines in proportion
    // a piece larger than a page: the parts printed (its drawing is shown only
    // through them), and the diamonds across the lines where they meet
    std::vector<Pattern_part> parts;
    std::vector<std::array<P2, 4>> marks;
    std::vector<Text> mark_labels;
  };
  std::string units;
  double page_width = 0, page_height = 0, page_margin = 0;
  std::size_t number_of_pages = 0;
  double line_width = 0;  // of the cut lines of the pieces 10 mm across and more, and of the frames
  double seam_allowance = 0;
  double font_size = 0;   // the largest label height
  double millimetre = 1;  // in drawing units
  std::vector<Piece> pieces;  // in drawing order
  std::vector<Text> assembly;  // the lines of the assembly page
  std::vector<Text> captions;  // on the pages of parts, in the top margin
  // the scale check in the bottom-left corner of every page, in the first
  // page's coordinates (internal/scale_check.h): its lines, their text, and
  // the bars' length (0: none)
  std::vector<std::array<P2, 2>> check_lines;
  Text check_label;
  double check_length = 0;

  // the number of page `page` (from 0), light, centred in the bottom margin,
  // and its height
  std::string page_number(std::size_t page) const
  {
    return "page " + std::to_string(page + 1) + " of " + std::to_string(number_of_pages);
  }
  double page_number_size() const { return (std::min)(0.8 * font_size, 0.8 * page_margin); }
};

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_IO_INTERNAL_PATTERN_PIECES_H
