// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_IO_INTERNAL_ASSEMBLY_PAGE_H
#define CGAL_QD_IO_INTERNAL_ASSEMBLY_PAGE_H

// The last pages of a printed pattern: the order in which to join the pieces
// (IO/internal/assembly_order.h), then the seams whose two sides differ, in
// up to three columns of text made smaller until they fit on a page, or, at
// the smallest readable height, on more pages.

#include <CGAL_QD/IO/pattern_options.h>

#include <algorithm>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace CGAL_QD {
namespace internal {

// the lines of the assembly pages, from page `page` of the drawing `d`
// (`Pattern_drawing`) on, in up to three columns, made smaller until they fit
// on one page, down to about half the largest label height (the smallest
// taken to be readable, as for the labels), and at that height on as many
// pages as they need; returns the number of pages
template <class Drawing>
std::size_t lay_out_assembly_pages(const std::vector<IO::Assembly_step>& steps,
                                   const std::vector<IO::Pattern_seam>& seams, const std::string& units,
                                   std::size_t page, Drawing& d)
{
  std::vector<std::string> steps_text;
  for(std::size_t i = 0; i < steps.size(); ++i) steps_text.push_back(IO::assembly_step_text(steps, i));
  // then the seams whose sides differ, each with its two lengths
  bool eased = false;
  for(const IO::Pattern_seam& s : seams) {
    if(s.matched) continue;
    if(!eased) steps_text.push_back("Ease in the longer side of these seams, whose sides differ by more than 0.5 %:");
    eased = true;
    steps_text.push_back(IO::pattern_seam_text(s, units));
  }
  const double m = d.page_margin, title = 1.2 * d.font_size, top = m + 2 * title;
  const double width = d.page_width - 2 * m, height = d.page_height - 2 * m - 2 * title;
  // a step longer than its column goes on, indented, after a comma
  auto wrap = [&](std::size_t max_chars) {
    std::vector<std::pair<bool, std::string>> lines;  // (goes on, text)
    for(std::string t : steps_text) {
      bool goes_on = false;
      while(t.size() > max_chars) {
        const std::size_t cut = t.rfind(", ", max_chars - 1);
        if(cut == std::string::npos || cut < 8) break;
        lines.emplace_back(goes_on, t.substr(0, cut + 1));
        t = t.substr(cut + 2);
        goes_on = true;
      }
      lines.emplace_back(goes_on, t);
    }
    return lines;
  };
  double size = d.font_size;
  std::vector<std::pair<bool, std::string>> lines;
  std::size_t columns = 1, rows = 1;
  for(;;) {
    rows = (std::max)(std::size_t(1), static_cast<std::size_t>(height / (1.5 * size)));
    for(columns = 1; columns <= 3; ++columns) {
      lines = wrap((std::max)(std::size_t(12), static_cast<std::size_t>(width / columns / (0.6 * size)) - 4));
      if(lines.size() <= columns * rows) break;
    }
    if(columns <= 3) break;
    columns = 3;
    if(0.9 * size < 0.5 * d.font_size) break;  // on more pages
    size *= 0.9;
  }
  const std::size_t per_page = columns * rows;
  const std::size_t pages = (std::max)(std::size_t(1), (lines.size() + per_page - 1) / per_page);
  for(std::size_t p = 0; p < pages; ++p)
    d.assembly.push_back({{{m, d.page_height * double(page + p) + m + title}},
                          title,
                          0.,
                          p == 0 ? "Assembly: join the pieces in this order, sewing or gluing the seams named"
                                 : "Assembly, continued",
                          false});
  for(std::size_t i = 0; i < lines.size(); ++i) {
    const std::size_t p = i / per_page, j = i % per_page;
    d.assembly.push_back({{{m + (j / rows) * width / columns + (lines[i].first ? 3 * size : 0.),
                            d.page_height * double(page + p) + top + (j % rows + 0.5) * 1.5 * size}},
                          size, 0., lines[i].second, false});
  }
  return pages;
}

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_IO_INTERNAL_ASSEMBLY_PAGE_H
