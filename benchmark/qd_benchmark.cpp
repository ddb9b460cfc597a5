// Copyright (c) 2026 The CGAL_QD developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// qd_benchmark: every flattening method on the same meshes, in one process.
// Each timing is the median of at least 5 runs, or of as many runs as fit in a
// time budget on big meshes (at least one). CGAL's results are normalised as in
// the paper before they are measured (a similarity puts the endpoints of the
// longest border edge at their 3D distance). Writes table.md, results.csv and
// scaling.svg into the output folder.
//
// usage: qd_benchmark [--out DIR] [--quick] [--max-faces N] [--budget SECONDS]
//        qd_benchmark --memory-probe FACES     (internal: peak memory of one flattening)
//        qd_benchmark --subdivide IN LEVELS OUT (IN Loop-subdivided LEVELS times, written to OUT;
//                                                for scripts/segmentation_benchmark.sh)

#include "mesh_generators.h"

#include <CGAL_QD/LPFB_border_parameterizer_3.h>
#include <CGAL_QD/distortion.h>
#include <CGAL_QD/flatten_patch.h>

#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh_parameterization/ARAP_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_conformal_map_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/LSCM_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Mean_value_coordinates_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/subdivision_method_3.h>
#ifdef CGAL_QD_HAS_UMFPACK
#include <Eigen/UmfPackSupport>
#endif

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

using namespace qd_test;
namespace SMP = CGAL::Surface_mesh_parameterization;
namespace QD = CGAL_QD;
typedef Surface_mesh Mesh;
typedef Mesh::Property_map<Mesh::Vertex_index, Epick::Point_2> UV_map;
typedef std::chrono::steady_clock Clock;

