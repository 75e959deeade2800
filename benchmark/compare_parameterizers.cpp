// The comparison harness: for a list of meshes, runs ours (each initial guess with the default
// ADMM solver, and the XY-MinMax guess with the ADMM solver's certified exact mode and with the
// interior-point solver; no cut; and the
// XY-MinMax guess with sign refinement, Euclidean refinement or both, and the Euclidean
// refinement after a loosely solved QP, see doc/refinement.md) and
// CGAL's LSCM, ARAP, discrete conformal, discrete authalic, mean value coordinates and
// iterative authalic (on a disk: the mesh cut by cut_to_disk where it is not one), each in a
// new process of its own (doc/performance.md, "Memory"), and prints one table as Markdown
// (stdout) and CSV (--csv), with a plot of time against vertex count (--svg). Progress goes to
// stderr.
//
// Usage: compare_parameterizers [--runs N] [--time-limit S] [--csv FILE] [--svg FILE]
//                               [--methods a,b,...] mesh...
// A mesh is a name of CGAL's collection (libcgal-demo), a path, or either followed by *K for
// K steps of Loop subdivision (mushroom*3).

#include "harness_process.h"
#include "time_plot.h"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Seam_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/subdivision_method_3.h>

#include <CGAL/Surface_mesh_parameterization/ARAP_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_authalic_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_conformal_map_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Iterative_authalic_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/LSCM_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Mean_value_coordinates_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Combination_initial_guess.h>
#include <CGAL/Surface_mesh_parameterization/Graph_based_initial_guess.h>
#include <CGAL/Surface_mesh_parameterization/Interior_point_quadratic_program_traits.h>
#include <CGAL/Surface_mesh_parameterization/Parameterization_distortion.h>
#include <CGAL/Surface_mesh_parameterization/cut_to_disk.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>
#include <CGAL/Surface_mesh_parameterization/texture_polygon_mesh.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace SMP = CGAL::Surface_mesh_parameterization;
using Kernel = CGAL::Simple_cartesian<double>;
using Point_2 = Kernel::Point_2;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using Vertex = Mesh::Vertex_index;
using Halfedge = Mesh::Halfedge_index;
using Seam_edge_map = Mesh::Property_map<Mesh::Edge_index, bool>;
using Seam_vertex_map = Mesh::Property_map<Vertex, bool>;
using Seam_mesh = CGAL::Seam_mesh<Mesh, Seam_edge_map, Seam_vertex_map>;

const std::vector<std::string> all_methods = {
  "ours-xy", "ours-combination", "ours-graph", "ours-certified", "ours-exact", "ours-signs", "ours-euclid", "ours-both", "ours-euclid-fast", "lscm", "arap",
  "discrete-conformal", "discrete-authalic", "mean-value", "iterative-authalic"};

struct Options
{
  int runs = 3;
  double time_limit = 600;
  std::string csv, svg;
  std::vector<std::string> methods = all_methods;
  std::vector<std::string> meshes;
};

// ---------------------------------------------------------------------------- the mesh

Mesh load(const std::string& spec)
{
  const std::size_t star = spec.find('*');
  const std::string name = spec.substr(0, star);
  const int steps = star == std::string::npos ? 0 : std::stoi(spec.substr(star + 1));
  const std::string path = name.find('.') != std::string::npos || name.find('/') != std::string::npos
                             ? name : std::string(NP_MESH_DIR) + "/" + name + ".off";
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(path, mesh) || is_empty(mesh))
    throw std::runtime_error("cannot read " + path);
  if(!CGAL::is_triangle_mesh(mesh))
    CGAL::Polygon_mesh_processing::triangulate_faces(mesh);
  if(steps > 0)
    CGAL::Subdivision_method_3::Loop_subdivision(mesh, CGAL::parameters::number_of_iterations(steps));
  return mesh;
}

struct Topology
{
  std::size_t components = 0, borders = 0;
  long genus = 0;
  std::string text() const
  {
    std::string t = borders == 0 ? "closed" : borders == 1 && genus == 0 ? "disk" : std::to_string(borders) + " borders";
    if(genus > 0 || borders == 0) t += " g=" + std::to_string(genus);
    if(components > 1) t += ", " + std::to_string(components) + " components";
    return t;
  }
};

