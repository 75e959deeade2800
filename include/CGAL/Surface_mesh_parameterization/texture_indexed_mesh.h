// Copyright (c) 2026  The CGAL_norm_preserving_parameterization authors.
// All rights reserved.
//
// This file is part of the package Norm_preserving_parameterization for CGAL (www.cgal.org).
//
// $URL$
// $Id$
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The CGAL_norm_preserving_parameterization authors
//
/// \file texture_indexed_mesh.h
/// \ingroup PkgNormPreservingParameterization
/// Texturing a user's own indexed mesh type.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_TEXTURE_INDEXED_MESH_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_TEXTURE_INDEXED_MESH_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <CGAL/disable_warnings.h>

#include <CGAL/Surface_mesh_parameterization/texture_polygon_mesh.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgNormPreservingParameterizationTypes
/// Adapts a user's indexed mesh type, which need not be a CGAL graph, to
/// `texture_indexed_mesh()`. There is no general definition: specialize it for your type
/// (or pass any class with the same static members as the `Traits` argument). A model of the
/// concept `IndexedMeshTraits`, which asks for:
/// - `static std::size_t number_of_vertices(const Mesh&)`;
/// - `static P point(const Mesh&, std::size_t i)`, the position of vertex `i`, where `P` has
///   `x()`, `y()`, `z()` convertible to `double`;
/// - `static std::size_t number_of_faces(const Mesh&)`;
/// - `static R face(const Mesh&, std::size_t f)`, the vertex indices of face `f` in order,
///   `R` being any range of integers (a triangle, a quad, any polygon).
///
/// \code
/// struct My_mesh { std::vector<std::array<double, 3> > xyz; std::vector<std::array<int, 3> > tris; };
/// template <> struct CGAL::Surface_mesh_parameterization::Indexed_mesh_traits<My_mesh> {
///   static std::size_t number_of_vertices(const My_mesh& m) { return m.xyz.size(); }
///   static CGAL::Simple_cartesian<double>::Point_3 point(const My_mesh& m, std::size_t i)
///   { return {m.xyz[i][0], m.xyz[i][1], m.xyz[i][2]}; }
///   static std::size_t number_of_faces(const My_mesh& m) { return m.tris.size(); }
///   static const std::array<int, 3>& face(const My_mesh& m, std::size_t f) { return m.tris[f]; }
/// };
/// \endcode
/// \tparam IndexedMesh the user's mesh type
template <typename IndexedMesh>
struct Indexed_mesh_traits;

/// \ingroup PkgNormPreservingParameterizationFunctions
/// textures a user's indexed mesh exactly as `texture_polygon_mesh()` textures the same
/// vertices and faces held in a CGAL mesh (the same uvs, bit for bit): `texture_polygon_soup()`
/// on the vertices and faces that `traits` reads, the uv of vertex `i` written as
/// `put(uvmap, i, uv)`. Vertices on no face are left as they were; on failure nothing is
/// written.
///
/// \tparam ConcurrencyTag as for `texture_polygon_soup()`
/// \tparam IndexedMesh the user's mesh type
/// \tparam VertexUVMap a model of `WritablePropertyMap` from `std::size_t` to a 2D point type
/// \tparam NamedParameters a sequence of named parameters
/// \tparam Traits a model of `IndexedMeshTraits`; default `Indexed_mesh_traits<IndexedMesh>`
/// \param mesh the mesh
/// \param uvmap receives the uvs
/// \param np the named parameters of `texture_polygon_soup()` (`fixed_pair` as vertex indices)
///        but `point_map` and `geom_traits`: `traits` reads the points
/// \param traits reads the mesh
template <typename ConcurrencyTag = CGAL::Parallel_if_available_tag,
          typename IndexedMesh, typename VertexUVMap,
          typename CGAL_NP_TEMPLATE_PARAMETERS,
          typename Traits = Indexed_mesh_traits<IndexedMesh> >
Error_code texture_indexed_mesh(const IndexedMesh& mesh, VertexUVMap uvmap,
                                const CGAL_NP_CLASS& np = CGAL::parameters::default_values(),
                                const Traits& traits = Traits())
{
  std::vector<std::array<double, 3> > positions;
  positions.reserve(traits.number_of_vertices(mesh));
  for(std::size_t i = 0; i < traits.number_of_vertices(mesh); ++i)
  {
    const auto& p = traits.point(mesh, i);
    positions.push_back({double(p.x()), double(p.y()), double(p.z())});
  }
  std::vector<std::vector<std::size_t> > polygons(traits.number_of_faces(mesh));
  for(std::size_t f = 0; f < polygons.size(); ++f)
    for(const auto& i : traits.face(mesh, f))
      polygons[f].push_back(std::size_t(i));
  return internal::Norm_preserving::texture_soup<ConcurrencyTag>(std::move(positions), polygons, uvmap, np,
                                                                 [](const auto& i) { return std::size_t(i); });
}

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif
