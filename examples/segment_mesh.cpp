// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Segments a triangle mesh into quasi-developable charts (error-controlled VSA,
// minimum-cut refinement, optional denoising, LPFB-based merging) and prints
// what every step did, or one JSON object with --json. With --out-dir it
// writes charts.ply (a colour and chart id per face), atlas.obj with atlas.mtl
// (every chart flattened and packed into the unit square), patterns.svg
// (every chart at true scale on pages, to print and cut) and segmentation.svg
// (a picture of the mesh in its chart colours) and report.json (what --json
// prints). The mesh is read and repaired by CGAL_QD::IO::read_and_repair_mesh()
// (duplicated points merged, orientation made consistent, non-manifold
// vertices split, polygons triangulated, degenerate faces removed), and the
// summary says what was repaired; a file that cannot be used gives a message
// saying why, exit code 1 and no output file. On a terminal a progress bar runs on standard error unless
// --quiet.
//
// The seams of the segmentation follow triangle edges; by default
// CGAL_QD::smooth_segmentation_seams() then replaces them by smooth curves
// through the triangles wherever every chart stays within the thresholds and
// every seam whose sides matched in length still does, and the outputs are
// written from the refined mesh (--no-smooth-seams keeps the edge seams).
//
// patterns.svg is drawn at --scale drawing units (--units, mm by default) per
// mesh unit, or with the model's largest dimension --size (200mm, 20cm, 8in);
// without either, the model is 200 mm at its largest, or less (to whole
// millimetres) so that every piece fits on a page, and the summary says which.
// --page, the margins, the spacing and the tabs are in millimetres whatever
// --units is.
//
// usage: segment_mesh <mesh> [--out-dir DIR] [--size 200mm | --scale S] [--units mm|cm|in|pt|pc|px]
//                     [--page a4|a3|letter] [--tabs] [--vsa-tolerance T] [--max-area-distortion 0.10]
//                     [--max-stretch 2.0] [--max-local-area-distortion 0.025]
//                     [--criterion lpfb-ip-arap|lpfb-ip] [--arap-border free|keep-lengths]
//                     [--denoise | --no-denoise] [--no-refine] [--no-merge] [--no-smooth-seams]
//                     [--merge-order largest|smallest|relative|compact] [--sequential]
//                     [--json] [--verbose] [--quiet]

#include <CGAL_QD/IO/charts_and_atlas.h>
#include <CGAL_QD/IO/patterns_svg.h>
#include <CGAL_QD/IO/read_mesh.h>
#include <CGAL_QD/IO/segmentation_svg.h>
#include <CGAL_QD/pack_charts.h>
#include <CGAL_QD/segment_quasi_developable.h>
#include <CGAL_QD/smooth_segmentation_seams.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <cstring>
#include <functional>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <set>
#include <string>

#include <unistd.h>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

