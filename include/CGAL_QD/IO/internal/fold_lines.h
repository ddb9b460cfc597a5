// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_IO_INTERNAL_FOLD_LINES_H
#define CGAL_QD_IO_INTERNAL_FOLD_LINES_H

// Which of the edges inside a printed piece that bend by more than the fold
// angle are drawn as fold lines. On a fine mesh of a smooth shape most such
// edges are the sampling's small bends, a millimetre or two long on paper and
// scattered, or side by side where the surface curves: drawn, they hatch the
// piece with dashes that nobody folds along, and the paper takes that shape by
// bending. A crease is a line: the edges are chained, edge to edge through a
// vertex where the line turns by at most `fold_line_max_turn` on the page
// (each end of an edge going on into the straightest edge of the same kind,
// mountain or valley, that meets it there on the page), and a line shorter
// than the smallest fold length on the page is drawn only where it ends on
// the piece's cut line or on another line drawn at both ends (the crease
// across a narrow strip, or between two longer creases).

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL_QD {
namespace internal {

// the largest turn (radians) of a fold line at a vertex: 30 degrees
constexpr double fold_line_max_turn = 0.5235987755982988;

struct Fold_edge
{
  std::array<std::size_t, 2> vertex;  // its two ends in the mesh
  std::array<double, 2> a, b;         // the same ends on the page
  int kind;                           // mountain or valley
};

// whether each edge lies on a fold line drawn: a line at least `min_length`
// long on the page, or a shorter one that ends at both ends on the piece's
// cut line (`border`: its vertices, sorted) or on a line drawn, such as a
// crease across a narrow strip or between two others; with `min_length` 0,
// every edge
inline std::vector<char> edges_on_fold_lines(const std::vector<Fold_edge>& edges, double min_length,
                                             const std::vector<std::size_t>& border)
{
  const std::size_t m = edges.size();
  if(!(min_length > 0)) return std::vector<char>(m, 1);
  std::vector<std::size_t> parent(m);
  for(std::size_t i = 0; i < m; ++i) parent[i] = i;
  auto root = [&](std::size_t i) {
    while(parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  // the ends of the edges, grouped by vertex
  std::vector<std::pair<std::size_t, std::size_t>> ends;  // (vertex, 2 edge + end)
  ends.reserve(2 * m);
  for(std::size_t i = 0; i < m; ++i)
    for(std::size_t s = 0; s < 2; ++s) ends.emplace_back(edges[i].vertex[s], 2 * i + s);
  std::sort(ends.begin(), ends.end());
  auto point = [&](std::size_t end) -> const std::array<double, 2>& {
    return end % 2 == 0 ? edges[end / 2].a : edges[end / 2].b;
  };
  // the unit direction of an edge away from one of its ends
  auto away = [&](std::size_t end) {
    const std::array<double, 2>& p = point(end);
    const std::array<double, 2>& q = point(end ^ 1);
    const double dx = q[0] - p[0], dy = q[1] - p[1], l = std::hypot(dx, dy);
    return l > 0 ? std::array<double, 2>{{dx / l, dy / l}} : std::array<double, 2>{{0., 0.}};
  };
  const double least_straightness = std::cos(fold_line_max_turn);
  struct Joint
  {
    double straightness;  // the cosine of the turn
    std::size_t x, y;     // two ends at the vertex
  };
  std::vector<Joint> joints;
  std::vector<char> joined(2 * m, 0);
  // the vertices of the edges numbered from 0, and the number of each end's
  std::vector<std::size_t> vertices, number_of_end(2 * m);
  for(std::size_t lo = 0; lo < ends.size();) {
    std::size_t hi = lo + 1;
    while(hi < ends.size() && ends[hi].first == ends[lo].first) ++hi;
    for(std::size_t p = lo; p < hi; ++p) number_of_end[ends[p].second] = vertices.size();
    vertices.push_back(ends[lo].first);
    joints.clear();
    for(std::size_t p = lo; p < hi; ++p)
      for(std::size_t q = p + 1; q < hi; ++q) {
        const std::size_t x = ends[p].second, y = ends[q].second;
        // the same kind, meeting on the page (not across a cut inside the piece)
        if(edges[x / 2].kind != edges[y / 2].kind || point(x) != point(y)) continue;
        const std::array<double, 2> u = away(x), w = away(y);
        const double straightness = -(u[0] * w[0] + u[1] * w[1]);
        if(straightness >= least_straightness) joints.push_back({straightness, x, y});
      }
    // the straightest joints first, each end in one joint at most
    std::sort(joints.begin(), joints.end(), [](const Joint& j, const Joint& k) {
      return j.straightness > k.straightness || (j.straightness == k.straightness && j.x < k.x) ||
             (j.straightness == k.straightness && j.x == k.x && j.y < k.y);
    });
    for(const Joint& j : joints) {
      if(joined[j.x] || joined[j.y]) continue;
      joined[j.x] = joined[j.y] = 1;
      parent[root(j.x / 2)] = root(j.y / 2);
    }
    lo = hi;
  }
  // the lines: their lengths and ends
  std::vector<double> length(m, 0.);
  std::vector<std::vector<std::size_t>> line_ends(m), members(m);  // numbered vertices, edges
  for(std::size_t i = 0; i < m; ++i) {
    const std::size_t r = root(i);
    members[r].push_back(i);
    length[r] += std::hypot(edges[i].b[0] - edges[i].a[0], edges[i].b[1] - edges[i].a[1]);
    for(std::size_t s = 0; s < 2; ++s)
      if(!joined[2 * i + s]) line_ends[r].push_back(number_of_end[2 * i + s]);
  }
  std::vector<std::vector<std::size_t>> lines_ending_at(vertices.size());  // open lines
  for(std::size_t r = 0; r < m; ++r)
    if(line_ends[r].size() == 2)
      for(std::size_t v : line_ends[r]) lines_ending_at[v].push_back(r);
  // drawn: the lines long enough, then, until none is added, the open lines
  // whose two ends are each on the border or on a line drawn
  std::vector<char> drawn(m, 0), anchored(vertices.size(), 0);
  for(std::size_t v = 0; v < vertices.size(); ++v)
    anchored[v] = std::binary_search(border.begin(), border.end(), vertices[v]);
  std::vector<std::size_t> newly_anchored;
  auto draw = [&](std::size_t r) {
    drawn[r] = 1;
    for(std::size_t i : members[r])
      for(std::size_t end : {2 * i, 2 * i + 1}) {
        const std::size_t k = number_of_end[end];
        if(!anchored[k]) anchored[k] = 1, newly_anchored.push_back(k);
      }
  };
  auto draw_if_anchored = [&](std::size_t r) {
    if(!drawn[r] && line_ends[r].size() == 2 && anchored[line_ends[r][0]] && anchored[line_ends[r][1]]) draw(r);
  };
  for(std::size_t r = 0; r < m; ++r)
    if(root(r) == r && length[r] >= min_length) draw(r);
  for(std::size_t r = 0; r < m; ++r)
    if(root(r) == r) draw_if_anchored(r);
  while(!newly_anchored.empty()) {
    const std::size_t v = newly_anchored.back();
    newly_anchored.pop_back();
    for(std::size_t r : lines_ending_at[v]) draw_if_anchored(r);
  }
  std::vector<char> on_line(m);
  for(std::size_t i = 0; i < m; ++i) on_line[i] = drawn[root(i)];
  return on_line;
}

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_IO_INTERNAL_FOLD_LINES_H
