// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_INTERNAL_CLUSTER_VSA_H
#define CGAL_QD_INTERNAL_CLUSTER_VSA_H

// Step 1's variational shape approximation run on clusters of faces instead
// of faces: on a fine mesh the Lloyd iteration floods the whole mesh three
// times per round of added proxies, and a mesh of a million faces needs tens
// of rounds. A cluster holds the faces within a small radius (the clusters of
// the normal smoothing, which never straddle a crease), and everything the
// iteration needs of a set of faces follows from two sums per cluster: with
// S = sum a_f n_f and A = sum a_f over its faces (unit normals n_f), the L2,1
// error of the cluster against a normal n is
//   sum a_f |n_f - n|^2 = A (1 + |n|^2) - 2 S.n,
// exactly, and the best normal of a chart is S / |S| over its clusters. The
// charts found on the clusters then seed the Lloyd iteration on the faces,
// which moves their borders off the clusters' edges.

#include <CGAL_QD/internal/charts.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL_QD {
namespace internal {

class Cluster_vsa
{
public:
  static constexpr std::size_t none = std::size_t(-1);

  // `sum`: S and A of every cluster ({S_x, S_y, S_z, A}); `first`, `next_to`:
  // the clusters next to cluster c are next_to[first[c]] to next_to[first[c + 1] - 1]
  Cluster_vsa(std::vector<std::array<double, 4>> sum, std::vector<std::size_t> first,
              std::vector<std::size_t> next_to)
      : m_sum(std::move(sum)), m_first(std::move(first)), m_next_to(std::move(next_to)),
        m_proxy_of(m_sum.size(), none)
  {}

  std::size_t number_of_clusters() const { return m_sum.size(); }
  std::size_t number_of_proxies() const { return m_proxies.size(); }
  // the proxy of every cluster
  const std::vector<std::size_t>& proxy_of() const { return m_proxy_of; }
  // the normalised L2,1 error and the area of the chart of proxy p (after `run()`)
  double chart_error(std::size_t p) const
  {
    return m_proxies[p].area > 0 ? m_proxies[p].error / m_proxies[p].area : 0.;
  }
  double chart_area(std::size_t p) const { return m_proxies[p].area; }

  // one proxy per connected component of the cluster graph
  void bootstrap()
  {
    std::fill(m_proxy_of.begin(), m_proxy_of.end(), none);
    m_proxies.clear();
    std::vector<std::size_t> stack;
    for(std::size_t s = 0; s < m_sum.size(); ++s) {
      if(m_proxy_of[s] != none) continue;
      const std::size_t p = m_proxies.size();
      m_proxies.push_back(Proxy());
      m_proxy_of[s] = p;
      stack.assign(1, s);
      while(!stack.empty()) {
        const std::size_t c = stack.back();
        stack.pop_back();
        for(std::size_t e = m_first[c]; e < m_first[c + 1]; ++e)
          if(m_proxy_of[m_next_to[e]] == none) {
            m_proxy_of[m_next_to[e]] = p;
            stack.push_back(m_next_to[e]);
          }
      }
    }
    refit();
  }

  // `iterations` rounds of flooding from the seeds and refitting
  void run(std::size_t iterations)
  {
    for(std::size_t i = 0; i < iterations; ++i) {
      partition();
      refit();
    }
  }

  // a proxy at the cluster that deviates most, per unit area, from the proxy
  // of the chart with the largest error; false if that chart is one cluster
  bool add_to_furthest_proxy()
  {
    std::size_t worst = 0;
    for(std::size_t p = 1; p < m_proxies.size(); ++p)
      if(m_proxies[worst].error < m_proxies[p].error) worst = p;
    std::size_t furthest = none;
    double most = 0;
    for(std::size_t c = 0; c < m_sum.size(); ++c) {
      if(m_proxy_of[c] != worst || c == m_proxies[worst].seed || !(m_sum[c][3] > 0)) continue;
      const double e = error(c, m_proxies[worst].normal) / m_sum[c][3];
      if(furthest == none || most < e) {
        most = e;
        furthest = c;
      }
    }
    if(furthest == none) return false;
    add_proxy_at(furthest);
    return true;
  }

