// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_IO_INTERNAL_ASSEMBLY_PAGE_H
#define CGAL_QD_IO_INTERNAL_ASSEMBLY_PAGE_H

// The last page of a printed pattern: the order in which to join the pieces
// (IO/internal/assembly_order.h), then the seams whose two sides differ, in
// up to three columns of text made smaller until they fit.

#include <CGAL_QD/IO/pattern_options.h>

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace CGAL_QD {
namespace internal {

// the lines of the assembly page, `page` of the drawing `d`
// (`Pattern_drawing`), in columns, made smaller until they fit
template <class Drawing>
void lay_out_assembly_page(const std::vector<IO::Assembly_step>& steps, const std::vector<IO::Pattern_seam>& seams,
                           const std::string& units, std::size_t page, Drawing& d)
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
  const double m = d.page_margin, title = 1.2 * d.font_size, top = d.page_height * page + m + 2 * title;
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
  for(int tries = 0; tries < 30; ++tries, size *= 0.9) {
    rows = (std::max)(std::size_t(1), static_cast<std::size_t>(height / (1.5 * size)));
    for(columns = 1; columns <= 3; ++columns) {
      lines = wrap((std::max)(std::size_t(12), static_cast<std::size_t>(width / columns / (0.6 * size)) - 4));
      if(lines.size() <= columns * rows) break;
    }
    if(columns <= 3) break;
    columns = 3;
  }
  d.assembly.push_back({{{m, d.page_height * page + m + title}}, title, 0.,
                        "Assembly: join the pieces in this order, sewing or gluing the seams named", false});
  for(std::size_t i = 0; i < lines.size(); ++i)
    d.assembly.push_back({{{m + (i / rows) * width / columns + (lines[i].first ? 3 * size : 0.),
                            top + (i % rows + 0.5) * 1.5 * size}},
                          size, 0., lines[i].second, false});
}

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_IO_INTERNAL_ASSEMBLY_PAGE_H
