// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_QD_INTERNAL_CHART_EVALUATOR_H
#define CGAL_QD_INTERNAL_CHART_EVALUATOR_H

// The evaluator that flattens one chart by its `Chart_criterion` and measures
// it into a `Chart_report` (chart_criterion.h): shared by the splitting, the
// merging (chart_merging.h) and the final flattening (flatten_charts.h).

#include <CGAL_QD/Error_code.h>
#include <CGAL_QD/chart_criterion.h>
#include <CGAL_QD/extract_chart.h>
#include <CGAL_QD/flatten_patch.h>
#include <CGAL_QD/optimize_flattening.h>
#include <CGAL_QD/parameters.h>
#include <CGAL_QD/internal/amd_order_of_triangles.h>
#include <CGAL_QD/internal/chart_mesh.h>
#include <CGAL_QD/internal/charts.h>
#include <CGAL_QD/internal/fit_chart_to_lengths.h>
#include <CGAL_QD/internal/flattening_cache.h>
#include <CGAL_QD/internal/hopeless_trial.h>
#include <CGAL_QD/internal/trial_memory.h>

#include <CGAL/Surface_mesh_parameterization/LSCM_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <utility>
#include <vector>

namespace CGAL_QD {
namespace internal {

// Flattens a set of faces of `tm` cut open along the cut edges, by LPFB+IP,
// and measures the result. Thread-safe: `evaluate` only reads shared data
// (and takes a scratch buffer from a pool under a lock).
template <class TriangleMesh, class FIM, class VIM>
class Chart_evaluator
{
public:
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::face_descriptor face_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef Chart_kernel K;
  typedef Chart_mesh Mesh;

  // `orderings`: the cache of the orderings of the charts' graphs, shared
  // with other evaluators of the same charts (nullptr: one of its own)
  Chart_evaluator(const TriangleMesh& tm, const FIM& fim, const VIM& vim,
                  const std::vector<std::array<double, 3>>& points, const Merge_thresholds& thresholds,
                  std::shared_ptr<Ordering_cache> orderings = nullptr)
      : m_tm(tm), m_fim(fim), m_vim(vim), m_points(points), m_thresholds(thresholds), m_corners(tm, fim),
        m_orderings(orderings ? std::move(orderings) : std::make_shared<Ordering_cache>())
  {}

  const std::shared_ptr<Ordering_cache>& orderings() const { return m_orderings; }

  // evaluations whose LPFB reached its iteration limit
  std::size_t lpfb_not_converged() const { return m_not_converged.load(); }

