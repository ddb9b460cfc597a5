// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_INTERNAL_NORMAL_VSA_H
#define CGAL_QD_INTERNAL_NORMAL_VSA_H

// The variational shape approximation of step 1 (Cohen-Steiner, Alliez,
// Desbrun, *Variational Shape Approximation*, SIGGRAPH 2004) with the L2,1
// metric on given per-face normals and areas: the operations of CGAL's
// `Variational_shape_approximation` that `segment_by_error_controlled_vsa()`
// uses (seeding from the connected components, Lloyd relaxation, proxies
// added by error diffusion or at the worst face), on arrays indexed by face.
//
// It takes the same decisions as CGAL's class with the metric
// `Given_normals_L21_metric` (same flooding order, same fitted proxies, same
// seeds, the same sums in the same order), so it gives the same charts; it
// avoids the per-face allocations of the fitting, the property-map lookups
// and the halfedge walks of every flooding, which made step 1 a fifth of the
// segmentation of a 75K-face mesh.

#include <CGAL_QD/internal/bucket_queue.h>
#include <CGAL_QD/internal/charts.h>
#include <CGAL_QD/internal/parallel.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stack>
#include <vector>

namespace CGAL_QD {
namespace internal {

class Normal_vsa
{
public:
  static constexpr std::size_t none = std::size_t(-1);
  // faces and proxies are numbered with 32 bits in the flooding
  static constexpr std::size_t max_faces = std::size_t(UINT32_MAX);

  // `geo`: unit normal and area of every face; `next_to`: the faces across
  // the edges of every face, in the order of `faces_around_face()` (`none`
  // across a border); `order`: the faces in the order of `faces(tm)`
  Normal_vsa(const std::vector<Face_geometry>& geo, const std::vector<std::array<std::size_t, 3>>& next_to,
             const std::vector<std::size_t>& order)
      : m_proxy_of(geo.size(), no_face)
  {
    // the faces numbered in breadth-first order from the first face of
    // `order` (and from the next face not reached yet, per component), and
    // what the flooding reads of a face packed: on a mesh of a million faces
    // the flooding missed the cache at nearly every face it reached. Every
    // loop keeps the order it had (of `order`, of the neighbours), so the
    // decisions are the same.
    const std::size_t nf = geo.size();
    std::vector<std::uint32_t> id(nf, no_face);
    m_face.reserve(nf);
    for(std::size_t s : order) {
      if(id[s] != no_face) continue;
      std::size_t q = m_face.size();
      id[s] = static_cast<std::uint32_t>(m_face.size());
      m_face.push_back(s);
      for(; q < m_face.size(); ++q)
        for(std::size_t g : next_to[m_face[q]])
          if(g != none && id[g] == no_face) {
            id[g] = static_cast<std::uint32_t>(m_face.size());
            m_face.push_back(g);
          }
    }
    m_geo.reserve(nf);
    m_next_to.reserve(nf);
    for(std::size_t f : m_face) {
      const Face_geometry& g = geo[f];
      m_geo.push_back({g.normal[0], g.normal[1], g.normal[2], g.area});
      std::array<std::uint32_t, 3> m;
      for(int k = 0; k < 3; ++k) m[k] = next_to[f][k] == none ? no_face : id[next_to[f][k]];
      m_next_to.push_back(m);
    }
    m_order.reserve(order.size());
    for(std::size_t f : order) m_order.push_back(id[f]);
    double largest_area = 0;
    for(const std::array<double, 4>& g : m_geo) largest_area = (std::max)(largest_area, g[3]);
    m_buckets.set_largest_key(4 * largest_area);  // two unit normals are at most 2 apart
  }

