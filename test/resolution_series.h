// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_TEST_RESOLUTION_SERIES_H
#define CGAL_QD_TEST_RESOLUTION_SERIES_H

// The same shape at several resolutions, to check that a segmentation depends
// on the shape and not on the number of faces: a mesh is Loop-subdivided
// (each round multiplies the faces by 4 and smooths the surface slightly) or
// simplified by edge collapse (Lindstrom-Turk cost and placement) down to a
// ratio of its faces.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Count_ratio_stop_predicate.h>

#include <string>

namespace qd_test {

typedef CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> Series_mesh;

// `level` > 0: Loop-subdivided `level` times; `level` < 0: simplified to
// 2^level of the faces (-1: a half, -2: a quarter); 0: a copy.
inline Series_mesh at_resolution(const Series_mesh& tm, int level)
{
  Series_mesh out = tm;
  if(level > 0) {
    CGAL::Subdivision_method_3::Loop_subdivision(out, CGAL::parameters::number_of_iterations(level));
  } else if(level < 0) {
    const CGAL::Surface_mesh_simplification::Count_ratio_stop_predicate<Series_mesh> stop(1. / double(1 << -level));
    CGAL::Surface_mesh_simplification::edge_collapse(out, stop);
    out.collect_garbage();
  }
  return out;
}

inline std::string resolution_name(int level)
{
  switch(level) {
  case -2: return "quarter";
  case -1: return "half";
  case 0: return "original";
  case 1: return "subdivided once";
  case 2: return "subdivided twice";
  default: return level > 0 ? "subdivided " + std::to_string(level) + " times"
                            : "1/" + std::to_string(1 << -level) + " of the faces";
  }
}

} // namespace qd_test

#endif // CGAL_QD_TEST_RESOLUTION_SERIES_H
