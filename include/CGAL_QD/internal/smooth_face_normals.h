// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_INTERNAL_SMOOTH_FACE_NORMALS_H
#define CGAL_QD_INTERNAL_SMOOTH_FACE_NORMALS_H

// The face normals of step 1 averaged over geodesic discs, face by face on
// coarse meshes and cluster by cluster on fine ones, where a disc holds
// thousands of faces.

#include <CGAL_QD/internal/charts.h>
#include <CGAL_QD/internal/constants.h>
#include <CGAL_QD/internal/parallel.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL_QD {
namespace internal {

// Beyond this mean number of faces per disc (the face count times the
// disc's share of the surface area), the discs are gathered from clusters of
// faces instead of faces: the face by face flood costs that many face visits
// per face, which grows with the square of the face count.
inline constexpr double clustered_disc_faces = 256;
// the radius of a cluster, relative to the radius of the discs
inline constexpr double disc_cluster_radius = 0.125;

// The neighbours of every face (by face index) across the edges that are not
// sharp: the dihedral angle turns the normal by at most acos(`sharp_cos`).
template <class TriangleMesh, class FIM>
std::vector<std::array<std::size_t, 3>> smooth_neighbours(const TriangleMesh& tm, const FIM& fim,
                                                          const std::vector<Face_geometry>& geo, double sharp_cos)
{
  const std::size_t none = std::size_t(-1);
  std::vector<std::array<std::size_t, 3>> next_to = face_neighbours(tm, fim);
  for(std::size_t i = 0; i < next_to.size(); ++i)
    for(std::size_t& g : next_to[i]) {
      if(g == none) continue;
      const double dot = geo[i].normal[0] * geo[g].normal[0] + geo[i].normal[1] * geo[g].normal[1] +
                         geo[i].normal[2] * geo[g].normal[2];
      if(dot < sharp_cos) g = none;
    }
  return next_to;
}

inline double squared_distance3(const std::array<double, 3>& a, const std::array<double, 3>& b)
{
  const double x = a[0] - b[0], y = a[1] - b[1], z = a[2] - b[2];
  return x * x + y * y + z * z;
}

// The indices 0 to n - 1 in the order of a Morton curve through the points
// `point(i)` (ties in index order): points close together come close
// together in the order.
template <class Point>
std::vector<std::size_t> morton_order(std::size_t n, const Point& point)
{
  std::array<double, 3> lo = {0., 0., 0.}, hi = {0., 0., 0.};
  for(std::size_t i = 0; i < n; ++i)
    for(int k = 0; k < 3; ++k) {
      lo[k] = i == 0 ? point(i)[k] : (std::min)(lo[k], point(i)[k]);
      hi[k] = i == 0 ? point(i)[k] : (std::max)(hi[k], point(i)[k]);
    }
  const double cells = double((1u << 21) - 1);  // 21 bits a coordinate, 63 bits a key
  const double extent = (std::max)(hi[0] - lo[0], (std::max)(hi[1] - lo[1], hi[2] - lo[2]));
  const double scale = extent > 0 ? cells / extent : 0.;
  // the bits of a 21-bit number spread to every third bit
  auto spread = [](std::uint64_t x) {
    x &= 0x1fffff;
    x = (x | x << 32) & 0x1f00000000ffffULL;
    x = (x | x << 16) & 0x1f0000ff0000ffULL;
    x = (x | x << 8) & 0x100f00f00f00f00fULL;
    x = (x | x << 4) & 0x10c30c30c30c30c3ULL;
    x = (x | x << 2) & 0x1249249249249249ULL;
    return x;
  };
  std::vector<std::pair<std::uint64_t, std::size_t>> key(n);
  for(std::size_t i = 0; i < n; ++i) {
    std::uint64_t code = 0;
    for(int k = 0; k < 3; ++k) {
      double q = (point(i)[k] - lo[k]) * scale;
      q = q >= 0 ? (std::min)(q, cells) : 0.;  // a NaN gives 0
      code |= spread(static_cast<std::uint64_t>(q)) << k;
    }
    key[i] = {code, i};
  }
  std::sort(key.begin(), key.end());
  std::vector<std::size_t> order(n);
  for(std::size_t i = 0; i < n; ++i) order[i] = key[i].second;
  return order;
}

// The sum of `weighted(i)` (an area-weighted normal) over the nodes i reached
// from `start` through `for_each_neighbour(i, visit)` without leaving the ball
// of squared radius `r2` around `centre`, with `position(i)`; `stamp` marks
// the nodes reached with `token`, `queue` is scratch.
template <class ForEachNeighbour, class Position, class Weighted>
std::array<double, 3> disc_sum(std::size_t start, const std::array<double, 3>& centre, double r2,
                               const ForEachNeighbour& for_each_neighbour, const Position& position,
                               const Weighted& weighted, std::size_t token, std::vector<std::size_t>& stamp,
                               std::vector<std::size_t>& queue)
{
  std::array<double, 3> sum = {0., 0., 0.};
  stamp[start] = token;
  queue.assign(1, start);
  for(std::size_t q = 0; q < queue.size(); ++q) {
    const std::size_t i = queue[q];
    const std::array<double, 3> w = weighted(i);
    for(int k = 0; k < 3; ++k) sum[k] += w[k];
    for_each_neighbour(i, [&](std::size_t g) {
      if(stamp[g] == token || squared_distance3(centre, position(g)) > r2) return;
      stamp[g] = token;
      queue.push_back(g);
    });
  }
  return sum;
}

// The normal of every face averaged, weighted by area, over the faces whose
// centroids lie within `radius` of its centroid and are reached from it
// through such faces across shared edges (a geodesic disc for a radius small
// against the curvature). An edge whose dihedral angle turns the normal by
// more than acos(`sharp_cos`) is not crossed, so creases stay sharp. A face
// whose neighbours are all farther than `radius` keeps its normal: the
// smoothing only removes variation at scales below `radius`.
//
// When a disc holds more than `cluster_above` faces on average, the faces are
// first grouped into clusters of radius `cluster_radius` times `radius`
// (grown across the same edges, so no cluster straddles a crease), and each
// face's disc is the union of the clusters whose centroids lie within
// `radius` of the face's centroid, reached through such clusters. The rim of
// the disc is then known to a cluster's width, and the cost per face is the
// number of clusters in a disc, which does not grow with the face count.
//
// Each connected component has its own radius: `component_radius[c]` for
// the faces with `component[face] == c` (a disc never leaves its component).
// Where the components hold more than `cluster_above` faces a disc on
// average (weighted by their faces), all are clustered.
//
// With `CGAL::Parallel_tag` the faces' discs are summed in parallel (the
// clusters are grown first, in order): the result is the same.
template <class ConcurrencyTag = CGAL::Sequential_tag, class TriangleMesh, class FIM>
std::vector<Face_geometry> smooth_face_normals(const TriangleMesh& tm, const FIM& fim,
                                               const std::vector<Face_geometry>& geo,
                                               const std::vector<std::size_t>& component,
                                               const std::vector<double>& component_radius, double sharp_cos,
                                               double cluster_above = clustered_disc_faces,
                                               double cluster_radius = disc_cluster_radius)
{
  const std::size_t nf = geo.size(), none = std::size_t(-1), nc0 = component_radius.size();
  std::vector<Face_geometry> out = geo;
  std::vector<double> r2_of_component(nc0, 0.);
  for(std::size_t c = 0; c < nc0; ++c)
    if(component_radius[c] > 0) r2_of_component[c] = component_radius[c] * component_radius[c];
  if(nf == 0 || std::none_of(r2_of_component.begin(), r2_of_component.end(), [](double r2) { return r2 > 0; }))
    return out;
  auto r2_of = [&](std::size_t face) { return r2_of_component[component[face]]; };
  const std::vector<std::array<std::size_t, 3>> next_to = smooth_neighbours(tm, fim, geo, sharp_cos);
  auto set_normal = [&](std::size_t s, const std::array<double, 3>& sum) {
    const double l = std::sqrt(sum[0] * sum[0] + sum[1] * sum[1] + sum[2] * sum[2]);
    if(l > 0)
      for(int k = 0; k < 3; ++k) out[s].normal[k] = sum[k] / l;
  };
  // the faces a disc holds on average
  bool clustered = false;
  if(nc0 == 1) {
    double area = 0;
    for(const Face_geometry& g : geo) area += g.area;
    clustered = area > 0 && double(nf) * pi * r2_of_component[0] / area > cluster_above;
  } else {
    std::vector<double> area(nc0, 0.), count(nc0, 0.);
    for(std::size_t i = 0; i < nf; ++i) {
      area[component[i]] += geo[i].area;
      count[component[i]] += 1;
    }
    double weighted = 0;  // sum of faces times the faces of their discs
    for(std::size_t c = 0; c < nc0; ++c)
      if(area[c] > 0) weighted += count[c] * (count[c] * pi * r2_of_component[c] / area[c]);
    clustered = weighted > cluster_above * double(nf);
  }

  // the faces in `blocks` ranges, each with its own scratch: every face's sum
  // is the same whatever the number of blocks
  const std::size_t blocks = (std::min)(nf, batch_size<ConcurrencyTag>());
  auto for_each_face = [&](std::size_t scratch_size, const auto& smooth) {
    for_each_index<ConcurrencyTag>(blocks, [&](std::size_t b) {
      std::vector<std::size_t> stamp(scratch_size, none), queue;
      for(std::size_t s = b * nf / blocks; s < (b + 1) * nf / blocks; ++s) smooth(s, stamp, queue);
    });
  };
  if(!clustered) {
    // the floods run on a copy of the faces renumbered in Morton order, so
    // that the faces of a disc lie close together in memory. A flood visits
    // the same faces in the same order as in the mesh's numbering (every face
    // keeps the order of its neighbours), so every sum is the same.
    const std::uint32_t nil = std::uint32_t(-1);
    struct Node
    {
      std::array<double, 3> centroid, weighted;  // the area-weighted normal
      std::array<std::uint32_t, 3> next;         // the smooth neighbours, `nil` for none
    };
    const std::vector<std::size_t> order =
        morton_order(nf, [&](std::size_t i) -> const std::array<double, 3>& { return geo[i].centroid; });
    std::vector<std::uint32_t> rank(nf);
    for(std::size_t r = 0; r < nf; ++r) rank[order[r]] = static_cast<std::uint32_t>(r);
    std::vector<Node> node(nf);
    for(std::size_t r = 0; r < nf; ++r) {
      const Face_geometry& g = geo[order[r]];
      node[r].centroid = g.centroid;
      for(int k = 0; k < 3; ++k) node[r].weighted[k] = g.area * g.normal[k];
      for(int j = 0; j < 3; ++j) node[r].next[j] = next_to[order[r]][j] == none ? nil : rank[next_to[order[r]][j]];
    }
    for_each_face(nf, [&](std::size_t s, std::vector<std::size_t>& stamp, std::vector<std::size_t>& queue) {
      const double r2 = r2_of(order[s]);
      if(!(r2 > 0)) return;
      bool near = false;  // most faces of a coarse mesh have no neighbour within the radius
      for(int j = 0; j < 3; ++j) {
        const std::uint32_t g = node[s].next[j];
        near = near || (g != nil && squared_distance3(node[s].centroid, node[g].centroid) <= r2);
      }
      if(!near) return;
      const std::array<double, 3> sum = disc_sum(
          s, node[s].centroid, r2,
          [&](std::size_t i, const auto& visit) {
            for(int j = 0; j < 3; ++j)
              if(node[i].next[j] != nil) visit(std::size_t(node[i].next[j]));
          },
          [&](std::size_t g) -> const std::array<double, 3>& { return node[g].centroid; },
          [&](std::size_t i) -> const std::array<double, 3>& { return node[i].weighted; }, s, stamp, queue);
      set_normal(order[s], sum);
    });
    return out;
  }

  // clusters: grown from the faces in index order, across smooth edges, to the
  // faces within the cluster radius of the seed's centroid
  std::vector<std::size_t> cluster_of(nf, none), queue;
  std::vector<std::array<double, 3>> normal_sum, centroid;  // area-weighted sum; centroid of the faces
  std::vector<double> cluster_area;
  for(std::size_t s = 0; s < nf; ++s) {
    if(cluster_of[s] != none) continue;
    const double c2 = cluster_radius * cluster_radius * r2_of(s);
    const std::size_t c = normal_sum.size();
    std::array<double, 3> n = {0., 0., 0.}, p = {0., 0., 0.};
    double a = 0;
    cluster_of[s] = c;
    queue.assign(1, s);
    for(std::size_t q = 0; q < queue.size(); ++q) {
      const std::size_t i = queue[q];
      for(int k = 0; k < 3; ++k) {
        n[k] += geo[i].area * geo[i].normal[k];
        p[k] += geo[i].area * geo[i].centroid[k];
      }
      a += geo[i].area;
      for(int j = 0; j < 3; ++j) {
        const std::size_t g = next_to[i][j];
        if(g == none || cluster_of[g] != none || squared_distance3(geo[s].centroid, geo[g].centroid) > c2) continue;
        cluster_of[g] = c;
        queue.push_back(g);
      }
    }
    if(a > 0)
      for(int k = 0; k < 3; ++k) p[k] /= a;
    else
      p = geo[s].centroid;
    normal_sum.push_back(n);
    centroid.push_back(p);
    cluster_area.push_back(a);
  }
  const std::size_t nc = normal_sum.size();
  // clusters next to each other across a smooth edge
  std::vector<std::vector<std::size_t>> adjacent(nc);
  for(std::size_t i = 0; i < nf; ++i)
    for(int j = 0; j < 3; ++j) {
      const std::size_t g = next_to[i][j];
      if(g != none && cluster_of[g] != cluster_of[i]) adjacent[cluster_of[i]].push_back(cluster_of[g]);
    }
  for(std::vector<std::size_t>& a : adjacent) {
    std::sort(a.begin(), a.end());
    a.erase(std::unique(a.begin(), a.end()), a.end());
  }
  // the floods run on the clusters renumbered in Morton order, each keeping
  // the order of its neighbours (so every sum is the same), and the faces are
  // taken in Morton order, so that consecutive discs share their clusters
  const std::vector<std::size_t> order =
      morton_order(nc, [&](std::size_t c) -> const std::array<double, 3>& { return centroid[c]; });
  std::vector<std::uint32_t> rank(nc);
  for(std::size_t r = 0; r < nc; ++r) rank[order[r]] = static_cast<std::uint32_t>(r);
  struct Cluster
  {
    std::array<double, 3> centroid, normal_sum;
    double area;
    std::size_t first;  // its neighbours in `neighbour`, from `first` to the next cluster's
  };
  std::vector<Cluster> cluster(nc + 1);
  std::vector<std::uint32_t> neighbour;
  for(std::size_t r = 0; r < nc; ++r) {
    const std::size_t c = order[r];
    cluster[r] = {centroid[c], normal_sum[c], cluster_area[c], neighbour.size()};
    for(std::size_t d : adjacent[c]) neighbour.push_back(rank[d]);
  }
  cluster[nc].first = neighbour.size();
  const std::vector<std::size_t> face_order =
      morton_order(nf, [&](std::size_t i) -> const std::array<double, 3>& { return geo[i].centroid; });
  for_each_face(nc, [&](std::size_t s, std::vector<std::size_t>& seen, std::vector<std::size_t>& scratch) {
    const std::size_t f = face_order[s], c0 = rank[cluster_of[f]];
    const double r2 = r2_of(f);
    if(!(r2 > 0)) return;
    bool near = cluster[c0].area > geo[f].area;  // the face's own cluster has other faces
    for(std::size_t e = cluster[c0].first; e < cluster[c0 + 1].first; ++e)
      near = near || squared_distance3(geo[f].centroid, cluster[neighbour[e]].centroid) <= r2;
    if(!near) return;
    const std::array<double, 3> sum = disc_sum(
        c0, geo[f].centroid, r2,
        [&](std::size_t c, const auto& visit) {
          for(std::size_t e = cluster[c].first; e < cluster[c + 1].first; ++e) visit(std::size_t(neighbour[e]));
        },
        [&](std::size_t c) -> const std::array<double, 3>& { return cluster[c].centroid; },
        [&](std::size_t c) -> const std::array<double, 3>& { return cluster[c].normal_sum; }, s, seen, scratch);
    set_normal(f, sum);
  });
  return out;
}

// the same with one radius for the whole mesh
template <class ConcurrencyTag = CGAL::Sequential_tag, class TriangleMesh, class FIM>
std::vector<Face_geometry> smooth_face_normals(const TriangleMesh& tm, const FIM& fim,
                                               const std::vector<Face_geometry>& geo, double radius,
                                               double sharp_cos, double cluster_above = clustered_disc_faces,
                                               double cluster_radius = disc_cluster_radius)
{
  return smooth_face_normals<ConcurrencyTag>(tm, fim, geo, std::vector<std::size_t>(geo.size(), 0),
                                             std::vector<double>(1, radius), sharp_cos, cluster_above,
                                             cluster_radius);
}

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_INTERNAL_SMOOTH_FACE_NORMALS_H
