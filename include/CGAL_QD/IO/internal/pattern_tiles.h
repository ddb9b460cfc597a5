// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_IO_INTERNAL_PATTERN_TILES_H
#define CGAL_QD_IO_INTERNAL_PATTERN_TILES_H

// A piece larger than a page, printed in parts: its box is cut into windows
// the size of a page's printable area, and every window that holds some of
// the piece is printed on a page of its own, within a grey frame. Where two
// parts meet, diamonds numbered alike are drawn across the line between them
// (half on each page): a person cuts one page along its frame, lays it edge to
// edge with the other and matches the half diamonds, as with the tiled
// patterns of sewing shops.

#include <CGAL_QD/IO/internal/pattern_layout.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace CGAL_QD {
namespace internal {

// One part of a piece: the window [low, low + size] of the piece's drawing
// (drawing units), shown on page `page` moved by `shift`, which puts it on the
// printable area of that page
struct Pattern_part
{
  std::size_t page = 0, row = 0, column = 0;
  std::array<double, 2> low{{0, 0}}, size{{0, 0}}, shift{{0, 0}};
  // the window where it is printed (x, y, width, height): the page's printable area, framed
  std::array<double, 4> on_page() const { return {{low[0] + shift[0], low[1] + shift[1], size[0], size[1]}}; }
};

// whether the segment a-b meets the box [low, low + size] (Liang and Barsky's
// clipping); `inside`, if given, receives the share of the segment in the box
inline bool segment_meets_box(const std::array<double, 2>& a, const std::array<double, 2>& b,
                              const std::array<double, 2>& low, const std::array<double, 2>& size,
                              double* inside = nullptr)
{
  double t0 = 0, t1 = 1;
  if(inside) *inside = 0;
  for(int c = 0; c < 2; ++c) {
    const double d = b[c] - a[c];
    const double p[2] = {-d, d}, q[2] = {a[c] - low[c], low[c] + size[c] - a[c]};
    for(int k = 0; k < 2; ++k) {
      if(p[k] == 0) {
        if(q[k] < 0) return false;
        continue;
      }
      const double t = q[k] / p[k];
      if(p[k] < 0)
        t0 = (std::max)(t0, t);
      else
        t1 = (std::min)(t1, t);
      if(t0 > t1) return false;
    }
  }
  if(inside) *inside = t1 - t0;
  return true;
}

// Cuts every piece of `d` whose placement in `place` (by chart) has more
// than one part into its parts (`Piece::parts`; the grid of windows shifted
// within the room the box leaves it, to need the fewest and to print no
// sliver where it can), each part that holds a line,
// a tab or an outline of the piece on a page of its own from page
// `first_page` on, row by row; draws the marks across the lines between two
// parts printed (`Piece::marks`, `Piece::mark_labels`) and, on every page of a
// part, a caption in the top margin (`captions`).
// `usable` is the printable area of a page, `mark` the half diagonal of a
// diamond. Returns the number of pages used.
template <class Drawing>
std::size_t cut_into_parts(Drawing& d, const std::vector<Piece_placement>& place, std::size_t first_page,
                           const std::array<double, 2>& usable, double mark)
{
  typedef std::array<double, 2> P2;
  const double margin = d.page_margin, ph = d.page_height;
  std::size_t page = first_page;
  for(auto& piece : d.pieces) {
    const Piece_placement& p = place[piece.chart];
    if(p.rows * p.columns <= 1) continue;
    // the windows: a grid of rows x columns over the piece's box, which it
    // exceeds by some slack; the grid placed, among 81 shifts within that
    // slack (eighths of it across and down), where the fewest windows hold
    // some of the piece, and among those where the window that holds least of
    // it holds most (the length of its lines there): a part that holds a
    // sliver of the piece still takes a page (the top left first on a tie)
    const P2 box{{p.at[0], double(piece.page) * ph + p.at[1]}};
    const P2 slack{{(std::max)(0., double(p.columns) * usable[0] - p.size[0]),
                    (std::max)(0., double(p.rows) * usable[1] - p.size[1])}};
    P2 origin = box;
    auto window_low = [&](std::size_t r, std::size_t c) {
      return P2{{origin[0] + double(c) * usable[0], origin[1] + double(r) * usable[1]}};
    };
    // the windows that a line, a tab or an outline of the piece meets, each
    // segment tried against the windows its box reaches (and those next to
    // them), and the length of those lines in each window
    std::vector<double> drawn;
    auto windows_met = [&]() {
      std::vector<char> met(p.rows * p.columns, 0);
      drawn.assign(p.rows * p.columns, 0.);
      auto index = [&](double x, int c, std::size_t n) {
        const double i = std::floor((x - origin[c]) / usable[c]);
        return i < 0 ? std::size_t(0) : (std::min)(n - 1, static_cast<std::size_t>(i));
      };
      auto add = [&](const P2& a, const P2& b) {
        const std::size_t c0 = index((std::min)(a[0], b[0]), 0, p.columns), c1 = index((std::max)(a[0], b[0]), 0, p.columns);
        const std::size_t r0 = index((std::min)(a[1], b[1]), 1, p.rows), r1 = index((std::max)(a[1], b[1]), 1, p.rows);
        for(std::size_t r = r0 > 0 ? r0 - 1 : 0; r <= (std::min)(r1 + 1, p.rows - 1); ++r)
          for(std::size_t c = c0 > 0 ? c0 - 1 : 0; c <= (std::min)(c1 + 1, p.columns - 1); ++c) {
            double inside = 0;
            if(segment_meets_box(a, b, window_low(r, c), usable, &inside)) {
              met[r * p.columns + c] = 1;
              drawn[r * p.columns + c] += inside * std::hypot(b[0] - a[0], b[1] - a[1]);
            }
          }
      };
      for(const auto& l : piece.lines) add(l.a, l.b);
      for(const auto& t : piece.tabs)
        for(int i = 0; i < 4; ++i) add(t[i], t[(i + 1) % 4]);
      for(const auto& outline : piece.allowance)
        for(std::size_t i = 0; i < outline.size(); ++i) add(outline[i], outline[(i + 1) % outline.size()]);
      return met;
    };
    std::vector<char> met;
    {
      P2 best = box;
      std::size_t fewest = p.rows * p.columns + 1;
      double best_least = 0;
      for(double fy : {0., 0.125, 0.25, 0.375, 0.5, 0.625, 0.75, 0.875, 1.})
        for(double fx : {0., 0.125, 0.25, 0.375, 0.5, 0.625, 0.75, 0.875, 1.}) {
          origin = {{box[0] - fx * slack[0], box[1] - fy * slack[1]}};
          const std::vector<char> m = windows_met();
          const std::size_t count = static_cast<std::size_t>(std::count(m.begin(), m.end(), 1));
          // the least drawn on a page of a part printed
          double least = std::numeric_limits<double>::infinity();
          for(std::size_t w = 0; w < m.size(); ++w)
            if(m[w]) least = (std::min)(least, drawn[w]);
          if(count < fewest || (count == fewest && least > best_least))
            fewest = count, best_least = least, best = origin, met = m;
        }
      origin = best;
    }
    auto printed = [&](std::size_t r, std::size_t c) { return met[r * p.columns + c] != 0; };
    for(std::size_t r = 0; r < p.rows; ++r)
      for(std::size_t c = 0; c < p.columns; ++c) {
        const P2 low = window_low(r, c);
        if(!printed(r, c)) continue;
        Pattern_part part;
        part.page = page++;
        part.row = r;
        part.column = c;
        part.low = low;
        part.size = usable;
        part.shift = {{margin - low[0], double(part.page) * ph + margin - low[1]}};
        piece.parts.push_back(part);
      }
    // two diamonds across every line between two parts printed, at a third and
    // two thirds of it, each numbered on both sides
    const double label = (std::min)(d.font_size, 2.5 * mark);
    std::size_t number = 0;
    auto diamond = [&](const P2& at, bool across_x) {
      piece.marks.push_back({{P2{{at[0] - mark, at[1]}}, P2{{at[0], at[1] - mark}}, P2{{at[0] + mark, at[1]}},
                              P2{{at[0], at[1] + mark}}}});
      const std::string text = std::to_string(piece.chart) + "\u00b7" + std::to_string(++number);  // a middle dot
      // beside the diamond on either side of the line
      const double away = across_x ? mark + 0.3 * label * double(text.size()) + 0.3 * label : mark + 0.8 * label;
      for(int side = -1; side <= 1; side += 2) {
        const P2 where = across_x ? P2{{at[0] + side * away, at[1]}} : P2{{at[0], at[1] + side * away}};
        piece.mark_labels.push_back({where, label, 0., text});
      }
    };
    for(std::size_t r = 0; r < p.rows; ++r)
      for(std::size_t c = 0; c < p.columns; ++c) {
        const P2 low = window_low(r, c);
        if(c + 1 < p.columns && printed(r, c) && printed(r, c + 1))
          for(double f : {1. / 3, 2. / 3}) diamond({{low[0] + usable[0], low[1] + f * usable[1]}}, true);
        if(r + 1 < p.rows && printed(r, c) && printed(r + 1, c))
          for(double f : {1. / 3, 2. / 3}) diamond({{low[0] + f * usable[0], low[1] + usable[1]}}, false);
      }
    // the caption of every part's page
    const std::size_t n = piece.parts.size();
    for(std::size_t i = 0; i < n; ++i) {
      const Pattern_part& part = piece.parts[i];
      const double top = double(part.page) * ph;
      const std::string text = "piece " + std::to_string(piece.chart) + ", part " + std::to_string(i + 1) + " of " +
                               std::to_string(n) + " (row " + std::to_string(part.row + 1) + ", column " +
                               std::to_string(part.column + 1) +
                               "): cut along the grey frame where parts meet, match the half diamonds";
      // about 0.55 of its height a character
      const double size = (std::min)({0.8 * d.font_size, 0.4 * margin, usable[0] / (0.55 * double(text.size()))});
      d.captions.push_back({{{d.page_width / 2, top + margin / 2}}, size, 0., text});
    }
    if(n > 0) piece.page = piece.parts.front().page;
  }
  return page - first_page;
}

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_IO_INTERNAL_PATTERN_TILES_H