  // `n` proxies spread over the charts in proportion to their error (error
  // diffusion, as CGAL's `add_proxies_error_diffusion()`), each at the
  // cluster of its chart that deviates most from the chart's proxy
  std::size_t add_proxies_error_diffusion(std::size_t n)
  {
    double total = 0;
    for(const Proxy& p : m_proxies) total += p.error;
    if(n == 0 || !(total > 0)) return 0;
    const double share = total / static_cast<double>(n);
    std::vector<std::size_t> by_error(m_proxies.size());
    for(std::size_t p = 0; p < by_error.size(); ++p) by_error[p] = p;
    std::stable_sort(by_error.begin(), by_error.end(),
                     [&](std::size_t a, std::size_t b) { return m_proxies[a].error < m_proxies[b].error; });
    std::vector<std::size_t> to_add(m_proxies.size(), 0);
    double residual = 0;
    for(std::size_t p : by_error) {
      const double x = (residual + m_proxies[p].error) / share, rounded = std::floor(x + 0.5);
      residual = (x - rounded) * share;
      to_add[p] = static_cast<std::size_t>((std::max)(0., rounded));
    }
    // the clusters of every chart, most deviant first
    const std::size_t np = m_proxies.size();
    std::vector<std::vector<std::pair<double, std::size_t>>> candidates(np);
    for(std::size_t c = 0; c < m_sum.size(); ++c) {
      const std::size_t p = m_proxy_of[c];
      if(to_add[p] == 0 || c == m_proxies[p].seed || !(m_sum[c][3] > 0)) continue;
      candidates[p].push_back({error(c, m_proxies[p].normal) / m_sum[c][3], c});
    }
    std::size_t added = 0;
    for(std::size_t p = 0; p < np; ++p) {
      std::vector<std::pair<double, std::size_t>>& list = candidates[p];
      const std::size_t k = (std::min)(to_add[p], list.size());
      std::partial_sort(list.begin(), list.begin() + k, list.end(),
                        [](const auto& a, const auto& b) { return a.first > b.first || (a.first == b.first && a.second < b.second); });
      for(std::size_t i = 0; i < k; ++i) {
        add_proxy_at(list[i].second);
        ++added;
      }
    }
    return added;
  }

private:
  struct Proxy
  {
    std::array<double, 3> normal = {{0., 0., 0.}};
    std::size_t seed = none;
    double error = 0, area = 0;
  };
  struct Queued
  {
    double error;
    std::size_t cluster, proxy;
    bool operator<(const Queued& other) const
    {
      // the least error first; ties by cluster, then proxy, so that the order is total
      if(error != other.error) return error > other.error;
      if(cluster != other.cluster) return cluster > other.cluster;
      return proxy > other.proxy;
    }
  };

  // the L2,1 error of the faces of cluster c against the normal n
  double error(std::size_t c, const std::array<double, 3>& n) const
  {
    const std::array<double, 4>& s = m_sum[c];
    return s[3] * (1 + n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) - 2 * (s[0] * n[0] + s[1] * n[1] + s[2] * n[2]);
  }

  // every cluster to the proxy that reaches it first, flooding from the
  // seeds in the order of the error of the cluster per unit area
  void partition()
  {
    std::fill(m_proxy_of.begin(), m_proxy_of.end(), none);
    m_queue.clear();
    auto push = [&](std::size_t c, std::size_t p) {
      const double a = m_sum[c][3];
      m_queue.push_back(Queued{a > 0 ? error(c, m_proxies[p].normal) / a : 0., c, p});
      std::push_heap(m_queue.begin(), m_queue.end());
    };
    for(std::size_t p = 0; p < m_proxies.size(); ++p)
      if(m_proxies[p].seed != none && m_proxy_of[m_proxies[p].seed] == none) m_proxy_of[m_proxies[p].seed] = p;
    for(std::size_t p = 0; p < m_proxies.size(); ++p) {
      const std::size_t s = m_proxies[p].seed;
      if(s == none || m_proxy_of[s] != p) continue;
      for(std::size_t e = m_first[s]; e < m_first[s + 1]; ++e)
        if(m_proxy_of[m_next_to[e]] == none) push(m_next_to[e], p);
    }
    while(!m_queue.empty()) {
      const Queued q = m_queue.front();
      std::pop_heap(m_queue.begin(), m_queue.end());
      m_queue.pop_back();
      if(m_proxy_of[q.cluster] != none) continue;
      m_proxy_of[q.cluster] = q.proxy;
      for(std::size_t e = m_first[q.cluster]; e < m_first[q.cluster + 1]; ++e)
        if(m_proxy_of[m_next_to[e]] == none) push(m_next_to[e], q.proxy);
    }
  }

  // every proxy fitted to its clusters: the normal S / |S|, the seed at the
  // cluster that deviates least from it per unit area, the error and area
  void refit()
  {
    const std::size_t np = m_proxies.size();
    std::vector<std::array<double, 4>> total(np, {{0., 0., 0., 0.}});
    for(std::size_t c = 0; c < m_sum.size(); ++c)
      if(m_proxy_of[c] != none)
        for(int k = 0; k < 4; ++k) total[m_proxy_of[c]][k] += m_sum[c][k];
    for(std::size_t p = 0; p < np; ++p) {
      const std::array<double, 4>& t = total[p];
      const double l = std::sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
      Proxy& proxy = m_proxies[p];
      if(l > 0) proxy.normal = {{t[0] / l, t[1] / l, t[2] / l}};
      proxy.area = t[3];
      proxy.error = 0;
      proxy.seed = none;
    }
    std::vector<double> least(np, 0.);
    for(std::size_t c = 0; c < m_sum.size(); ++c) {
      const std::size_t p = m_proxy_of[c];
      if(p == none) continue;
      const double e = error(c, m_proxies[p].normal), a = m_sum[c][3], per_area = a > 0 ? e / a : 0.;
      m_proxies[p].error += e;
      if(m_proxies[p].seed == none || per_area < least[p]) {
        least[p] = per_area;
        m_proxies[p].seed = c;
      }
    }
  }

