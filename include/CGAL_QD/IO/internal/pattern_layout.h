// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_IO_INTERNAL_PATTERN_LAYOUT_H
#define CGAL_QD_IO_INTERNAL_PATTERN_LAYOUT_H

// The page layout of a printed pattern: the scale (given, or chosen so that
// the model has a physical size and every piece fits on a page), and every
// piece's box packed on pages.

#include <CGAL_QD/pack_charts.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL_QD {
namespace internal {

// where one piece goes: its points turned by `angle` lie in [low, low + size / scale]
// (mesh units), drawn with the top-left corner of its box (`size`, drawing
// units, with padding) at `at` on page `page`. A piece larger than a page is
// printed in parts: `rows` x `columns` windows of the page's printable area
// (pattern_tiles.h), from page `page` on.
struct Piece_placement
{
  double angle = 0;
  std::array<double, 2> low{{0, 0}}, size{{0, 0}}, at{{0, 0}};
  std::size_t page = 0, rows = 1, columns = 1;
  bool used = false;
};

struct Page_layout
{
  std::vector<Piece_placement> pieces;  // by chart id
  std::vector<std::size_t> order;       // the charts in drawing order
  std::size_t number_of_pages = 0;
  std::size_t first_part_page = 0;  // after the pages of the pieces that fit on one
  std::size_t oversized = 0;  // pieces larger than a page, printed in parts on pages of their own
};

// The largest scale (drawing units per mesh unit) at which every rectangle of
// `boxes` (mesh units), padded by `pad` on every side, fits into usable_w x
// usable_h, turned if need be; infinity without boxes, 0 when the padding alone
// does not fit.
inline double largest_fitting_scale(const std::vector<Rectangle>& boxes, double usable_w, double usable_h, double pad)
{
  const double u1 = (std::max)(usable_w, usable_h) - 2 * pad, u2 = (std::min)(usable_w, usable_h) - 2 * pad;
  if(!(u2 > 0)) return 0;
  double s = std::numeric_limits<double>::infinity();
  for(const Rectangle& r : boxes) {
    const double a = (std::max)(r.size[0], r.size[1]), b = (std::min)(r.size[0], r.size[1]);
    if(a > 0) s = (std::min)(s, u1 / a);
    if(b > 0) s = (std::min)(s, u2 / b);
  }
  return s;
}

// Places the boxes of the charts (`boxes[k]`, mesh units; `used[k]` false for
// an id without faces) at `scale` on pages of page_w x page_h with `margin`
// free on every side, each box padded by `pad`: the tallest first, packed
// bottom-left on a skyline page by page; a box larger than a page after the
// others, turned the way that needs the fewest parts of a page's printable
// area, on as many pages of its own as it has parts.
inline Page_layout lay_out_pieces(const std::vector<Rectangle>& boxes, const std::vector<bool>& used, double scale,
                                  double page_w, double page_h, double margin, double pad)
{
  Page_layout layout;
  const std::size_t n = boxes.size();
  layout.pieces.resize(n);
  const double usable_w = page_w - 2 * margin, usable_h = page_h - 2 * margin;
  // turns a piece by 90 degrees: turning (x, y) -> (-y, x) maps [lx, lx + w] x
  // [ly, ly + h] to [-ly - h, -ly] x [lx, lx + w] (h, its height in mesh units)
  auto turn = [](Piece_placement& p, double h) {
    p.angle += 1.5707963267948966;
    p.low = {{-p.low[1] - h, p.low[0]}};
    std::swap(p.size[0], p.size[1]);
  };
  for(std::size_t k = 0; k < n; ++k) {
    if(!used[k]) continue;
    const Rectangle& r = boxes[k];
    Piece_placement& p = layout.pieces[k];
    p.used = true;
    p.angle = r.angle;
    p.low = r.low;
    p.size = {{r.size[0] * scale + 2 * pad, r.size[1] * scale + 2 * pad}};
    // lay it flat, or upright if it fits only so; a piece larger than a page
    // the way that cuts it into the fewest parts (upright on a tie if the page is)
    const bool fits = p.size[0] <= usable_w && p.size[1] <= usable_h;
    const bool fits_turned = p.size[1] <= usable_w && p.size[0] <= usable_h;
    auto parts = [&](double w, double h) { return std::ceil(w / usable_w) * std::ceil(h / usable_h); };
    const double flat = parts(p.size[0], p.size[1]), upright = parts(p.size[1], p.size[0]);
    if((!fits && fits_turned) ||
       (!fits && !fits_turned &&
        (upright < flat || (upright == flat && p.size[0] > p.size[1] && usable_h > usable_w))))
      turn(p, r.size[1]);
    if(p.size[0] > usable_w || p.size[1] > usable_h) {
      ++layout.oversized;
      // (a million at most each way: the caller refuses so many pages anyway)
      p.columns = static_cast<std::size_t>((std::min)(std::ceil(p.size[0] / usable_w), 1e6));
      p.rows = static_cast<std::size_t>((std::min)(std::ceil(p.size[1] / usable_h), 1e6));
    }
    layout.order.push_back(k);
  }
  // the pieces that fit on a page, tallest first, page by page: each page
  // packed bottom-left on a skyline (a piece may be turned), what does not fit
  // goes on to the next page
  std::stable_sort(layout.order.begin(), layout.order.end(), [&](std::size_t a, std::size_t b) {
    return layout.pieces[a].size[1] > layout.pieces[b].size[1];
  });
  std::vector<Packing_box> todo;
  for(std::size_t k : layout.order) {
    const Piece_placement& p = layout.pieces[k];
    if(p.size[0] <= usable_w && p.size[1] <= usable_h) todo.push_back({k, p.size[0], p.size[1]});
  }
  std::size_t page = 0;
  while(!todo.empty()) {
    skyline_pack(todo, usable_w, usable_h);
    std::vector<Packing_box> later;
    for(const Packing_box& b : todo) {
      if(!b.placed) {
        later.push_back({b.chart, b.w, b.h});
        continue;
      }
      Piece_placement& p = layout.pieces[b.chart];
      if(b.turned) turn(p, (p.size[1] - 2 * pad) / scale);
      p.page = page;
      p.at = {{margin + b.x, margin + b.y}};
    }
    const bool progress = later.size() < todo.size();  // always: every piece here fits on an empty page
    todo.swap(later);
    ++page;
    if(!progress) break;
  }
  // a piece larger than a page: at the top left of the printable area of its
  // first page, its parts on pages of their own, row by row
  layout.first_part_page = page;
  for(std::size_t k : layout.order) {
    Piece_placement& p = layout.pieces[k];
    if(p.size[0] <= usable_w && p.size[1] <= usable_h) continue;
    p.page = page;
    p.at = {{margin, margin}};
    page += p.rows * p.columns;
  }
  layout.number_of_pages = page;
  return layout;
}

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_IO_INTERNAL_PATTERN_LAYOUT_H
