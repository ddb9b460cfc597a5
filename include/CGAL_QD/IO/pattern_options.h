// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_IO_PATTERN_OPTIONS_H
#define CGAL_QD_IO_PATTERN_OPTIONS_H

/// \file IO/pattern_options.h
/// What a printed pattern looks like (`Pattern_options`) and what was drawn
/// (`Pattern_result`), for `write_patterns_SVG()` and `write_patterns_PDF()`.

#include <CGAL_QD/Error_code.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <string>
#include <vector>

namespace CGAL_QD {
namespace IO {

/// \ingroup PkgCGAL_QDRef
/// millimetres per drawing unit for the units the pattern writers know
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
/// options of `write_patterns_SVG()` and `write_patterns_PDF()`. Every length is in drawing units
/// (`units`); the defaults are for millimetres.
struct Pattern_options
{
  /// drawing units per mesh unit; 0 (the default): chosen from `model_size`. A scale at which the
  /// model would be under 1 mm at its largest is refused (`INVALID_ARGUMENT`, with
  /// `Pattern_result::model_size`): its lines would hide its pieces
  double scale = 0;
  /// with `scale` 0, the model's largest dimension (the longest side of the
  /// axis-aligned bounding box of the pieces drawn, without the loose pieces left
  /// out by `min_loose_piece_size`) on paper; 0 (the default): 200 mm, made
  /// smaller (to whole millimetres) where a piece would not fit on a page at that size
  double model_size = 0;
  /// the unit of the drawing (the SVG's width and height are in it): `mm`, `cm`, `in`, `pt`, `pc` or `px`
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
  /// the shortest fold line drawn, on the page; 0 (the default): `min_fold_share` of the model's
  /// largest dimension on the page. The edges that bend more than `fold_angle` are chained into lines,
  /// edge to edge through a vertex where the line turns by at most 30 degrees on the page (each edge
  /// going on into the straightest edge of the same kind, mountain or valley), and a line shorter than
  /// this on the page is drawn only where each of its ends lies on the piece's cut line or on another
  /// line drawn (a crease across a narrow strip, or between two longer ones): on a fine mesh of a
  /// smooth shape, those edges are mostly small bends of the sampling, scattered or side by side where
  /// the surface curves, and the paper takes that shape by bending
  double min_fold_length = 0;
  /// with `min_fold_length` 0, the shortest fold line drawn as a share of the model's largest dimension
  /// on the page (`Pattern_result::model_size`): 10 mm on a model printed 200 mm long, so that the
  /// pattern shows the same fold lines at every size. With both 0, every edge that bends more than
  /// `fold_angle` is drawn
  double min_fold_share = 0.05;
  /// the largest height of the label text (0: from the page size); a piece's
  /// labels are made smaller where the piece is small
  double font_size = 0;
  /// notches across the cut line, into the piece, about this far apart along every seam (0: none):
  /// the same number on the two sides of a seam, at the same fractions of their lengths, numbered;
  /// under 1 mm is refused (`INVALID_COORDINATES`): notches so close could not be cut
  double notch_spacing = 0;
  /// a seam allowance this wide around every piece (0: none): the cut line then runs this far outside
  /// the piece's border, which becomes a dashed stitch line; needs Clipper (`CGAL_QD_HAS_CLIPPER`)
  double seam_allowance = 0;
  /// a piece that is a whole connected component of the mesh (a loose part: it shares no seam with
  /// another piece) and whose smallest enclosing rectangle has no side this long on the page is left off
  /// the pattern and out of the assembly (`Pattern_result::left_out_pieces`), unless every piece would
  /// be: the specks a scan leaves beside a model cannot be cut out. The model's size is then that of
  /// the pieces drawn (`model_size`): the pieces shorter at the scale of the whole mesh are left out,
  /// then those still shorter at the scale chosen for the others (larger where a speck lay apart from
  /// the model), until every piece left out is shorter at the scale of the pieces drawn.
  /// 0 (the default): every piece is drawn
  double min_loose_piece_size = 0;
  /// a last page lists the order in which to join the pieces (`Pattern_result::assembly`), in up to
  /// three columns made smaller until they fit, down to half the largest label height; a longer list
  /// goes on over more pages at that height (`Pattern_result::assembly_pages`)
  bool assembly_page = true;
  /// a scale check in the bottom-left corner of every page, in the margins: two bars of the same
  /// length from the corner, along the bottom margin and up the left one, with their length written
  /// beside ("50 mm at 100 %"), to measure with a ruler that the pattern printed at its real size.
  /// 50, 20 or 10 mm (2, 1 or 1/2 inch when `units` is `in`), the longest whose text ends before the
  /// page number; none on margins under 4 mm (`Pattern_result::scale_check`)
  bool scale_check = true;
  /// the most pages a pattern may take: at a scale that would need more (pieces larger than a
  /// page take a page per part), or with an assembly list that would take the pattern beyond them,
  /// nothing is drawn and the writers return `INVALID_ARGUMENT`, with
  /// `Pattern_result::number_of_pages` at least the pages the layout needs (and
  /// `Pattern_result::assembly_pages` those of the list)
  std::size_t max_pages = 1000;

  /// the room the layout keeps around every piece, on each side: half the `spacing`, the
  /// `tab_width` with `tabs`, and the `seam_allowance`. Twice this must be less than the page's
  /// smaller side within its margins, or the writers refuse the options
  double space_around_piece() const { return spacing / 2 + (tabs ? tab_width : 0) + seam_allowance; }
};

/// \ingroup PkgCGAL_QDRef
/// one step of the assembly of the pieces (`Pattern_result::assembly`).
struct Assembly_step
{
  std::size_t piece = 0;  ///< the piece joined at this step
  /// the piece it is joined to, the one with which it shares the longest seams; `piece` itself for the
  /// first piece of the model, or of a part of it that no seam joins to the rest
  std::size_t onto = 0;
  /// the labels of the seams sewn or glued at this step: those between `piece` and the pieces joined
  /// before, and the cuts inside `piece`, in label order
  std::vector<std::string> seams;
};

/// \ingroup PkgCGAL_QDRef
/// the sentence of step `i` (from 0) of an assembly, as the pattern's last page prints it:
/// "2. piece 5 onto piece 3: A, B" (the first step "1. piece 3 (the largest)").
inline std::string assembly_step_text(const std::vector<Assembly_step>& steps, std::size_t i)
{
  std::string t = std::to_string(i + 1) + ". piece " + std::to_string(steps[i].piece);
  if(i == 0) t += " (the largest)";
  if(steps[i].onto != steps[i].piece) t += " onto piece " + std::to_string(steps[i].onto);
  for(std::size_t k = 0; k < steps[i].seams.size(); ++k) t += (k == 0 ? ": " : ", ") + steps[i].seams[k];
  return t;
}

/// \ingroup PkgCGAL_QDRef
/// a seam curve as the pattern draws it (`Pattern_result::seams`): its label and the lengths of its two
/// sides on paper. Where the flattening could not bring the two sides within 0.5 % of each other, the
/// longer side is to be eased in when the seam is sewn or glued.
struct Pattern_seam
{
  std::string label;  ///< as printed on both sides: "A", "B", ...
  /// the pieces on its two sides (the same piece twice for a cut inside a piece)
  std::array<std::size_t, 2> pieces = {{0, 0}};
  /// the length of each side as drawn, in drawing units: side k on piece `pieces[k]`
  std::array<double, 2> sides = {{0., 0.}};
  /// whether the two sides differ by at most 0.5 % of the longer
  bool matched = true;
};

/// \ingroup PkgCGAL_QDRef
/// the line the pattern's assembly page prints for a seam whose sides differ: "G: 152.3 mm on piece 3,
/// 139.1 mm on piece 5 (8.7 %)", the lengths to three significant digits and at least one decimal
/// (at most three), the difference as a percentage of the longer side
inline std::string pattern_seam_text(const Pattern_seam& s, const std::string& units)
{
  auto fixed = [](double x, int decimals) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, x);
    return std::string(buffer);
  };
  const double longer = (std::max)(s.sides[0], s.sides[1]);
  const int decimals =
      longer > 0 && std::isfinite(longer) ? (std::min)(3, (std::max)(1, 2 - int(std::floor(std::log10(longer))))) : 1;
  const double difference = longer > 0 ? 100 * std::abs(s.sides[0] - s.sides[1]) / longer : 0.;
  return s.label + ": " + fixed(s.sides[0], decimals) + " " + units + " on piece " + std::to_string(s.pieces[0]) +
         ", " + fixed(s.sides[1], decimals) + " " + units + " on piece " + std::to_string(s.pieces[1]) + " (" +
         fixed(difference, 1) + " %)";
}

