// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// segment_mesh: cuts a triangle mesh into quasi-developable pieces and writes
// what a maker needs to build it from paper, felt or fabric, or a texture atlas.
//
// It reads and repairs the mesh (CGAL_QD::IO::read_and_repair_mesh()), segments
// it (CGAL_QD::segment_quasi_developable(): error-controlled VSA, minimum-cut
// refinement, optional denoising, merging judged by LPFB+IP and ARAP), smooths
// the seams through the triangles where every piece stays within the
// thresholds (CGAL_QD::smooth_segmentation_seams()), and prints what every step
// did, or one JSON object with --json. With --out-dir it writes charts.ply,
// atlas.obj with atlas.mtl, patterns.svg and, when built with cairo,
// patterns.pdf (every piece at a real size on pages), segmentation.svg and
// report.json; all of them or, if one cannot be written,
// none. A file that cannot be used, or a bad option, gives a message that says
// what is wrong, exit code 1 and no output. `segment_mesh --help` lists every
// option with its default and unit.

#include "segment_mesh_options.h"
#include "segment_mesh_report.h"

#include <CGAL_QD/IO/charts_and_atlas.h>
#include <CGAL_QD/IO/patterns_svg.h>
#ifdef CGAL_QD_HAS_CAIRO
#include <CGAL_QD/IO/patterns_pdf.h>
#endif
#include <CGAL_QD/IO/read_mesh.h>
#include <CGAL_QD/IO/segmentation_svg.h>
#include <CGAL_QD/pack_charts.h>
#include <CGAL_QD/segment_quasi_developable.h>
#include <CGAL_QD/smooth_segmentation_seams.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <unistd.h>

#ifndef CGAL_QD_VERSION
#define CGAL_QD_VERSION "unknown"
#endif

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

namespace {

int fail(const std::string& message)
{
  std::cerr << "segment_mesh: " << message << "\n";
  return EXIT_FAILURE;
}

// Files written next to their final names and renamed into place together
// once every one is complete: a failed run leaves none of its files behind
// (those of an earlier run into the same directory stay as they were).
class Output_files
{
public:
  explicit Output_files(const std::filesystem::path& dir) : m_dir(dir) {}
  ~Output_files() { discard(); }

  // the directory, created if needed; otherwise why not
  std::string open()
  {
    std::error_code ec;
    m_created = !std::filesystem::exists(m_dir, ec) && std::filesystem::create_directories(m_dir, ec);
    if(ec) return ec.message();
    if(!std::filesystem::is_directory(m_dir, ec)) return "it is not a directory";
    return std::string();
  }
  std::ofstream& file(const std::string& name)
  {
    m_names.push_back(name);
    m_streams.emplace_back(new std::ofstream(part(name), std::ios::binary));
    return *m_streams.back();
  }
  // true if every file was written and moved into place
  bool commit()
  {
    for(auto& s : m_streams) {
      s->close();
      if(!*s) return false;
    }
    std::error_code ec;
    for(const std::string& name : m_names) {
      std::filesystem::rename(part(name), m_dir / name, ec);
      if(ec) return false;
      m_moved.push_back(name);
    }
    m_names.clear();
    m_moved.clear();
    m_created = false;
    return true;
  }

private:
  std::filesystem::path part(const std::string& name) const { return m_dir / ("." + name + ".part"); }
  void discard()
  {
    std::error_code ec;
    m_streams.clear();
    for(const std::string& name : m_names) std::filesystem::remove(part(name), ec);
    for(const std::string& name : m_moved) std::filesystem::remove(m_dir / name, ec);  // a half-done commit
    if(m_created) std::filesystem::remove(m_dir, ec);  // only if it is empty again
  }

  std::filesystem::path m_dir;
  bool m_created = false;
  std::vector<std::string> m_names, m_moved;
  std::vector<std::unique_ptr<std::ofstream>> m_streams;
};

} // namespace

