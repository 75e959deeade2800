#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_PARAMETERIZATION_DISTORTION_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_PARAMETERIZATION_DISTORTION_H

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/number_utils.h>

#include <boost/property_map/property_map.hpp>

#include <array>
#include <cmath>
#include <cstddef>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgNormPreservingParameterization
/// Distortion of a uv map of a triangle mesh, over the faces and edges whose vertices all
/// have a uv.
/// Edge-length errors are measured after scaling the uv map by the one factor that best fits
/// the 3D lengths (least squares), relative to the mean 3D edge length.
struct Parameterization_distortion
{
  std::size_t faces = 0;               ///< faces measured
  std::size_t edges = 0;               ///< edges measured
  double edge_length_error = 0;        ///< RMS of (s ||uv_i - uv_j||_2 - ||P_i - P_j||_2) / mean 3D length
  double l1_edge_length_error = 0;     ///< RMS of (s (|du| + |dv|) - ||P_i - P_j||_1) / mean 3D L1 length
  std::size_t flipped_faces = 0;       ///< faces oriented against the orientation of most of the 3D area
  double flipped_area_fraction = 0;    ///< 3D area of those faces over the total 3D area
  std::size_t degenerate_uv_faces = 0; ///< faces of zero uv area
};

/// \ingroup PkgNormPreservingParameterization
/// measures the distortion of `uvmap` on `mesh`; `vpmap` tells which vertices have a uv.
/// \tparam TriangleMesh a model of `FaceGraph` with an internal `vertex_point` map
/// \tparam VertexUVMap a model of `ReadablePropertyMap` from vertices to a 2D point type
/// \tparam VertexParameterizedMap a model of `ReadablePropertyMap` from vertices to `bool`
template <typename TriangleMesh, typename VertexUVMap, typename VertexParameterizedMap>
Parameterization_distortion measure_distortion(const TriangleMesh& mesh, VertexUVMap uvmap,
                                               VertexParameterizedMap vpmap)
{
  using halfedge_descriptor = typename boost::graph_traits<TriangleMesh>::halfedge_descriptor;
  Parameterization_distortion d;
  const auto ppmap = get(CGAL::vertex_point, mesh);
  auto xyz = [&](auto v) -> std::array<double, 3> {
    const auto& p = get(ppmap, v);
    return {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
  };
  auto uv = [&](auto v) -> std::array<double, 2> {
    const auto& p = get(uvmap, v);
    return {CGAL::to_double(p.x()), CGAL::to_double(p.y())};
  };

  // Best scales s = sum(l3 l2) / sum(l2^2), then RMS errors by expanding the squares.
  double l2_33 = 0, l2_32 = 0, l2_22 = 0, l2_sum = 0;
  double l1_33 = 0, l1_32 = 0, l1_22 = 0, l1_sum = 0;
  for(auto e : edges(mesh))
  {
    const halfedge_descriptor h = halfedge(e, mesh);
    const auto i = source(h, mesh), j = target(h, mesh);
    if(!get(vpmap, i) || !get(vpmap, j)) continue;
    const auto p = xyz(i), q = xyz(j);
    const auto a = uv(i), b = uv(j);
    const double du = a[0] - b[0], dv = a[1] - b[1];
    const double L2 = std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]));
    const double L1 = std::abs(p[0] - q[0]) + std::abs(p[1] - q[1]) + std::abs(p[2] - q[2]);
    const double t2 = std::sqrt(du * du + dv * dv), t1 = std::abs(du) + std::abs(dv);
    l2_33 += L2 * L2; l2_32 += L2 * t2; l2_22 += t2 * t2; l2_sum += L2;
    l1_33 += L1 * L1; l1_32 += L1 * t1; l1_22 += t1 * t1; l1_sum += L1;
    ++d.edges;
  }
  auto rms = [&](double s33, double s32, double s22, double sum) {
    if(d.edges == 0 || !(sum > 0)) return 0.;
    const double s = s22 > 0 ? s32 / s22 : 0.;
    const double mean = sum / double(d.edges);
    return std::sqrt((std::max)(0., s33 - 2 * s * s32 + s * s * s22) / double(d.edges)) / mean;
  };
  d.edge_length_error = rms(l2_33, l2_32, l2_22, l2_sum);
  d.l1_edge_length_error = rms(l1_33, l1_32, l1_22, l1_sum);

  double positive_area = 0, negative_area = 0, total_area = 0;
  std::size_t positive = 0, negative = 0;
  for(auto f : faces(mesh))
  {
    const halfedge_descriptor h = halfedge(f, mesh);
    const auto v0 = source(h, mesh), v1 = target(h, mesh), v2 = target(next(h, mesh), mesh);
    if(!get(vpmap, v0) || !get(vpmap, v1) || !get(vpmap, v2)) continue;
    const auto a = uv(v0), b = uv(v1), c = uv(v2);
    const double uv_area = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    const auto p = xyz(v0), q = xyz(v1), r = xyz(v2);
    const std::array<double, 3> e1 = {q[0] - p[0], q[1] - p[1], q[2] - p[2]}, e2 = {r[0] - p[0], r[1] - p[1], r[2] - p[2]};
    const std::array<double, 3> n = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
    const double area = 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    total_area += area;
    ++d.faces;
    if(uv_area > 0) { ++positive; positive_area += area; }
    else if(uv_area < 0) { ++negative; negative_area += area; }
    else ++d.degenerate_uv_faces;
  }
  const bool positive_is_reference = positive_area >= negative_area;
  d.flipped_faces = positive_is_reference ? negative : positive;
  d.flipped_area_fraction = total_area > 0 ? (positive_is_reference ? negative_area : positive_area) / total_area : 0.;
  return d;
}

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
