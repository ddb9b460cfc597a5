// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_IO_INTERNAL_PATTERN_SCALE_H
#define CGAL_QD_IO_INTERNAL_PATTERN_SCALE_H

// The scale of a printed pattern and the loose pieces it leaves out: the
// model's largest dimension is that of the pieces drawn, so that the specks a
// scan leaves apart from a model, once left out, make the model no smaller.

#include <CGAL_QD/IO/internal/pattern_layout.h>
#include <CGAL_QD/IO/pattern_options.h>
#include <CGAL_QD/pack_charts.h>

#include <CGAL/Bbox_3.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL_QD {
namespace internal {

struct Pattern_scale
{
  double scale = 0;             // drawing units per mesh unit
  bool reduced_to_fit = false;  // chosen, and made smaller so that every piece drawn fits on a page
  double extent = 0;            // the largest side of the 3D bounding box of the pieces drawn
  std::vector<bool> drawn;      // by chart id
  std::vector<std::size_t> left_out;  // the loose pieces left out, by chart id
};

// The scale of a pattern and the pieces drawn. The scale is `options.scale`,
// or the one that gives the pieces drawn the largest dimension
// `options.model_size`; without either, the one that gives them 200 mm
// (`mm_per_unit` millimetres per drawing unit), made smaller where needed so
// that every piece drawn, padded by `pad`, fits on a page (to whole
// millimetres where that leaves at least one). Per chart id k: `boxes[k]` is
// the smallest rectangle of its flattening and `box_3d[k]` its 3D bounding
// box (mesh units), `used[k]` whether it has faces, `loose[k]` whether it is
// a whole connected component of the mesh. With
// `options.min_loose_piece_size`, the loose pieces shorter than that on the
// page are left out, unless every piece would be: those shorter at the scale
// of every piece, then, with the scale chosen for the others (larger where a
// speck lay apart from the model), those still shorter, and so on until every
// piece left out is shorter at the scale of the pieces drawn.
inline Pattern_scale choose_pattern_scale(const std::vector<Rectangle>& boxes, const std::vector<CGAL::Bbox_3>& box_3d,
                                          const std::vector<bool>& used, const std::vector<bool>& loose,
                                          const IO::Pattern_options& options, double mm_per_unit, double pad)
{
  const std::size_t n = boxes.size();
  const double mm = 1 / mm_per_unit;  // drawing units per millimetre
  auto extent_of = [&](const std::vector<bool>& drawn) {
    CGAL::Bbox_3 all;  // empty
    for(std::size_t k = 0; k < n; ++k)
      if(drawn[k]) all += box_3d[k];
    return (std::max)({all.x_span(), all.y_span(), all.z_span()});
  };
  auto scale_for = [&](const std::vector<bool>& drawn) {
    Pattern_scale s;
    s.drawn = drawn;
    s.extent = extent_of(drawn);
    if(options.scale > 0) {
      s.scale = options.scale;
      return s;
    }
    s.scale = (options.model_size > 0 ? options.model_size : 200 * mm) / s.extent;
    if(options.model_size == 0) {
      std::vector<Rectangle> drawn_boxes;
      for(std::size_t k = 0; k < n; ++k)
        if(drawn[k]) drawn_boxes.push_back(boxes[k]);
      const double fit = largest_fitting_scale(drawn_boxes, options.page_width - 2 * options.page_margin,
                                               options.page_height - 2 * options.page_margin, pad);
      if(fit < s.scale) {
        // whole millimetres, where that leaves at least one
        const double whole = std::floor(fit * s.extent * mm_per_unit);
        s.scale = whole >= 1 ? whole * mm / s.extent : fit;
        s.reduced_to_fit = true;
      }
    }
    return s;
  };
  auto valid = [](const Pattern_scale& s) { return s.extent > 0 && std::isfinite(s.scale) && s.scale > 0; };
  Pattern_scale result = scale_for(used);
  if(!(options.min_loose_piece_size > 0) || !valid(result)) return result;
  auto shorter_at = [&](double scale, std::size_t k) {
    return scale * (std::max)(boxes[k].size[0], boxes[k].size[1]) < options.min_loose_piece_size;
  };
  std::vector<std::size_t> small;
  std::size_t pieces = 0;
  for(std::size_t k = 0; k < n; ++k) {
    if(!used[k]) continue;
    ++pieces;
    if(loose[k] && shorter_at(result.scale, k)) small.push_back(k);
  }
  // `small` only shrinks: at most one round per piece
  while(!small.empty() && small.size() < pieces) {
    std::vector<bool> drawn = used;
    for(std::size_t k : small) drawn[k] = false;
    Pattern_scale candidate = scale_for(drawn);
    if(!valid(candidate)) break;
    std::vector<std::size_t> still;
    for(std::size_t k : small)
      if(shorter_at(candidate.scale, k)) still.push_back(k);
    if(still.size() == small.size()) {
      candidate.left_out.swap(small);
      return candidate;
    }
    small.swap(still);
  }
  return result;
}

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_IO_INTERNAL_PATTERN_SCALE_H