  // one proxy per connected component, fitted to all its faces
  void bootstrap()
  {
    std::fill(m_proxy_of.begin(), m_proxy_of.end(), no_face);
    m_proxies.clear();
    if(m_order.empty()) return;
    std::vector<std::vector<std::size_t>> components;
    std::size_t seed = m_order.front(), component = 0, next = 0;
    for(;;) {
      std::vector<std::size_t> patch(1, seed);
      std::stack<std::size_t> stack;
      stack.push(seed);
      m_proxy_of[seed] = static_cast<std::uint32_t>(component);
      while(!stack.empty()) {
        const std::size_t f = stack.top();
        stack.pop();
        for(std::uint32_t g : m_next_to[f])
          if(g != no_face && m_proxy_of[g] == no_face) {
            patch.push_back(g);
            stack.push(g);
            m_proxy_of[g] = static_cast<std::uint32_t>(component);
          }
      }
      components.push_back(std::move(patch));
      // the first face not reached yet, in face order (the faces before the
      // last seed all were)
      while(next < m_order.size() && m_proxy_of[m_order[next]] != no_face) ++next;
      if(next == m_order.size()) break;
      ++component;
      seed = m_order[next];
    }
    for(const std::vector<std::size_t>& patch : components) m_proxies.push_back(fit(patch.begin(), patch.end()));
    m_fitted = false;  // fitted to the faces in another order than `m_order`
  }

  // `iterations` rounds of flooding from the seeds and refitting; the total error
  double run(std::size_t iterations)
  {
    for(std::size_t i = 0; i < iterations; ++i) {
      partition();
      refit();
    }
    return total_error();
  }

  double total_error() const
  {
    double sum = 0;
    for(const Proxy& p : m_proxies) sum += p.error;
    return sum;
  }

  // one proxy at the face of the worst chart furthest from its proxy
  std::size_t add_to_furthest_proxies(std::size_t n, std::size_t iterations)
  {
    std::size_t added = 0;
    while(added < n) {
      if(!add_to_furthest_proxy()) break;
      ++added;
      run(iterations);
    }
    return added;
  }

  // `n` proxies spread over the charts in proportion to their error
  std::size_t add_proxies_error_diffusion(std::size_t n)
  {
    const double avg_error = total_error() / static_cast<double>(n);
    std::vector<std::size_t> to_add(m_proxies.size(), 0);
    if(avg_error <= 0.0) {
      const double avg_faces = static_cast<double>(m_order.size()) / static_cast<double>(n);
      std::vector<double> size(m_proxies.size(), 0.0);
      for(std::size_t f : m_order) size[m_proxy_of[f]] += 1.0;
      double residual = 0.0;
      for(std::size_t i = 0; i < m_proxies.size(); ++i) {
        const double x = (residual + size[i]) / avg_faces, rounded = std::floor(x + 0.5);
        residual = (x - rounded) * avg_faces;
        to_add[i] = static_cast<std::size_t>(rounded);
      }
    } else {
      std::vector<Proxy_error> by_error;
      for(std::size_t i = 0; i < m_proxies.size(); ++i) by_error.push_back(Proxy_error{i, m_proxies[i].error});
      std::sort(by_error.begin(), by_error.end());
      double residual = 0.0;
      for(std::size_t i = 0; i < m_proxies.size(); ++i) {
        const double x = (residual + by_error[i].error) / avg_error, rounded = std::floor(x + 0.5);
        residual = (x - rounded) * avg_error;
        to_add[by_error[i].proxy] = static_cast<std::size_t>(rounded);
      }
    }
    std::size_t added = 0;
    for(std::size_t f : m_order) {
      const std::size_t p = m_proxy_of[f];
      if(m_proxies[p].seed == f) continue;
      if(to_add[p] > 0) {
        add_proxy_at(f);
        --to_add[p];
        ++added;
      }
    }
    return added;
  }

  std::size_t number_of_proxies() const { return m_proxies.size(); }

  // whether a flood met two entries of the same error, and floods with every
  // copy since (see `partition()`)
  bool floods_with_copies() const { return m_ties; }

  // whether the proxies are fitted to their charts in parallel (each on its
  // own, so the same numbers), on the threads of CGAL::Parallel_tag
  void fit_in_parallel(bool parallel) { m_parallel = parallel; }

  // Whether every proxy was last fitted to its chart's faces in the order of
  // `m_order` (by a relaxation), so that its error and area are those
  // `chart_errors()` (vsa_segmentation.h) computes of the chart, to the last
  // bit: the same sums in the same order.
  bool fitted_to_charts() const { return m_fitted; }