  // a new proxy fitted to cluster c alone; the cluster leaves its chart
  void add_proxy_at(std::size_t c)
  {
    Proxy p;
    const std::array<double, 4>& s = m_sum[c];
    const double l = std::sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
    if(l > 0) p.normal = {{s[0] / l, s[1] / l, s[2] / l}};
    p.seed = c;
    p.area = s[3];
    p.error = error(c, p.normal);
    Proxy& before = m_proxies[m_proxy_of[c]];
    before.error -= error(c, before.normal);
    before.area -= s[3];
    m_proxy_of[c] = m_proxies.size();
    m_proxies.push_back(p);
  }

  std::vector<std::array<double, 4>> m_sum;
  std::vector<std::size_t> m_first, m_next_to;
  std::vector<std::size_t> m_proxy_of;
  std::vector<Proxy> m_proxies;
  std::vector<Queued> m_queue;
};

// The Lloyd iteration on the clusters `cluster_of` (by face index) of the
// faces `geo`, next to each other across any edge of `next_to`, creases
// included.
inline Cluster_vsa cluster_vsa(const std::vector<Face_geometry>& geo,
                               const std::vector<std::array<std::size_t, 3>>& next_to,
                               const std::vector<std::size_t>& cluster_of)
{
  const std::size_t none = std::size_t(-1);
  std::size_t nc = 0;
  for(std::size_t c : cluster_of) nc = (std::max)(nc, c + 1);
  std::vector<std::array<double, 4>> sum(nc, {{0., 0., 0., 0.}});
  for(std::size_t f = 0; f < geo.size(); ++f) {
    std::array<double, 4>& s = sum[cluster_of[f]];
    for(int k = 0; k < 3; ++k) s[k] += geo[f].area * geo[f].normal[k];
    s[3] += geo[f].area;
  }
  std::vector<std::vector<std::size_t>> adjacent(nc);
  for(std::size_t f = 0; f < geo.size(); ++f)
    for(std::size_t g : next_to[f])
      if(g != none && cluster_of[g] != cluster_of[f]) adjacent[cluster_of[f]].push_back(cluster_of[g]);
  std::vector<std::size_t> start(nc + 1, 0), neighbours;
  for(std::size_t c = 0; c < nc; ++c) {
    std::sort(adjacent[c].begin(), adjacent[c].end());
    adjacent[c].erase(std::unique(adjacent[c].begin(), adjacent[c].end()), adjacent[c].end());
    neighbours.insert(neighbours.end(), adjacent[c].begin(), adjacent[c].end());
    start[c + 1] = neighbours.size();
    std::vector<std::size_t>().swap(adjacent[c]);
  }
  return Cluster_vsa(std::move(sum), std::move(start), std::move(neighbours));
}

// Step 1's proxies found on the clusters of a fine mesh (`cluster_of`, by
// face index): bootstrap and relax, then add proxies in rounds as on the
// faces until every chart of at least `min_area` is within `tolerance` or
// there are `max_proxies`. `cluster_of` receives the chart of every face (n
// charts, each with faces), `first` the proxies of the bootstrap; returns the
// rounds of additions.
inline std::size_t vsa_on_clusters(const std::vector<Face_geometry>& geo,
                                   const std::vector<std::array<std::size_t, 3>>& next_to, double tolerance,
                                   double min_area, std::size_t max_proxies, std::size_t relaxations,
                                   std::vector<std::size_t>& cluster_of, std::size_t& first, std::size_t& n)
{
  const std::size_t none = std::size_t(-1);
  Cluster_vsa vsa = cluster_vsa(geo, next_to, cluster_of);
  vsa.bootstrap();
  first = vsa.number_of_proxies();
  vsa.run(relaxations);
  std::size_t rounds = 0;
  for(;;) {
    std::size_t violating = 0;
    for(std::size_t p = 0; p < vsa.number_of_proxies(); ++p)
      violating += vsa.chart_error(p) > tolerance && vsa.chart_area(p) >= min_area ? 1 : 0;
    if(violating == 0 || vsa.number_of_proxies() >= max_proxies) break;
    const std::size_t add = (std::min)(max_proxies - vsa.number_of_proxies(), violating);
    const std::size_t added = add == 1 ? std::size_t(vsa.add_to_furthest_proxy()) : vsa.add_proxies_error_diffusion(add);
    if(added == 0) break;
    vsa.run(relaxations);
    ++rounds;
  }
  // the charts by face, numbered without gaps
  const std::vector<std::size_t>& proxy = vsa.proxy_of();
  std::vector<std::size_t> number(vsa.number_of_proxies(), none);
  n = 0;
  for(std::size_t& c : cluster_of) {
    std::size_t& k = number[proxy[c]];
    if(k == none) k = n++;
    c = k;
  }
  return rounds;
}

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_INTERNAL_CLUSTER_VSA_H