  // `faces` in increasing face index; `corner_uv`, if given, receives the UVs
  // of the corners (3 per face, in the order of `faces`). `border_target`, if
  // given, holds per corner the target 2D length of the edge that ends at it
  // (used for the border edges of the chart cut open), and `start_uv` the
  // chart's flattening by corner, fitted to those lengths instead of
  // flattening the chart again: every border edge at exactly its target
  // length where the thresholds allow it (`exact`), or else pulled towards
  // it with `pull_weight` (`Arap_border::KEEP_LENGTHS`; with a small weight,
  // a step towards the targets that the chart takes as far as its rigidity
  // lets it). `start_uv` without `border_target`: the chart's optimisation
  // starts from that flattening instead of LPFB+IP (the corners of a wedge at
  // the mean of their UVs, so that a cut the chart no longer has is closed
  // halfway between its two sides); with the paper's criterion, which judges
  // LPFB+IP itself, it is not used. `stop`, if given, is looked at between the steps of a trial
  // (without `corner_uv`) and at every iteration of its optimisation: once it
  // is set, the trial gives up, and its report, rejected, means nothing.
  template <class IsCut>
  Chart_report evaluate(const std::vector<face_descriptor>& faces, const IsCut& is_cut,
                        std::vector<std::array<double, 2>>* corner_uv = nullptr,
                        const std::vector<double>* border_target = nullptr,
                        const std::vector<std::array<double, 2>>* start_uv = nullptr, double pull_weight = 1000.,
                        bool exact = true, const std::atomic<bool>* stop = nullptr) const
  {
    Wedges<TriangleMesh> wedges;
    {
      // the position of every face of the set, in a buffer kept between
      // trials: a trial sets and resets only its own faces
      Scratch_buffer local(*this);
      for(std::size_t i = 0; i < faces.size(); ++i) (*local)[get(m_fim, faces[i])] = static_cast<long>(i);
      compute_wedges(m_corners, m_tm, m_fim, faces, *local, is_cut, wedges);
      for(face_descriptor f : faces) (*local)[get(m_fim, f)] = -1;
    }
    if(!m_cache)
      return flatten(faces.size(), std::move(wedges), corner_uv, border_target, start_uv, pull_weight, exact, stop);
    // the chart cut open, the fit's targets and start, and the thresholds
    Digest digest;
    const std::uint64_t flags =
        (corner_uv ? 1u : 0u) | (border_target ? 2u : 0u) | (start_uv ? 4u : 0u) | (exact ? 8u : 0u);
    digest.add(&flags, sizeof(flags));
    digest.add(&pull_weight, sizeof(pull_weight));
    const double t[] = {m_thresholds.max_area_distortion, m_thresholds.max_l2_stretch,
                        m_thresholds.max_local_area_distortion, m_thresholds.border_length_weight,
                        m_thresholds.overlap_tolerance, m_thresholds.area_preservation};
    const std::uint64_t modes[] = {std::uint64_t(m_thresholds.criterion), std::uint64_t(m_thresholds.arap_border)};
    digest.add(t, sizeof(t));
    digest.add(modes, sizeof(modes));
    add_chart(wedges, digest);
    if(border_target) digest.add_vector(*border_target);
    if(start_uv) digest.add_vector(*start_uv);
    const auto key = digest.value();
    // stored by wedge: every corner of a wedge has the wedge's UV
    Chart_report rep;
    std::vector<std::array<double, 2>> wedge_uv;
    if(m_cache->find(key, rep, &wedge_uv)) {
      if(corner_uv && !wedge_uv.empty()) {
        corner_uv->resize(wedges.wedge_of_corner.size());
        for(std::size_t c = 0; c < wedges.wedge_of_corner.size(); ++c)
          (*corner_uv)[c] = wedge_uv[wedges.wedge_of_corner[c]];
      }
      return rep;
    }
    rep = flatten(faces.size(), wedges, corner_uv, border_target, start_uv, pull_weight, exact, stop);
    if(stopped(stop)) return rep;
    if(corner_uv && corner_uv->size() == wedges.wedge_of_corner.size()) {
      wedge_uv.resize(wedges.size());
      for(std::size_t c = 0; c < wedges.wedge_of_corner.size(); ++c)
        wedge_uv[wedges.wedge_of_corner[c]] = (*corner_uv)[c];
    }
    m_cache->store(key, rep, &wedge_uv);
    return rep;
  }

  // flattenings are looked up in `cache` (and stored there) from now on; nullptr: none
  void set_cache(Flattening_cache<Chart_report>* cache) { m_cache = cache; }

