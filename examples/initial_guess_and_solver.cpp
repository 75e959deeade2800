// Choosing the initial guess and the QP solver, both template parameters: the paper's three
// guesses with the default solver (ADMM, to a tolerance), then its exact mode (certified to
// 1e-9) and the interior-point solver on the same guess, two ways to the optimum.
//
// Usage: initial_guess_and_solver [triangle mesh]

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_parameterization/Combination_initial_guess.h>
#include <CGAL/Surface_mesh_parameterization/Graph_based_initial_guess.h>
#include <CGAL/Surface_mesh_parameterization/Interior_point_quadratic_program_traits.h>
#include <CGAL/Surface_mesh_parameterization/Norm_preserving_parameterizer_3.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <cmath>
#include <iostream>
#include <string>

namespace SMP = CGAL::Surface_mesh_parameterization;
typedef CGAL::Simple_cartesian<double> Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
typedef boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;

// Parameterizes the whole (connected) mesh and prints the objective at the guess and at the
// end, with the solver's certified bound on its distance to the optimum.
template <typename Parameterizer>
double run(const char* name, Parameterizer parameterizer, Mesh& mesh)
{
  auto uvmap = mesh.add_property_map<vertex_descriptor, Kernel::Point_2>("v:uv").first;
  auto has_uv = mesh.add_property_map<vertex_descriptor, bool>("v:has_uv", false).first;
  parameterizer.set_automatic_fixed_pair();
  if(parameterizer.parameterize(mesh, *halfedges(mesh).begin(), uvmap, get(CGAL::vertex_index, mesh), has_uv) != SMP::OK)
  {
    std::cout << name << ": " << parameterizer.report().message << '\n';
    return -1;
  }
  const SMP::Norm_preserving_report& r = parameterizer.report();
  std::cout << name << ": objective " << r.initial_objective << " at the guess -> " << r.objective;
  if(std::isfinite(r.solver.optimality_gap))
    std::cout << " (certified within " << r.solver.optimality_gap << " of the optimum)";
  else
    std::cout << " (no certificate)";
  std::cout << ", " << r.seconds << " s\n";
  return r.objective;
}

int main(int argc, char** argv)
{
  const std::string input = argc > 1 ? argv[1] : std::string(NP_MESH_DIR) + "/mushroom.off";
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(input, mesh) || is_empty(mesh) || !is_triangle_mesh(mesh))
  {
    std::cerr << "error: " << input << " is not a triangle mesh\n";
    return 1;
  }
  std::cout << input << ": " << num_vertices(mesh) << " vertices\n";

  run("XY-MinMax guess (default), ADMM", SMP::Norm_preserving_parameterizer_3<Mesh>(), mesh);
  run("Combination guess, ADMM", SMP::Norm_preserving_parameterizer_3<Mesh, SMP::Combination_initial_guess>(), mesh);
  run("Graph-based guess, ADMM", SMP::Norm_preserving_parameterizer_3<Mesh, SMP::Graph_based_initial_guess>(), mesh);

  // The exact mode of the ADMM solver, and the interior point, on the default guess.
  typedef SMP::Interior_point_quadratic_program_traits<double> Interior_point;
  const double certified = run("XY-MinMax guess, ADMM certified to 1e-9",
                               SMP::Norm_preserving_parameterizer_3<Mesh>(SMP::XY_min_max_initial_guess(),
                                                                          SMP::Norm_preserving_ADMM_solver::certified()),
                               mesh);
  const double interior = run("XY-MinMax guess, interior point",
                              SMP::Norm_preserving_parameterizer_3<Mesh, SMP::XY_min_max_initial_guess, Interior_point>(), mesh);
  std::cout << "relative difference of the interior point from the certified optimum: "
            << (interior - certified) / certified << '\n';
  return 0;
}
