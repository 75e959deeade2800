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
/// \file cut_to_disk.h
/// \ingroup PkgNormPreservingParameterization
/// A short cut that makes a mesh component a topological disk, for cut-based methods.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_CUT_TO_DISK_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_CUT_TO_DISK_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <CGAL/disable_warnings.h>

#include <CGAL/Surface_mesh_parameterization/Error_code.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Tree_cotree_cut.h>

#include <CGAL/assertions.h>
#include <CGAL/boost/graph/Seam_mesh.h>

#include <cstddef>
#include <string>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgNormPreservingParameterizationTypes
/// What `cut_to_disk()` did.
/// \tparam SeamMesh the `CGAL::Seam_mesh` type
template <typename SeamMesh>
struct Disk_cut_result
{
  /// halfedge handle of the seam mesh
  typedef typename boost::graph_traits<SeamMesh>::halfedge_descriptor halfedge_descriptor;

  Error_code status = OK;        ///< result of the call
  std::string message;           ///< readable reason of a failure, empty on success
  std::size_t genus = 0;         ///< genus of the component before the cut
  std::size_t border_loops = 0;  ///< border loops of the component before the cut
  std::size_t seam_edges = 0;    ///< edges marked as seams
  double seam_length = 0;        ///< total 3D length of the seam edges
  /// a border halfedge of the cut component in the seam mesh, as CGAL's
  /// `parameterize(seam_mesh, parameterizer, bhd, uvmap)` expects it
  halfedge_descriptor border_halfedge;
};

/// \ingroup PkgNormPreservingParameterizationFunctions
/// cuts the connected component of `h` into a topological disk, for the parameterizers that
/// need one (LSCM, ARAP, the fixed-border ones): marks seam edges in `seam_mesh` with
/// `Seam_mesh::add_seam()`, so that the component of the seam mesh has exactly one border
/// loop and Euler characteristic 1, and returns one of its border halfedges. Marking through
/// the seam mesh keeps its seam count (`number_of_seam_edges()`, `num_edges()`) right, which a
/// `Seam_mesh` constructed on already filled maps would have at 0.
///
/// The cut is computed by tree-cotree, with the greedy choice of Erickson and Whittlesey
/// ("Greedy optimal homotopy and homology generators", SODA 2005), which keeps the loops short:
/// - `T`: the shortest-path tree (Dijkstra, 3D edge lengths) of the vertex-edge graph, rooted at
///   the vertex of smallest x (lowest index on ties; indices follow the mesh's vertex order);
/// - `C`: a spanning tree of the dual graph (faces across non-border edges) by Kruskal, edges
///   outside `T` first, the one closing the longest loop through `T` first among them (on a
///   closed component `C` needs no edge of `T`; with border loops it may);
/// - the cut: every non-border edge outside `C`, pruned of dangling branches (an edge ending at
///   a vertex that touches no other cut or border edge).
///
/// On a closed component of genus `g` the cut is the `2g` generator loops closed through `T`;
/// with border loops it also holds the paths of `T` that join every border loop into one. A
/// disk needs no cut (`seam_edges == 0`). A closed component of genus 0 has an empty cut graph,
/// but a seam mesh needs a seam to have a border: it is slit along the path of `T` from the
/// root to the vertex farthest from it (lowest index on ties), which leaves one border loop
/// running along both sides of the slit.
///
/// Deterministic: the cut depends on the component, not on which of its halfedges `h` is.
/// `O(n log n)` for `n` edges of the component.
///
/// Errors (nothing is marked): `ERROR_EMPTY_MESH`; `ERROR_WRONG_PARAMETER` when `h` is null or
/// has no incident face, when a vertex of the component has a non-finite coordinate or is
/// already on a seam, or when the component's Euler characteristic and border loops fit no
/// orientable surface (a non-manifold component).
///
/// \tparam TriangleMesh a model of `FaceListGraph` with an internal `vertex_point` map; faces
///         may be any polygons, though CGAL's parameterizers then need triangles
/// \tparam SeamEdgeMap the seam edge map of the `Seam_mesh`
/// \tparam SeamVertexMap the seam vertex map of the `Seam_mesh`
///
/// \param seam_mesh the seam mesh of the mesh to cut, built with both maps `false` on the
///        component
/// \param h any halfedge of the component to cut
///
/// \pre the component of `h` is an orientable 2-manifold, with or without border.
template <typename TriangleMesh, typename SeamEdgeMap, typename SeamVertexMap>
Disk_cut_result<CGAL::Seam_mesh<TriangleMesh, SeamEdgeMap, SeamVertexMap> >
cut_to_disk(CGAL::Seam_mesh<TriangleMesh, SeamEdgeMap, SeamVertexMap>& seam_mesh,
            typename boost::graph_traits<TriangleMesh>::halfedge_descriptor h)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef Disk_cut_result<CGAL::Seam_mesh<TriangleMesh, SeamEdgeMap, SeamVertexMap> > Result;
  typedef typename Result::halfedge_descriptor halfedge_descriptor;
  namespace NP = internal::Norm_preserving;

  const TriangleMesh& mesh = seam_mesh.mesh();
  Result result;
  auto fail = [&result](Error_code status, const std::string& message) {
    result.status = status;
    result.message = message;
    return result;
  };
  if(faces(mesh).empty())
    return fail(ERROR_EMPTY_MESH, "the mesh has no face");
  if(h == GT::null_halfedge())
    return fail(ERROR_WRONG_PARAMETER, "the halfedge is null");
  const auto seed = is_border(h, mesh) ? face(opposite(h, mesh), mesh) : face(h, mesh);
  if(seed == GT::null_face())
    return fail(ERROR_WRONG_PARAMETER, "the halfedge has no incident face");

  NP::Disk_cut<TriangleMesh> cut;
  const Error_code status = NP::tree_cotree_cut(mesh, seed, cut, result.message);
  if(status != OK)
    return fail(status, result.message);
  // Earlier seams would make the cut component something else than a disk.
  for(auto v : cut.vertices)
    if(seam_mesh.has_on_seam(v))
      return fail(ERROR_WRONG_PARAMETER, "the component already has seams");

  for(auto sh : cut.seam)
  {
    CGAL_assertion_code(const bool added =) seam_mesh.add_seam(source(sh, mesh), target(sh, mesh));
    CGAL_assertion(added);
  }
  result.genus = cut.genus;
  result.border_loops = cut.border_loops;
  result.seam_edges = cut.seam.size();
  result.seam_length = cut.seam_length;
  // The seam side of a seam edge has no face in the seam mesh: it is a border halfedge.
  result.border_halfedge = cut.seam.empty() ? halfedge_descriptor(cut.border, false)
                                            : halfedge_descriptor(cut.seam.front(), true);
  return result;
}

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif
