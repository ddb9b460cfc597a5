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
// With `CGAL::Parallel_tag` the faces' discs are summed in parallel (the
// clusters are grown first, in order): the result is the same.
template <class ConcurrencyTag = CGAL::Sequential_tag, class TriangleMesh, class FIM>
std::vector<Face_geometry> smooth_face_normals(const TriangleMesh& tm, const FIM& fim,
                                               const std::vector<Face_geometry>& geo, double radius,
                                               double sharp_cos, double cluster_above = clustered_disc_faces,
                                               double cluster_radius = disc_cluster_radius)
{
  const std::size_t nf = geo.size(), none = std::size_t(-1);
  std::vector<Face_geometry> out = geo;
  if(!(radius > 0) || nf == 0) return out;
  const double r2 = radius * radius;
  const std::vector<std::array<std::size_t, 3>> next_to = smooth_neighbours(tm, fim, geo, sharp_cos);
  auto set_normal = [&](std::size_t s, const std::array<double, 3>& sum) {
    const double l = std::sqrt(sum[0] * sum[0] + sum[1] * sum[1] + sum[2] * sum[2]);
    if(l > 0)
      for(int k = 0; k < 3; ++k) out[s].normal[k] = sum[k] / l;
  };
  double area = 0;
  for(const Face_geometry& g : geo) area += g.area;
  const bool clustered = area > 0 && double(nf) * pi * r2 / area > cluster_above;

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
    for_each_face(nf, [&](std::size_t s, std::vector<std::size_t>& stamp, std::vector<std::size_t>& queue) {
      bool near = false;  // most faces of a coarse mesh have no neighbour within the radius
      for(int j = 0; j < 3; ++j) {
        const std::size_t g = next_to[s][j];
        near = near || (g != none && squared_distance3(geo[s].centroid, geo[g].centroid) <= r2);
      }
      if(!near) return;
      const std::array<double, 3> sum = disc_sum(
          s, geo[s].centroid, r2,
          [&](std::size_t i, const auto& visit) {
            for(int j = 0; j < 3; ++j)
              if(next_to[i][j] != none) visit(next_to[i][j]);
          },
          [&](std::size_t g) -> const std::array<double, 3>& { return geo[g].centroid; },
          [&](std::size_t i) {
            return std::array<double, 3>{geo[i].area * geo[i].normal[0], geo[i].area * geo[i].normal[1],
                                         geo[i].area * geo[i].normal[2]};
          },
          s, stamp, queue);
      set_normal(s, sum);
    });
    return out;
  }

  // clusters: grown from the faces in index order, across smooth edges, to the
  // faces within the cluster radius of the seed's centroid
  const double c2 = cluster_radius * cluster_radius * r2;
  std::vector<std::size_t> cluster_of(nf, none), queue;
  std::vector<std::array<double, 3>> normal_sum, centroid;  // area-weighted sum; centroid of the faces
  std::vector<double> cluster_area;
  for(std::size_t s = 0; s < nf; ++s) {
    if(cluster_of[s] != none) continue;
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
  for_each_face(nc, [&](std::size_t s, std::vector<std::size_t>& seen, std::vector<std::size_t>& scratch) {
    const std::size_t c0 = cluster_of[s];
    bool near = cluster_area[c0] > geo[s].area;  // the face's own cluster has other faces
    for(std::size_t d : adjacent[c0]) near = near || squared_distance3(geo[s].centroid, centroid[d]) <= r2;
    if(!near) return;
    const std::array<double, 3> sum = disc_sum(
        c0, geo[s].centroid, r2,
        [&](std::size_t c, const auto& visit) {
          for(std::size_t d : adjacent[c]) visit(d);
        },
        [&](std::size_t c) -> const std::array<double, 3>& { return centroid[c]; },
        [&](std::size_t c) -> const std::array<double, 3>& { return normal_sum[c]; }, s, seen, scratch);
    set_normal(s, sum);
  });
  return out;
}

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_INTERNAL_SMOOTH_FACE_NORMALS_H