namespace {

int usage()
{
  std::cerr << "usage: segment_mesh <mesh> [--out-dir DIR] [--size 200mm | --scale S] [--units mm|cm|in|pt|pc|px]\n"
               "                    [--page a4|a3|letter] [--tabs]\n"
               "                    [--vsa-tolerance T] [--max-area-distortion 0.10] [--max-stretch 2.0]\n"
               "                    [--max-local-area-distortion 0.025] [--criterion lpfb-ip-arap|lpfb-ip]\n"
               "                    [--arap-border free|keep-lengths]\n"
               "                    [--denoise | --no-denoise] [--no-refine] [--no-merge] [--no-smooth-seams]\n"
               "                    [--merge-order largest|smallest|relative|compact]\n"
               "                    [--sequential] [--json] [--verbose] [--quiet]\n";
  return EXIT_FAILURE;
}

bool read_number(int& i, int argc, char** argv, double& value)
{
  if(i + 1 >= argc) return false;
  char* end = nullptr;
  value = std::strtod(argv[++i], &end);
  return end != argv[i] && *end == '\0' && std::isfinite(value) && value > 0;
}

// JSON has no NaN or infinity
std::string number(double x)
{
  if(!std::isfinite(x)) return "null";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", x);
  return buffer;
}

// what the seam smoothing did
struct Smoothing
{
  bool requested = false;
  std::size_t input_faces = 0;  // the faces of the mesh before the smoothing refined it
  CGAL_QD::Seam_smoothing_result<Mesh> result;  // its flattening moved into the segmentation's when kept
};

template <class Result>
void print_json(std::ostream& out, const Result& r, const CGAL_QD::Repair_report& input, const Smoothing& smoothing,
                const CGAL_QD::IO::Pattern_result* patterns = nullptr, const std::string& units = std::string())
{
  out << "{\"status\": \"" << CGAL_QD::error_message(r.status) << "\", \"faces\": "
      << (smoothing.result.kept ? smoothing.input_faces : r.number_of_faces)
            << ", \"repairs\": [";
  const std::vector<std::string> repairs = input.repairs();
  for(std::size_t k = 0; k < repairs.size(); ++k) out << (k ? ", " : "") << '"' << repairs[k] << '"';
  out << "], \"connected_components\": " << input.result.connected_components
            << ", \"needle_faces\": " << input.result.needle_faces
            << ", \"charts_after_vsa\": " << r.charts_after_vsa
            << ", \"charts_after_refinement\": " << r.charts_after_refinement
            << ", \"charts_before_merging\": " << r.charts_before_merging << ", \"charts\": " << r.number_of_charts
            << ", \"merge_trials\": " << r.merging.trials << ", \"merges\": " << r.merging.merges
            << ", \"max_area_distortion_pct\": " << number(r.max_area_distortion)
            << ", \"max_l2_stretch\": " << number(r.max_l2_stretch)
            << ", \"max_local_area_distortion_pct\": " << number(r.max_local_area_distortion)
            << ", \"max_seam_length_mismatch\": " << number(r.max_seam_length_mismatch)
            << ", \"seam_curves\": " << r.number_of_seam_curves << ", \"seam_curves_matched\": " << r.seam_curves_matched
            << ", \"seam_zigzag\": " << number(r.seam_zigzag) << ", \"compactness\": " << number(r.compactness)
            << ", \"overlapping_charts\": " << r.overlapping_charts << ", \"rejected_charts\": " << r.rejected_charts
            << ", \"seam_length\": " << number(r.seam_length) << ", \"time_vsa_ms\": " << number(r.time_vsa_ms)
            << ", \"time_refine_ms\": " << number(r.time_refine_ms)
            << ", \"time_denoise_ms\": " << number(r.time_denoise_ms)
            << ", \"time_merge_ms\": " << number(r.time_merge_ms)
            << ", \"time_flatten_ms\": " << number(r.time_flatten_ms)
            << ", \"time_total_ms\": " << number(r.time_total_ms);
  if(smoothing.requested)
    out << ", \"seam_smoothing\": {\"kept\": " << (smoothing.result.kept ? "true" : "false")
        << ", \"curves\": " << smoothing.result.number_of_curves
        << ", \"curves_smoothed\": " << smoothing.result.smoothing.curves_smoothed
        << ", \"curves_failed\": " << smoothing.result.smoothing.curves_failed
        << ", \"zigzag_before\": " << number(smoothing.result.smoothing.zigzag_before)
        << ", \"zigzag_after\": " << number(smoothing.result.smoothing.zigzag_after)
        << ", \"vertices_added\": " << smoothing.result.smoothing.vertices_added
        << ", \"faces_added\": " << (smoothing.result.kept ? r.number_of_faces - smoothing.input_faces : 0)
        << ", \"rejected_charts\": " << smoothing.result.rejected_charts << ", \"tries\": " << smoothing.result.tries
        << ", \"time_ms\": " << number(smoothing.result.time_ms) << "}";
  if(patterns)  // in report.json: how patterns.svg was drawn
    out << ", \"patterns\": {\"pages\": " << patterns->number_of_pages << ", \"units\": \"" << units
        << "\", \"scale\": " << number(patterns->scale) << ", \"model_size\": " << number(patterns->model_size)
        << ", \"reduced_to_fit\": " << (patterns->reduced_to_fit ? "true" : "false")
        << ", \"oversized_pieces\": " << patterns->oversized_charts << "}";
  out << ", \"per_chart\": [";
  for(std::size_t k = 0; k < r.charts.size(); ++k) {
    const CGAL_QD::Chart_report& c = r.charts[k];
    out << (k ? ", " : "") << "{\"chart\": " << k << ", \"status\": \"" << CGAL_QD::error_message(c.status)
              << "\", \"faces\": " << c.number_of_faces << ", \"area\": " << number(c.area)
              << ", \"border_loops\": " << c.number_of_border_loops
              << ", \"area_distortion_pct\": " << number(c.area_distortion)
              << ", \"l2_stretch\": " << number(c.l2_stretch)
              << ", \"local_area_distortion_pct\": " << number(c.local_area_distortion)
              << ", \"max_border_length_error\": " << number(c.max_border_length_error)
              << ", \"flattening\": \"" << (c.optimized ? "ARAP" : "LPFB+IP") << '"'
              << ", \"seam_lengths_matched\": " << (c.lengths_matched ? "true" : "false")
              << ", \"seams_matched\": " << (c.seams_matched ? "true" : "false")
              << ", \"overlap\": " << (c.overlap ? "true" : "false")
              << "}";
  }
  out << "]}\n";
}

} // namespace

