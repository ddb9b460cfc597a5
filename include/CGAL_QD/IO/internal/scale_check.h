// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_IO_INTERNAL_SCALE_CHECK_H
#define CGAL_QD_IO_INTERNAL_SCALE_CHECK_H

// The scale check of a printed pattern: in the bottom-left corner of every
// page, in the margins, two bars of a round length from the same corner, one
// along the bottom margin and one up the left margin, with ticks, and their
// length written beside. A printer told to fit the page shrinks the pattern by
// a few per cent, which no one sees on the pieces but everyone sees with a
// ruler laid along a bar; two bars show a print stretched in one direction.

#include <algorithm>
#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL_QD {
namespace internal {

// The bars of `d` (`Pattern_drawing`), in the first page's coordinates: the
// longest of 50, 20 and 10 mm (2, 1 and 1/2 inch when `inches`) whose bar and
// text end before the page number, in the bottom margin, and whose bar fits in
// the left margin's height; ticks every 10 or 5 mm (a quarter inch). None on
// margins under 4 mm: `d.check_lines` (empty before) stays empty where none fits.
template <class Drawing>
void lay_out_scale_check(Drawing& d, bool inches)
{
  typedef typename Drawing::P2 P2;
  const double mm = d.millimetre, m = d.page_margin;
  if(!(m >= 4 * mm)) return;
  // the height of the page number, which the text shares
  const double size = d.page_number_size();
  const std::string number = d.page_number(d.number_of_pages - 1);  // the widest
  // texts are at most 0.7 of their height wide per character (label_placement.h)
  const double number_left = d.page_width / 2 - 0.35 * size * double(number.size());
  // 0.65 of the margin from the paper's edges, where few printers cannot
  // print, the ticks into the page up to 0.9 of it
  const double x0 = 0.65 * m, y0 = d.page_height - 0.65 * m, tick = (std::min)(0.25 * m, 2.5 * mm);
  const std::array<double, 3> lengths = inches ? std::array<double, 3>{{2., 1., 0.5}}
                                               : std::array<double, 3>{{50., 20., 10.}};
  const std::array<const char*, 3> names = inches ? std::array<const char*, 3>{{"2 in", "1 in", "1/2 in"}}
                                                  : d.units == "cm" ? std::array<const char*, 3>{{"5 cm", "2 cm", "1 cm"}}
                                                                    : std::array<const char*, 3>{{"50 mm", "20 mm", "10 mm"}};
  for(std::size_t i = 0; i < lengths.size(); ++i) {
    const double unit = inches ? 25.4 * mm : mm, length = lengths[i] * unit;
    const std::string text = std::string(names[i]) + " at 100 %";
    const double text_width = 0.7 * size * double(text.size());
    if(x0 + length + 0.5 * size + text_width > number_left - size) continue;  // meets the page number
    if(y0 - length < m) continue;                                                // taller than the page
    d.check_lines.push_back({{P2{{x0, y0}}, P2{{x0 + length, y0}}}});
    d.check_lines.push_back({{P2{{x0, y0}}, P2{{x0, y0 - length}}}});
    const double step = (inches ? 0.25 : (lengths[i] >= 50 ? 10. : 5.)) * unit;
    const int ticks = static_cast<int>(length / step + 0.5);
    for(int k = 0; k <= ticks; ++k) {
      // into the page, the ends and the middle longer
      const double along = k * step, t = k == 0 || k == ticks || 2 * k == ticks ? tick : 0.6 * tick;
      d.check_lines.push_back({{P2{{x0 + along, y0}}, P2{{x0 + along, y0 - t}}}});
      if(k > 0) d.check_lines.push_back({{P2{{x0, y0 - along}}, P2{{x0 + t, y0 - along}}}});
    }
    d.check_label = {{{x0 + length + 0.5 * size + text_width / 2, y0}}, size, 0., text};
    d.check_length = length;
    return;
  }
}

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_IO_INTERNAL_SCALE_CHECK_H
