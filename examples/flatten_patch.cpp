// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Flattens a triangle patch and measures the result. Methods: LPFB+IP (ours),
// and CGAL's LSCM (free border), DCM and MVC (circular arc-length border) and
// ARAP. The CGAL results are normalised as in the paper before measuring: a
// similarity puts the endpoints of the longest border edge at their 3D distance.
//
// usage: flatten_patch <mesh> [--method lpfb|lscm|dcm|mvc|arap] [--out uv.obj] [--json]

#include <CGAL_QD/distortion.h>
#include <CGAL_QD/flatten_patch.h>
#include <CGAL_QD/validate_patch.h>

#include <CGAL/Polygon_mesh_processing/measure.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_parameterization/ARAP_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Circular_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_conformal_map_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/LSCM_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Mean_value_coordinates_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <string>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Property_map<Mesh::Vertex_index, K::Point_2> UV_map;
namespace SMP = CGAL::Surface_mesh_parameterization;

namespace {

int usage()
{
  std::cerr << "usage: flatten_patch <mesh> [--method lpfb|lscm|dcm|mvc|arap] [--out uv.obj] [--json]\n";
  return EXIT_FAILURE;
}


template <class Parameterizer>
SMP::Error_code run_cgal(Mesh& mesh, Parameterizer p, UV_map uv)
{
  return SMP::parameterize(mesh, p, CGAL::Polygon_mesh_processing::longest_border(mesh).first, uv);
}

std::size_t count_loops(const Mesh& mesh)
{
  std::set<Mesh::Halfedge_index> seen;
  std::size_t loops = 0;
  for(Mesh::Halfedge_index h : halfedges(mesh))
    if(is_border(h, mesh) && !seen.count(h)) {
      ++loops;
      for(Mesh::Halfedge_index g : CGAL::halfedges_around_face(h, mesh)) seen.insert(g);
    }
  return loops;
}

bool write_obj(const std::string& path, const Mesh& mesh, UV_map uv)
{
  std::ofstream out(path);
  if(!out) return false;
  out.precision(17);
  std::map<Mesh::Vertex_index, std::size_t> id;
  for(Mesh::Vertex_index v : vertices(mesh)) {
    id[v] = id.size() + 1;
    out << "v " << mesh.point(v) << "\nvt " << uv[v] << "\n";
  }
  for(Mesh::Face_index f : faces(mesh)) {
    out << "f";
    for(Mesh::Vertex_index v : CGAL::vertices_around_face(halfedge(f, mesh), mesh)) out << " " << id[v] << "/" << id[v];
    out << "\n";
  }
  return bool(out);
}

} // namespace

