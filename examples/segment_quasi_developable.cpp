// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Cuts a triangle mesh into quasi-developable charts (A(Omega) <= 10 % and
// L2 <= 2.0, the paper's thresholds, and A_loc <= 2.5 %: the defaults, given
// here by name), prints how every chart flattens, and writes the mesh with a
// colour and a chart id per face as a PLY file. The command-line program
// `segment_mesh` (programs/) does the same with every option and output.
//
// usage: segment_quasi_developable [mesh.off|obj|ply|stl] [charts.ply]

#include <CGAL_QD/IO/charts_and_atlas.h>
#include <CGAL_QD/segment_quasi_developable.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Surface_mesh.h>

#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

int main(int argc, char** argv)
{
  const std::string in = argc > 1 ? argv[1] : CGAL_QD_DATA_DIR "/wavy_sheet_with_hole.off";
  const std::string out = argc > 2 ? argv[2] : "charts.ply";

  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(in, mesh) || !CGAL::is_triangle_mesh(mesh)) {
    std::cerr << "error: cannot read a triangle mesh from '" << in << "'\n";
    return EXIT_FAILURE;
  }
  auto chart = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:chart", 0).first;

  const CGAL_QD::Segmentation_result<Mesh> r = CGAL_QD::segment_quasi_developable(
      mesh, chart, CGAL_QD::parameters::max_area_distortion(0.10, CGAL_QD::parameters::max_l2_stretch(2.0)));
  if(!r) {
    std::cerr << "error: " << CGAL_QD::error_message(r.status) << "\n";
    return EXIT_FAILURE;
  }
  std::cout << in << ": " << num_faces(mesh) << " faces, " << r.charts_after_vsa << " charts after VSA, "
            << r.number_of_charts << " after merging, in " << r.time_total_ms << " ms\n";
  for(std::size_t k = 0; k < r.charts.size(); ++k) {
    const CGAL_QD::Chart_report& c = r.charts[k];
    std::cout << "  chart " << k << ": " << c.number_of_faces << " faces, A(Omega) " << c.area_distortion
              << " %, L2 " << c.l2_stretch << ", A_loc " << c.local_area_distortion << " %"
              << (c.overlap ? ", overlapping" : "") << "\n";
  }

  std::ofstream ply(out, std::ios::binary);
  if(!CGAL_QD::IO::write_PLY_with_charts(ply, mesh, chart)) {
    std::cerr << "error: cannot write '" << out << "'\n";
    return EXIT_FAILURE;
  }
  std::cout << "wrote " << out << "\n";
  return EXIT_SUCCESS;
}