Topology topology(const Mesh& mesh)
{
  Topology t;
  Mesh copy = mesh;
  auto id = copy.add_property_map<Mesh::Face_index, std::size_t>("f:id").first;
  t.components = CGAL::Polygon_mesh_processing::connected_components(copy, id);
  auto seen = copy.add_property_map<Halfedge, bool>("h:seen", false).first;
  for(Halfedge h : halfedges(copy))
    if(is_border(h, copy) && !get(seen, h))
    {
      ++t.borders;
      for(Halfedge g : CGAL::halfedges_around_face(h, copy)) put(seen, g, true);
    }
  // Euler: V - E + F = 2c - 2g - b over all components (genus summed).
  const long chi = long(num_vertices(mesh)) - long(num_edges(mesh)) + long(num_faces(mesh));
  t.genus = (2 * long(t.components) - long(t.borders) - chi) / 2;
  return t;
}

// ---------------------------------------------------------------------------- one measurement

struct Measurement
{
  double seconds = 0, peak_mib = 0, seam_length = 0;
  double optimality_gap = std::numeric_limits<double>::quiet_NaN(); // ours: the certified bound
  SMP::Parameterization_distortion d;

  std::string serialize() const
  {
    std::ostringstream out;
    out.precision(17);
    out << seconds << ' ' << peak_mib << ' ' << seam_length << ' ' << d.faces << ' ' << d.edges << ' '
        << d.edge_length_error << ' ' << d.l1_edge_length_error << ' ' << d.l1_objective << ' '
        << d.mean_angle_distortion << ' ' << d.max_angle_distortion << ' ' << d.area_distortion << ' '
        << d.l2_stretch << ' ' << d.linf_stretch << ' ' << d.flipped_faces << ' ' << d.flipped_area_fraction
        << ' ' << d.degenerate_uv_faces << ' ' << optimality_gap;
    return out.str();
  }
  static Measurement parse(const std::string& text)
  {
    Measurement m;
    std::istringstream in(text);
    in >> m.seconds >> m.peak_mib >> m.seam_length >> m.d.faces >> m.d.edges >> m.d.edge_length_error
       >> m.d.l1_edge_length_error >> m.d.l1_objective >> m.d.mean_angle_distortion >> m.d.max_angle_distortion
       >> m.d.area_distortion >> m.d.l2_stretch >> m.d.linf_stretch >> m.d.flipped_faces
       >> m.d.flipped_area_fraction >> m.d.degenerate_uv_faces;
    std::string gap;
    in >> gap;
    m.optimality_gap = std::stod(gap); // "nan" and "inf" are not read by operator>>
    return m;
  }
};

// Median time of up to `runs` calls of `f` (a single call when one takes over 2 s); `f`
// returns an error message, empty on success.
template <typename F>
double median_seconds(int runs, F&& f)
{
  std::vector<double> times;
  for(int r = 0; r < runs; ++r)
  {
    const auto start = std::chrono::steady_clock::now();
    const std::string error = f();
    times.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    if(!error.empty()) throw std::runtime_error(error);
    if(times.back() > 2) break;
  }
  std::sort(times.begin(), times.end());
  return times[times.size() / 2];
}

// The refinements of doc/refinement.md: at most 10 rounds of sign refinement, at most 1000
// steps of the Euclidean refinement, each with its default tolerance; "ours-euclid-fast" solves
// the QP, only the refinement's start, to 1e-2 instead of the default 2.5e-5.
const int harness_sign_rounds = 10, harness_euclidean_iterations = 1000;
const double harness_fast_qp_tolerance = 1e-2;