int main(int argc, char** argv)
{
  std::string in, method = "lpfb", out;
  bool json = false;
  for(int i = 1; i < argc; ++i) {
    if(!std::strcmp(argv[i], "--method") && i + 1 < argc) method = argv[++i];
    else if(!std::strcmp(argv[i], "--out") && i + 1 < argc) out = argv[++i];
    else if(!std::strcmp(argv[i], "--json")) json = true;
    else if(argv[i][0] == '-') return usage();
    else in = argv[i];
  }
  if(in.empty()) in = CGAL_QD_DATA_DIR "/wavy_sheet_with_hole.off";
  if(method != "lpfb" && method != "lscm" && method != "dcm" && method != "mvc" && method != "arap") return usage();

  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(in, mesh) || faces(mesh).empty()) {
    std::cerr << "error: cannot read a polygon mesh from '" << in << "'\n";
    return EXIT_FAILURE;
  }
  UV_map uv = mesh.add_property_map<Mesh::Vertex_index, K::Point_2>("v:uv", K::Point_2(0, 0)).first;

  // every method gets the same validated patch
  std::string status = "success";
  double time_border_ms = -1, time_total_ms = 0;
  CGAL_QD::Flattening_result fr;
  if(method == "lpfb") {
    fr = CGAL_QD::flatten_patch(mesh, uv);
    time_total_ms = fr.time_total_ms;
    time_border_ms = fr.time_border_ms;
    if(!fr) status = CGAL_QD::error_message(fr.status);
  } else {
    // the same input checks as ours, so that a closed or broken mesh gets the same message
    const CGAL_QD::Error_code check = CGAL_QD::validate_patch(mesh);
    if(check != CGAL_QD::Error_code::OK) {
      status = CGAL_QD::error_message(check);
    } else {
      const auto t = std::chrono::steady_clock::now();
      SMP::Error_code err = SMP::OK;
      if(method == "lscm") err = run_cgal(mesh, SMP::LSCM_parameterizer_3<Mesh>(), uv);
      else if(method == "dcm") err = run_cgal(mesh, SMP::Discrete_conformal_map_parameterizer_3<Mesh>(), uv);
      else if(method == "mvc") err = run_cgal(mesh, SMP::Mean_value_coordinates_parameterizer_3<Mesh>(), uv);
      else err = run_cgal(mesh, SMP::ARAP_parameterizer_3<Mesh>(), uv);
      time_total_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count();
      if(err != SMP::OK) status = SMP::get_error_message(err);
      else CGAL_QD::normalize_by_longest_border_edge(mesh, uv);
    }
  }
  if(status != "success") {
    if(json) std::cout << "{\"status\": \"" << status << "\", \"method\": \"" << method << "\"}\n";
    else std::cerr << "error: " << status << "\n";
    return EXIT_FAILURE;
  }

  const auto d = CGAL_QD::compute_distortion(mesh, uv);
  std::size_t border_vertices = 0;
  for(Mesh::Vertex_index v : vertices(mesh)) if(is_border(v, mesh)) ++border_vertices;
  if(json) {
    std::cout << "{\"status\": \"" << status << "\", \"method\": \"" << method << "\", \"faces\": " << num_faces(mesh)
              << ", \"vertices\": " << num_vertices(mesh) << ", \"border_vertices\": " << border_vertices
              << ", \"loops\": " << count_loops(mesh) << ", \"time_border_ms\": ";
    if(time_border_ms >= 0) std::cout << time_border_ms; else std::cout << "null";
    std::cout << ", \"time_total_ms\": " << time_total_ms << ", \"area_distortion_pct\": " << d.area_distortion
              << ", \"l2_stretch\": " << d.l2_stretch << ", \"l2_stretch_normalized\": " << d.l2_stretch_normalized
              << ", \"linf_stretch\": " << d.linf_stretch << ", \"angle_distortion\": " << d.angle_distortion
              << ", \"boundary_length_error\": " << d.boundary_length_error
              << ", \"boundary_angle_error\": " << d.boundary_angle_error << ", \"flipped\": " << d.flipped_faces
              << ", \"border_crossings\": " << d.border_crossings.size()
              << ", \"overlap\": " << (d.overlap ? "true" : "false");
    if(method == "lpfb")
      std::cout << ", \"iterations\": " << fr.border.iterations << ", \"solver\": \"" << fr.solver
                << "\", \"time_assembly_ms\": " << fr.time_assembly_ms
                << ", \"time_factorization_ms\": " << fr.time_factorization_ms
                << ", \"time_solve_ms\": " << fr.time_solve_ms;
    std::cout << "}\n";
  } else {
    std::cout << "mesh:            " << in << " (" << num_faces(mesh) << " faces, " << num_vertices(mesh)
              << " vertices, " << border_vertices << " on " << count_loops(mesh) << " border loops)\n"
              << "method:          " << method << "\n"
              << "time:            " << time_total_ms << " ms";
    if(method == "lpfb")
      std::cout << " (border " << fr.time_border_ms << ", assembly " << fr.time_assembly_ms << ", factorization "
                << fr.time_factorization_ms << ", solve " << fr.time_solve_ms << "; " << fr.solver << ")";
    std::cout << "\nA (area):        " << d.area_distortion << " %\n"
              << "L2 stretch:      " << d.l2_stretch << " (normalised " << d.l2_stretch_normalized << ")\n"
              << "Pi_L, Pi_theta:  " << d.boundary_length_error << ", " << d.boundary_angle_error << "\n"
              << "flipped faces:   " << d.flipped_faces << "\n"
              << "overlap:         " << (d.overlap ? "yes" : "no") << "\n";
  }
  if(!out.empty()) {
    if(!write_obj(out, mesh, uv)) {
      std::cerr << "error: cannot write '" << out << "'\n";
      return EXIT_FAILURE;
    }
    if(!json) std::cout << "wrote " << out << "\n";
  }
  return EXIT_SUCCESS;
}
