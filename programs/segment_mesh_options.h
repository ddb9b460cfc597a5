// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The command line of segment_mesh: every option with its default and unit,
// parsed by CLI11, checked, and turned into the pattern options and the named
// parameters of the segmentation.

#ifndef CGAL_QD_PROGRAMS_SEGMENT_MESH_OPTIONS_H
#define CGAL_QD_PROGRAMS_SEGMENT_MESH_OPTIONS_H

#include <CGAL_QD/IO/patterns_svg.h>
#include <CGAL_QD/chart_merging.h>
#include <CGAL_QD/optimize_flattening.h>

#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdlib>
#include <map>
#include <string>

namespace segment_mesh {

struct Options
{
  std::string mesh;
  std::string out_dir;
  // the pattern
  std::string size;  // a length with its unit, resolved once the units are known
  double scale = 0;
  std::string units = "mm";
  std::string page = "a4";
  bool tabs = false;
  bool assembly_page = true;
  bool scale_check = true;
  double fold_angle = 10;  // degrees
  std::string min_fold_length = "5%";  // a length with its unit, or a share of the model's size
  std::string notches;  // the spacing of the notches, a length with its unit
  std::string seam_allowance;  // a length with its unit
  std::string min_loose_piece = "2mm";  // a length with its unit, or 0
  // the segmentation
  double vsa_tolerance = 0.25;
  double max_area_distortion = 0.10;
  double max_stretch = 2.0;
  double max_local_area_distortion = 0.025;
  double area_preservation = 0.5;
  std::string criterion = "lpfb-ip-arap";
  std::string arap_border = "free";
  std::string merge_order = "smallest";
  double compactness_ratio = 0.6;
  bool denoise = false, refine = true, merge = true, share_out = true, shorten_cuts = true, smooth_seams = true, sequential = false;
  // the output
  bool json = false, verbose = false, quiet = false;
};

// a finite number above zero; CLI11's own conversion accepts "inf" and "nan"
inline std::string check_positive(const std::string& text)
{
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if(end == text.c_str() || *end != '\0' || !std::isfinite(value) || !(value > 0))
    return "'" + text + "' is not a positive number";
  return std::string();
}

// a finite number in [0, 1]
inline std::string check_fraction(const std::string& text)
{
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if(end == text.c_str() || *end != '\0' || !(value >= 0 && value <= 1))
    return "'" + text + "' is not a number from 0 to 1";
  return std::string();
}

// a page size in millimetres
inline bool page_size(const std::string& page, double& width, double& height)
{
  static const std::map<std::string, std::pair<double, double>> pages = {
      {"a4", {210, 297}}, {"a3", {297, 420}}, {"letter", {215.9, 279.4}}};
  const auto it = pages.find(page);
  if(it == pages.end()) return false;
  width = it->second.first;
  height = it->second.second;
  return true;
}

// the named values of the options, once they are checked
inline CGAL_QD::Chart_criterion criterion(const Options& o)
{
  return o.criterion == "lpfb-ip" ? CGAL_QD::Chart_criterion::LPFB_IP : CGAL_QD::Chart_criterion::LPFB_IP_THEN_ARAP;
}
inline CGAL_QD::Arap_border arap_border(const Options& o)
{
  return o.arap_border == "keep-lengths" ? CGAL_QD::Arap_border::KEEP_LENGTHS : CGAL_QD::Arap_border::FREE;
}
inline CGAL_QD::Merge_order merge_order(const Options& o)
{
  if(o.merge_order == "largest") return CGAL_QD::Merge_order::LARGEST_AREA_FIRST;
  if(o.merge_order == "relative") return CGAL_QD::Merge_order::LONGEST_RELATIVE_CURVE_FIRST;
  if(o.merge_order == "compact") return CGAL_QD::Merge_order::MOST_COMPACT_FIRST;
  return CGAL_QD::Merge_order::SMALLEST_AREA_FIRST;
}

// declares every option of segment_mesh on `app`, writing into `o`
inline void add_options(CLI::App& app, Options& o)
{
  app.get_formatter()->column_width(44);
  app.option_defaults()->always_capture_default();
  const CLI::Validator positive(check_positive, "POSITIVE");
  const CLI::Validator fraction(check_fraction, "0..1");

  app.add_option("mesh", o.mesh, "The triangle mesh: OFF, OBJ, PLY or STL (repaired on reading)")->required();
  app.add_option("--out-dir", o.out_dir,
                 "Write charts.ply, atlas.obj, atlas.mtl, patterns.svg, patterns.pdf (when built with cairo), "
                 "segmentation.svg, viewer.html (when built with three.js) and report.json into DIR "
                 "(created if needed)")
      ->type_name("DIR");

  const char* pattern = "Pattern (patterns.svg)";
  CLI::Option* size =
      app.add_option("--size", o.size,
                     "The model's largest dimension on the pattern (loose pieces left off by --min-loose-piece do not "
                     "count), with its unit (200mm, 20cm, 8in; a bare number is in --units). Default: 200 mm, or "
                     "less (to whole millimetres) so that every piece fits on a page; a piece larger than a page is "
                     "printed in parts, with marks to join them")
          ->type_name("LENGTH")
          ->group(pattern);
  app.add_option("--scale", o.scale, "Drawing units (--units) per mesh unit, instead of --size (default: the scale --size gives)")
      ->type_name("S")
      ->default_str("")
      ->check(positive)
      ->excludes(size)
      ->group(pattern);
  app.add_option("--units", o.units, "The unit of the drawing")
      ->check(CLI::IsMember({"mm", "cm", "in", "pt", "pc", "px"}))
      ->group(pattern);
  app.add_option("--page", o.page, "The page, portrait (a4: 210 x 297 mm, a3: 297 x 420 mm, letter: 8.5 x 11 in)")
      ->check(CLI::IsMember({"a4", "a3", "letter"}))
      ->group(pattern);
  app.add_flag("--tabs", o.tabs, "Draw a 5 mm glue tab on one side of every seam")->group(pattern);
  app.add_option("--notches", o.notches,
                 "Notches along every seam, about LENGTH apart (50mm, 2in; a bare number is in --units): the same "
                 "number on both sides of a seam, numbered, where the two sides meet. Default: none")
      ->type_name("LENGTH")
      ->group(pattern);
  app.add_option("--seam-allowance", o.seam_allowance,
                 "Cut LENGTH (6mm, 0.25in; a bare number is in --units) outside every piece, with the piece's border "
                 "dashed as the stitch line. Default: none (cut on the border)")
      ->type_name("LENGTH")
      ->group(pattern);
  app.add_option("--fold-angle", o.fold_angle,
                 "Draw fold lines on the edges inside a piece that bend more than DEGREES (for paper and card; "
                 "180: none, for fabric)")
      ->type_name("DEGREES")
      ->check(CLI::Range(0., 180.))
      ->group(pattern);
  app.add_option("--min-fold-length", o.min_fold_length,
                 "Draw fold lines where the edges that bend more than --fold-angle make a line at least LENGTH long "
                 "on the page (10mm, 0.5in; a bare number is in --units; 5%: a twentieth of the model's largest "
                 "dimension on the page, 10 mm at 200 mm, the same lines at every size), turning by at most 30 "
                 "degrees from edge to edge, or a shorter one between the cut line and other fold lines; the others "
                 "are small bends that paper takes by bending. 0: every edge that bends more than --fold-angle")
      ->type_name("LENGTH")
      ->default_str("5%")
      ->group(pattern);
  app.add_option("--min-loose-piece", o.min_loose_piece,
                 "Leave off the pattern the loose pieces (each a whole part of the mesh, sewn to no other piece) "
                 "shorter than LENGTH on the page (2mm, 0.1in; a bare number is in --units), unless that would "
                 "leave none: specks a scan leaves beside a model, too small to cut. They stay in the atlas and "
                 "the meshes. 0: every piece")
      ->type_name("LENGTH")
      ->default_str("2mm")
      ->group(pattern);
  app.add_flag("!--no-assembly-page", o.assembly_page,
               "Leave out the last page, which lists the order in which to join the pieces")
      ->group(pattern);
  app.add_flag("!--no-scale-check", o.scale_check,
               "Leave out the bars in the bottom-left corner of every page (50 mm, or 2 in with --units in) that "
               "measure whether the pattern printed at its real size")
      ->group(pattern);

  const char* segmentation = "Segmentation";
  app.add_option("--vsa-tolerance", o.vsa_tolerance,
                 "How planar the charts of step 1 are: the L2,1 error of a chart against its proxy, relative to "
                 "its area (no unit)")
      ->type_name("T")
      ->check(positive)
      ->group(segmentation);
  app.add_option("--max-area-distortion", o.max_area_distortion,
                 "The largest area distortion A(Omega) of a chart, as a fraction (0.10 is 10 %)")
      ->type_name("A")
      ->check(positive)
      ->group(segmentation);
  app.add_option("--max-stretch", o.max_stretch, "The largest L2 stretch of a chart (1 is none)")
      ->type_name("L2")
      ->check(positive)
      ->group(segmentation);
  app.add_option("--max-local-area-distortion", o.max_local_area_distortion,
                 "The largest local area distortion A_loc of a chart, as a fraction (0.025 is 2.5 %; not used "
                 "by --criterion lpfb-ip)")
      ->type_name("A_LOC")
      ->check(positive)
      ->group(segmentation);
  app.add_option("--criterion", o.criterion,
                 "How a chart is flattened and judged: lpfb-ip-arap (LPFB+IP, then free-boundary ARAP, with "
                 "A_loc) or lpfb-ip (the paper's: LPFB+IP with A(Omega) and L2)")
      ->check(CLI::IsMember({"lpfb-ip-arap", "lpfb-ip"}))
      ->group(segmentation);
  app.add_option("--area-preservation", o.area_preservation,
                 "How much of its anisotropy each triangle keeps in the targets of the ARAP flattening: 0 is "
                 "plain ARAP (rotations), 1 area-preserving targets; more trades a little shear for less area "
                 "distortion")
      ->type_name("ALPHA")
      ->check(fraction)
      ->group(segmentation);
  app.add_option("--arap-border", o.arap_border,
                 "The border of the ARAP flattening of a trial: free, or keep-lengths (pulled to its 3D lengths)")
      ->check(CLI::IsMember({"free", "keep-lengths"}))
      ->group(segmentation);
  app.add_option("--merge-order", o.merge_order,
                 "Which border the merging tries first: smallest (the two smallest charts), largest (the "
                 "paper's), relative (the longest border for its charts' size), compact (the roundest result)")
      ->check(CLI::IsMember({"smallest", "largest", "relative", "compact"}))
      ->group(segmentation);
  app.add_option("--compactness-ratio", o.compactness_ratio,
                 "Try to join two charts only where the joined piece keeps at least RHO of the compactness "
                 "(4 pi area / perimeter^2) of the less compact of the two: rounder pieces rather than sprawling "
                 "ones; 0 tries every join (the paper's merging)")
      ->type_name("RHO")
      ->check(fraction)
      ->group(segmentation);
  app.add_flag("--denoise,!--no-denoise", o.denoise, "Denoise the chart borders (step 3; off by default)")
      ->group(segmentation);
  app.add_flag("!--no-refine", o.refine, "Skip the minimum-cut refinement of the chart borders (step 2)")
      ->group(segmentation);
  app.add_flag("!--no-merge", o.merge, "Skip the merging (step 4): the charts of steps 1 to 3, split where they fail")
      ->group(segmentation);
  app.add_flag("!--no-share-out", o.share_out,
               "Keep the small charts that the merging leaves instead of sharing them out among their neighbours "
               "(never done with --criterion lpfb-ip)")
      ->group(segmentation);
  app.add_flag("!--no-shorten-cuts", o.shorten_cuts,
               "Keep the cuts inside the pieces as the merging leaves them instead of closing them where the piece "
               "still passes without them (never done with --criterion lpfb-ip)")
      ->group(segmentation);
  app.add_flag("!--no-smooth-seams", o.smooth_seams,
               "Keep the seams along the triangle edges instead of smoothing them through the triangles")
      ->group(segmentation);
  app.add_flag("--sequential", o.sequential, "One thread (the result is the same)")->group(segmentation);

  const char* output = "Output";
  app.add_flag("--json", o.json, "Print one JSON object (doc/report.schema.json) instead of the summary")
      ->group(output);
  app.add_flag("--verbose", o.verbose, "Print every step and every merging trial on standard error")->group(output);
  app.add_flag("--quiet", o.quiet, "No progress bar")->group(output);
}

} // namespace segment_mesh

#endif // CGAL_QD_PROGRAMS_SEGMENT_MESH_OPTIONS_H