template <typename InitialGuess, typename Solver = SMP::Norm_preserving_ADMM_solver>
Measurement measure_ours(Mesh& mesh, int runs, int sign_rounds = 0, int euclidean_iterations = 0,
                         const Solver& solver = Solver())
{
  auto uv = mesh.add_property_map<Vertex, Point_2>("v:uv").first;
  Measurement m;
  np_benchmark::reset_peak_memory();
  m.seconds = median_seconds(runs, [&] {
    SMP::Texture_polygon_mesh_report report;
    const bool ok = SMP::texture_polygon_mesh(mesh, uv,
                                              SMP::parameters::initial_guess(InitialGuess()).combine(
                                                SMP::parameters::solver(solver),
                                                SMP::parameters::texture_fit(SMP::NORM_PRESERVING_NO_FIT),
                                                SMP::parameters::sign_refinement(sign_rounds),
                                                SMP::parameters::euclidean_refinement(euclidean_iterations),
                                                SMP::parameters::report(report))) == SMP::OK;
    m.optimality_gap = report.optimality_gap;
    return ok ? std::string() : report.message;
  });
  m.peak_mib = np_benchmark::peak_memory_mib();
  auto on_face = mesh.add_property_map<Vertex, bool>("v:on_face").first;
  for(Vertex v : vertices(mesh)) put(on_face, v, !mesh.is_isolated(v));
  m.d = SMP::measure_distortion(mesh, uv, on_face);
  return m;
}

// A CGAL parameterizer on every component, each cut to a disk where needed (the cuts not
// timed); the time is that of all the components, as ours textures them all.
template <typename Parameterize>
Measurement measure_on_disk(Mesh& mesh, const Topology& topology, int runs, Parameterize&& parameterize)
{
  Seam_edge_map seam_edges = mesh.add_property_map<Mesh::Edge_index, bool>("e:seam", false).first;
  Seam_vertex_map seam_vertices = mesh.add_property_map<Vertex, bool>("v:seam", false).first;
  Seam_mesh seam_mesh(mesh, seam_edges, seam_vertices);
  Measurement m;
  std::vector<typename boost::graph_traits<Seam_mesh>::halfedge_descriptor> borders;
  const bool is_disk = topology.components == 1 && topology.borders == 1 && topology.genus == 0;
  if(is_disk)
    borders.push_back({*std::find_if(halfedges(mesh).begin(), halfedges(mesh).end(),
                                     [&](Halfedge h) { return is_border(h, mesh); }), false});
  else
  {
    auto component = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:component").first;
    std::vector<bool> cut(CGAL::Polygon_mesh_processing::connected_components(mesh, component), false);
    for(auto f : faces(mesh))
      if(!cut[get(component, f)])
      {
        cut[get(component, f)] = true;
        const SMP::Disk_cut_result result = SMP::cut_to_disk(seam_mesh, halfedge(f, mesh));
        if(result.status != SMP::OK) throw std::runtime_error("cut: " + result.message);
        m.seam_length += result.seam_length;
        borders.push_back(result.border_halfedge);
      }
  }
  std::vector<typename boost::graph_traits<Seam_mesh>::face_descriptor> disk_faces;
  std::vector<decltype(get(CGAL::dynamic_vertex_property_t<int>(), seam_mesh))> indices; // one per component
  for(auto border : borders)
  {
    CGAL::Polygon_mesh_processing::connected_component(face(opposite(border, seam_mesh), seam_mesh), seam_mesh,
                                                       std::back_inserter(disk_faces));
    indices.push_back(get(CGAL::dynamic_vertex_property_t<int>(), seam_mesh));
    SMP::internal::fill_index_map_of_cc(border, seam_mesh, indices.back());
  }

  auto uv = mesh.add_property_map<Halfedge, Point_2>("h:uv").first;           // seam-mesh vertex -> uv
  auto done = mesh.add_property_map<Halfedge, bool>("h:done", false).first;    // seam-mesh vertex -> has uv
  np_benchmark::reset_peak_memory();
  m.seconds = median_seconds(runs, [&] {
    for(std::size_t k = 0; k < borders.size(); ++k)
    {
      const SMP::Error_code status = parameterize(seam_mesh, borders[k], uv, indices[k], done);
      if(status != SMP::OK)
        return std::string(SMP::norm_preserving_error_message(status));
    }
    return std::string();
  });
  m.peak_mib = np_benchmark::peak_memory_mib();
  // The parameterizers mark only the vertices they fixed; every vertex of the disk has a uv.
  for(auto f : disk_faces)
    for(auto v : vertices_around_face(halfedge(f, seam_mesh), seam_mesh)) put(done, v, true);
  m.d = SMP::measure_distortion(seam_mesh, uv, done);
  return m;
}

