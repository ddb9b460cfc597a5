// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_IO_INTERNAL_SEAM_LABELS_H
#define CGAL_QD_IO_INTERNAL_SEAM_LABELS_H

// The seam curves that the outputs label (A, B, ... as on the printed
// pattern): maximal chains of seam edges that keep the same two charts on
// their sides, in a fixed order, so that the pattern and the viewer name
// every curve alike.

#include <CGAL_QD/segmentation_measures.h>

#include <CGAL/boost/graph/iterator.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <cstddef>
#include <set>
#include <utility>
#include <vector>

namespace CGAL_QD {
namespace internal {

// `chart` by face index; `seam` holds the seam edges. Curve k, labelled
// `seam_label(k)`, is given by its halfedges in order along it, each in a face
// (a seam edge is never a border edge of the mesh).
template <class TriangleMesh, class SeamSet, class FIM, class VIM, class HIM>
std::vector<std::vector<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor>>
labelled_seam_curves(const TriangleMesh& tm, const std::vector<std::size_t>& chart, const SeamSet& seam,
                     const FIM& fim, const VIM& vim, const HIM& him)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  std::vector<halfedge_descriptor> seam_halfedges;
  for(auto e : seam)
    if(!is_border_edge(halfedge(e, tm), tm)) seam_halfedges.push_back(halfedge(e, tm));
  auto pair_of = [&](halfedge_descriptor h) {
    const std::size_t a = chart[get(fim, face(h, tm))], b = chart[get(fim, face(opposite(h, tm), tm))];
    return std::make_pair((std::min)(a, b), (std::max)(a, b));
  };
  // a curve also ends where the two charts on its sides change
  auto pair_changes = [&](vertex_descriptor v) {
    std::set<std::pair<std::size_t, std::size_t>> pairs;
    for(halfedge_descriptor h : CGAL::halfedges_around_target(v, tm))
      if(seam.count(edge(h, tm)) && !is_border_edge(h, tm)) pairs.insert(pair_of(h));
    return pairs.size() > 1;
  };
  std::vector<std::vector<halfedge_descriptor>> curves;
  for(auto& c : seam_curves(tm, seam_halfedges, vim, him, pair_changes)) curves.push_back(std::move(c.halfedges));
  return curves;
}

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_IO_INTERNAL_SEAM_LABELS_H
