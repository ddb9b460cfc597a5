// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// One mesh of the robustness sweep: reads and repairs the file, flattens the
// largest disk-like patch (the largest connected component when it is a disk
// with or without holes, otherwise a disk grown breadth-first from its first
// face over half its area), then segments the whole mesh. Prints one Markdown
// table row (or, with --header, the table's header).
//
// The exit code is 0 when every target holds: the mesh is either used or
// refused with a named status, nothing is NaN, no final chart overlaps, and the
// LPFB of the patch converges (merging trials whose LPFB does not converge are
// rejected by the merging and counted in the last column).
// It is 1 when a target is missed (the row says which), 2 on an exception.
//
// test_robustness runs it instead of its test cases when its first argument
// is --sweep (the sweep shares the executable, and the compile, of the
// robustness tests):
// usage: test_robustness --sweep <mesh> | test_robustness --sweep --header

#ifndef CGAL_QD_TEST_SWEEP_MESH_H
#define CGAL_QD_TEST_SWEEP_MESH_H

#include "disk_patches.h"

#include <CGAL_QD/IO/read_mesh.h>
#include <CGAL_QD/distortion.h>
#include <CGAL_QD/flatten_patch.h>
#include <CGAL_QD/segment_quasi_developable.h>
#include <CGAL_QD/validate_patch.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <sys/resource.h>

namespace qd_test {
namespace sweep {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef boost::graph_traits<Mesh>::face_descriptor face_descriptor;

inline std::string fixed(double x, int digits)
{
  if(!std::isfinite(x)) return "NaN";
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", digits, x);
  return buffer;
}

inline double elapsed_ms(std::chrono::steady_clock::time_point since)
{
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - since).count();
}

// the faces of the largest component (by area)
inline std::vector<face_descriptor> largest_component(const Mesh& tm)
{
  std::vector<std::size_t> component(num_faces(tm), 0);
  const std::size_t n = CGAL::Polygon_mesh_processing::connected_components(
      tm, boost::make_iterator_property_map(component.begin(), get(CGAL::face_index, tm)));
  std::vector<double> area(n, 0);
  for(const face_descriptor f : faces(tm)) area[component[f.idx()]] += CGAL::Polygon_mesh_processing::face_area(f, tm);
  const std::size_t best = static_cast<std::size_t>(std::max_element(area.begin(), area.end()) - area.begin());
  std::vector<face_descriptor> members;
  for(const face_descriptor f : faces(tm))
    if(component[f.idx()] == best) members.push_back(f);
  return members;
}

inline bool finite_uv(const std::vector<std::array<double, 2>>& uv)
{
  for(const auto& p : uv)
    if(!std::isfinite(p[0]) || !std::isfinite(p[1])) return false;
  return true;
}

} // namespace sweep