Measurement measure(const std::string& method, Mesh& mesh, const Topology& t, int runs)
{
  using SM = Seam_mesh;
  if(method == "ours-xy") return measure_ours<SMP::XY_min_max_initial_guess>(mesh, runs);
  if(method == "ours-combination") return measure_ours<SMP::Combination_initial_guess>(mesh, runs);
  if(method == "ours-graph") return measure_ours<SMP::Graph_based_initial_guess>(mesh, runs);
  if(method == "ours-certified")
    return measure_ours<SMP::XY_min_max_initial_guess>(mesh, runs, 0, 0, SMP::Norm_preserving_ADMM_solver::certified());
  if(method == "ours-exact")
    return measure_ours<SMP::XY_min_max_initial_guess, SMP::Interior_point_quadratic_program_traits<double> >(mesh, runs);
  if(method == "ours-signs") return measure_ours<SMP::XY_min_max_initial_guess>(mesh, runs, harness_sign_rounds);
  if(method == "ours-euclid")
    return measure_ours<SMP::XY_min_max_initial_guess>(mesh, runs, 0, harness_euclidean_iterations);
  if(method == "ours-both")
    return measure_ours<SMP::XY_min_max_initial_guess>(mesh, runs, harness_sign_rounds, harness_euclidean_iterations);
  if(method == "ours-euclid-fast")
    return measure_ours<SMP::XY_min_max_initial_guess>(mesh, runs, 0, harness_euclidean_iterations,
                                                       SMP::Norm_preserving_ADMM_solver(harness_fast_qp_tolerance));
  auto with = [&](auto make) {
    return measure_on_disk(mesh, t, runs, [&](SM& sm, auto bhd, auto uv, auto index, auto done) {
      auto parameterizer = make();
      return parameterizer.parameterize(sm, bhd, uv, index, done);
    });
  };
  if(method == "lscm") return with([] { return SMP::LSCM_parameterizer_3<SM>(); });
  if(method == "arap") return with([] { return SMP::ARAP_parameterizer_3<SM>(); });
  if(method == "discrete-conformal") return with([] { return SMP::Discrete_conformal_map_parameterizer_3<SM>(); });
  if(method == "discrete-authalic") return with([] { return SMP::Discrete_authalic_parameterizer_3<SM>(); });
  if(method == "mean-value") return with([] { return SMP::Mean_value_coordinates_parameterizer_3<SM>(); });
  if(method == "iterative-authalic")
    return measure_on_disk(mesh, t, runs, [&](SM& sm, auto bhd, auto uv, auto index, auto done) {
      SMP::Iterative_authalic_parameterizer_3<SM> parameterizer; // not copyable
      return parameterizer.parameterize(sm, bhd, uv, index, done);
    });
  throw std::runtime_error("unknown method " + method);
}

// ---------------------------------------------------------------------------- the table

struct Row
{
  std::string mesh, topology, method, status;
  std::size_t vertices = 0, faces = 0;
  Measurement m;
};

std::string number(double x, const char* format = "%.4g")
{
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, format, x);
  return buffer;
}

std::vector<std::string> cells(const Row& r)
{
  const bool ok = r.status == "ok";
  auto value = [&](double x, const char* format = "%.4g") { return ok ? number(x, format) : std::string(); };
  const auto& d = r.m.d;
  return {r.mesh, std::to_string(r.vertices), std::to_string(r.faces), r.topology, r.method, r.status,
          value(r.m.seconds, "%.4f"), value(r.m.peak_mib, "%.1f"), value(d.edge_length_error),
          value(d.l1_edge_length_error), value(d.l1_objective, "%.10g"), value(d.mean_angle_distortion, "%.2f"),
          value(d.max_angle_distortion, "%.1f"), value(d.area_distortion), value(d.l2_stretch),
          value(d.linf_stretch), ok ? std::to_string(d.flipped_faces) : "", value(d.flipped_area_fraction, "%.3f"),
          ok ? std::to_string(d.degenerate_uv_faces) : "", value(r.m.seam_length),
          ok && !std::isnan(r.m.optimality_gap) ? number(r.m.optimality_gap, "%.3g") : ""};
}

const std::vector<std::string> header = {
  "mesh", "vertices", "faces", "topology", "method", "status", "seconds", "peak MiB", "edge error",
  "L1 edge error", "Eq. 3", "mean angle (deg)", "max angle (deg)", "area (RMS log)", "L2 stretch",
  "Linf stretch", "flipped", "flipped area", "degenerate", "seam length", "certified gap"};

