// The input of the solver's parts: the geometry of a mesh's component, as the package extracts
// it, and a feasible start on it, for the tests of the factorization, the ADMM's projection and
// the active-set polish.

#ifndef NP_TEST_GEOMETRY_H
#define NP_TEST_GEOMETRY_H

#include "test_meshes.h"

#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Mesh_component.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Sign_constrained_qp.h>

#include <gtest/gtest.h>

#include <array>
#include <cstddef>
#include <string>

namespace np_test {

// The geometry the solver receives: the package's extraction of the first halfedge's component.
inline CGAL::Surface_mesh_parameterization::Norm_preserving_geometry component_geometry(Mesh mesh)
{
  namespace SMP = CGAL::Surface_mesh_parameterization;
  SMP::internal::Norm_preserving::Mesh_component<Mesh> component;
  std::string message;
  EXPECT_EQ(SMP::internal::Norm_preserving::extract_component(mesh, *halfedges(mesh).begin(), component, message),
            SMP::OK) << message;
  return component.geometry;
}

// A feasible start for Eq. 5 on a component: the guess (x + 0.3 z, y), the signs taken from
// it, and the ends of the first edge fixed at their guessed values.
struct Skewed_start
{
  CGAL::Surface_mesh_parameterization::internal::Norm_preserving::UV_vector guess;
  CGAL::Surface_mesh_parameterization::internal::Norm_preserving::Edge_signs signs;
  std::array<CGAL::Surface_mesh_parameterization::internal::Norm_preserving::Fixed_vertex, 2> fixed;
};

inline Skewed_start skewed_start(const CGAL::Surface_mesh_parameterization::Norm_preserving_geometry& geometry)
{
  namespace NP = CGAL::Surface_mesh_parameterization::internal::Norm_preserving;
  Skewed_start start;
  start.guess.resize(geometry.points.size());
  for(std::size_t i = 0; i < start.guess.size(); ++i)
    start.guess[i] = {geometry.points[i][0] + 0.3 * geometry.points[i][2], geometry.points[i][1]};
  start.signs = NP::edge_signs(geometry, start.guess);
  start.fixed = {NP::Fixed_vertex{geometry.edges[0][0], start.guess[geometry.edges[0][0]]},
                 NP::Fixed_vertex{geometry.edges[0][1], start.guess[geometry.edges[0][1]]}};
  return start;
}

} // namespace np_test

#endif