  // the normalised L2,1 error and the area of every chart, as
  // `chart_errors()` computes them; only where `fitted_to_charts()`
  void chart_errors(std::vector<double>& error, std::vector<double>& area) const
  {
    error.resize(m_proxies.size());
    area.resize(m_proxies.size());
    for(std::size_t k = 0; k < m_proxies.size(); ++k) {
      area[k] = m_proxies[k].area;
      error[k] = area[k] > 0 ? m_proxies[k].error / area[k] : 0.;
    }
  }

  // the proxy of every face
  std::vector<std::size_t> proxy_of() const
  {
    std::vector<std::size_t> p(m_proxy_of.size());
    for(std::size_t i = 0; i < p.size(); ++i) p[m_face[i]] = m_proxy_of[i] == no_face ? none : m_proxy_of[i];
    return p;
  }

private:
  static constexpr std::uint32_t no_face = UINT32_MAX;  // no neighbour; no proxy yet
  struct Proxy
  {
    std::array<double, 3> normal;
    std::size_t seed;
    double error;
    double area;  // of its faces
  };
  // 16 bytes: the heap moves these around more than anything else
  struct Face_to_integrate
  {
    double error;
    std::uint32_t face, proxy;
    bool operator<(const Face_to_integrate& other) const { return error > other.error; }
  };
  struct Error_of
  {
    double operator()(const Face_to_integrate& e) const { return e.error; }
  };
  struct Proxy_error
  {
    std::size_t proxy;
    double error;
    bool operator<(const Proxy_error& other) const { return error < other.error; }
  };

  // asks the processor to bring `p` into its cache (a hint; nothing where
  // the compiler has no way to say it)
  static void prefetch(const void* p)
  {
#if defined(__GNUC__) || defined(__clang__)
    __builtin_prefetch(p);
#else
    (void)p;
#endif
  }

  double error(std::size_t f, const std::array<double, 3>& n) const
  {
    const std::array<double, 4>& d = m_geo[f];
    const double x = d[0] - n[0], y = d[1] - n[1], z = d[2] - n[2];
    return d[3] * (x * x + y * y + z * z);
  }

  // the area-weighted mean normal of the faces, the face nearest to it, the
  // error; the faces are scattered in memory and asked for 16 ahead
  template <class Iterator>
  Proxy fit(Iterator begin, Iterator end) const
  {
    double s[3] = {0., 0., 0.}, area = 0.;
    for(Iterator it = begin; it != end; ++it) {
      if(end - it > 16) prefetch(&m_geo[*(it + 16)]);
      const std::array<double, 4>& d = m_geo[*it];
      for(int i = 0; i < 3; ++i) s[i] += d[3] * d[i];
      area += d[3];
    }
    const double l = std::sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
    Proxy p;
    p.normal = l > 0 ? std::array<double, 3>{s[0] / l, s[1] / l, s[2] / l} : std::array<double, 3>{0., 0., 0.};
    p.seed = *begin;
    double least = error(p.seed, p.normal), sum = 0.0;
    for(Iterator it = begin; it != end; ++it) {
      if(end - it > 16) prefetch(&m_geo[*(it + 16)]);
      const double e = error(*it, p.normal);
      sum += e;
      if(e < least) {
        least = e;
        p.seed = *it;
      }
    }
    p.error = sum;
    p.area = area;
    return p;
  }

  // Every face to the proxy that reaches it first, flooding from the seeds
  // in the order of the error of the face to the proxy it would join.
  //
  // A face is queued once per neighbour that joins a proxy, so mostly two or
  // three times with the same proxy; the copies are taken from the queue
  // after the first, and skipped. Without them the flood takes the same
  // decisions whenever no two entries of the queue have the same error: the
  // queue then gives its entries in the order of their errors, whatever it
  // holds besides. Where two have the same error, the binary heap's own
  // arrangement, which the copies change, decides which comes first (CGAL's
  // class, whose decisions step 1 takes, keeps every copy). So each flood
  // first runs without the copies, and as soon as the entry next to be taken
  // has the error of the one just taken, it starts again with every copy and
  // keeps them for the floods that follow (meshes with planar parts have such
  // ties; scanned surfaces, as a rule, none). Since the flood without the
  // copies only ever takes an entry whose error no other entry has, any
  // queue that gives the smallest error first gives its order: it runs
  // through a queue of buckets (bucket_queue.h), which takes an entry in a
  // few bit scans instead of a binary heap's dozen levels (`bunny00`'s 39
  // floods: 3 million entries); the flood with every copy keeps the binary
  // heap of CGAL's class, whose arrangement decides its ties.
  void partition()
  {
    if(!m_ties && partition_without_copies()) return;
    m_ties = true;
    partition_with_copies();
  }