  // accepted trials are remembered in `trials`, and a final flattening of a
  // chart remembered there starts from its trial (the same map, to the last
  // bit); nullptr: none. Shared with the evaluator of the final flattening.
  void set_trial_memory(std::shared_ptr<Trial_memory> trials) { m_trials = std::move(trials); }
  const std::shared_ptr<Trial_memory>& trial_memory() const { return m_trials; }

private:
  // the chart of `n_faces` faces cut open into `wedges`, flattened and measured
  Chart_report flatten(std::size_t n_faces, Wedges<TriangleMesh> wedges,
                       std::vector<std::array<double, 2>>* corner_uv, const std::vector<double>* border_target,
                       const std::vector<std::array<double, 2>>* start_uv, double pull_weight, bool exact,
                       const std::atomic<bool>* stop) const
  {
    // the vertices of the chart cut open in the AMD order of its graph: the
    // systems of its flattening and of its optimisation, each on a part of
    // the vertices, take their order from that one ordering (`solver()`)
    to_amd_order(wedges);
    Chart_report rep;
    rep.number_of_faces = n_faces;
    Mesh sm;
    rep.status = build_chart_mesh(wedges, n_faces, m_vim, m_points, sm, rep.area);
    if(rep.status != Error_code::OK) return rep;
    typedef typename Mesh::Vertex_index V;
    auto uv = sm.template add_property_map<V, K::Point_2>("v:uv", K::Point_2(0, 0)).first;
    auto write_corner_uv = [&] {
      if(!corner_uv) return;
      corner_uv->resize(3 * n_faces);
      for(std::size_t c = 0; c < 3 * n_faces; ++c) {
        const K::Point_2& p = get(uv, V(static_cast<typename Mesh::size_type>(wedges.wedge_of_corner[c])));
        (*corner_uv)[c] = {p.x(), p.y()};
      }
    };
    if(border_target) {
      // the chart's flattening `start_uv` with its border edges given the
      // target lengths: the seams of the pieces match
      for(std::size_t c = 0; c < 3 * n_faces; ++c)
        put(uv, V(static_cast<typename Mesh::size_type>(wedges.wedge_of_corner[c])),
            K::Point_2((*start_uv)[c][0], (*start_uv)[c][1]));
      fit_chart_to_lengths(sm, uv, wedges.wedge_of_corner, *border_target, pull_weight, exact, m_thresholds, rep,
                           write_corner_uv);
      return rep;
    }
    if(stopped(stop)) return rep;
    const bool paper = m_thresholds.criterion == Chart_criterion::LPFB_IP;
    // a final flattening of a chart that a trial accepted starts from that
    // trial's start and optimisation (trial_memory.h)
    Trial_start resumed;
    const bool resume = corner_uv && m_trials && m_trials->find(trial_key(wedges), resumed);
    const bool seeded = !resume && start_uv && !paper;
    if(resume) {
      for(auto v : vertices(sm)) put(uv, v, K::Point_2(resumed.lpfb_ip[v][0], resumed.lpfb_ip[v][1]));
      rep.number_of_border_loops = resumed.border_loops;
    } else if(seeded) {
      // the flattening given, each wedge at the mean of its corners
      std::vector<std::array<double, 3>> sum(num_vertices(sm), {0., 0., 0.});
      for(std::size_t c = 0; c < 3 * n_faces; ++c) {
        std::array<double, 3>& s = sum[wedges.wedge_of_corner[c]];
        s[0] += (*start_uv)[c][0];
        s[1] += (*start_uv)[c][1];
        s[2] += 1.;
      }
      for(auto v : vertices(sm)) put(uv, v, K::Point_2(sum[v][0] / sum[v][2], sum[v][1] / sum[v][2]));
      rep.number_of_border_loops = number_of_border_loops(sm);
    } else {
      // SimplicialLDLT, not the default's supernodal factorisation for large
      // charts: the charts are flattened on the threads of the segmentation's
      // parallel loops, where BLAS threads and the analysis thread of the
      // supernodal path would compete with them (bunny00 subdivided twice,
      // 1.2M faces: merging 56.4 s with SimplicialLDLT, 67.5 s with the default)
      const Flattening_result flat = flatten_patch(sm, uv, parameters::sparse_solver(solver()));
      rep.number_of_border_loops = flat.border.number_of_loops;
      if(!flat) {
        rep.status = flat.status;
        if(flat.status == Error_code::NOT_CONVERGED) ++m_not_converged;
        return rep;
      }
    }
    const auto lpfb_ip_uv = uv;  // LPFB+IP's map (or the start given): a trial writes no other into it
    if(!measure(sm, uv, rep)) {
      // a start given may fold where a cut is closed: the optimisation unfolds it
      if(!seeded) return rep;
      rep.status = Error_code::OK;
      rep.accepted = false;
    }
    // an optimised flattening `map` replaces the flattening of `rep` when it is
    // accepted and that one is not, or when both are and it has less local
    // area distortion; a trial that rejects both reports the optimised map,
    // the last it judged, and a final flattening that rejects both keeps the
    // one nearer the thresholds (`nearer_thresholds()`)
    auto better = [&](const auto& map, const Optimization_result& r) {
      Chart_report candidate = rep;
      if(!r || !measure(sm, map, candidate)) return false;
      candidate.optimized = true;
      if(!candidate.accepted) {
        if(rep.accepted) return false;
        if(!corner_uv) {
          rep = candidate;
          return false;
        }
        if(!nearer_thresholds(candidate, rep, m_thresholds)) return false;
        rep = candidate;
        return true;
      }
      if(rep.accepted && !(candidate.local_area_distortion < rep.local_area_distortion)) return false;
      rep = candidate;
      return true;
    };
    auto last = uv;       // the latest optimisation started from LPFB+IP
    bool capped = false;  // whether it stopped at its iteration cap
    Optimization_result trial_optimization;  // a trial's, where it ran one
    bool trial_optimized = false;
    // a final flattening with area-preserving targets that is not accepted
    // also tries plain ARAP from LPFB+IP: those targets take a chart that
    // develops onto the plane towards its isometric unfolding only slowly (the
    // anisotropy of its faces falls to about the share kept at each iteration)
    const bool plain_too = !paper && corner_uv && m_thresholds.area_preservation > 0;
    auto lpfb_ip = sm.template add_property_map<typename Mesh::Vertex_index, K::Point_2>("v:lpfb", K::Point_2(0, 0)).first;
    if(plain_too)
      for(auto v : vertices(sm)) put(lpfb_ip, v, get(uv, v));
    if(!paper && (!rep.accepted || corner_uv)) {
      // free-boundary ARAP started from LPFB+IP
      auto opt = sm.template add_property_map<typename Mesh::Vertex_index, K::Point_2>("v:opt", K::Point_2(0, 0)).first;
      for(auto v : vertices(sm)) put(opt, v, get(uv, v));
      Optimization_result o;
      if(corner_uv && resume && !resumed.optimized.empty()) {
        for(auto v : vertices(sm)) put(opt, v, K::Point_2(resumed.optimized[v][0], resumed.optimized[v][1]));
        o = resumed.optimization;
      } else if(corner_uv) {
        o = optimize_flattening(sm, opt, trial_parameters());
      } else {
        // a trial gives up where its A_loc is too far above the bound to come
        // below it by iteration 30
        const Hopeless_trial<Mesh> hopeless(sm, m_thresholds.max_local_area_distortion, 30);
        o = optimize_flattening(sm, opt, parameters::iteration_callback([&](std::size_t iterations) {
          return stopped(stop) || hopeless(opt, iterations);
        }, trial_parameters()));
        if(o.stopped_by_callback) {  // rejected
          if(!stopped(stop)) {
            rep.optimized = true;
            rep.given_up_after = o.iterations;
            rep.area_distortion = hopeless.area_distortion();
            rep.local_area_distortion = hopeless.local_area_distortion();
            rep.l2_stretch = rep.max_border_length_error = 0;
            rep.overlap = false;
          }
          return rep;
        }
        trial_optimization = o;
        trial_optimized = true;
      }
      last = opt;
      capped = o && o.iterations == 30;
      if(better(opt, o)) uv = opt;
      // a trial stops after 30 iterations; a final flattening goes on until it
      // converges (at most 70 more), kept if it is still accepted and better
      if(corner_uv && o && o.iterations == 30) {
        // on a copy: `uv` may now be the same map as `opt`
        auto more = sm.template add_property_map<typename Mesh::Vertex_index, K::Point_2>("v:more", K::Point_2(0, 0)).first;
        for(auto v : vertices(sm)) put(more, v, get(opt, v));
        const Optimization_result r = optimize_flattening(sm, more, trial_parameters().number_of_iterations(70));
        last = more;
        capped = r && r.iterations == 70;
        if(better(more, r)) uv = more;
      }
    }
    if(plain_too && !rep.accepted) {
      const Optimization_result o =
          optimize_flattening(sm, lpfb_ip, trial_parameters(0.).number_of_iterations(100));
      if(better(lpfb_ip, o)) uv = lpfb_ip;
    }
    if(!paper && corner_uv && !rep.accepted)
      go_on_from_the_cap_and_lscm(sm, uv, last, capped, rep.number_of_border_loops, better);
    write_corner_uv();
    if(!corner_uv && m_trials && rep.accepted && !stopped(stop)) {
      Trial_start start;
      start.border_loops = rep.number_of_border_loops;
      start.lpfb_ip.resize(num_vertices(sm));
      if(trial_optimized) start.optimized.resize(num_vertices(sm));
      for(auto v : vertices(sm)) {
        start.lpfb_ip[v] = {get(lpfb_ip_uv, v).x(), get(lpfb_ip_uv, v).y()};
        if(trial_optimized) start.optimized[v] = {get(last, v).x(), get(last, v).y()};
      }
      start.optimization = trial_optimization;
      m_trials->store(trial_key(wedges), std::move(start));
    }
    return rep;
  }

