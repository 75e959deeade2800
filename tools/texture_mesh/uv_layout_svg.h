// Writes the uv layout of a mesh as an SVG picture: the face edges as thin strokes (on large
// meshes, the area covered), flipped faces (clockwise in uv) shaded red, v pointing up. When every uv lies in [0,1]^2 the
// picture is that square, drawn as a frame; otherwise it is the bounding square of the uvs.

#ifndef NP_EXAMPLES_UV_LAYOUT_SVG_H
#define NP_EXAMPLES_UV_LAYOUT_SVG_H

#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace np_examples {

// Maps uv to picture units: [0,1000] across, y pointing down as SVG wants.
struct Uv_layout_frame
{
  double low_u = 0, low_v = 0, scale = 1000;
  std::array<long, 2> point(double u, double v) const
  {
    return {std::lround((u - low_u) * scale), std::lround(1000 - (v - low_v) * scale)};
  }
};

// Writes the layout of `mesh` under `uv` to `path`. With more than `max_faces` faces, only
// every k-th face is written (the smallest k that keeps at most `max_faces`), which keeps the
// file small: they are drawn widened, without edges, so that the picture shows which area is
// covered, and the title says so. Returns false when the file cannot be written.
inline bool write_uv_layout_svg(const std::string& path,
                                const std::vector<std::vector<std::array<double, 2> > >& polygons,
                                std::size_t max_faces = 10000)
{
  const double infinity = std::numeric_limits<double>::infinity();
  double low[2] = {infinity, infinity}, high[2] = {-infinity, -infinity};
  bool in_unit_square = true;
  for(const auto& polygon : polygons)
    for(const auto& p : polygon)
      for(int c = 0; c < 2; ++c)
      {
        low[c] = (std::min)(low[c], p[c]);
        high[c] = (std::max)(high[c], p[c]);
        in_unit_square = in_unit_square && p[c] >= -1e-9 && p[c] <= 1 + 1e-9;
      }
  Uv_layout_frame frame;
  if(!in_unit_square && low[0] <= high[0])
  {
    const double extent = (std::max)(high[0] - low[0], high[1] - low[1]);
    frame = {low[0], low[1], extent > 0 ? 1000 / extent : 1000};
  }

  const std::size_t stride = max_faces == 0 ? 1 : (std::max<std::size_t>)(1, (polygons.size() + max_faces - 1) / max_faces);
  std::ostringstream kept, flipped;
  std::size_t flipped_count = 0, edges = 0;
  double edge_length = 0; // in picture units, summed over the drawn faces
  for(std::size_t i = 0; i < polygons.size(); ++i)
  {
    const auto& polygon = polygons[i];
    double twice_area = 0; // shoelace, in uv: negative when the face is flipped
    for(std::size_t k = 0; k < polygon.size(); ++k)
    {
      const auto& a = polygon[k];
      const auto& b = polygon[(k + 1) % polygon.size()];
      twice_area += a[0] * b[1] - a[1] * b[0];
    }
    flipped_count += twice_area < 0;
    if(i % stride != 0) continue;
    std::ostringstream& out = twice_area < 0 ? flipped : kept;
    for(std::size_t k = 0; k < polygon.size(); ++k)
    {
      const std::array<long, 2> p = frame.point(polygon[k][0], polygon[k][1]);
      out << (k == 0 ? 'M' : 'L') << p[0] << ' ' << p[1];
      const auto& b = polygon[(k + 1) % polygon.size()];
      edge_length += frame.scale * std::hypot(b[0] - polygon[k][0], b[1] - polygon[k][1]);
      ++edges;
    }
    out << 'Z';
  }

  std::ofstream svg(path);
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:xlink=\"http://www.w3.org/1999/xlink\" "
         "viewBox=\"-20 -20 1040 1040\" width=\"480\" height=\"480\">\n"
      << "<title>uv layout: " << polygons.size() << " faces, " << flipped_count << " flipped (red)";
  if(stride > 1)
    svg << "; one face in " << stride << " drawn, widened to show the covered area, without edges";
  svg << "</title>\n<defs>\n<path id=\"kept\" d=\"" << kept.str() << "\"/>\n<path id=\"flipped\" d=\""
      << flipped.str() << "\"/>\n</defs>\n"
      << "<rect x=\"-20\" y=\"-20\" width=\"1040\" height=\"1040\" fill=\"white\"/>\n";
  if(in_unit_square)
    svg << "<rect x=\"0\" y=\"0\" width=\"1000\" height=\"1000\" fill=\"none\" stroke=\"#888\" stroke-width=\"2\"/>\n";
  // Every stride-th face leaves gaps about sqrt(stride) edges wide: a stroke twice that closes them.
  const double widen = stride > 1 && edges > 0 ? 2 * edge_length / double(edges) * std::sqrt(double(stride)) : 0;
  const char* colors[2][2] = {{"kept", "#dfe6f5"}, {"flipped", "#e03030"}};
  for(const auto& c : colors)
  {
    svg << "<use xlink:href=\"#" << c[0] << "\" fill=\"" << c[1] << "\" stroke-linejoin=\"round\"";
    if(widen > 0) svg << " stroke=\"" << c[1] << "\" stroke-width=\"" << widen << "\"";
    else svg << " stroke=\"#223\" stroke-width=\"0.6\"";
    svg << (c[0][0] == 'f' ? " opacity=\"0.45\"" : "") << "/>\n";
  }
  svg << "</svg>\n";
  return bool(svg);
}

// The layout of the faces of `mesh` under `uv`, as above.
template <typename PolygonMesh, typename VertexUVMap>
bool write_uv_layout_svg(const std::string& path, const PolygonMesh& mesh, VertexUVMap uv,
                         std::size_t max_faces = 10000)
{
  std::vector<std::vector<std::array<double, 2> > > polygons;
  for(auto f : faces(mesh))
  {
    polygons.emplace_back();
    for(auto v : CGAL::vertices_around_face(halfedge(f, mesh), mesh))
      polygons.back().push_back({double(get(uv, v).x()), double(get(uv, v).y())});
  }
  return write_uv_layout_svg(path, polygons, max_faces);
}

} // namespace np_examples

#endif
