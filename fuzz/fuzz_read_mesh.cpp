// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A libFuzzer target for the mesh readers of CGAL_QD/IO/read_mesh.h: every
// input is written to a file and read back, as a user's file would be.
// QD_FUZZ_FORMAT chooses what is exercised:
//   off, obj, ply, stl  read_polygon_soup() on a file with that extension;
//   repair              read_and_repair_mesh(): the first byte picks the
//                       extension (off, obj, ply, stl), the rest is the file.
// Besides the sanitizers' findings, the target aborts when a reader breaks
// its contract: a failure that leaves points or polygons behind or has no
// message, a success without faces, or a repaired mesh that is not a valid
// triangle mesh with finite points.
// scripts/fuzz.sh builds it with clang (-fsanitize=fuzzer,address,undefined)
// and runs every mode on the seed corpus in fuzz/corpus/.

#include <CGAL_QD/IO/read_mesh.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

std::string mode()
{
  const char* m = std::getenv("QD_FUZZ_FORMAT");
  return m ? std::string(m) : std::string("off");
}

// a file of this process, in the temporary directory
std::string file_named(const std::string& extension)
{
  const char* dir = std::getenv("TMPDIR");
  return std::string(dir ? dir : "/tmp") + "/qd_fuzz_" + std::to_string(getpid()) + "." + extension;
}

void check(bool ok, const char* what)
{
  if(!ok) {
    std::fprintf(stderr, "fuzz_read_mesh: %s\n", what);
    std::abort();
  }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  static const std::string how = mode();
  static const char* const extensions[] = {"off", "obj", "ply", "stl"};
  const bool repair = how == "repair";
  if(repair && size == 0) return 0;
  const std::string extension = repair ? extensions[data[0] % 4] : how;
  const std::string path = file_named(extension);
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    if(repair) out.write(reinterpret_cast<const char*>(data) + 1, static_cast<std::streamsize>(size - 1));
    else out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  if(repair) {
    Mesh mesh;
    const CGAL_QD::Repair_report r = CGAL_QD::IO::read_and_repair_mesh(path, mesh);
    if(r) {
      check(!faces(mesh).empty(), "a repaired mesh without faces");
      check(CGAL::is_valid_polygon_mesh(mesh) && CGAL::is_triangle_mesh(mesh), "a repaired mesh that is not valid");
      for(auto v : vertices(mesh)) {
        const K::Point_3& p = mesh.point(v);
        check(std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z()), "a non-finite repaired point");
      }
    } else {
      check(faces(mesh).empty(), "a failed repair left faces");
      check(!r.message.empty(), "a failed repair without a message");
    }
  } else {
    std::vector<K::Point_3> points;
    std::vector<std::vector<std::size_t>> polygons;
    const CGAL_QD::IO::Read_status s = CGAL_QD::IO::read_polygon_soup(path, points, polygons);
    if(s) {
      check(!polygons.empty(), "a file read without faces");
    } else {
      check(points.empty() && polygons.empty(), "a failed read left points or polygons");
      check(!s.message.empty(), "a failed read without a message");
    }
  }
  std::remove(path.c_str());
  return 0;
}
