// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Computes the length-preserved free boundary of a triangle patch and writes
// its border loops as an OBJ file: one `v` (3D position) and one `vt` (planar
// position) per border vertex, and one closed `l` polyline per loop.
//
// usage: length_preserved_free_boundary [mesh.off|obj|ply|stl] [out.obj]

#include <CGAL_QD/length_preserved_free_boundary.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Surface_mesh.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <string>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

int main(int argc, char** argv)
{
  const std::string in = argc > 1 ? argv[1] : CGAL_QD_DATA_DIR "/wavy_sheet_with_hole.off";
  const std::string out = argc > 2 ? argv[2] : "length_preserved_free_boundary.obj";

  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(in, mesh)) {
    std::cerr << "error: cannot read a polygon mesh from '" << in << "'\n";
    return EXIT_FAILURE;
  }
  std::cout << "mesh: " << in << " (" << num_vertices(mesh) << " vertices, " << num_faces(mesh) << " faces)\n";

  auto uv = mesh.add_property_map<Mesh::Vertex_index, K::Point_2>("v:uv").first;
  const auto start = std::chrono::steady_clock::now();
  const CGAL_QD::Free_boundary_result r =
      CGAL_QD::compute_length_preserved_free_boundary(mesh, uv, CGAL::parameters::default_values());
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();

  std::cout << "status:                 " << CGAL_QD::error_message(r.status) << "\n";
  if(!r) return EXIT_FAILURE;
  std::cout << "border loops:           " << r.number_of_loops << "\n"
            << "border vertices:        " << r.number_of_border_vertices << "\n"
            << "iterations:             " << r.iterations << "\n"
            << "constraint residual:    " << r.constraint_residual << "\n"
            << "coincidence error:      " << r.coincidence_error << "\n"
            << "objective:              " << r.objective << "\n"
            << "Pi_L (length error):    " << r.boundary_length_error << "\n"
            << "Pi_theta (angle error): " << r.boundary_angle_error << " rad\n"
            << "cut path length:        " << r.cut_length << "\n"
            << "time:                   " << ms << " ms (validation, cutting and solve)\n";

  std::ofstream obj(out);
  if(!obj) {
    std::cerr << "error: cannot write '" << out << "'\n";
    return EXIT_FAILURE;
  }
  obj.precision(17);
  obj << "# length-preserved free boundary of " << in << "\n";
  std::map<Mesh::Vertex_index, std::size_t> index;
  std::set<Mesh::Halfedge_index> seen;
  std::vector<std::vector<std::size_t>> loops;
  for(Mesh::Halfedge_index b : halfedges(mesh)) {
    if(!is_border(b, mesh) || seen.count(b)) continue;
    std::vector<std::size_t> loop;
    for(Mesh::Halfedge_index h : CGAL::halfedges_around_face(b, mesh)) {
      seen.insert(h);
      const Mesh::Vertex_index v = target(h, mesh);
      if(!index.count(v)) {
        const std::size_t k = index.size() + 1;
        index[v] = k;
        obj << "v " << mesh.point(v) << "\nvt " << uv[v] << "\n";
      }
      loop.push_back(index[v]);
    }
    loops.push_back(loop);
  }
  for(const auto& loop : loops) {
    obj << "l";
    for(std::size_t k : loop) obj << " " << k << "/" << k;
    obj << " " << loop.front() << "/" << loop.front() << "\n";
  }
  std::cout << "wrote " << out << "\n";
  return EXIT_SUCCESS;
}