  // face g's entry for proxy p
  Face_to_integrate entry(std::size_t g, std::size_t p) const
  {
    return Face_to_integrate{error(g, m_proxies[p].normal), std::uint32_t(g), std::uint32_t(p)};
  }

  // the flood with every copy, as CGAL's class floods
  void partition_with_copies()
  {
    flood(m_heap, [&](std::size_t g, std::size_t p) { m_heap.push(entry(g, p)); }, [](std::size_t) {},
          [](const Face_to_integrate&) { return true; });
  }

  // the flood without the copies; false where two entries had the same error
  bool partition_without_copies()
  {
    const std::array<std::uint32_t, 3> nothing = {no_face, no_face, no_face};
    m_queued.assign(m_proxy_of.size(), nothing);
    return flood(m_buckets, [&](std::size_t g, std::size_t p) {
      // the proxies it is queued with (at most one per neighbour)
      std::array<std::uint32_t, 3>& q = m_queued[g];
      int k = 0;
      while(k < 3 && q[k] != no_face) {
        if(q[k] == p) return;
        ++k;
      }
      if(k < 3) q[k] = std::uint32_t(p);
      m_buckets.push(entry(g, p));
    }, [&](std::size_t g) { prefetch(&m_queued[g]); }, [&](const Face_to_integrate& taken) { return m_buckets.empty() || m_buckets.front().error != taken.error; });
  }

  // the flood through `queue` with `push(face, proxy)`, which reads what
  // `ahead(face)` asks for besides the face's chart and normal; it stops,
  // returning false, where `go_on(entry just taken)` is false
  template <class Queue, class Push, class Ahead, class GoOn>
  bool flood(Queue& queue, const Push& push, const Ahead& ahead, const GoOn& go_on)
  {
    std::fill(m_proxy_of.begin(), m_proxy_of.end(), no_face);
    queue.clear();
    for(std::size_t p = 0; p < m_proxies.size(); ++p) {
      const std::size_t f = m_proxies[p].seed;
      m_proxy_of[f] = static_cast<std::uint32_t>(p);
      for(std::uint32_t g : m_next_to[f])
        if(g != no_face && m_proxy_of[g] == no_face) push(g, p);
    }
    // On a large mesh the faces taken from the queue lie far apart in memory,
    // and most of the time went into waiting for them (bunny00 subdivided
    // once, 302K faces). The loop asks for them ahead: what it reads of the
    // neighbours of the face taken (their charts, normals and, without
    // copies, the proxies they are queued with) and their own neighbours
    // (the queue often gives one of them next) while the queue is reordered,
    // the next face's neighbours and chart a turn ahead. The order of
    // everything is the same.
    while(!queue.empty()) {
      const Face_to_integrate c = queue.front();
      const bool taken = m_proxy_of[c.face] != no_face;
      const std::array<std::uint32_t, 3>& next = m_next_to[c.face];
      if(!taken)
        for(std::uint32_t g : next)
          if(g != no_face) {
            prefetch(&m_proxy_of[g]);
            ahead(g);
            prefetch(&m_geo[g]);
            prefetch(&m_next_to[g]);
          }
      queue.pop();
      if(!go_on(c)) return false;
      if(!queue.empty()) {
        prefetch(&m_next_to[queue.front().face]);
        prefetch(&m_proxy_of[queue.front().face]);
      }
      if(taken) continue;
      m_proxy_of[c.face] = c.proxy;
      for(std::uint32_t g : next)
        if(g != no_face && m_proxy_of[g] == no_face) push(g, c.proxy);
    }
    return true;
  }

