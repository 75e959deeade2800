// measure_distortion against values computed by hand on small meshes.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_parameterization/Parameterization_distortion.h>

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace {

namespace SMP = CGAL::Surface_mesh_parameterization;
using Kernel = CGAL::Simple_cartesian<double>;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using Vertex = Mesh::Vertex_index;

struct Mapped
{
  Mesh mesh;
  Mesh::Property_map<Vertex, Kernel::Point_2> uv;
  Mesh::Property_map<Vertex, bool> all;
  std::vector<Vertex> v;

  Mapped()
  {
    uv = mesh.add_property_map<Vertex, Kernel::Point_2>("v:uv").first;
    all = mesh.add_property_map<Vertex, bool>("v:all", true).first;
  }
  void add(double x, double y, double z, double u, double w)
  {
    v.push_back(mesh.add_vertex(Kernel::Point_3(x, y, z)));
    put(uv, v.back(), Kernel::Point_2(u, w));
  }
  SMP::Parameterization_distortion measure() { return SMP::measure_distortion(mesh, uv, all); }
};

TEST(Distortion, ASimilarityHasNoEdgeLengthError)
{
  Mapped m; // right triangle, uv = 2 * xy rotated by 90 degrees
  m.add(0, 0, 0, 0, 0); m.add(1, 0, 0, 0, 2); m.add(0, 1, 0, -2, 0);
  m.mesh.add_face(m.v[0], m.v[1], m.v[2]);
  const auto d = m.measure();
  EXPECT_EQ(d.faces, 1u);
  EXPECT_EQ(d.edges, 3u);
  EXPECT_NEAR(d.scale, 0.5, 1e-15);
  EXPECT_NEAR(d.edge_length_error, 0, 1e-15);
  EXPECT_NEAR(d.l1_objective, 0, 1e-28);
  EXPECT_NEAR(d.max_angle_distortion, 0, 1e-12);
  EXPECT_NEAR(d.area_distortion, 0, 1e-15);
  EXPECT_NEAR(d.l2_stretch, 1, 1e-15);
  EXPECT_NEAR(d.linf_stretch, 1, 1e-15);
  EXPECT_EQ(d.flipped_faces, 0u);
  EXPECT_EQ(d.degenerate_uv_faces, 0u);
}

TEST(Distortion, AnAffineStretchMatchesTheHandComputedError)
{
  Mapped m; // u = 2x, v = y: 3D lengths 1, 1, sqrt 2; uv lengths 2, 1, sqrt 5
  m.add(0, 0, 0, 0, 0); m.add(1, 0, 0, 2, 0); m.add(0, 1, 0, 0, 1);
  m.mesh.add_face(m.v[0], m.v[1], m.v[2]);
  const double L[3] = {1, 1, std::sqrt(2.)}, T[3] = {2, 1, std::sqrt(5.)};
  const double s = (3 + std::sqrt(10.)) / 10; // sum(L T) / sum(T^2)
  double squares = 0;
  for(int k = 0; k < 3; ++k) squares += (s * T[k] - L[k]) * (s * T[k] - L[k]);
  const double mean = (2 + std::sqrt(2.)) / 3;
  EXPECT_NEAR(m.measure().edge_length_error, std::sqrt(squares / 3) / mean, 1e-14);
  // L1: 3D lengths 1, 1, 2; uv L1 lengths 2, 1, 3; s = (2 + 1 + 6) / (4 + 1 + 9).
  const double s1 = 9. / 14, L1[3] = {1, 1, 2}, T1[3] = {2, 1, 3};
  double squares1 = 0;
  for(int k = 0; k < 3; ++k) squares1 += (s1 * T1[k] - L1[k]) * (s1 * T1[k] - L1[k]);
  EXPECT_NEAR(m.measure().l1_edge_length_error, std::sqrt(squares1 / 3) / (4. / 3), 1e-14);
  EXPECT_NEAR(m.measure().l1_objective, squares1, 1e-14);
}

TEST(Distortion, AnAffineStretchMatchesTheHandComputedAnglesAreasAndStretch)
{
  Mapped m; // u = 2x, v = y on a right isosceles triangle
  m.add(0, 0, 0, 0, 0); m.add(1, 0, 0, 2, 0); m.add(0, 1, 0, 0, 1);
  m.mesh.add_face(m.v[0], m.v[1], m.v[2]);
  const auto d = m.measure();
  const double s = (3 + std::sqrt(10.)) / 10;
  // Corner angles 90, 45, 45 become 90, atan(1/2), atan(2).
  const double pi = 3.14159265358979323846, off = 45 - std::atan(0.5) * 180 / pi;
  EXPECT_NEAR(d.max_angle_distortion, off, 1e-12);
  EXPECT_NEAR(d.mean_angle_distortion, 2 * off / 3, 1e-12);
  // Scaled uv area s^2 against 3D area 1/2.
  EXPECT_NEAR(d.area_distortion, std::abs(std::log(2 * s * s)), 1e-12);
  // The map uv -> 3D is diag(1 / 2s, 1 / s): singular values 1/s and 1/(2s).
  EXPECT_NEAR(d.linf_stretch, 1 / s, 1e-12);
  EXPECT_NEAR(d.l2_stretch, std::sqrt(5. / 8) / s, 1e-12);
}

TEST(Distortion, DoesNotDependOnTheScaleOfTheMeshOrOfTheMap)
{
  // The stretch above, away from the origin, its 3D positions and its uvs scaled by factors
  // whose squares (or their products) overflow or underflow a double.
  auto measure = [](double xyz, double uv) {
    Mapped m;
    m.add(3 * xyz, -xyz, 2 * xyz, 5 * uv, uv);
    m.add(4 * xyz, -xyz, 2 * xyz, 7 * uv, uv);
    m.add(3 * xyz, 0, 2 * xyz, 5 * uv, 2 * uv);
    m.mesh.add_face(m.v[0], m.v[1], m.v[2]);
    return m.measure();
  };
  const auto unit = measure(1, 1);
  EXPECT_NEAR(unit.linf_stretch, 10 / (3 + std::sqrt(10.)), 1e-12); // 1/s, as above
  const double factors[][2] = {{1e-200, 1}, {1e200, 1}, {1, 1e-250}, {1, 1e250},
                               {1e-180, 1e-150}, {1e180, 1e160}, {1e-100, 1e-100}};
  for(const auto& f : factors)
  {
    const auto d = measure(f[0], f[1]);
    EXPECT_NEAR(d.scale / (unit.scale * f[0] / f[1]), 1, 1e-14);
    EXPECT_NEAR(d.edge_length_error, unit.edge_length_error, 1e-14);
    EXPECT_NEAR(d.l1_edge_length_error, unit.l1_edge_length_error, 1e-14);
    EXPECT_NEAR(d.mean_angle_distortion, unit.mean_angle_distortion, 1e-12);
    EXPECT_NEAR(d.max_angle_distortion, unit.max_angle_distortion, 1e-12);
    EXPECT_NEAR(d.area_distortion, unit.area_distortion, 1e-12);
    EXPECT_NEAR(d.l2_stretch, unit.l2_stretch, 1e-12);
    EXPECT_NEAR(d.linf_stretch, unit.linf_stretch, 1e-12);
    EXPECT_EQ(d.degenerate_uv_faces, 0u);
    EXPECT_EQ(d.flipped_faces, 0u);
  }
  // Eq. 3 is in squared 3D units.
  EXPECT_NEAR(measure(1e-100, 1e-100).l1_objective / (unit.l1_objective * 1e-200), 1, 1e-14);
}

TEST(Distortion, CountsAFlippedFaceAndItsArea)
{
  Mapped m; // faces of 3D areas 1/2 and 1, oriented oppositely in uv: the smaller one is flipped
  m.add(0, 0, 0, 0, 0); m.add(1, 0, 0, 1, 0); m.add(0, 1, 0, 0, 1); m.add(0, -2, 0, 0, 0.5);
  m.mesh.add_face(m.v[0], m.v[1], m.v[2]);
  m.mesh.add_face(m.v[0], m.v[3], m.v[1]);
  const auto d = m.measure();
  EXPECT_EQ(d.faces, 2u);
  EXPECT_EQ(d.flipped_faces, 1u);
  EXPECT_NEAR(d.flipped_area_fraction, 1. / 3, 1e-15);
}

TEST(Distortion, CountsDegenerateUVFacesAndSkipsUnmappedVertices)
{
  Mapped m;
  m.add(0, 0, 0, 0, 0); m.add(1, 0, 0, 1, 1); m.add(0, 1, 0, 2, 2); m.add(1, 1, 1, 5, 5);
  m.mesh.add_face(m.v[0], m.v[1], m.v[2]);
  m.mesh.add_face(m.v[2], m.v[1], m.v[3]);
  put(m.all, m.v[3], false);
  const auto d = m.measure();
  EXPECT_EQ(d.faces, 1u);
  EXPECT_EQ(d.edges, 3u);
  EXPECT_EQ(d.degenerate_uv_faces, 1u);
}

} // namespace