int main(int argc, char** argv)
{
  segment_mesh::Options o;
  CLI::App app("Cuts a triangle mesh into quasi-developable pieces, flattens each with almost no stretch, and "
               "writes them as patterns to print and cut, a texture atlas, pictures and a report.",
               "segment_mesh");
  app.set_version_flag("--version", std::string("segment_mesh (CGAL_QD) ") + CGAL_QD_VERSION);
  app.footer("Example: segment_mesh fandisk.off --out-dir out --size 150mm --tabs");
  segment_mesh::add_options(app, o);
  try {
    app.parse(argc, argv);
  } catch(const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch(const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch(const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch(const CLI::ParseError& e) {
    std::cerr << "segment_mesh: " << e.what() << "\nRun with --help for every option.\n";
    return EXIT_FAILURE;
  }

  // the page, its margin, the spacing and the tabs are given in millimetres:
  // into the drawing's units
  CGAL_QD::IO::Pattern_options pattern;
  pattern.units = o.units;
  pattern.scale = o.scale;
  pattern.tabs = o.tabs;
  pattern.assembly_page = o.assembly_page;
  pattern.fold_angle = o.fold_angle * 3.141592653589793 / 180;
  const double mm_per_unit = CGAL_QD::IO::millimetres_per_unit(pattern.units);
  double page_mm[2] = {210, 297};
  segment_mesh::page_size(o.page, page_mm[0], page_mm[1]);
  pattern.page_width = page_mm[0] / mm_per_unit;
  pattern.page_height = page_mm[1] / mm_per_unit;
  pattern.page_margin /= mm_per_unit;
  pattern.spacing /= mm_per_unit;
  pattern.tab_width /= mm_per_unit;
  // a length with its unit (200mm, 20cm, 8in), or a number in the drawing's units; 0 if it is not one
  auto length = [&](const std::string& text) {
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    const std::string unit = end == text.c_str() ? std::string() : std::string(end);
    const double factor = unit.empty() ? 1. : CGAL_QD::IO::millimetres_per_unit(unit) / mm_per_unit;
    return end == text.c_str() || !(factor > 0) || !std::isfinite(value) || !(value > 0) ? 0. : value * factor;
  };
  if(!o.size.empty() && !((pattern.model_size = length(o.size)) > 0))
    return fail("--size: '" + o.size + "' is not a positive length such as 200mm, 20cm or 8in");
  if(!o.notches.empty() && !((pattern.notch_spacing = length(o.notches)) > 0))
    return fail("--notches: '" + o.notches + "' is not a positive length such as 50mm or 2in");
  if(!o.seam_allowance.empty() && !((pattern.seam_allowance = length(o.seam_allowance)) > 0))
    return fail("--seam-allowance: '" + o.seam_allowance + "' is not a positive length such as 6mm or 0.25in");
#ifndef CGAL_QD_HAS_CLIPPER
  if(pattern.seam_allowance > 0)
    return fail("--seam-allowance: this segment_mesh was built without Clipper (libpolyclipping-dev)");
#endif

  // reading and repairs in one place: say what was repaired, or what is wrong
  Mesh mesh;
  const CGAL_QD::Repair_report input = CGAL_QD::IO::read_and_repair_mesh(o.mesh, mesh);
  if(!input)
    return fail("cannot use '" + o.mesh + "': " + input.message + " (" + CGAL_QD::error_message(input.status) + ")");
  std::string repaired;
  for(const std::string& line : input.repairs()) repaired += "  repaired       " + line + "\n";
  if(input.result.needle_faces > 0)
    repaired += "  warning        " + std::to_string(input.result.needle_faces) +
                " needle faces (longest edge over 1000 times the shortest) are kept\n";
  // a progress bar on a terminal
  const bool bar = !o.quiet && !o.json && !o.verbose && isatty(fileno(stderr));
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
  const auto np = QP::arap_border(
      segment_mesh::arap_border(o),
      QP::max_local_area_distortion(
          o.max_local_area_distortion,
          QP::chart_criterion(
              segment_mesh::criterion(o),
              QP::vsa_tolerance(
                  o.vsa_tolerance,
                  QP::max_area_distortion(
                      o.max_area_distortion,
                      QP::max_l2_stretch(
                          o.max_stretch,
                          QP::denoise_boundaries(
                              o.denoise,
                              QP::refine_boundaries(
                                  o.refine,
                                  QP::merge_charts(
                                      o.merge,
                                      QP::merge_order(segment_mesh::merge_order(o),
                                                      CGAL::parameters::verbose(o.verbose).callback(
                                                          std::function<void(const char*, double)>(progress))))))))))));
  CGAL_QD::Segmentation_result<Mesh> r =
      o.sequential ? CGAL_QD::segment_quasi_developable<CGAL::Sequential_tag>(mesh, chart, np)
                   : CGAL_QD::segment_quasi_developable<CGAL::Parallel_if_available_tag>(mesh, chart, np);
  // smooth seams through the triangles, on a copy of the mesh kept only if
  // every chart still flattens within the thresholds and every seam that
  // matched in length still does (CGAL_QD::smooth_segmentation_seams())
  segment_mesh::Smoothing<Mesh> smoothing;
  Mesh smoothed;
  if(r && o.smooth_seams && r.number_of_charts > 1) {
    smoothing.requested = true;
    smoothing.input_faces = r.number_of_faces;
    auto smoothed_chart = smoothed.add_property_map<Mesh::Face_index, std::size_t>("f:chart", 0).first;
    const auto snp = QP::max_local_area_distortion(
        o.max_local_area_distortion,
        QP::chart_criterion(segment_mesh::criterion(o),
                            QP::max_area_distortion(o.max_area_distortion, QP::max_l2_stretch(o.max_stretch))));
    CGAL_QD::Seam_smoothing_result<Mesh>& s = smoothing.result;
    s = o.sequential
            ? CGAL_QD::smooth_segmentation_seams<CGAL::Sequential_tag>(mesh, chart, r, smoothed, smoothed_chart, snp)
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
  if(!r) {
    if(o.json) std::cout << segment_mesh::report(r, input, smoothing).dump() << "\n";
    return fail(CGAL_QD::error_message(r.status));
  }

  std::string written;
  if(!o.out_dir.empty()) {
    const std::filesystem::path dir(o.out_dir);
    Output_files files(dir);
    const std::string problem = files.open();
    if(!problem.empty()) return fail("cannot write into '" + o.out_dir + "': " + problem);
    const CGAL_QD::Atlas_result atlas = CGAL_QD::pack_charts(out_mesh, out_chart, r.corner_uv);
    if(!atlas) return fail(std::string("cannot pack the charts into an atlas: ") + CGAL_QD::error_message(atlas.status));
    CGAL_QD::IO::Pattern_result pages;
    bool ok = CGAL_QD::IO::write_PLY_with_charts(files.file("charts.ply"), out_mesh, out_chart) &&
              CGAL_QD::IO::write_OBJ_with_uv(files.file("atlas.obj"), out_mesh, atlas.corner_uv, "atlas.mtl",
                                             "atlas");
    if(ok)
      ok = bool(files.file("atlas.mtl") << "# the material of atlas.obj\nnewmtl atlas\nKd 0.8 0.8 0.8\nKa 0 0 0\n"
                                           "Ks 0 0 0\n");
    if(ok)
      ok = bool(pages = CGAL_QD::IO::write_patterns_SVG(files.file("patterns.svg"), out_mesh, out_chart,
                                                         r.corner_uv, r.seam_edges, pattern));
#ifdef CGAL_QD_HAS_CAIRO
    const bool pdf = true;
    if(ok)
      ok = bool(CGAL_QD::IO::write_patterns_PDF(files.file("patterns.pdf"), out_mesh, out_chart, r.corner_uv,
                                                r.seam_edges, pattern));
#else
    const bool pdf = false;
#endif
    if(ok)
      ok = CGAL_QD::IO::write_segmentation_SVG(files.file("segmentation.svg"), out_mesh, out_chart, r.seam_edges) ==
           CGAL_QD::Error_code::OK;
    if(ok)
      ok = bool(files.file("report.json")
                << segment_mesh::report(r, input, smoothing, segment_mesh::Pattern_report{&pages, pattern.units, pdf, pattern.seam_allowance})
                       .dump(2)
                << "\n");
    if(!ok || !files.commit()) return fail("cannot write into '" + o.out_dir + "'");
    std::ostringstream message;
    message << "  wrote charts.ply, atlas.obj, atlas.mtl (atlas coverage " << atlas.coverage << "), patterns.svg"
            << (pdf ? " and patterns.pdf (" : " (") << pages.number_of_pages << (pages.number_of_pages == 1 ? " page" : " pages") << ", the model "
            << segment_mesh::text(pages.model_size) << ' ' << pattern.units << " at its largest, "
            << segment_mesh::text(pages.scale) << ' ' << pattern.units << " per mesh unit";
    if(pages.reduced_to_fit)
      message << ", less than " << segment_mesh::text(200 / mm_per_unit) << ' ' << pattern.units
              << " so that every piece fits on a page";
    if(pattern.scale == 0 && pattern.model_size == 0) message << "; --size or --scale to change";
    if(pages.notches > 0) message << ", " << pages.notches << " notches";
    if(pages.oversized_charts > 0)
      message << ", " << pages.oversized_charts << (pages.oversized_charts == 1 ? " piece" : " pieces") << " larger than a page";
    message << "), segmentation.svg and report.json into " << dir.string() << "\n";
    // the order in which to join the pieces, as on the pattern's last page
    for(std::size_t i = 0; i < pages.assembly.size(); ++i)
      message << (i == 0 ? "  assembly       " : "                 ")
              << CGAL_QD::IO::assembly_step_text(pages.assembly, i) << "\n";
    written = message.str();
  }
  if(o.json) {
    std::cout << segment_mesh::report(r, input, smoothing).dump() << "\n";  // one line
    return EXIT_SUCCESS;
  }
  std::cout << o.mesh << ": " << (smoothing.result.kept ? smoothing.input_faces : r.number_of_faces) << " faces\n"
            << repaired
            << "  VSA            " << r.charts_after_vsa << " charts, " << r.time_vsa_ms << " ms\n"
            << "  refinement     " << r.charts_after_refinement << " charts, " << r.time_refine_ms << " ms\n"
            << "  denoising      " << (o.denoise ? std::to_string(r.time_denoise_ms) + " ms" : std::string("off"))
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
                          segment_mesh::text(smoothing.result.smoothing.zigzag_before) + " -> " +
                          segment_mesh::text(smoothing.result.smoothing.zigzag_after)
                    : smoothing.result.smoothing.curves_smoothed == 0
                        ? std::string("no curve could be smoothed; seams follow the triangle edges")
                        : std::to_string(smoothing.result.rejected_charts) +
                              " charts beyond the thresholds once smoothed; seams follow the triangle edges")
            << "\n"
            << "  total          " << r.time_total_ms << " ms\n"
            << written;
  return EXIT_SUCCESS;
}