namespace {

// ------------------------------------------------------------------ meshes

struct Mesh_case
{
  std::string name;
  Mesh mesh;
};

Mesh from_soup(const Soup& s)
{
  Mesh m;
  build(s, m);
  return m;
}

// the cylinder of the paper's Table 1: cut open, with a few noisy vertices
Mesh noisy_cylinder()
{
  Soup s = grid(100, 30, cylinder(1.0, 1.9 * pi, 3.0));
  std::mt19937 gen(11);
  std::uniform_int_distribution<std::size_t> pick(0, s.points.size() - 1);
  for(int k = 0; k < 12; ++k) {
    P3& p = s.points[pick(gen)];
    const double r = std::hypot(p[0], p[1]);
    p[0] *= (r + 0.04) / r;
    p[1] *= (r + 0.04) / r;
  }
  return from_soup(s);
}

#ifdef CGAL_QD_DEMO_MESH_DIR
bool bunny_patch(std::size_t faces, int subdivisions, Mesh& out)
{
  Mesh bunny;
  if(!CGAL::IO::read_polygon_mesh(std::string(CGAL_QD_DEMO_MESH_DIR) + "/bunny00.off", bunny)) return false;
  grow_disk_patch(bunny, *CGAL::faces(bunny).begin(), faces, out);
  if(subdivisions > 0)
    CGAL::Subdivision_method_3::Loop_subdivision(out, CGAL::parameters::number_of_iterations(subdivisions));
  return true;
}
#endif

// ----------------------------------------------------------------- methods

struct Method
{
  std::string name, solver;
  std::function<bool(Mesh&, UV_map)> run;  // false on failure
  bool normalise = false;                  // a CGAL method, scaled as in the paper
  std::size_t max_faces = std::size_t(-1);
};

template <class P>
std::function<bool(Mesh&, UV_map)> cgal(std::function<P()> make)
{
  return [make](Mesh& m, UV_map uv) {
    P p = make();
    return SMP::parameterize(m, p, CGAL::Polygon_mesh_processing::longest_border(m).first, uv) == SMP::OK;
  };
}

template <class Solver>
using DCM = SMP::Discrete_conformal_map_parameterizer_3<Mesh, SMP::Circular_border_arc_length_parameterizer_3<Mesh>,
                                                        CGAL::Eigen_solver_traits<Solver>>;
template <class Solver>
using MVC = SMP::Mean_value_coordinates_parameterizer_3<Mesh, SMP::Circular_border_arc_length_parameterizer_3<Mesh>,
                                                        CGAL::Eigen_solver_traits<Solver>>;
typedef Eigen::SparseLU<CGAL::Eigen_sparse_matrix<double>::EigenType> SparseLU;
#ifdef CGAL_QD_HAS_UMFPACK
typedef Eigen::UmfPackLU<CGAL::Eigen_sparse_matrix<double>::EigenType> UmfPack;
#endif

// the default solver of flatten_patch(), as the header of table.md describes it
std::string default_solver_label()
{
#ifdef CGAL_QD_USE_CHOLMOD
  return "default: SimplicialLDLT, CHOLMOD supernodal from " +
         std::to_string(QD::Default_flattening_solver().supernodal_threshold()) + " unknowns";
#else
  return "default: SimplicialLDLT";
#endif
}

std::vector<Method> all_methods()
{
  std::vector<Method> ms;
  ms.push_back({"LPFB+IP (flatten_patch)", "default",
                [](Mesh& m, UV_map uv) { return bool(QD::flatten_patch(m, uv)); }});
#ifdef CGAL_QD_USE_CHOLMOD
  // the two solvers of the default, each alone, and CHOLMOD left to its own choices
  ms.push_back({"LPFB+IP (flatten_patch)", "SimplicialLDLT", [](Mesh& m, UV_map uv) {
                  return bool(QD::flatten_patch(m, uv, QD::parameters::sparse_solver(QD::Simplicial_LDLT_solver())));
                }});
  ms.push_back({"LPFB+IP (flatten_patch)", "CHOLMOD supernodal", [](Mesh& m, UV_map uv) {
                  return bool(QD::flatten_patch(m, uv, QD::parameters::sparse_solver(QD::Cholmod_supernodal_solver())));
                }});
  ms.push_back({"LPFB+IP (flatten_patch)", "CHOLMOD", [](Mesh& m, UV_map uv) {
                  return bool(QD::flatten_patch(m, uv, QD::parameters::sparse_solver(QD::Cholmod_solver())));
                }});
#endif
  ms.push_back({"LPFB alone", "-", [](Mesh& m, UV_map uv) {
                  return bool(QD::compute_length_preserved_free_boundary(m, uv, CGAL::parameters::default_values()));
                }});
  ms.push_back({"LPFB+IP (CGAL parameterize)", "BiCGSTAB (default)",
                cgal<SMP::Discrete_conformal_map_parameterizer_3<Mesh, QD::LPFB_border_parameterizer_3<Mesh>>>(
                    [] { return SMP::Discrete_conformal_map_parameterizer_3<Mesh, QD::LPFB_border_parameterizer_3<Mesh>>(); })});
  ms.push_back({"CGAL LSCM", "OpenNL (default)", cgal<SMP::LSCM_parameterizer_3<Mesh>>([] {
                  return SMP::LSCM_parameterizer_3<Mesh>();
                }), true});
  ms.push_back({"CGAL DCM, circular border", "BiCGSTAB (default)",
                cgal<SMP::Discrete_conformal_map_parameterizer_3<Mesh>>([] {
                  return SMP::Discrete_conformal_map_parameterizer_3<Mesh>();
                }), true});
  ms.push_back({"CGAL DCM, circular border", "SparseLU",
                cgal<DCM<SparseLU>>([] { return DCM<SparseLU>(); }), true});
#ifdef CGAL_QD_HAS_UMFPACK
  ms.push_back({"CGAL DCM, circular border", "UMFPACK", cgal<DCM<UmfPack>>([] { return DCM<UmfPack>(); }), true});
#endif
  ms.push_back({"CGAL MVC, circular border", "BiCGSTAB (default)",
                cgal<SMP::Mean_value_coordinates_parameterizer_3<Mesh>>([] {
                  return SMP::Mean_value_coordinates_parameterizer_3<Mesh>();
                }), true});
#ifdef CGAL_QD_HAS_UMFPACK
  ms.push_back({"CGAL MVC, circular border", "UMFPACK", cgal<MVC<UmfPack>>([] { return MVC<UmfPack>(); }), true});
#else
  ms.push_back({"CGAL MVC, circular border", "SparseLU", cgal<MVC<SparseLU>>([] { return MVC<SparseLU>(); }), true});
#endif
  Method arap{"CGAL ARAP", "SparseLU (default)",
              cgal<SMP::ARAP_parameterizer_3<Mesh>>([] { return SMP::ARAP_parameterizer_3<Mesh>(); }), true};
  arap.max_faces = 40000;
  ms.push_back(arap);
  return ms;
}


// --------------------------------------------------------------- measuring

struct Row
{
  std::string mesh, method, solver, status = "ok";
  std::size_t faces = 0, vertices = 0, border = 0, runs = 0, flips = 0;
  double median_ms = 0, ratio = 0, l2 = 0, area = 0, pi_l = 0, pi_theta = 0;
  bool overlap = false, measured = false;
};

double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

Row measure(const Mesh_case& mc, const Method& m, double budget_s, bool distortion)
{
  Row r;
  r.mesh = mc.name;
  r.method = m.name;
  r.solver = m.solver;
  r.faces = num_faces(mc.mesh);
  r.vertices = num_vertices(mc.mesh);
  for(auto v : vertices(mc.mesh)) if(is_border(v, mc.mesh)) ++r.border;
  Mesh mesh = mc.mesh;  // CGAL's parameterize() takes a non-const mesh
  UV_map uv = mesh.add_property_map<Mesh::Vertex_index, Epick::Point_2>("v:uv", Epick::Point_2(0, 0)).first;
  std::vector<double> times;
  double spent = 0;
  while(times.size() < 5 && (times.empty() || spent + median(times) < budget_s * 1000)) {
    const auto t = Clock::now();
    const bool ok = m.run(mesh, uv);
    const double ms = std::chrono::duration<double, std::milli>(Clock::now() - t).count();
    if(!ok) { r.status = "failed"; break; }
    times.push_back(ms);
    spent += ms;
  }
  r.runs = times.size();
  if(times.empty()) return r;
  r.median_ms = median(times);
  if(distortion && m.name != "LPFB alone") {
    if(m.normalise) CGAL_QD::normalize_by_longest_border_edge(mesh, uv);
    const auto d = QD::compute_distortion(mesh, uv);
    r.measured = true;
    r.l2 = d.l2_stretch;
    r.area = d.area_distortion;
    r.pi_l = d.boundary_length_error;
    r.pi_theta = d.boundary_angle_error;
    r.flips = d.flipped_faces;
    r.overlap = d.overlap;
  }
  return r;
}

// ---------------------------------------------------------- machine facts

std::string first_line_with(const char* path, const char* key)
{
  std::ifstream in(path);
  std::string line;
  while(std::getline(in, line))
    if(line.rfind(key, 0) == 0) return line.substr(line.find(':') + 2);
  return "unknown";
}

std::string blas_in_use()
{
  char buf[512];
  const ssize_t n = readlink("/etc/alternatives/libblas.so.3-x86_64-linux-gnu", buf, sizeof(buf) - 1);
  if(n <= 0) return "unknown";
  buf[n] = 0;
  return buf;
}

std::string fmt(double x, int precision = 3)
{
  std::ostringstream o;
  if(std::isinf(x)) o << "inf";
  else o << std::setprecision(precision) << x;
  return o.str();
}

// ------------------------------------------------------------ memory probe

Mesh scaling_mesh(std::size_t faces)
{
  const std::size_t n = std::max<std::size_t>(4, std::size_t(std::lround(std::sqrt(faces / 2.0))));
  return from_soup(grid(n, n, bump(0.3)));
}

// peak resident memory (MB) of a fresh process that builds the mesh and flattens it
double peak_memory_mb(const char* self, std::size_t faces)
{
  const pid_t pid = fork();
  if(pid == 0) {
    const std::string arg = std::to_string(faces);
    execl(self, self, "--memory-probe", arg.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  int status = 0;
  struct rusage usage;
  if(pid < 0 || wait4(pid, &status, 0, &usage) < 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0) return -1;
  return usage.ru_maxrss / 1024.0;
}

// ----------------------------------------------------------------- the plot

void write_svg(const std::string& path, const std::vector<Row>& rows, const std::vector<std::string>& series)
{
  double xmin = 1e300, xmax = 0, ymin = 1e300, ymax = 0;
  for(const Row& r : rows)
    if(r.runs) {
      xmin = std::min(xmin, double(r.faces)); xmax = std::max(xmax, double(r.faces));
      ymin = std::min(ymin, r.median_ms); ymax = std::max(ymax, r.median_ms);
    }
  if(xmax <= 0) return;
  const double lx0 = std::floor(std::log10(xmin) + 1e-9), lx1 = std::ceil(std::log10(xmax) - 1e-9);
  const double ly0 = std::floor(std::log10(ymin)), ly1 = std::ceil(std::log10(ymax));
  const double W = 960, H = 480, L = 70, R = 400, T = 30, B = 50;
  auto X = [&](double f) { return L + (std::log10(f) - lx0) / (lx1 - lx0) * (W - L - R); };
  auto Y = [&](double t) { return H - B - (std::log10(t) - ly0) / (ly1 - ly0) * (H - T - B); };
  const char* colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b", "#e377c2", "#7f7f7f"};
  std::ofstream o(path);
  o << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << W << "\" height=\"" << H
    << "\" font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  for(double e = lx0; e <= lx1; ++e)
    o << "<line x1=\"" << X(std::pow(10, e)) << "\" y1=\"" << T << "\" x2=\"" << X(std::pow(10, e)) << "\" y2=\""
      << H - B << "\" stroke=\"#ddd\"/><text x=\"" << X(std::pow(10, e)) << "\" y=\"" << H - B + 18
      << "\" text-anchor=\"middle\">1e" << e << "</text>\n";
  for(double e = ly0; e <= ly1; ++e)
    o << "<line x1=\"" << L << "\" y1=\"" << Y(std::pow(10, e)) << "\" x2=\"" << W - R << "\" y2=\""
      << Y(std::pow(10, e)) << "\" stroke=\"#ddd\"/><text x=\"" << L - 6 << "\" y=\"" << Y(std::pow(10, e)) + 4
      << "\" text-anchor=\"end\">1e" << e << "</text>\n";
  o << "<text x=\"" << (L + W - R) / 2 << "\" y=\"18\" text-anchor=\"middle\" font-weight=\"bold\">Flattening time "
       "against mesh size (log-log)</text>\n";
  o << "<text x=\"" << (L + W - R) / 2 << "\" y=\"" << H - 12 << "\" text-anchor=\"middle\">faces</text>\n"
    << "<text x=\"16\" y=\"" << (T + H - B) / 2 << "\" transform=\"rotate(-90 16 " << (T + H - B) / 2
    << ")\" text-anchor=\"middle\">median time (ms)</text>\n";
  for(std::size_t s = 0; s < series.size(); ++s) {
    std::ostringstream pts;
    for(const Row& r : rows)
      if(r.runs && r.method + " / " + r.solver == series[s]) pts << X(double(r.faces)) << "," << Y(r.median_ms) << " ";
    const char* c = colours[s % 8];
    o << "<polyline fill=\"none\" stroke=\"" << c << "\" stroke-width=\"2\" points=\"" << pts.str() << "\"/>\n"
      << "<rect x=\"" << W - R + 12 << "\" y=\"" << T + 18 * s << "\" width=\"12\" height=\"12\" fill=\"" << c
      << "\"/><text x=\"" << W - R + 30 << "\" y=\"" << T + 18 * s + 10 << "\">" << series[s] << "</text>\n";
  }
  o << "</svg>\n";
}

} // namespace

int main(int argc, char** argv)
{
  std::string out = "benchmark/results";
  bool quick = false;
  double budget_s = 30;
  std::size_t max_faces = 1000000;
  for(int i = 1; i < argc; ++i) {
    if(!std::strcmp(argv[i], "--memory-probe") && i + 1 < argc) {
      Mesh m = scaling_mesh(std::stoul(argv[i + 1]));
      UV_map uv = m.add_property_map<Mesh::Vertex_index, Epick::Point_2>("v:uv").first;
      return QD::flatten_patch(m, uv) ? 0 : 1;
    }
    if(!std::strcmp(argv[i], "--subdivide") && i + 3 < argc) {
      Mesh m;
      if(!CGAL::IO::read_polygon_mesh(argv[i + 1], m) || !CGAL::is_triangle_mesh(m)) {
        std::cerr << "qd_benchmark: cannot read a triangle mesh from '" << argv[i + 1] << "'\n";
        return EXIT_FAILURE;
      }
      const int levels = std::atoi(argv[i + 2]);
      if(levels > 0) CGAL::Subdivision_method_3::Loop_subdivision(m, CGAL::parameters::number_of_iterations(levels));
      if(!CGAL::IO::write_polygon_mesh(argv[i + 3], m, CGAL::parameters::stream_precision(17))) {
        std::cerr << "qd_benchmark: cannot write '" << argv[i + 3] << "'\n";
        return EXIT_FAILURE;
      }
      return EXIT_SUCCESS;
    }
    if(!std::strcmp(argv[i], "--out") && i + 1 < argc) out = argv[++i];
    else if(!std::strcmp(argv[i], "--quick")) quick = true;
    else if(!std::strcmp(argv[i], "--max-faces") && i + 1 < argc) max_faces = std::stoul(argv[++i]);
    else if(!std::strcmp(argv[i], "--budget") && i + 1 < argc) budget_s = std::stod(argv[++i]);
    else {
      std::cerr << "usage: qd_benchmark [--out DIR] [--quick] [--max-faces N] [--budget SECONDS]\n";
      return EXIT_FAILURE;
    }
  }
  if(quick) { max_faces = std::min<std::size_t>(max_faces, 30000); budget_s = std::min(budget_s, 2.0); }
  if(std::system(("mkdir -p '" + out + "'").c_str()) != 0) {
    std::cerr << "error: cannot create " << out << "\n";
    return EXIT_FAILURE;
  }
  const auto run_start = Clock::now();

  // ------------------------------------------------- Table 1 style meshes
  std::vector<Mesh_case> table;
  table.push_back({"noisy cylinder, cut open", noisy_cylinder()});
  table.push_back({"cube opened by five cuts", from_soup(cube_opened_by_five_cuts(25))});
  table.push_back({"patch with two holes", from_soup(grid(24, 24, bump(0.3), holes({{4, 8, 5, 9}, {14, 19, 12, 16}})))});
  std::string missing;
#ifdef CGAL_QD_DEMO_MESH_DIR
  for(auto spec : std::vector<std::pair<std::size_t, int>>{{5000, 0}, {27500, 0}, {27500, 2}}) {
    Mesh m;
    if(!bunny_patch(spec.first, spec.second, m)) { missing = "bunny00.off could not be read"; break; }
    if(num_faces(m) > max_faces) continue;
    table.push_back({"bunny00 patch" + std::string(spec.second ? ", Loop x2" : ""), std::move(m)});
  }
#else
  missing = "libcgal-demo was not found at configure time: the bunny00 patches are left out";
#endif

  const std::vector<Method> methods = all_methods();
  std::vector<Row> rows;
  for(const Mesh_case& mc : table) {
    std::cerr << "table: " << mc.name << " (" << num_faces(mc.mesh) << " faces)\n";
    std::vector<Row> these;
    for(const Method& m : methods) {
      if(num_faces(mc.mesh) > m.max_faces) continue;
      these.push_back(measure(mc, m, budget_s, true));
      std::cerr << "  " << m.name << " / " << m.solver << ": " << these.back().median_ms << " ms\n";
    }
    for(Row& r : these) r.ratio = these[0].median_ms > 0 ? r.median_ms / these[0].median_ms : 0;
    rows.insert(rows.end(), these.begin(), these.end());
  }

  // ------------------------------------------------------- scaling series
  std::vector<std::string> scaling_methods = {"LPFB+IP (flatten_patch) / default",
                                              "LPFB alone / -", "CGAL LSCM / OpenNL (default)",
                                              "CGAL DCM, circular border / BiCGSTAB (default)"};
#ifdef CGAL_QD_HAS_UMFPACK
  scaling_methods.push_back("CGAL DCM, circular border / UMFPACK");
#else
  scaling_methods.push_back("CGAL DCM, circular border / SparseLU");
#endif
  std::vector<Row> scaling;
  std::map<std::string, double> last_time;
  for(std::size_t target : {1000, 3000, 10000, 30000, 100000, 300000, 1000000}) {
    if(target > max_faces) break;
    Mesh_case mc{"bump disk", scaling_mesh(target)};
    std::cerr << "scaling: " << num_faces(mc.mesh) << " faces\n";
    for(const Method& m : methods) {
      const std::string key = m.name + " / " + m.solver;
      if(std::find(scaling_methods.begin(), scaling_methods.end(), key) == scaling_methods.end()) continue;
      // a method that took over a minute at the previous size is not run larger
      if(last_time.count(key) && last_time[key] > 60000) continue;
      Row r = measure(mc, m, budget_s, false);
      last_time[key] = r.median_ms;
      scaling.push_back(r);
      std::cerr << "  " << key << ": " << r.median_ms << " ms\n";
    }
  }
  // exponent of LPFB+IP from 10K faces up (least squares in log-log)
  double sx = 0, sy = 0, sxx = 0, sxy = 0, k = 0;
  for(const Row& r : scaling)
    if(r.method + " / " + r.solver == scaling_methods[0] && r.faces >= 9000 && r.runs) {
      const double x = std::log(double(r.faces)), y = std::log(r.median_ms);
      sx += x; sy += y; sxx += x * x; sxy += x * y; ++k;
    }
  const double exponent = k >= 2 ? (k * sxy - sx * sy) / (k * sxx - sx * sx) : std::nan("");

  // LPFB alone against the border size
  std::vector<std::array<double, 4>> border_series;  // border vertices, faces, ms, iterations
  for(std::size_t sectors : {500, 1000, 2000, 4000, 8000, 16000}) {
    Mesh m = from_soup(polar(8, sectors, tilted_cap(0.6, 0.2, 1.5)));
    UV_map uv = m.add_property_map<Mesh::Vertex_index, Epick::Point_2>("v:uv").first;
    std::vector<double> t;
    QD::Free_boundary_result fr;
    for(int i = 0; i < 7; ++i) {
      const auto s = Clock::now();
      fr = QD::compute_length_preserved_free_boundary(m, uv, CGAL::parameters::default_values());
      t.push_back(std::chrono::duration<double, std::milli>(Clock::now() - s).count());
    }
    border_series.push_back({double(fr.number_of_border_vertices), double(num_faces(m)), median(t), double(fr.iterations)});
  }

  const double memory_mb = peak_memory_mb(argv[0], std::min<std::size_t>(max_faces, 1000000));
  const double total_s = std::chrono::duration<double>(Clock::now() - run_start).count();

  // ---------------------------------------------------------------- output
  std::ofstream csv(out + "/results.csv");
  csv << "section,mesh,faces,vertices,border_vertices,method,solver,runs,median_ms,ratio_to_ours,l2_stretch,"
         "area_distortion_pct,pi_l,pi_theta,flipped,overlap,status\n";
  auto csv_row = [&](const char* section, const Row& r) {
    csv << section << ",\"" << r.mesh << "\"," << r.faces << "," << r.vertices << "," << r.border << ",\"" << r.method
        << "\",\"" << r.solver << "\"," << r.runs << "," << r.median_ms << "," << r.ratio << ",";
    if(r.measured)
      csv << r.l2 << "," << r.area << "," << r.pi_l << "," << r.pi_theta << "," << r.flips << ","
          << (r.overlap ? 1 : 0);
    else csv << ",,,,,";
    csv << "," << r.status << "\n";
  };
  for(const Row& r : rows) csv_row("table", r);
  for(const Row& r : scaling) csv_row("scaling", r);

  std::ofstream md(out + "/table.md");
  md << "# qd_benchmark results\n\n"
     << "Medians of 5 runs (fewer on big meshes: as many as fit in " << budget_s
     << " s, at least one; the runs column says how many), on a shared machine: treat single figures with care and "
        "compare ratios measured in the same run. Ratio = time / time of LPFB+IP (flatten_patch, default solver) on "
        "the same mesh. CGAL results are scaled as in the paper before they are measured.\n\n"
     << "- CPU: " << first_line_with("/proc/cpuinfo", "model name") << ", " << std::thread::hardware_concurrency()
     << " hardware threads\n- compiler: g++ " << __VERSION__ << ", flags `" << CGAL_QD_BENCHMARK_FLAGS << "`\n"
     << "- solver of flatten_patch: " << default_solver_label()
     << "; BLAS: " << blas_in_use() << "\n- total benchmark time: " << fmt(total_s, 4) << " s\n";
  if(!missing.empty()) md << "- note: " << missing << "\n";
  md << "\n## Table 1: every method on the same meshes\n\n"
     << "| mesh | faces | vertices | border | method | solver | runs | median ms | ratio | L² | A(Ω) % | Π_L | Π_θ | "
        "flips | overlap |\n|---|---:|---:|---:|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---|\n";
  for(const Row& r : rows) {
    md << "| " << r.mesh << " | " << r.faces << " | " << r.vertices << " | " << r.border << " | " << r.method << " | "
       << r.solver << " | " << r.runs << " | " << fmt(r.median_ms, 4) << " | " << fmt(r.ratio, 3) << " | ";
    if(r.measured)
      md << fmt(r.l2) << " | " << fmt(r.area) << " | " << fmt(r.pi_l, 2) << " | " << fmt(r.pi_theta, 2) << " | "
         << r.flips << " | " << (r.overlap ? "yes" : "no");
    else md << "- | - | - | - | - | -";
    if(r.status != "ok") md << " (" << r.status << ")";
    md << " |\n";
  }
  md << "\n## Scaling: a bump-shaped disk from 1K to 1M faces\n\n"
     << "| faces | method | solver | runs | median ms |\n|---:|---|---|---:|---:|\n";
  for(const Row& r : scaling)
    md << "| " << r.faces << " | " << r.method << " | " << r.solver << " | " << r.runs << " | " << fmt(r.median_ms, 4)
       << " |\n";
  md << "\nFitted exponent of LPFB+IP (time ~ faces^e, 10K faces and up): e = " << fmt(exponent) << "\n\n"
     << "Peak resident memory of a process that builds the " << std::min<std::size_t>(max_faces, 1000000)
     << "-face target mesh and flattens it: " << fmt(memory_mb, 4) << " MB\n\n"
     << "## LPFB alone against the border size (tilted sphere cap, 8 rings)\n\n"
     << "| border vertices | faces | iterations | median ms | µs per border vertex |\n|---:|---:|---:|---:|---:|\n";
  for(const auto& b : border_series)
    md << "| " << b[0] << " | " << b[1] << " | " << b[3] << " | " << fmt(b[2], 4) << " | " << fmt(1000 * b[2] / b[0], 3)
       << " |\n";
  md << "\nThe time includes the validation of every face of the patch.\n";
  write_svg(out + "/scaling.svg", scaling, scaling_methods);
  std::cout << "wrote " << out << "/table.md, results.csv and scaling.svg in " << fmt(total_s, 4) << " s\n";
  return EXIT_SUCCESS;
}
