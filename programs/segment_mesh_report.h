// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What segment_mesh did, as one JSON object (nlohmann-json): what --json
// prints and report.json holds. doc/report.schema.json describes every field.

#ifndef CGAL_QD_PROGRAMS_SEGMENT_MESH_REPORT_H
#define CGAL_QD_PROGRAMS_SEGMENT_MESH_REPORT_H

#include <CGAL_QD/Error_code.h>
#include <CGAL_QD/IO/patterns_svg.h>
#include <CGAL_QD/repair_mesh.h>
#include <CGAL_QD/segment_quasi_developable.h>
#include <CGAL_QD/shorten_chart_cuts.h>
#include <CGAL_QD/smooth_segmentation_seams.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace segment_mesh {

typedef nlohmann::ordered_json Json;

// six significant digits, as a reader wants them
inline std::string text(double x)
{
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", x);
  return buffer;
}

// the same in JSON, which has no NaN or infinity
inline Json number(double x)
{
  if(!std::isfinite(x)) return nullptr;
  return std::strtod(text(x).c_str(), nullptr);
}

// what the seam smoothing and the cut shortening after it did
template <class Mesh>
struct Smoothing
{
  bool requested = false;
  std::size_t input_faces = 0;  // the faces of the mesh before the smoothing refined it
  CGAL_QD::Seam_smoothing_result<Mesh> result;  // its flattening moved into the segmentation's when kept
  bool shortening_requested = false;
  CGAL_QD::Cut_shortening_result<Mesh> shortening;  // likewise
};

// how patterns.svg (and patterns.pdf) was drawn, for report.json
struct Pattern_report
{
  const CGAL_QD::IO::Pattern_result* result = nullptr;
  std::string units;
  bool pdf = false;  // whether patterns.pdf was written too
  double seam_allowance = 0;  // in the drawing's units
  bool viewer = false;        // whether viewer.html was written
};

