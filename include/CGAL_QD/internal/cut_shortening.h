// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_INTERNAL_CUT_SHORTENING_H
#define CGAL_QD_INTERNAL_CUT_SHORTENING_H

// After the merging and the sharing: the cuts left inside the charts (seams
// with the same chart on both sides, most of them darts that end loose inside
// their chart) are closed where the chart still passes the merging's trial
// without them, whole or shortened from their loose end. A shorter cut is
// shorter to cut and to sew, and the piece is rounder, since a cut counts
// twice in its perimeter.

#include <CGAL_QD/internal/charts.h>
#include <CGAL_QD/internal/parallel.h>
#include <CGAL_QD/internal/validation.h>
#include <CGAL_QD/segmentation_measures.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL_QD {
namespace internal {

struct Cut_shortening
{
  std::size_t cut_curves = 0;       // the cut curves found inside the charts
  std::size_t curves_shortened = 0; // closed whole or in part
  double length_before = 0;         // of every cut curve
  std::size_t trials = 0;
};

// a cut curve closed whole or in part: the halfedge indices closed (both of
// each edge), their length, and whether the curve was closed whole
struct Closed_cut
{
  std::vector<std::size_t> halfedges;
  double length = 0;
  bool whole = false;
};

// `chart`: the chart of every face by face index, ids 0 to n - 1; `seam`: by
// halfedge index (both halfedges of an edge), the edges cut. `evaluate(faces,
// is_cut)` is the merging's trial of a chart (faces in increasing index).
//
// A cut curve is a chain of cut edges inside one chart between ends: vertices
// on the chart's border or the mesh's border, junctions of three or more
// cuts, and loose ends (a vertex inside the chart with one cut edge). The
// curves of each chart are taken from the longest; each is closed whole if
// the chart passes the trial without it, else, from its loose end, over half
// of its edges, else a quarter, and so on down to one edge, keeping the first
// that passes; a curve without a loose end is closed whole or not at all.
// Each curve is tried with the cuts as the curves before it left them (a
// junction whose other cuts were closed may have become a loose end). The
// charts are independent and are done in parallel, the dearest first, and
// the trials of a curve two at a time (in the order above; both count); the
// result does not depend on the threads. `seam` is updated, and `closed`
// receives the curves every chart's shortening closed, in the order they
// were closed (with the curves before it, each passed a trial).
template <class ConcurrencyTag, class TriangleMesh, class FIM, class HIM, class VIM, class Evaluate>
Cut_shortening shorten_cuts(const TriangleMesh& tm, const FIM& fim, const HIM& him, const VIM& vim,
                            const std::vector<std::array<double, 3>>& points, const Evaluate& evaluate,
                            const std::vector<std::size_t>& chart, std::size_t n, std::vector<char>& seam,
                            std::vector<std::vector<Closed_cut>>& closed)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;
  Cut_shortening result;
  const std::size_t nf = chart.size();
  std::vector<face_descriptor> face_of(nf);
  for(face_descriptor f : faces(tm)) face_of[get(fim, f)] = f;
  auto chart_of = [&](halfedge_descriptor h) { return chart[get(fim, face(h, tm))]; };
  auto length = [&](halfedge_descriptor h) {
    return distance3(points[get(vim, source(h, tm))], points[get(vim, target(h, tm))]);
  };

  // the cuts, and the vertices on a chart's border or the mesh's border
  // (whether `seam` marks the chart's border or not)
  std::vector<halfedge_descriptor> cuts;
  std::vector<char> fixed(num_vertices(tm), 0);
  for(auto e : edges(tm)) {
    const halfedge_descriptor h = halfedge(e, tm), o = opposite(h, tm);
    if(is_border(h, tm) || is_border(o, tm) || chart_of(h) != chart_of(o)) {
      fixed[get(vim, source(h, tm))] = fixed[get(vim, target(h, tm))] = 1;
    } else if(seam[get(him, h)]) {
      cuts.push_back(h);
    }
  }
  closed.assign(n, std::vector<Closed_cut>());
  if(cuts.empty()) return result;

  // every curve goes through vertices inside one chart only, whose edges no
  // other chart's task touches
  std::vector<std::vector<Seam_curve<TriangleMesh>>> curves(n);
  for(auto& c : seam_curves(tm, cuts, vim, him, [&](vertex_descriptor v) { return fixed[get(vim, v)] != 0; })) {
    ++result.cut_curves;
    const std::size_t k = chart_of(c.halfedges.front());
    curves[k].push_back(std::move(c));
  }
  std::vector<std::vector<face_descriptor>> members(n);
  for(std::size_t i = 0; i < nf; ++i)
    if(!curves[chart[i]].empty()) members[chart[i]].push_back(face_of[i]);