int main(int argc, char** argv)
{
  if(argc < 2) return usage();
  const std::string path = argv[1];
  double vsa_tolerance = 0.25, max_area = 0.10, max_stretch = 2.0, max_local = 0.025;
  CGAL_QD::Chart_criterion criterion = CGAL_QD::Chart_criterion::LPFB_IP_THEN_ARAP;
  bool json = false, verbose = false, quiet = false, denoise = false, refine = true, merge = true, sequential = false,
       smooth_seams = true;
  CGAL_QD::Merge_order order = CGAL_QD::Merge_order::SMALLEST_AREA_FIRST;
  CGAL_QD::Arap_border arap_border = CGAL_QD::Arap_border::FREE;
  std::string out_dir;
  CGAL_QD::IO::Pattern_options pattern;
  std::string size;  // --size, resolved once the units are known
  double page_mm[2] = {210, 297};
  for(int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    if(a == "--json") json = true;
    else if(a == "--verbose") verbose = true;
    else if(a == "--quiet") quiet = true;
    else if(a == "--denoise") denoise = true;
    else if(a == "--no-denoise") denoise = false;  // the default
    else if(a == "--no-refine") refine = false;
    else if(a == "--no-merge") merge = false;
    else if(a == "--no-smooth-seams") smooth_seams = false;
    else if(a == "--sequential") sequential = true;
    else if(a == "--out-dir" && i + 1 < argc) out_dir = argv[++i];
    else if(a == "--scale") { if(!read_number(i, argc, argv, pattern.scale)) return usage(); }
    else if(a == "--size" && i + 1 < argc) size = argv[++i];
    else if(a == "--units" && i + 1 < argc) pattern.units = argv[++i];
    else if(a == "--tabs") pattern.tabs = true;
    else if(a == "--page" && i + 1 < argc) {
      const std::string page = argv[++i];
      if(page == "a4") page_mm[0] = 210, page_mm[1] = 297;
      else if(page == "a3") page_mm[0] = 297, page_mm[1] = 420;
      else if(page == "letter") page_mm[0] = 215.9, page_mm[1] = 279.4;
      else return usage();
    }
    else if(a == "--merge-order" && i + 1 < argc) {
      const std::string o = argv[++i];
      if(o == "largest") order = CGAL_QD::Merge_order::LARGEST_AREA_FIRST;
      else if(o == "smallest") order = CGAL_QD::Merge_order::SMALLEST_AREA_FIRST;
      else if(o == "relative") order = CGAL_QD::Merge_order::LONGEST_RELATIVE_CURVE_FIRST;
      else if(o == "compact") order = CGAL_QD::Merge_order::MOST_COMPACT_FIRST;
      else return usage();
    }
    else if(a == "--vsa-tolerance") { if(!read_number(i, argc, argv, vsa_tolerance)) return usage(); }
    else if(a == "--max-area-distortion") { if(!read_number(i, argc, argv, max_area)) return usage(); }
    else if(a == "--max-stretch") { if(!read_number(i, argc, argv, max_stretch)) return usage(); }
    else if(a == "--max-local-area-distortion") { if(!read_number(i, argc, argv, max_local)) return usage(); }
    else if(a == "--criterion" && i + 1 < argc) {
      const std::string c = argv[++i];
      if(c == "lpfb-ip-arap") criterion = CGAL_QD::Chart_criterion::LPFB_IP_THEN_ARAP;
      else if(c == "lpfb-ip") criterion = CGAL_QD::Chart_criterion::LPFB_IP;
      else return usage();
    }
    else if(a == "--arap-border" && i + 1 < argc) {
      const std::string b = argv[++i];
      if(b == "free") arap_border = CGAL_QD::Arap_border::FREE;
      else if(b == "keep-lengths") arap_border = CGAL_QD::Arap_border::KEEP_LENGTHS;
      else return usage();
    }
    else return usage();
  }
  // the page, its margin, the spacing and the tabs are given in millimetres:
  // into the drawing's units
  const double mm_per_unit = CGAL_QD::IO::millimetres_per_unit(pattern.units);
  if(mm_per_unit == 0) {
    std::cerr << "segment_mesh: --units " << pattern.units << " is not one of mm, cm, in, pt, pc, px\n";
    return EXIT_FAILURE;
  }
  pattern.page_width = page_mm[0] / mm_per_unit;
  pattern.page_height = page_mm[1] / mm_per_unit;
  pattern.page_margin /= mm_per_unit;
  pattern.spacing /= mm_per_unit;
  pattern.tab_width /= mm_per_unit;
  if(!size.empty()) {
    // a length with its unit (200mm, 20cm, 8in), or a number in the drawing's units
    char* end = nullptr;
    const double value = std::strtod(size.c_str(), &end);
    const std::string unit = end == size.c_str() ? std::string() : std::string(end);
    const double factor = unit.empty() ? 1. : CGAL_QD::IO::millimetres_per_unit(unit) / mm_per_unit;
    if(end == size.c_str() || !(factor > 0) || !std::isfinite(value) || !(value > 0) || pattern.scale > 0) {
      std::cerr << "segment_mesh: --size " << size
                << (pattern.scale > 0 ? " and --scale cannot be given together"
                                      : " is not a positive length such as 200mm, 20cm or 8in")
                << "\n";
      return EXIT_FAILURE;
    }
    pattern.model_size = value * factor;
  }

  // reading and repairs in one place: say what was repaired, or what is wrong
  Mesh mesh;
  const CGAL_QD::Repair_report input = CGAL_QD::IO::read_and_repair_mesh(path, mesh);
  if(!input) {
    std::cerr << "segment_mesh: cannot use '" << path << "': " << input.message << " ("
              << CGAL_QD::error_message(input.status) << ")\n";
    return EXIT_FAILURE;
  }
  std::string repaired;
  for(const std::string& line : input.repairs()) repaired += "  repaired       " + line + "\n";
  if(input.result.needle_faces > 0)
    repaired += "  warning        " + std::to_string(input.result.needle_faces) +
                " needle faces (longest edge over 1000 times the shortest) are kept\n";
  // a progress bar on a terminal
  const bool bar = !quiet && !json && !verbose && isatty(fileno(stderr));
  auto progress = [&](const char* step, double done) {
    if(!bar) return;
    const int width = 30, filled = static_cast<int>(done * width + 0.5);
    std::fprintf(stderr, "\r%-8s [%s%s] %3d%%", step, std::string(filled, '#').c_str(),
                 std::string(width - filled, ' ').c_str(), static_cast<int>(100 * done + 0.5));
    std::fflush(stderr);
  };

  auto chart = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:chart", 0).first;
  namespace QP = CGAL_QD::parameters;
  // CGAL_QD's parameters take the rest of the pack as a second argument
  const auto np = QP::arap_border(arap_border, QP::max_local_area_distortion(max_local, QP::chart_criterion(criterion, QP::vsa_tolerance(
      vsa_tolerance,
      QP::max_area_distortion(
          max_area, QP::max_l2_stretch(
                        max_stretch, QP::denoise_boundaries(
                                         denoise, QP::refine_boundaries(
                                                      refine, QP::merge_charts(
                                                                  merge, QP::merge_order(
                                                                             order, CGAL::parameters::verbose(verbose).callback(
                                                                                        std::function<void(const char*, double)>(
                                                                                            progress))))))))))));
  CGAL_QD::Segmentation_result<Mesh> r =
      sequential ? CGAL_QD::segment_quasi_developable<CGAL::Sequential_tag>(mesh, chart, np)
                 : CGAL_QD::segment_quasi_developable<CGAL::Parallel_if_available_tag>(mesh, chart, np);
  // smooth seams through the triangles, on a copy of the mesh kept only if
  // every chart still flattens within the thresholds and every seam that
  // matched in length still does (CGAL_QD::smooth_segmentation_seams())
  Smoothing smoothing;
  Mesh smoothed;
  if(r && smooth_seams && r.number_of_charts > 1) {
    smoothing.requested = true;
    smoothing.input_faces = r.number_of_faces;
    auto smoothed_chart = smoothed.add_property_map<Mesh::Face_index, std::size_t>("f:chart", 0).first;
    const auto snp = QP::max_local_area_distortion(
        max_local, QP::chart_criterion(criterion, QP::max_area_distortion(max_area, QP::max_l2_stretch(max_stretch))));
    CGAL_QD::Seam_smoothing_result<Mesh>& s = smoothing.result;
    s = sequential ? CGAL_QD::smooth_segmentation_seams<CGAL::Sequential_tag>(mesh, chart, r, smoothed, smoothed_chart, snp)
                   : CGAL_QD::smooth_segmentation_seams<CGAL::Parallel_if_available_tag>(mesh, chart, r, smoothed,
                                                                                         smoothed_chart, snp);
    if(s.kept) {
      const double total = r.time_total_ms + s.time_ms;
      static_cast<CGAL_QD::Chart_flattening_result<Mesh>&>(r) = std::move(s.flattening);
      r.time_total_ms = total;
    }
  }
  const Mesh& out_mesh = smoothing.result.kept ? smoothed : mesh;
  const auto out_chart = out_mesh.property_map<Mesh::Face_index, std::size_t>("f:chart").first;
  if(bar) std::fprintf(stderr, "\r%60s\r", "");
  std::string written;
  CGAL_QD::IO::Pattern_result pages;
  if(r && !out_dir.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(out_dir, ec);
    const std::filesystem::path dir(out_dir);
    const CGAL_QD::Atlas_result atlas = CGAL_QD::pack_charts(out_mesh, out_chart, r.corner_uv);
    std::ofstream ply(dir / "charts.ply"), obj(dir / "atlas.obj"), mtl(dir / "atlas.mtl"), svg(dir / "patterns.svg"),
        picture(dir / "segmentation.svg"), report(dir / "report.json");
    const bool ok = !ec && atlas && CGAL_QD::IO::write_PLY_with_charts(ply, out_mesh, out_chart) &&
                    CGAL_QD::IO::write_OBJ_with_uv(obj, out_mesh, atlas.corner_uv, "atlas.mtl", "atlas") &&
                    (mtl << "# the material of atlas.obj\nnewmtl atlas\nKd 0.8 0.8 0.8\nKa 0 0 0\nKs 0 0 0\n") &&
                    (pages = CGAL_QD::IO::write_patterns_SVG(svg, out_mesh, out_chart, r.corner_uv, r.seam_edges, pattern)) &&
                    CGAL_QD::IO::write_segmentation_SVG(picture, out_mesh, out_chart, r.seam_edges) == CGAL_QD::Error_code::OK &&
                    (print_json(report, r, input, smoothing, &pages, pattern.units), bool(report));
    if(!ok) {
      std::cerr << "segment_mesh: cannot write into '" << out_dir << "'\n";
      return EXIT_FAILURE;
    }
    std::ostringstream message;
    message << "  wrote charts.ply, atlas.obj, atlas.mtl (atlas coverage " << atlas.coverage << "), patterns.svg ("
            << pages.number_of_pages << (pages.number_of_pages == 1 ? " page" : " pages") << ", the model "
            << number(pages.model_size) << ' ' << pattern.units << " at its largest, " << number(pages.scale) << ' '
            << pattern.units << " per mesh unit";
    if(pages.reduced_to_fit)
      message << ", less than " << number(200 / mm_per_unit) << ' ' << pattern.units
              << " so that every piece fits on a page";
    if(pattern.scale == 0 && pattern.model_size == 0) message << "; --size or --scale to change";
    if(pages.oversized_charts > 0) message << ", " << pages.oversized_charts << " pieces larger than a page";
    message << "), segmentation.svg and report.json into " << dir.string() << "\n";
    written = message.str();
  }
  if(json) {
    print_json(std::cout, r, input, smoothing);
    return r ? EXIT_SUCCESS : EXIT_FAILURE;
  }
  if(!r) {
    std::cerr << "segment_mesh: " << CGAL_QD::error_message(r.status) << "\n";
    return EXIT_FAILURE;
  }
  std::cout << path << ": " << (smoothing.result.kept ? smoothing.input_faces : r.number_of_faces) << " faces\n"
            << repaired
            << "  VSA            " << r.charts_after_vsa << " charts, " << r.time_vsa_ms << " ms\n"
            << "  refinement     " << r.charts_after_refinement << " charts, " << r.time_refine_ms << " ms\n"
            << "  denoising      " << (denoise ? std::to_string(r.time_denoise_ms) + " ms" : std::string("off"))
            << "\n"
            << "  merging        " << r.charts_before_merging << " -> " << r.number_of_charts << " charts, "
            << r.merging.trials << " trials, " << r.time_merge_ms << " ms\n"
            << "  flattening     " << r.time_flatten_ms << " ms\n"
            << "  max A(Omega)   " << r.max_area_distortion << " %\n"
            << "  max L2         " << r.max_l2_stretch << "\n"
            << "  max A_loc      " << r.max_local_area_distortion << " %\n"
            << "  overlapping    " << r.overlapping_charts << " charts\n"
            << "  seam length    " << r.seam_length << ", zigzag " << r.seam_zigzag << ", sides within 0.5 % on "
            << r.seam_curves_matched << " of " << r.number_of_seam_curves << " curves, at most "
            << 100 * r.max_seam_length_mismatch << " % apart\n"
            << "  compactness    " << r.compactness << "\n"
            << "  smooth seams   "
            << (!smoothing.requested ? std::string("off")
                : smoothing.result.kept
                    ? std::to_string(smoothing.result.smoothing.curves_smoothed) + " of " +
                          std::to_string(smoothing.result.number_of_curves) + " curves through the triangles (" +
                          std::to_string(r.number_of_faces - smoothing.input_faces) + " faces added), zigzag " +
                          number(smoothing.result.smoothing.zigzag_before) + " -> " +
                          number(smoothing.result.smoothing.zigzag_after)
                    : smoothing.result.smoothing.curves_smoothed == 0
                        ? std::string("no curve could be smoothed; seams follow the triangle edges")
                        : std::to_string(smoothing.result.rejected_charts) +
                              " charts beyond the thresholds once smoothed; seams follow the triangle edges")
            << "\n"
            << "  total          " << r.time_total_ms << " ms\n"
            << written;
  return EXIT_SUCCESS;
}