  // the key of a chart cut open into `wedges` (in AMD order) in the trial
  // memory: the chart and the options of its flattening
  Trial_memory::Key trial_key(const Wedges<TriangleMesh>& wedges) const
  {
    Digest digest;
    const double options[] = {m_thresholds.area_preservation, m_thresholds.border_length_weight};
    const std::uint64_t modes[] = {std::uint64_t(m_thresholds.criterion), std::uint64_t(m_thresholds.arap_border)};
    digest.add(options, sizeof(options));
    digest.add(modes, sizeof(modes));
    add_chart(wedges, digest);
    return digest.value();
  }

  // the chart cut open into `wedges` added to `digest`: the wedges of its
  // corners and the points of its wedges
  void add_chart(const Wedges<TriangleMesh>& wedges, Digest& digest) const
  {
    digest.add_vector(wedges.wedge_of_corner);
    for(std::size_t w = 0; w < wedges.size(); ++w)
      digest.add(m_points[get(m_vim, wedges.vertex_of_wedge[w])].data(), 3 * sizeof(double));
  }

  // A final flattening still outside the thresholds: the optimisation
  // from LPFB+IP goes on from `last` where it stopped at its cap (`capped`; at
  // most 300 iterations in all), and, for a chart with one border loop
  // (`border_loops`), one is started from LSCM (at most 300 iterations).
  // `better(map, result)` tells whether a map is better than the chart's
  // flattening (and takes its measures); `uv` then receives it.
  template <class UVMap, class Better>
  void go_on_from_the_cap_and_lscm(Mesh& sm, UVMap uv, UVMap last, bool capped, std::size_t border_loops,
                                   const Better& better) const
  {
    auto again = sm.template add_property_map<typename Mesh::Vertex_index, K::Point_2>("v:again", K::Point_2(0, 0)).first;
    for(int start = 0; start < 2; ++start) {
      std::size_t iterations = 300;
      if(start == 0) {
        if(!capped) continue;  // it converged: going on would give the same map
        for(auto v : vertices(sm)) put(again, v, get(last, v));
        iterations = 200;
      } else {
        typename Mesh::Halfedge_index border;
        for(auto h : halfedges(sm))
          if(is_border(h, sm)) {
            border = h;
            break;
          }
        if(border_loops != 1 || border == Mesh::null_halfedge() ||
           CGAL::Surface_mesh_parameterization::parameterize(
               sm, CGAL::Surface_mesh_parameterization::LSCM_parameterizer_3<Mesh>(), border, again) !=
               CGAL::Surface_mesh_parameterization::OK)
          break;
      }
      if(better(again, optimize_flattening(sm, again, trial_parameters().number_of_iterations(iterations))))
        for(auto v : vertices(sm)) put(uv, v, get(again, v));  // a copy: `again` is used again
    }
  }