// argv[0] is "--sweep"; argv[1] the mesh or --header
inline int sweep_mesh(int argc, char** argv)
{
  using namespace sweep;
  if(argc == 2 && std::string(argv[1]) == "--header") {
    std::cout << "| mesh | faces | repairs | patch faces | loops | flattening | A % | L² | flips | overlap | Π_L | "
                 "flatten s | segmentation | charts | max A % | max L² | overlapping | segment s | total s | peak MB | targets |\n"
              << "|---|---:|---|---:|---:|---|---:|---:|---:|---|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|---|\n";
    return EXIT_SUCCESS;
  }
  if(argc != 2) {
    std::cerr << "usage: test_robustness --sweep <mesh> | test_robustness --sweep --header\n";
    return EXIT_FAILURE;
  }
  const std::string path = argv[1];
  const std::string name = std::filesystem::path(path).filename().string();
  const auto start = std::chrono::steady_clock::now();
  std::ostringstream row;
  std::vector<std::string> missed;
  // merging trials whose LPFB did not converge: reported (the trial is rejected)
  std::size_t trials_not_converged = 0;
  try {
    Mesh tm;
    const CGAL_QD::Repair_report input = CGAL_QD::IO::read_and_repair_mesh(path, tm);
    if(!input) {
      row << "| " << name << " | – | " << input.message << " | – | – | – | – | – | – | – | – | – | "
          << CGAL_QD::error_message(input.status) << " | – | – | – | – | – | " << fixed(elapsed_ms(start) / 1000, 2)
          << " | – | met |";
      std::cout << row.str() << "\n";
      return EXIT_SUCCESS;
    }
    std::string repairs;
    for(const std::string& r : input.repairs()) repairs += (repairs.empty() ? "" : "; ") + r;
    row << "| " << name << " | " << num_faces(tm) << " | " << (repairs.empty() ? std::string("none") : repairs)
        << " | ";

    // the largest disk-like patch
    const std::vector<face_descriptor> component = largest_component(tm);
    Mesh patch;
    qd_test::copy_faces(tm, component, patch);
    if(CGAL_QD::validate_patch(patch) != CGAL_QD::Error_code::OK) {
      double area = 0;
      for(const face_descriptor f : component) area += CGAL::Polygon_mesh_processing::face_area(f, tm);
      const auto grown = qd_test::grow_disk(tm, component.front(), component.size(), area / 2);
      qd_test::copy_faces(tm, grown.faces, patch);
    }
    auto uv = patch.add_property_map<Mesh::Vertex_index, K::Point_2>("v:uv").first;
    const auto flatten_start = std::chrono::steady_clock::now();
    const CGAL_QD::Flattening_result flat = CGAL_QD::flatten_patch(patch, uv);
    const double flatten_s = elapsed_ms(flatten_start) / 1000;  // the measures are not included
    const std::size_t loops = CGAL_QD::inspect_mesh(patch).border_loops;
    row << num_faces(patch) << " | " << loops << " | " << CGAL_QD::error_message(flat.status) << " | ";
    if(flat.status == CGAL_QD::Error_code::NOT_CONVERGED) missed.push_back("LPFB not converged on the patch");
    if(flat) {
      const auto d = CGAL_QD::compute_distortion(patch, uv);
      bool nan = false;
      for(const auto v : vertices(patch)) nan = nan || !std::isfinite(uv[v].x()) || !std::isfinite(uv[v].y());
      if(nan || !std::isfinite(d.area_distortion) || !std::isfinite(d.l2_stretch)) missed.push_back("NaN in the flattening");
      row << fixed(d.area_distortion, 2) << " | " << fixed(d.l2_stretch, 3) << " | " << d.flipped_faces << " | "
          << (d.overlap ? "yes" : "no") << " | " << (d.boundary_length_error < 1e-12 ? std::string("< 1e-12") : fixed(d.boundary_length_error, 14)) << " | ";
    }
    else
      row << "– | – | – | – | – | ";
    row << fixed(flatten_s, 2) << " | ";

    // the whole mesh
    auto chart = tm.add_property_map<Mesh::Face_index, std::size_t>("f:chart", 0).first;
    const CGAL_QD::Segmentation_result<Mesh> s = CGAL_QD::segment_quasi_developable(tm, chart);
    row << CGAL_QD::error_message(s.status) << " | ";
    if(s) {
      if(!finite_uv(s.corner_uv) || !std::isfinite(s.max_area_distortion) || !std::isfinite(s.max_l2_stretch))
        missed.push_back("NaN in the segmentation");
      if(s.overlapping_charts > 0) missed.push_back("overlapping charts");
      trials_not_converged = s.merging.lpfb_not_converged;
      row << s.number_of_charts << " | " << fixed(s.max_area_distortion, 2) << " | " << fixed(s.max_l2_stretch, 3)
          << " | " << s.overlapping_charts << " | ";
    }
    else
      row << "– | – | – | – | ";
    row << fixed(s.time_total_ms / 1000, 2) << " | ";
  }
  catch(const std::exception& e) {
    std::cout << "| " << name << " | exception: " << e.what() << " |\n";
    return 2;
  }
  row << fixed(elapsed_ms(start) / 1000, 2) << " | ";
  // the process's peak resident memory: reading, the patch's flattening and the segmentation
  struct rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  row << fixed(double(usage.ru_maxrss) / 1024, 0) << " | ";
  if(missed.empty()) {
    row << "met";
    if(trials_not_converged > 0) row << " (LPFB not converged in " << trials_not_converged << " trials)";
    row << " |";
  }
  else {
    row << "**missed:";
    for(const std::string& m : missed) row << ' ' << m << ';';
    row << "** |";
  }
  std::cout << row.str() << "\n";
  return missed.empty() ? EXIT_SUCCESS : EXIT_FAILURE;
}

} // namespace qd_test

#endif // CGAL_QD_TEST_SWEEP_MESH_H
