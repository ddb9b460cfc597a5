// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_IO_INTERNAL_CLOSED_COMPONENTS_H
#define CGAL_QD_IO_INTERNAL_CLOSED_COMPONENTS_H

// Which side of every face is outside, where its connected component is
// closed: a picture leaves out the faces of a closed surface that are turned
// away from the viewer, since the faces turned towards it cover them.

#include <CGAL_QD/internal/union_find.h>
#include <CGAL_QD/internal/validation.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <boost/graph/graph_traits.hpp>

#include <array>
#include <cstddef>
#include <vector>

namespace CGAL_QD {
namespace internal {

// For every face of `tm`, by its index in `fim` (in [0, number of faces)): 0
// where its connected component (faces joined through edges) has a border
// edge or no volume, else +1 or -1, the sign of the volume the closed
// component bounds (+1: the faces are oriented with the outside on their
// front).
template <class TriangleMesh, class VPM, class FIM>
std::vector<int> outside_of_closed_components(const TriangleMesh& tm, const VPM& vpm, const FIM& fim)
{
  typedef std::array<double, 3> P;
  const std::size_t nf = static_cast<std::size_t>(num_faces(tm));
  Union_find components(nf);
  std::vector<char> open(nf, 0);
  for(auto f : faces(tm)) {
    const std::size_t i = static_cast<std::size_t>(get(fim, f));
    for(auto h : CGAL::halfedges_around_face(halfedge(f, tm), tm)) {
      const auto o = opposite(h, tm);
      if(is_border(o, tm))
        open[i] = 1;
      else
        components.unite(i, static_cast<std::size_t>(get(fim, face(o, tm))));
    }
  }
  // the volume of every component, from a point near the mesh (the first
  // vertex) to keep the products small
  P origin = {0., 0., 0.};
  if(!vertices(tm).empty()) origin = point_of<TriangleMesh>(*vertices(tm).begin(), vpm);
  std::vector<double> volume(nf, 0.);
  std::vector<char> has_border(nf, 0);
  for(auto f : faces(tm)) {
    const std::size_t i = static_cast<std::size_t>(get(fim, f)), root = components.find(i);
    if(open[i]) has_border[root] = 1;
    std::vector<P> c;
    for(auto v : CGAL::vertices_around_face(halfedge(f, tm), tm)) {
      const P p = point_of<TriangleMesh>(v, vpm);
      c.push_back({{p[0] - origin[0], p[1] - origin[1], p[2] - origin[2]}});
    }
    for(std::size_t k = 1; k + 1 < c.size(); ++k) {  // a fan over a polygon
      const P &a = c[0], &b = c[k], &d = c[k + 1];
      volume[root] += a[0] * (b[1] * d[2] - b[2] * d[1]) + a[1] * (b[2] * d[0] - b[0] * d[2]) +
                      a[2] * (b[0] * d[1] - b[1] * d[0]);
    }
  }
  std::vector<int> side(nf, 0);
  for(std::size_t i = 0; i < nf; ++i) {
    const std::size_t root = components.find(i);
    if(!has_border[root]) side[i] = volume[root] > 0 ? 1 : (volume[root] < 0 ? -1 : 0);
  }
  return side;
}

// the z component of the normal of the polygon `c` (its first three corners)
// in a frame whose z axis points toward the viewer: positive where its front
// faces the viewer
inline double screen_normal_z(const std::vector<std::array<double, 3>>& c)
{
  return (c[1][0] - c[0][0]) * (c[2][1] - c[0][1]) - (c[1][1] - c[0][1]) * (c[2][0] - c[0][0]);
}

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_IO_INTERNAL_CLOSED_COMPONENTS_H