  static bool stopped(const std::atomic<bool>* stop) { return stop && stop->load(std::memory_order_relaxed); }

  // a face-index buffer of the mesh's size, all -1, taken from the
  // evaluator's pool for one trial and given back (all -1 again) after it
  class Scratch_buffer
  {
  public:
    explicit Scratch_buffer(const Chart_evaluator& e) : m_e(e)
    {
      {
        std::lock_guard<std::mutex> lock(m_e.m_scratch_mutex);
        if(!m_e.m_scratch.empty()) {
          m_buffer = std::move(m_e.m_scratch.back());
          m_e.m_scratch.pop_back();
        }
      }
      if(!m_buffer) m_buffer.reset(new std::vector<long>(num_faces(m_e.m_tm), -1));
    }
    ~Scratch_buffer()
    {
      std::lock_guard<std::mutex> lock(m_e.m_scratch_mutex);
      m_e.m_scratch.push_back(std::move(m_buffer));
    }
    Scratch_buffer(const Scratch_buffer&) = delete;
    Scratch_buffer& operator=(const Scratch_buffer&) = delete;
    std::vector<long>& operator*() { return *m_buffer; }

  private:
    const Chart_evaluator& m_e;
    std::unique_ptr<std::vector<long>> m_buffer;
  };

  // the parameters of the optimisation, with the thresholds' area
  // preservation or the one given
  auto trial_parameters(double area_preservation = -1.) const
  {
    return parameters::sparse_solver(
        solver(), parameters::arap_border(
                      m_thresholds.arap_border,
                      parameters::border_length_weight(
                          m_thresholds.border_length_weight,
                          parameters::area_preservation(area_preservation < 0 ? m_thresholds.area_preservation
                                                                              : area_preservation))));
  }