template <class Result, class Mesh>
Json report(const Result& r, const CGAL_QD::Repair_report& input, const Smoothing<Mesh>& smoothing,
            const Pattern_report& patterns = Pattern_report())
{
  Json j;
  j["status"] = CGAL_QD::error_message(r.status);
  j["faces"] = smoothing.result.kept ? smoothing.input_faces : r.number_of_faces;
  j["repairs"] = input.repairs();
  j["connected_components"] = input.result.connected_components;
  j["needle_faces"] = input.result.needle_faces;
  j["charts_after_vsa"] = r.charts_after_vsa;
  j["charts_after_refinement"] = r.charts_after_refinement;
  j["charts_before_merging"] = r.charts_before_merging;
  j["charts"] = r.number_of_charts;
  j["merge_trials"] = r.merging.trials;
  j["merges"] = r.merging.merges;
  j["charts_shared_out"] = r.merging.charts_shared_out;
  j["sharing_trials"] = r.merging.sharing_trials;
  j["lpfb_not_converged"] = r.merging.lpfb_not_converged;
  j["max_area_distortion_pct"] = number(r.max_area_distortion);
  j["max_l2_stretch"] = number(r.max_l2_stretch);
  j["max_local_area_distortion_pct"] = number(r.max_local_area_distortion);
  j["max_seam_length_mismatch"] = number(r.max_seam_length_mismatch);
  j["seam_curves"] = r.number_of_seam_curves;
  j["seam_curves_matched"] = r.seam_curves_matched;
  j["seam_zigzag"] = number(r.seam_zigzag);
  j["compactness"] = number(r.compactness);
  j["overlapping_charts"] = r.overlapping_charts;
  j["rejected_charts"] = r.rejected_charts;
  j["seam_length"] = number(r.seam_length);
  j["time_vsa_ms"] = number(r.time_vsa_ms);
  j["time_refine_ms"] = number(r.time_refine_ms);
  j["time_denoise_ms"] = number(r.time_denoise_ms);
  j["time_merge_ms"] = number(r.time_merge_ms);
  j["time_flatten_ms"] = number(r.time_flatten_ms);
  j["time_total_ms"] = number(r.time_total_ms);
  if(smoothing.requested) {
    const auto& s = smoothing.result;
    j["seam_smoothing"] = {{"status", CGAL_QD::error_message(s.status)},
                           {"kept", s.kept},
                           {"curves", s.number_of_curves},
                           {"curves_smoothed", s.smoothing.curves_smoothed},
                           {"curves_failed", s.smoothing.curves_failed},
                           {"zigzag_before", number(s.smoothing.zigzag_before)},
                           {"zigzag_after", number(s.smoothing.zigzag_after)},
                           {"vertices_added", s.smoothing.vertices_added},
                           {"faces_added", s.kept ? r.number_of_faces - smoothing.input_faces : 0},
                           {"rejected_charts", s.rejected_charts},
                           {"tries", s.tries},
                           {"time_ms", number(s.time_ms)}};
  }
  if(smoothing.shortening_requested) {
    const auto& c = smoothing.shortening;
    j["cut_shortening"] = {{"status", CGAL_QD::error_message(c.status)},
                           {"kept", c.kept},
                           {"cut_curves", c.cut_curves},
                           {"cuts_passing_trials", c.cuts_passing_trials},
                           {"cuts_shortened", c.cuts_shortened},
                           {"cuts_closed", c.cuts_closed},
                           {"cut_length", number(c.cut_length)},
                           {"cut_length_closed", number(c.cut_length_closed)},
                           {"trials", c.trials},
                           {"flattenings", c.flattenings},
                           {"time_ms", number(c.time_ms)}};
  }
  if(patterns.result) {
    const CGAL_QD::IO::Pattern_result& p = *patterns.result;
    j["patterns"] = {{"pages", p.number_of_pages},
                     {"units", patterns.units},
                     {"scale", number(p.scale)},
                     {"model_size", number(p.model_size)},
                     {"reduced_to_fit", p.reduced_to_fit},
                     {"oversized_pieces", p.oversized_charts},
                     {"part_pages", p.part_pages},
                     {"notches", p.notches},
                     {"left_out_pieces", p.left_out_pieces},
                     {"crowded_pieces", p.crowded_pieces},
                     {"fold_lines", p.fold_lines},
                     {"min_fold_length", number(p.min_fold_length)},
                     {"seam_allowance", number(patterns.seam_allowance)},
                     {"scale_check", number(p.scale_check)},
                     {"pdf", patterns.pdf}};
    Json seams = Json::array();
    for(const CGAL_QD::IO::Pattern_seam& seam : p.seams)
      seams.push_back({{"label", seam.label},
                       {"pieces", {seam.pieces[0], seam.pieces[1]}},
                       {"sides", {number(seam.sides[0]), number(seam.sides[1])}},
                       {"matched", seam.matched}});
    j["patterns"]["seams"] = std::move(seams);
    j["viewer"] = patterns.viewer;
    Json steps = Json::array();
    for(std::size_t i = 0; i < p.assembly.size(); ++i)
      steps.push_back({{"step", i + 1},
                       {"piece", p.assembly[i].piece},
                       {"onto", p.assembly[i].onto},
                       {"seams", p.assembly[i].seams}});
    j["assembly"] = std::move(steps);
  }
  Json charts = Json::array();
  for(std::size_t k = 0; k < r.charts.size(); ++k) {
    const CGAL_QD::Chart_report& c = r.charts[k];
    charts.push_back({{"chart", k},
                      {"status", CGAL_QD::error_message(c.status)},
                      {"faces", c.number_of_faces},
                      {"area", number(c.area)},
                      {"border_loops", c.number_of_border_loops},
                      {"area_distortion_pct", number(c.area_distortion)},
                      {"l2_stretch", number(c.l2_stretch)},
                      {"local_area_distortion_pct", number(c.local_area_distortion)},
                      {"max_border_length_error", number(c.max_border_length_error)},
                      {"flattening", c.optimized ? "ARAP" : "LPFB+IP"},
                      {"seam_lengths_matched", c.lengths_matched},
                      {"seams_matched", c.seams_matched},
                      {"compactness", number(c.compactness)},
                      {"overlap", c.overlap}});
  }
  j["per_chart"] = std::move(charts);
  return j;
}

} // namespace segment_mesh

#endif // CGAL_QD_PROGRAMS_SEGMENT_MESH_REPORT_H
