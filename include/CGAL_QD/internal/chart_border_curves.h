// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_INTERNAL_CHART_BORDER_CURVES_H
#define CGAL_QD_INTERNAL_CHART_BORDER_CURVES_H

// The border curves between the charts of a segmentation: the edges between
// each pair of charts, grouped into connected chains. They are what the
// merging of `merge_charts_by_boundaries()` tries to remove.

#include <CGAL_QD/internal/union_find.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <cstddef>
#include <tuple>
#include <utility>
#include <vector>

namespace CGAL_QD {
namespace internal {

template <class HalfedgeDescriptor>
struct Chart_border_curve
{
  std::size_t a = 0, b = 0;                  // the charts on either side, a < b
  std::vector<HalfedgeDescriptor> halfedges;  // one per edge, in a face of chart a
  double length = 0;                         // the sum of `edge_length()` over its edges
};

// The curves between the charts given by `chart_of(h)` (the chart of the face
// of a halfedge h not on the mesh border): the edges between the same two
// charts that share a vertex are in the same curve, and the curves come in
// the order of their first edge in `edges(tm)`. `curve_of` receives the curve
// of both halfedges of every edge of a curve, by halfedge index, and -1 for
// every other halfedge.
template <class TriangleMesh, class HIM, class ChartOf, class EdgeLength>
std::vector<Chart_border_curve<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor>>
chart_border_curves(const TriangleMesh& tm, const HIM& him, const ChartOf& chart_of, const EdgeLength& edge_length,
                    std::vector<long>& curve_of)
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  std::vector<Chart_border_curve<halfedge_descriptor>> curves;
  curve_of.assign(num_halfedges(tm), -1);
  std::vector<halfedge_descriptor> border;
  for(auto e : edges(tm)) {
    const halfedge_descriptor h = halfedge(e, tm);
    if(is_border_edge(h, tm)) continue;
    if(chart_of(h) != chart_of(opposite(h, tm))) border.push_back(h);
  }
  Union_find chains(border.size());
  auto pair_of = [&](halfedge_descriptor h) {
    const std::size_t x = chart_of(h), y = chart_of(opposite(h, tm));
    return std::make_pair((std::min)(x, y), (std::max)(x, y));
  };
  std::vector<long> edge_at(num_halfedges(tm), -1);  // border edge index by halfedge
  for(std::size_t i = 0; i < border.size(); ++i) {
    edge_at[get(him, border[i])] = static_cast<long>(i);
    edge_at[get(him, opposite(border[i], tm))] = static_cast<long>(i);
  }
  for(std::size_t i = 0; i < border.size(); ++i)
    for(halfedge_descriptor end : {border[i], opposite(border[i], tm)})
      for(halfedge_descriptor h : CGAL::halfedges_around_target(end, tm)) {
        const long j = edge_at[get(him, h)];
        if(j < 0 || std::size_t(j) == i || pair_of(border[j]) != pair_of(border[i])) continue;
        chains.unite(i, std::size_t(j));
      }
  std::vector<long> curve_of_root(border.size(), -1);
  for(std::size_t i = 0; i < border.size(); ++i) {
    const std::size_t r = chains.find(i);
    if(curve_of_root[r] < 0) {
      curve_of_root[r] = static_cast<long>(curves.size());
      Chart_border_curve<halfedge_descriptor> c;
      std::tie(c.a, c.b) = pair_of(border[i]);
      curves.push_back(c);
    }
    Chart_border_curve<halfedge_descriptor>& c = curves[curve_of_root[r]];
    c.halfedges.push_back(chart_of(border[i]) == c.a ? border[i] : opposite(border[i], tm));
    c.length += edge_length(border[i]);
    curve_of[get(him, border[i])] = curve_of[get(him, opposite(border[i], tm))] = curve_of_root[r];
  }
  return curves;
}

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_INTERNAL_CHART_BORDER_CURVES_H