  std::vector<std::size_t> todo, size;
  for(std::size_t k = 0; k < n; ++k)
    if(!curves[k].empty()) {
      todo.push_back(k);
      size.push_back(members[k].size());
    }
  const std::vector<std::size_t> order = dearest_first(size);
  std::vector<Cut_shortening> done(todo.size());
  std::vector<std::vector<Closed_cut>> closed_in(todo.size());
  // the position along the curve being tried of each of its edges (by
  // halfedge index, both halfedges), `none` elsewhere: a trial closes the
  // edges before a count. The curves of different charts share no edge.
  const std::size_t none = static_cast<std::size_t>(-1);
  std::vector<std::size_t> rank(seam.size(), none);
  for_each_index<ConcurrencyTag>(order.size(), [&](std::size_t t) {
    const std::size_t k = todo[order[t]];
    Cut_shortening& out = done[order[t]];
    std::vector<std::pair<double, std::size_t>> by_length;
    for(std::size_t i = 0; i < curves[k].size(); ++i) {
      double l = 0;
      for(halfedge_descriptor h : curves[k][i].halfedges) l += length(h);
      out.length_before += l;
      by_length.push_back({-l, i});  // the longest first, ties in curve order
    }
    std::sort(by_length.begin(), by_length.end());
    // a vertex inside the chart with a single cut edge
    auto loose = [&](vertex_descriptor v) {
      if(fixed[get(vim, v)]) return false;
      std::size_t d = 0;
      for(halfedge_descriptor h : CGAL::halfedges_around_source(v, tm)) d += seam[get(him, h)] ? 1 : 0;
      return d == 1;
    };
    auto set = [&](halfedge_descriptor h, char value) {
      seam[get(him, h)] = seam[get(him, opposite(h, tm))] = value;
    };
    for(const auto& entry : by_length) {
      Seam_curve<TriangleMesh> c = curves[k][entry.second];
      const std::size_t m = c.halfedges.size();
      bool from_end = false;
      if(!c.closed && !loose(c.vertices.front()) && loose(c.vertices.back())) {
        std::reverse(c.halfedges.begin(), c.halfedges.end());
        from_end = true;
      }
      const bool shortenable = !c.closed && (from_end || loose(c.vertices.front()));
      std::vector<std::size_t> counts;  // the edges to close, in the order tried
      for(std::size_t count = m; count > 0; count = shortenable ? count / 2 : 0) counts.push_back(count);
      for(std::size_t i = 0; i < m; ++i)
        rank[get(him, c.halfedges[i])] = rank[get(him, opposite(c.halfedges[i], tm))] = i;
      // the trials two at a time: the second, which the first passing makes
      // needless, runs beside it on a thread that would otherwise wait once
      // the other charts are done (the counts do not depend on the threads)
      std::size_t kept = 0;
      for(std::size_t first = 0; first < counts.size() && kept == 0; first += 2) {
        const std::size_t batch = (std::min)(std::size_t(2), counts.size() - first);
        std::array<char, 2> passed = {0, 0};
        for_each_index<ConcurrencyTag>(batch, [&](std::size_t j) {
          const std::size_t count = counts[first + j];
          passed[j] = evaluate(members[k], [&](halfedge_descriptor h) {
            const std::size_t i = get(him, h);
            return seam[i] != 0 && rank[i] >= count;
          }) ? 1 : 0;
        });
        out.trials += batch;
        for(std::size_t j = 0; j < batch && kept == 0; ++j)
          if(passed[j]) kept = counts[first + j];
      }
      for(halfedge_descriptor h : c.halfedges) rank[get(him, h)] = rank[get(him, opposite(h, tm))] = none;
      if(kept == 0) continue;
      ++out.curves_shortened;
      Closed_cut cut;
      cut.whole = kept == m;
      for(std::size_t i = 0; i < kept; ++i) {
        set(c.halfedges[i], 0);
        cut.length += length(c.halfedges[i]);
        cut.halfedges.push_back(get(him, c.halfedges[i]));
        cut.halfedges.push_back(get(him, opposite(c.halfedges[i], tm)));
      }
      closed_in[order[t]].push_back(std::move(cut));
    }
  });
  for(std::size_t t = 0; t < todo.size(); ++t) {
    const Cut_shortening& s = done[t];
    closed[todo[t]] = std::move(closed_in[t]);
    result.curves_shortened += s.curves_shortened;
    result.length_before += s.length_before;
    result.trials += s.trials;
  }
  return result;
}

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_INTERNAL_CUT_SHORTENING_H