  // the wedges renumbered in the AMD order of the chart's graph (taken from
  // the evaluator's orderings where the chart was ordered before)
  void to_amd_order(Wedges<TriangleMesh>& w) const
  {
    const std::vector<int> order = amd_order_of_triangles(w.size(), w.wedge_of_corner, m_orderings.get());
    std::vector<std::size_t> position(w.size());
    std::vector<typename GT::vertex_descriptor> vertex(w.size());
    for(std::size_t k = 0; k < w.size(); ++k) {
      position[static_cast<std::size_t>(order[k])] = k;
      vertex[k] = w.vertex_of_wedge[static_cast<std::size_t>(order[k])];
    }
    w.vertex_of_wedge.swap(vertex);
    for(std::size_t& c : w.wedge_of_corner) c = position[c];
  }

  // the solver of every flattening: the rows come in the order of the
  // vertices, which `to_amd_order()` made a fill-reducing one
  Simplicial_LDLT_natural_solver solver() const { return Simplicial_LDLT_natural_solver(); }

  // measures the flattening `uv` of `sm` into `rep`; false if it cannot be measured
  template <class UVMap>
  bool measure(const Mesh& sm, const UVMap& uv, Chart_report& rep) const
  {
    return measure_chart_flattening(sm, uv, m_thresholds, rep);
  }

  const TriangleMesh& m_tm;
  FIM m_fim;
  VIM m_vim;
  const std::vector<std::array<double, 3>>& m_points;
  Merge_thresholds m_thresholds;
  Corner_table<TriangleMesh> m_corners;  // the corners of the mesh, for the wedges of every evaluation
  mutable std::atomic<std::size_t> m_not_converged{0};
  mutable std::mutex m_scratch_mutex;
  mutable std::vector<std::unique_ptr<std::vector<long>>> m_scratch;  // one per trial run at the same time
  Flattening_cache<Chart_report>* m_cache = nullptr;
  std::shared_ptr<Trial_memory> m_trials;
  // the AMD orderings of the graphs of the charts it flattened: a chart
  // flattened again (the final flattening of a chart its last merging trial
  // made, the fits of its seams) takes its ordering from there
  std::shared_ptr<Ordering_cache> m_orderings;
};

} // namespace internal
} // namespace CGAL_QD

#endif // CGAL_QD_INTERNAL_CHART_EVALUATOR_H
