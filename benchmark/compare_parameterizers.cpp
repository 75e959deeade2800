// Runs the norm-preserving parameterizer and CGAL's LSCM on the same real meshes, in one
// program, and prints a Markdown table: sizes, objective before/after the QP, active sign
// constraints, times (median of several runs) and edge-length distortion.
//
// Usage: compare_parameterizers [runs] [mesh names...]   (meshes from libcgal-demo)

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_parameterization/LSCM_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Norm_preserving_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Parameterization_distortion.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

namespace SMP = CGAL::Surface_mesh_parameterization;
using Kernel = CGAL::Simple_cartesian<double>;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using Vertex = Mesh::Vertex_index;

template <typename F>
double median_seconds(int runs, F&& f)
{
  std::vector<double> t;
  for(int r = 0; r < runs; ++r)
  {
    const auto start = std::chrono::steady_clock::now();
    f();
    t.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
}

int main(int argc, char** argv)
{
  const int runs = argc > 1 ? std::max(1, std::atoi(argv[1])) : 3;
  std::vector<std::string> names(argv + std::min(argc, 2), argv + argc);
  if(names.empty())
    names = {"nefertiti", "mushroom", "cow", "camel", "knot1", "eight", "elephant", "holes", "lion", "bunny00"};

  std::printf("| mesh | vertices | borders | objective at guess | objective | active / constraints | KKT residual "
              "| ours (s) | edge error | LSCM (s) | LSCM edge error | LSCM / ours |\n"
              "|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for(const std::string& name : names)
  {
    Mesh mesh;
    if(!CGAL::IO::read_polygon_mesh(std::string(NP_MESH_DIR) + "/" + name + ".off", mesh))
    {
      std::cerr << name << ": cannot read\n";
      continue;
    }
    std::cerr << name << ": norm-preserving\n";
    auto uv = mesh.add_property_map<Vertex, Kernel::Point_2>("v:uv").first;
    auto has_uv = mesh.add_property_map<Vertex, bool>("v:has_uv", false).first;
    SMP::Norm_preserving_parameterizer_3<Mesh> ours;
    ours.set_automatic_fixed_pair();
    SMP::Error_code status = SMP::OK;
    const double t_ours = median_seconds(runs, [&] {
      status = ours.parameterize(mesh, *halfedges(mesh).begin(), uv, get(CGAL::vertex_index, mesh), has_uv);
    });
    const SMP::Norm_preserving_report report = ours.report();
    const double ours_error = SMP::measure_distortion(mesh, uv, has_uv).edge_length_error;

    std::size_t borders = 0;
    Mesh::Halfedge_index border = Mesh::null_halfedge();
    auto seen = mesh.add_property_map<Mesh::Halfedge_index, bool>("h:seen", false).first;
    for(auto h : halfedges(mesh))
      if(is_border(h, mesh) && !get(seen, h))
      {
        ++borders;
        if(border == Mesh::null_halfedge()) border = h;
        for(auto g : CGAL::halfedges_around_face(h, mesh)) put(seen, g, true);
      }
    std::string lscm_time = "needs a border", lscm_error = "-", ratio = "-";
    if(border != Mesh::null_halfedge())
    {
      std::cerr << name << ": LSCM\n";
      auto lscm_uv = mesh.add_property_map<Vertex, Kernel::Point_2>("v:lscm_uv").first;
      SMP::Error_code lscm_status = SMP::OK;
      const double t_lscm = median_seconds(runs, [&] {
        lscm_status = SMP::parameterize(mesh, SMP::LSCM_parameterizer_3<Mesh>(), border, lscm_uv);
      });
      char buffer[64];
      std::snprintf(buffer, sizeof buffer, "%.3f", t_lscm); lscm_time = buffer;
      if(lscm_status == SMP::OK)
      {
        auto all = mesh.add_property_map<Vertex, bool>("v:all", true).first;
        std::snprintf(buffer, sizeof buffer, "%.4f", SMP::measure_distortion(mesh, lscm_uv, all).edge_length_error);
        lscm_error = buffer;
      }
      else lscm_error = SMP::error_message(lscm_status);
      std::snprintf(buffer, sizeof buffer, "%.1fx", t_lscm / t_ours); ratio = buffer;
    }
    if(status != SMP::OK)
    {
      std::printf("| %s | %zu | %zu | failed: %s |\n", name.c_str(), std::size_t(num_vertices(mesh)), borders, report.message.c_str());
      continue;
    }
    std::printf("| %s | %zu | %zu | %.6g | %.10g | %zu / %zu | %.1e | %.3f | %.4f | %s | %s | %s |\n",
                name.c_str(), report.vertices, borders, report.initial_objective, report.objective,
                report.active_constraints, report.constraints, report.kkt_residual, t_ours, ours_error,
                lscm_time.c_str(), lscm_error.c_str(), ratio.c_str());
    std::fflush(stdout);
  }
  return 0;
}