Options parse(int argc, char** argv)
{
  Options o;
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    auto next = [&]() -> std::string {
      if(i + 1 >= argc) throw std::runtime_error(a + " needs a value");
      return argv[++i];
    };
    if(a == "--runs") o.runs = std::max(1, std::stoi(next()));
    else if(a == "--time-limit") o.time_limit = std::stod(next());
    else if(a == "--csv") o.csv = next();
    else if(a == "--svg") o.svg = next();
    else if(a == "--methods")
    {
      o.methods.clear();
      std::stringstream list(next());
      for(std::string m; std::getline(list, m, ',');) o.methods.push_back(m);
    }
    else if(a == "--help" || a == "-h")
    {
      std::cout << "compare_parameterizers [--runs N] [--time-limit S] [--csv FILE] [--svg FILE] "
                   "[--methods a,b,...] mesh...\nmethods:";
      for(const auto& m : all_methods) std::cout << ' ' << m;
      std::cout << "\nmesh: a name of CGAL's collection, a path, or either with *K for K Loop subdivisions\n";
      std::exit(0);
    }
    else o.meshes.push_back(a);
  }
  if(o.meshes.empty())
    o.meshes = {"nefertiti", "mushroom", "cow", "knot1", "eight", "holes"};
  return o;
}

int main(int argc, char** argv)
{
  // The measuring side of np_benchmark::run_in_new_process(): --child METHOD MESH RUNS.
  if(argc == 5 && std::string(argv[1]) == "--child")
    std::_Exit(np_benchmark::run_as_child([&] {
      Mesh mesh = load(argv[3]);
      return measure(argv[2], mesh, topology(mesh), std::stoi(argv[4])).serialize();
    }));
  Options options;
  try { options = parse(argc, argv); }
  catch(const std::exception& e) { std::cerr << "error: " << e.what() << '\n'; return 2; }

  std::vector<Row> rows;
  for(const std::string& spec : options.meshes)
  {
    Row base;
    base.mesh = spec;
    try
    {
      const Mesh mesh = load(spec);
      base.vertices = num_vertices(mesh);
      base.faces = num_faces(mesh);
      base.topology = topology(mesh).text();
    }
    catch(const std::exception& e)
    {
      std::cerr << spec << ": " << e.what() << '\n';
      base.status = e.what();
      rows.push_back(base);
      continue;
    }
    for(const std::string& method : options.methods)
    {
      std::cerr << spec << " (" << base.vertices << " vertices): " << method << "...\n";
      Row row = base;
      row.method = method;
      const np_benchmark::Child_result result =
        np_benchmark::run_in_new_process({"--child", method, spec, std::to_string(options.runs)}, options.time_limit);
      row.status = result.status;
      if(row.status == "ok")
      {
        try { row.m = Measurement::parse(result.payload); }
        catch(const std::exception&) { row.status = "bad payload"; }
      }
      std::cerr << "  " << row.status << (row.status == "ok" ? ", " + number(row.m.seconds) + " s" : "") << '\n';
      rows.push_back(row);
    }
  }

  std::cout << '|';
  for(const auto& h : header) std::cout << ' ' << h << " |";
  std::cout << "\n|";
  for(std::size_t i = 0; i < header.size(); ++i) std::cout << "---|";
  std::cout << '\n';
  for(const Row& r : rows)
  {
    std::cout << '|';
    for(const auto& c : cells(r)) std::cout << ' ' << c << " |";
    std::cout << '\n';
  }
  if(!options.csv.empty())
  {
    std::ofstream csv(options.csv);
    for(std::size_t i = 0; i < header.size(); ++i) csv << (i ? "," : "") << header[i];
    csv << '\n';
    for(const Row& r : rows)
    {
      const auto c = cells(r);
      for(std::size_t i = 0; i < c.size(); ++i) csv << (i ? "," : "") << '"' << c[i] << '"';
      csv << '\n';
    }
  }
  if(!options.svg.empty())
  {
    std::map<std::string, std::vector<std::pair<double, double> > > series;
    for(const Row& r : rows)
      if(r.status == "ok") series[r.method].push_back({double(r.vertices), r.m.seconds});
    np_benchmark::write_time_plot(options.svg, series);
  }
  return 0;
}