  // every proxy fitted to its faces, taken in the order of `m_order`; the
  // faces met further along the order are asked for ahead, as in `fit()`
  void refit()
  {
    const std::size_t n = m_proxies.size();
    m_start.assign(n + 1, 0);
    const std::size_t nf = m_order.size();
    for(std::size_t i = 0; i < nf; ++i) {
      if(i + 32 < nf) prefetch(&m_proxy_of[m_order[i + 32]]);
      ++m_start[m_proxy_of[m_order[i]] + 1];
    }
    for(std::size_t p = 0; p < n; ++p) m_start[p + 1] += m_start[p];
    m_faces.resize(m_order.size());
    m_fill.assign(m_start.begin(), m_start.end() - 1);
    for(std::size_t i = 0; i < nf; ++i) {
      if(i + 32 < nf) prefetch(&m_proxy_of[m_order[i + 32]]);
      const std::size_t f = m_order[i];
      m_faces[m_fill[m_proxy_of[f]]++] = f;
    }
    // each proxy on its own: on both threads where asked
    auto refit_proxy = [this](std::size_t p) {
      if(m_start[p] < m_start[p + 1])
        m_proxies[p] = fit(m_faces.begin() + m_start[p], m_faces.begin() + m_start[p + 1]);
      else {
        m_proxies[p].error = 0;  // its seed went to another proxy: it keeps its normal, with no face
        m_proxies[p].area = 0;
      }
    };
    if(m_parallel)
      for_each_index<CGAL::Parallel_tag>(n, refit_proxy);
    else
      for_each_index<CGAL::Sequential_tag>(n, refit_proxy);
    m_fitted = true;
  }

  bool add_to_furthest_proxy()
  {
    double max_error = m_proxies.front().error;
    std::size_t worst = 0;
    for(std::size_t i = 0; i < m_proxies.size(); ++i)
      if(max_error < m_proxies[i].error) {
        max_error = m_proxies[i].error;
        worst = i;
      }
    std::size_t furthest = none;
    for(std::size_t f : m_order) {
      if(m_proxy_of[f] != worst || f == m_proxies[worst].seed) continue;
      const double e = error(f, m_proxies[worst].normal);
      if(furthest == none || max_error < e) {
        max_error = e;
        furthest = f;
      }
    }
    if(furthest == none) return false;
    add_proxy_at(furthest);
    return true;
  }

  // a new proxy fitted to the face alone; the face leaves its chart
  void add_proxy_at(std::size_t f)
  {
    const std::size_t one[1] = {f};
    Proxy p = fit(one, one + 1);
    const std::size_t before = m_proxy_of[f];
    m_fitted = false;
    m_proxies[before].error -= error(f, m_proxies[before].normal);
    m_proxy_of[f] = static_cast<std::uint32_t>(m_proxies.size());
    m_proxies.push_back(p);
  }

  std::vector<std::array<double, 4>> m_geo;  // unit normal and area, by number
  std::vector<std::array<std::uint32_t, 3>> m_next_to;
  std::vector<std::size_t> m_face;         // the face index of every face, by number
  std::vector<std::uint32_t> m_order;      // the faces in the order of `faces(tm)`, by number
  std::vector<std::uint32_t> m_proxy_of;  // by number; `no_face` for none
  // by number, in a flood without copies: the proxies a face is queued with
  std::vector<std::array<std::uint32_t, 3>> m_queued;
  bool m_ties = false;  // whether a flood met two entries of the same error
  bool m_fitted = false;  // see `fitted_to_charts()`
  bool m_parallel = false;  // see `fit_in_parallel()`
  std::vector<Proxy> m_proxies;
  Binary_heap<Face_to_integrate> m_heap;  // for the flood with every copy
  Bucket_queue<Face_to_integrate, Error_of> m_buckets;  // for the flood without them
  std::vector<std::size_t> m_start, m_fill, m_faces;  // the faces of every proxy, by proxy
};

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_INTERNAL_NORMAL_VSA_H