/// \ingroup PkgCGAL_QDRef
/// what `write_patterns_SVG()` or `write_patterns_PDF()` drew.
struct Pattern_result
{
  Error_code status = Error_code::OK;
  /// the scale used, in drawing units per mesh unit
  double scale = 0;
  /// the model's largest dimension (the longest bounding-box side of the pieces drawn) on paper, in
  /// drawing units
  double model_size = 0;
  /// whether the scale was chosen (`Pattern_options::scale` 0) and made smaller
  /// than the one of the default model size, so that every piece fits on a page
  bool reduced_to_fit = false;
  std::size_t number_of_pages = 0;
  /// the pages of the assembly list, the last ones (`Pattern_options::assembly_page`): one, or more
  /// where the list would be under half the largest label height on one
  std::size_t assembly_pages = 0;
  std::size_t number_of_charts = 0;  ///< the pieces drawn
  /// the loose pieces left out (`Pattern_options::min_loose_piece_size`), by chart id
  std::vector<std::size_t> left_out_pieces;
  /// charts larger than a page (after turning them): each is printed in parts, a page's printable area
  /// each, on pages of its own, with marks to join them
  std::size_t oversized_charts = 0;
  std::size_t part_pages = 0;  ///< the pages of those parts (a part that holds nothing of its piece is left out)
  std::size_t cut_edges = 0;    ///< edges on the charts' borders, each drawn once per side
  std::size_t seam_labels = 0;  ///< labels of seam curves, each drawn on both sides
  std::size_t fold_lines = 0;   ///< edges drawn as fold lines (see `Pattern_options::min_fold_length`)
  /// the shortest fold line drawn, in drawing units: `Pattern_options::min_fold_length`, or the share of
  /// the model's size it was 0 for (0: every edge beyond the fold angle was drawn)
  double min_fold_length = 0;
  std::size_t tabs = 0;
  std::size_t notches = 0;  ///< on both sides of every seam, counted once per side
  /// the order in which to join the pieces, built outward from the largest (by 3D area): each step
  /// joins the piece that shares the longest seams with those joined before
  std::vector<Assembly_step> assembly;
  /// every labelled seam curve, in label order; the assembly page lists those not `matched`
  std::vector<Pattern_seam> seams;
  /// the pieces too small at this scale for their seam labels and number, by chart id: a label that
  /// found no place apart from the others, the piece's number and the cut lines, inside the piece or
  /// outside it; a number outside that found none apart from the labels; or a label or number drawn
  /// smaller than half the largest label height (`Pattern_options::font_size`, or 1/60 of the page's
  /// smaller side), since texts inside are at most a quarter (labels) or a third (numbers) of a
  /// piece's smaller side. A larger scale gives them room.
  std::vector<std::size_t> crowded_pieces;
  /// the length of the scale check's bars (`Pattern_options::scale_check`), in drawing units; 0 where
  /// none is drawn
  double scale_check = 0;
  /// the largest label height, in drawing units: `Pattern_options::font_size`, or 1/60 of the page's
  /// smaller side
  double font_size = 0;

  explicit operator bool() const { return status == Error_code::OK; }
};


} // namespace IO
} // namespace CGAL_QD

#endif // CGAL_QD_IO_PATTERN_OPTIONS_H
