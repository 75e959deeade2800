// The Python module norm_preserving: the package's whole-soup call on NumPy arrays, with the
// options of the command-line tool (tools/texture_mesh/texture_settings.h: one definition of their names,
// defaults and ranges), CGAL's LSCM and ARAP on the mesh cut to a disk, the distortion measures
// and the command-line tool's mesh reader and textured OBJ writer (soup_reader.h,
// textured_obj_writer.h). The user's guide is doc/manual.md, section 7 (Python); the types,
// norm_preserving.pyi.
//
// The caller's arrays are read in place, never written, and kept alive by the call: the package
// makes its own copy of the soup, and the module adds none. Everything the module can check is
// checked before the GIL is released; the solve runs without it, so the arrays must not be
// modified by another thread during a call.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#ifndef NP_PYTHON_WITHOUT_PNG
#include "checkerboard.h"
#endif
#include "output_files.h"
#include "soup_reader.h"
#include "texture_settings.h"
#include "textured_obj_writer.h"

#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_parameterization/ARAP_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/LSCM_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Parameterization_distortion.h>
#include <CGAL/Surface_mesh_parameterization/cut_to_disk.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/Seam_mesh.h>
#include <CGAL/property_map.h>

#include <boost/iterator/iterator_facade.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <future>
#include <iterator>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <system_error>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

namespace py = pybind11;
namespace SMP = CGAL::Surface_mesh_parameterization;
namespace PMP = CGAL::Polygon_mesh_processing;
using Kernel = CGAL::Simple_cartesian<double>;
using Point_2 = Kernel::Point_2;
using Point_3 = Kernel::Point_3;

// An argument that NumPy makes an array of (or a sequence of index sequences, for faces), read
// by the module itself; named ArrayLike in the signatures that help() shows, as in NumPy's.
struct Array_like
{
  py::object object;
};

// The progress callback: None or a callable, refused before the call otherwise.
struct Progress_callable
{
  py::object object;
};

namespace pybind11 {
namespace detail {
template <>
struct type_caster<Array_like>
{
  PYBIND11_TYPE_CASTER(Array_like, const_name("ArrayLike"));
  bool load(handle source, bool)
  {
    value.object = reinterpret_borrow<object>(source);
    return true;
  }
};

template <>
struct type_caster<Progress_callable>
{
  PYBIND11_TYPE_CASTER(Progress_callable, const_name("Optional[Callable[[Progress], Optional[bool]]]"));
  bool load(handle source, bool)
  {
    value.object = reinterpret_borrow<object>(source);
    return source.is_none() || PyCallable_Check(source.ptr());
  }
};
} // namespace detail
} // namespace pybind11

namespace {

// ------------------------------------------------------------------------------ the arrays in

py::array as_array(py::handle object)
{
  return py::module_::import("numpy").attr("asarray")(object);
}

std::string dtype_name(const py::array& a)
{
  return a.dtype().attr("name").cast<std::string>();
}

std::string shape_of(const py::array& a)
{
  std::string text = "(";
  for(py::ssize_t d = 0; d < a.ndim(); ++d)
    text += (d > 0 ? ", " : "") + std::to_string(a.shape(d));
  return text + (a.ndim() == 1 ? ",)" : ")");
}

// A random-access iterator over 0, 1, 2, ... that yields `at(i)` by value: the iterator of the
// views below. (Boost's transform_iterator, yielding by value, calls itself an input iterator,
// and CGAL takes std::prev() of a polygon's end.)
template <typename At>
class Index_iterator : public boost::iterator_facade<Index_iterator<At>, std::invoke_result_t<At, std::size_t>,
                                                     std::random_access_iterator_tag,
                                                     std::invoke_result_t<At, std::size_t> >
{
public:
  Index_iterator() = default;
  Index_iterator(std::size_t i, At at) : m_i(i), m_at(at) {}

private:
  friend class boost::iterator_core_access;
  std::invoke_result_t<At, std::size_t> dereference() const { return m_at(m_i); }
  bool equal(const Index_iterator& other) const { return m_i == other.m_i; }
  void increment() { ++m_i; }
  void decrement() { --m_i; }
  void advance(std::ptrdiff_t n) { m_i = std::size_t(std::ptrdiff_t(m_i) + n); }
  std::ptrdiff_t distance_to(const Index_iterator& other) const { return std::ptrdiff_t(other.m_i) - std::ptrdiff_t(m_i); }

  std::size_t m_i = 0;
  At m_at{};
};

// An (n, D) array of coordinates as a random-access range of points (D = 3) or uvs (D = 2),
// read in place when it holds native float32 or float64 (any strides), else converted once to
// float64 (integers, float16, long double: never the bulk of a mesh).
template <int D>
class Coordinate_array
{
public:
  using Point = std::conditional_t<D == 3, Point_3, Point_2>;

  Coordinate_array(const Array_like& argument, const std::string& name) : m_array(as_array(argument.object))
  {
    const py::dtype type = m_array.dtype();
    if(type.kind() != 'f' && type.kind() != 'i' && type.kind() != 'u')
      throw py::type_error(name + " must hold numbers, not " + dtype_name(m_array));
    if(m_array.ndim() != 2 || m_array.shape(1) != D)
      throw py::value_error(name + " must be an (n, " + std::to_string(D) + ") array, not of shape " + shape_of(m_array));
    if(type.kind() != 'f' || (type.itemsize() != 4 && type.itemsize() != 8) || !type.attr("isnative").cast<bool>())
      m_array = m_array.attr("astype")(py::dtype::of<double>());
    m_single = m_array.dtype().itemsize() == 4;
    m_data = static_cast<const char*>(m_array.data());
    m_strides = {m_array.strides(0), m_array.strides(1)};
    m_size = std::size_t(m_array.shape(0));
  }

  // Read without the GIL: nothing below touches a Python object.
  std::size_t size() const { return m_size; }

  double coordinate(std::size_t i, int c) const
  {
    const char* p = m_data + py::ssize_t(i) * m_strides[0] + c * m_strides[1];
    if(m_single)
    {
      float x;
      std::memcpy(&x, p, sizeof x);
      return x;
    }
    double x;
    std::memcpy(&x, p, sizeof x);
    return x;
  }

  Point operator[](std::size_t i) const
  {
    if constexpr(D == 3)
      return Point(coordinate(i, 0), coordinate(i, 1), coordinate(i, 2));
    else
      return Point(coordinate(i, 0), coordinate(i, 1));
  }

  struct Point_at
  {
    const Coordinate_array* array;
    Point operator()(std::size_t i) const { return (*array)[i]; }
  };
  using value_type = Point;
  using iterator = Index_iterator<Point_at>;
  using const_iterator = iterator;
  iterator begin() const { return iterator(0, Point_at{this}); }
  iterator end() const { return iterator(size(), Point_at{this}); }

private:
  py::array m_array; // keeps the caller's array alive while it is read
  const char* m_data = nullptr;
  std::array<py::ssize_t, 2> m_strides = {0, 0};
  std::size_t m_size = 0;
  bool m_single = false;
};

using Vertex_array = Coordinate_array<3>;

// A readable property map over a uv array: the uv of vertex i, and whether it has one (finite).
struct Uv_map
{
  typedef std::size_t key_type;
  typedef Point_2 value_type;
  typedef Point_2 reference;
  typedef boost::readable_property_map_tag category;
  const Coordinate_array<2>* uv;
  friend Point_2 get(const Uv_map& m, std::size_t i) { return (*m.uv)[i]; }
};
struct Has_uv_map
{
  typedef std::size_t key_type;
  typedef bool value_type;
  typedef bool reference;
  typedef boost::readable_property_map_tag category;
  const Coordinate_array<2>* uv;
  friend bool get(const Has_uv_map& m, std::size_t i) { return std::isfinite(m.uv->coordinate(i, 0)); }
};

// Writes the package's uvs into the (n, 2) float64 array that texture() returns.
struct Uv_output_map
{
  typedef std::size_t key_type;
  typedef Point_2 value_type;
  typedef Point_2 reference;
  typedef boost::writable_property_map_tag category;
  double* data;
  friend void put(const Uv_output_map& m, std::size_t i, const Point_2& uv)
  {
    m.data[2 * i] = uv.x();
    m.data[2 * i + 1] = uv.y();
  }
};

// A vertex index of any integer dtype, read from its bytes; a uint64 beyond int64 saturates
// (it is out of range either way).
using Index_reader = std::int64_t (*)(const char*);
template <typename T>
std::int64_t read_index(const char* p)
{
  T value;
  std::memcpy(&value, p, sizeof value);
  if constexpr(std::is_unsigned_v<T> && sizeof(T) == 8)
    if(value > T((std::numeric_limits<std::int64_t>::max)()))
      return (std::numeric_limits<std::int64_t>::max)();
  return std::int64_t(value);
}

Index_reader index_reader(const py::dtype& type)
{
  const int size = int(type.itemsize());
  if(type.kind() == 'i')
    return size == 1 ? read_index<std::int8_t> : size == 2 ? read_index<std::int16_t>
         : size == 4 ? read_index<std::int32_t> : read_index<std::int64_t>;
  return size == 1 ? read_index<std::uint8_t> : size == 2 ? read_index<std::uint16_t>
       : size == 4 ? read_index<std::uint32_t> : read_index<std::uint64_t>;
}

// The faces as a random-access range of ranges of vertex indices, as the package's soup calls
// take: an (m, k) integer array of any integer dtype and strides read in place, or a sequence
// of index sequences of mixed lengths gathered once into int64.
class Face_array
{
public:
  // One face: its corners, read from the buffer as std::size_t.
  class Face
  {
  public:
    struct Corner_at
    {
      const char* first;
      py::ssize_t stride;
      Index_reader read;
      std::size_t operator()(std::size_t k) const { return std::size_t(read(first + py::ssize_t(k) * stride)); }
    };
    using value_type = std::size_t;
    using iterator = Index_iterator<Corner_at>;
    using const_iterator = iterator;

    Face(const char* first, py::ssize_t stride, std::size_t size, Index_reader read)
      : m_corner{first, stride, read}, m_size(size) {}
    std::size_t size() const { return m_size; }
    std::size_t operator[](std::size_t k) const { return m_corner(k); }
    std::int64_t signed_corner(std::size_t k) const
    {
      return m_corner.read(m_corner.first + py::ssize_t(k) * m_corner.stride);
    }
    iterator begin() const { return iterator(0, m_corner); }
    iterator end() const { return iterator(m_size, m_corner); }

  private:
    Corner_at m_corner;
    std::size_t m_size;
  };

  explicit Face_array(const Array_like& argument)
  {
    const py::object& object = argument.object;
    std::optional<py::array> array;
    try
    {
      array = as_array(object);
    }
    catch(const py::error_already_set& e)
    {
      if(!e.matches(PyExc_ValueError)) // NumPy's word for faces of mixed sizes
        throw;
    }
    if(array && array->ndim() == 2)
      read_in_place(*array);
    else if(array && array->ndim() == 1 && array->size() == 0)
      m_count = 0; // no face: the package says so
    else if(!array || (array->ndim() == 1 && array->dtype().kind() == 'O'))
      gather(object);
    else
    {
      require_integers(*array);
      throw py::value_error("faces must be an (m, k) array or a sequence of index sequences, not of shape " +
                            shape_of(*array));
    }
  }

  std::size_t size() const { return m_count; }
  bool empty() const { return m_count == 0; }
  // The number of corners of every face, or nothing when they differ.
  std::optional<std::size_t> corners_per_face() const
  {
    return m_offsets.empty() ? std::optional<std::size_t>(m_corners) : std::nullopt;
  }

  Face operator[](std::size_t f) const
  {
    if(m_offsets.empty())
      return Face(m_data + py::ssize_t(f) * m_strides[0], m_strides[1], m_corners, m_read);
    return Face(reinterpret_cast<const char*>(m_gathered.data() + m_offsets[f]), sizeof(std::int64_t),
                m_offsets[f + 1] - m_offsets[f], m_read);
  }

  struct Face_at
  {
    const Face_array* faces;
    Face operator()(std::size_t f) const { return (*faces)[f]; }
  };
  using value_type = Face;
  using size_type = std::size_t;
  using iterator = Index_iterator<Face_at>;
  using const_iterator = iterator;
  iterator begin() const { return iterator(0, Face_at{this}); }
  iterator end() const { return iterator(m_count, Face_at{this}); }

private:
  static void require_integers(const py::array& a)
  {
    if(a.dtype().kind() != 'i' && a.dtype().kind() != 'u')
      throw py::type_error("faces must hold integer vertex indices, not " + dtype_name(a));
  }

  void read_in_place(py::array array)
  {
    require_integers(array);
    if(!array.dtype().attr("isnative").cast<bool>())
      array = array.attr("astype")(array.dtype().attr("newbyteorder")("="));
    m_array = array;
    m_read = index_reader(array.dtype());
    m_data = static_cast<const char*>(array.data());
    m_strides = {array.strides(0), array.strides(1)};
    m_count = std::size_t(array.shape(0));
    m_corners = std::size_t(array.shape(1));
  }

  // Faces of mixed sizes: a Python sequence holds no buffer to read in place.
  void gather(py::handle object)
  {
    if(!py::isinstance<py::sequence>(object) || py::isinstance<py::str>(object))
      throw py::type_error("faces must be an integer array or a sequence of index sequences, not " +
                           py::str(py::type::of(object)).cast<std::string>());
    m_offsets.push_back(0);
    for(py::handle face : object)
    {
      const py::array corners = as_array(face);
      require_integers(corners);
      if(corners.ndim() != 1)
        throw py::value_error("face " + std::to_string(m_offsets.size() - 1) + " must be a sequence of indices, not of shape " +
                              shape_of(corners));
      const py::array_t<std::int64_t> wide = corners.attr("astype")(py::dtype::of<std::int64_t>());
      m_gathered.insert(m_gathered.end(), wide.data(), wide.data() + wide.size());
      m_offsets.push_back(m_gathered.size());
    }
    m_count = m_offsets.size() - 1;
    m_read = read_index<std::int64_t>;
  }

  py::array m_array; // keeps the caller's array alive while it is read
  const char* m_data = nullptr;
  std::array<py::ssize_t, 2> m_strides = {0, 0};
  std::size_t m_count = 0, m_corners = 0;
  Index_reader m_read = read_index<std::int64_t>;
  std::vector<std::int64_t> m_gathered;
  std::vector<std::size_t> m_offsets; // of each gathered face, and the end; empty when read in place
};

// The checks every call makes before its work, in the package's words: a face, and every
// corner a vertex.
void check_faces(const Face_array& faces, std::size_t vertices)
{
  if(faces.empty())
    throw py::value_error("the mesh has no face");
  for(std::size_t f = 0; f < faces.size(); ++f)
  {
    const Face_array::Face face = faces[f];
    for(std::size_t k = 0; k < face.size(); ++k)
    {
      const std::int64_t i = face.signed_corner(k);
      if(i < 0 || std::uint64_t(i) >= vertices)
        throw py::value_error("face " + std::to_string(f) + " refers to vertex " + std::to_string(i) + " of " +
                              std::to_string(vertices));
    }
  }
}

// The vertices and faces of a call, checked.
struct Soup
{
  Soup(const Array_like& vertices, const Array_like& faces) : points(vertices, "vertices"), polygons(faces)
  {
    check_faces(polygons, points.size());
  }

  Vertex_array points;
  Face_array polygons;
};

// A uv array of the soup: one uv per vertex.
Coordinate_array<2> uv_per_vertex(const Array_like& uv, const Soup& soup)
{
  Coordinate_array<2> uvs(uv, "uv");
  if(uvs.size() != soup.points.size())
    throw py::value_error("uv must have one row per vertex: " + std::to_string(uvs.size()) + " rows for " +
                          std::to_string(soup.points.size()) + " vertices");
  return uvs;
}

// ------------------------------------------------------------------------------ the errors

// A failed call as the Python exception for its kind: bad input is a ValueError, a method that
// fails on good input a RuntimeError; the message is the package's.
[[noreturn]] void raise_error(SMP::Error_code status, const std::string& message)
{
  const std::string text = message.empty() ? std::string(SMP::norm_preserving_error_message(status)) : message;
  if(status == SMP::ERROR_CANNOT_SOLVE_LINEAR_SYSTEM || status == SMP::ERROR_NO_1_TO_1_MAPPING)
    throw std::runtime_error(text);
  throw py::value_error(text);
}

// ------------------------------------------------------------------------------ the solve

// A call's way to stop: the caller's progress callback, and Ctrl-C. The package calls
// `keep_going()` from its worker threads, one call at a time, without the GIL; Python runs
// its signal handlers on the main thread only, so the calling thread waits for the work on
// another thread and checks for Ctrl-C (`run()`). What stopped the call is raised after it.
class Stoppable_call
{
public:
  explicit Stoppable_call(py::object callback) : m_callback(std::move(callback)) {}

  bool keep_going(const SMP::Norm_preserving_progress& progress)
  {
    if(m_stop)
      return false;
    if(m_callback.is_none())
      return true;
    py::gil_scoped_acquire gil;
    try
    {
      // None goes on; any other false value (False, 0, numpy.False_) stops.
      const py::object answer = m_callback(progress);
      if(!answer.is_none())
      {
        const int truth = PyObject_IsTrue(answer.ptr());
        if(truth < 0) // its truth cannot be told: its exception stops the call
          throw py::error_already_set();
        if(truth == 0)
          m_stop = true;
      }
    }
    catch(py::error_already_set& e)
    {
      stop_with(std::move(e));
    }
    return !m_stop;
  }

  // Runs `work` (no Python in it) on a thread of its own, the GIL released, checking for
  // Ctrl-C every 20 ms until it returns; its result.
  template <typename Work>
  auto run(Work work)
  {
    auto result = std::async(std::launch::async, std::move(work));
    py::gil_scoped_release release;
    while(result.wait_for(std::chrono::milliseconds(20)) != std::future_status::ready)
    {
      py::gil_scoped_acquire gil;
      if(PyErr_CheckSignals() != 0)
        stop_with(py::error_already_set());
    }
    return result.get();
  }

  // With the GIL, after the call: raises what stopped it (a KeyboardInterrupt, the callback's
  // exception), if anything did.
  void raise_pending()
  {
    if(m_error)
      throw py::error_already_set(std::move(*m_error));
  }

private:
  void stop_with(py::error_already_set&& e) // with the GIL
  {
    if(!m_error)
      m_error.emplace(std::move(e));
    m_stop = true;
  }

  py::object m_callback;
  std::atomic<bool> m_stop{false};
  std::optional<py::error_already_set> m_error;
};

// The texture report and the distortion of its uvs, as texture() returns them.
struct Texture_report : SMP::Texture_polygon_mesh_report
{
  SMP::Parameterization_distortion distortion;
};

std::tuple<py::array_t<double>, Texture_report>
texture(const Array_like& vertices, const Array_like& faces, const std::string& guess, const std::string& fit,
        std::pair<int, int> tiles, std::optional<std::pair<std::int64_t, std::int64_t> > fixed_pair, bool keep_coincident,
        bool refine_signs, bool refine_euclidean, const std::string& quality, std::optional<double> tolerance,
        std::optional<double> time_limit, const Progress_callable& progress)
{
  const Soup soup(vertices, faces);
  const Vertex_array& points = soup.points;
  const Face_array& polygons = soup.polygons;

  np_examples::Texture_settings settings;
  settings.guess = guess;
  settings.fit = fit;
  settings.tiles_u = tiles.first;
  settings.tiles_v = tiles.second;
  settings.keep_coincident = keep_coincident;
  settings.refine_signs = refine_signs;
  settings.refine_euclidean = refine_euclidean;
  settings.quality = quality;
  settings.tolerance = tolerance;
  if(time_limit)
    settings.time_limit = *time_limit;
  if(fixed_pair)
  {
    if(fixed_pair->first < 0 || fixed_pair->second < 0)
      throw py::value_error("fixed_pair takes two vertex indices");
    settings.fixed_pair = std::make_pair(std::size_t(fixed_pair->first), std::size_t(fixed_pair->second));
  }
  if(const std::optional<std::string> problem = np_examples::settings_problem(settings))
    throw py::value_error(*problem);

  // NaN for the vertices on no face, which get no uv.
  py::array_t<double> uv({py::ssize_t(points.size()), py::ssize_t(2)});
  std::fill(uv.mutable_data(), uv.mutable_data() + uv.size(), std::numeric_limits<double>::quiet_NaN());
  const Coordinate_array<2> uv_read(Array_like{uv}, "uv");
  Texture_report report;
  Stoppable_call call(progress.object);
  const SMP::Error_code status = call.run([&, out = Uv_output_map{uv.mutable_data()}] {
    const SMP::Error_code s = np_examples::texture_with_settings(
      points, polygons, out, settings, static_cast<SMP::Texture_polygon_mesh_report&>(report),
      [&call](const SMP::Norm_preserving_progress& p) { return call.keep_going(p); });
    if(s == SMP::OK)
      report.distortion = SMP::measure_soup_distortion(points, polygons, Uv_map{&uv_read}, Has_uv_map{&uv_read});
    return s;
  });
  call.raise_pending();
  if(status != SMP::OK)
    raise_error(status, report.message);
  return {uv, report};
}

// ------------------------------------------------------------------------------ LSCM and ARAP

using Mesh = CGAL::Surface_mesh<Point_3>;
using Halfedge = Mesh::Halfedge_index;
using Seam_mesh = CGAL::Seam_mesh<Mesh, Mesh::Property_map<Mesh::Edge_index, bool>, Mesh::Property_map<Mesh::Vertex_index, bool> >;

// What lscm() and arap() did.
struct Cut_report
{
  std::string method;
  std::size_t components = 0;  // connected components, each cut and mapped on its own
  std::size_t seam_edges = 0;  // edges cut, over all components
  double seam_length = 0;      // their 3D length
  double cut_seconds = 0;      // building the mesh, cutting and triangulating it
  double seconds = 0;          // the parameterizer's calls
  SMP::Parameterization_distortion distortion;
};

double seconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The soup as a Surface_mesh, vertex i and face f those of the input, and the halfedge of each
// input corner (its target the corner, in its face), which the triangulation and the seams keep.
std::vector<Halfedge> build_mesh(const Vertex_array& points, const Face_array& faces, Mesh& mesh)
{
  if(!PMP::is_polygon_soup_a_polygon_mesh(faces))
    throw py::value_error("the faces do not form an oriented 2-manifold, which lscm() and arap() need "
                          "(texture() takes any soup)");
  for(const Point_3& p : points)
    mesh.add_vertex(p);
  std::vector<Halfedge> corners;
  std::vector<Mesh::Vertex_index> around;
  for(const Face_array::Face& face : faces)
  {
    around.clear();
    for(std::size_t i : face)
      around.push_back(Mesh::Vertex_index(Mesh::size_type(i)));
    const Halfedge first = halfedge(CGAL::Euler::add_face(around, mesh), mesh);
    std::vector<Halfedge> of_face;
    for(Halfedge h : halfedges_around_face(first, mesh))
      of_face.push_back(h);
    // In corner order: the halfedge whose target is the first corner, then around.
    const auto start =
      std::find_if(of_face.begin(), of_face.end(), [&](Halfedge h) { return target(h, mesh) == around[0]; });
    std::rotate(of_face.begin(), start, of_face.end());
    corners.insert(corners.end(), of_face.begin(), of_face.end());
  }
  return corners;
}

// `Parameterizer` (LSCM or ARAP) on every component of the soup, each cut to a disk by the
// package's cut_to_disk() (no cut on a disk) before its polygons are triangulated, so that a
// seam never runs inside an input face; the uv of every input corner.
template <typename Parameterizer>
std::tuple<py::object, Cut_report> parameterize_cut(const Array_like& vertex_object, const Array_like& face_object,
                                                    const char* method)
{
  const Soup soup(vertex_object, face_object);
  const Face_array& polygons = soup.polygons;
  auto start = std::chrono::steady_clock::now();
  Mesh mesh;
  const std::vector<Halfedge> corners = build_mesh(soup.points, polygons, mesh);

  Cut_report report;
  report.method = method;
  std::vector<Point_2> corner_uv(corners.size());
  std::optional<std::pair<SMP::Error_code, std::string> > failure;
  {
    py::gil_scoped_release release;
    auto seam_edges = mesh.add_property_map<Mesh::Edge_index, bool>("e:seam", false).first;
    auto seam_vertices = mesh.add_property_map<Mesh::Vertex_index, bool>("v:seam", false).first;
    Seam_mesh seam_mesh(mesh, seam_edges, seam_vertices);
    auto component = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:component").first;
    report.components = PMP::connected_components(mesh, component);
    std::vector<boost::graph_traits<Seam_mesh>::halfedge_descriptor> borders(report.components);
    std::vector<bool> cut(report.components, false);
    for(auto f : faces(mesh))
      if(!cut[get(component, f)] && !failure)
      {
        cut[get(component, f)] = true;
        const auto result = SMP::cut_to_disk(seam_mesh, halfedge(f, mesh));
        if(result.status != SMP::OK)
          failure.emplace(result.status, result.message);
        borders[get(component, f)] = result.border_halfedge;
        report.seam_edges += result.seam_edges;
        report.seam_length += result.seam_length;
      }
    if(!failure && !PMP::triangulate_faces(mesh))
      failure.emplace(SMP::ERROR_NON_TRIANGULAR_MESH, "a face could not be triangulated");
    report.cut_seconds = seconds_since(start);

    auto uvmap = mesh.add_property_map<Halfedge, Point_2>("h:uv").first; // seam-mesh vertex -> uv
    start = std::chrono::steady_clock::now();
    for(std::size_t c = 0; c < borders.size() && !failure; ++c)
    {
      const SMP::Error_code status = SMP::parameterize(seam_mesh, Parameterizer(), borders[c], uvmap);
      if(status != SMP::OK)
        failure.emplace(status, std::string());
    }
    report.seconds = seconds_since(start);
    if(!failure)
    {
      for(std::size_t k = 0; k < corners.size(); ++k)
        corner_uv[k] = get(uvmap, target(boost::graph_traits<Seam_mesh>::halfedge_descriptor(corners[k]), seam_mesh));
      report.distortion = SMP::measure_distortion(seam_mesh, uvmap, CGAL::Constant_property_map<
                                                  boost::graph_traits<Seam_mesh>::vertex_descriptor, bool>(true));
    }
  }
  if(failure)
    raise_error(failure->first, failure->second);

  // Per corner: an (m, k, 2) array when every face has k corners, else one (k, 2) array a face.
  auto corner_array = [&](std::size_t first, std::size_t count, std::vector<py::ssize_t> shape) {
    py::array_t<double> a(shape);
    for(std::size_t k = 0; k < count; ++k)
    {
      a.mutable_data()[2 * k] = corner_uv[first + k].x();
      a.mutable_data()[2 * k + 1] = corner_uv[first + k].y();
    }
    return a;
  };
  if(const std::optional<std::size_t> k = polygons.corners_per_face())
    return {corner_array(0, corners.size(), {py::ssize_t(polygons.size()), py::ssize_t(*k), 2}), report};
  py::list per_face;
  std::size_t first = 0;
  for(const Face_array::Face& face : polygons)
  {
    per_face.append(corner_array(first, face.size(), {py::ssize_t(face.size()), 2}));
    first += face.size();
  }
  return {per_face, report};
}

// ------------------------------------------------------------------------------ the rest

SMP::Parameterization_distortion measure_distortion(const Array_like& vertices, const Array_like& faces,
                                                    const Array_like& uv)
{
  const Soup soup(vertices, faces);
  const Coordinate_array<2> uvs = uv_per_vertex(uv, soup);
  py::gil_scoped_release release;
  return SMP::measure_soup_distortion(soup.points, soup.polygons, Uv_map{&uvs}, Has_uv_map{&uvs});
}

#ifndef NP_PYTHON_WITHOUT_PNG
// write_obj() writes a checkerboard PNG with libpng, which the module of the Blender add-on's zip
// leaves out (blender/CMakeLists.txt).

// Raises OSError(message).
[[noreturn]] void raise_os_error(const std::string& message)
{
  PyErr_SetObject(PyExc_OSError, py::str(message).ptr());
  throw py::error_already_set();
}

void write_obj(const std::filesystem::path& path, const Array_like& vertices, const Array_like& faces,
               const Array_like& uv)
{
  namespace fs = std::filesystem;
  const Soup soup(vertices, faces);
  const Coordinate_array<2> uvs = uv_per_vertex(uv, soup);
  if(const auto v = np_examples::first_non_finite_vertex(soup.points, soup.polygons))
    throw py::value_error(np_examples::non_finite_vertex_message(*v));
  // The basename, as the command-line tool takes it: a trailing .obj (in any case) is dropped.
  std::string basename = path.string();
  if(np_examples::lower_case(path.extension().string()) == ".obj")
    basename.erase(basename.size() - 4);
  const fs::path name = fs::path(basename).filename();
  if(name.empty() || name == "." || name == "..")
    throw py::value_error("the basename must end in a file name, not '" + path.string() + "'");
  const fs::path target = fs::absolute(basename);
  np_examples::Output_files files{target.parent_path(), target.filename().string(), {}};
  std::optional<std::string> problem;
  {
    py::gil_scoped_release release;
    const np_examples::Texture_image checkerboard = np_examples::checkerboard_texture();
    files.files = np_examples::textured_obj_files(files.stem, soup.points, soup.polygons, uvs, checkerboard);
    problem = np_examples::write_outputs(files);
  }
  if(problem)
    raise_os_error("cannot write " + (files.directory / np_examples::file_list(files)).string() + ": " + *problem +
                   "; nothing written");
}
#endif

std::tuple<py::array_t<double>, py::object> read_mesh(const std::filesystem::path& path)
{
  std::error_code ec;
  if(!std::filesystem::exists(path, ec))
  {
    PyErr_SetObject(PyExc_FileNotFoundError, py::str("no such file: " + path.string()).ptr());
    throw py::error_already_set();
  }
  std::vector<Point_3> points;
  std::vector<std::vector<std::size_t> > polygons;
  std::optional<std::string> wrong;
  {
    py::gil_scoped_release release;
    wrong = np_examples::read_soup(path.string(), points, polygons);
  }
  if(wrong)
    throw py::value_error("cannot read " + path.string() + ": " + *wrong);

  py::array_t<double> vertices({py::ssize_t(points.size()), py::ssize_t(3)});
  for(std::size_t i = 0; i < points.size(); ++i)
    for(int c = 0; c < 3; ++c)
      vertices.mutable_data()[3 * i + std::size_t(c)] = points[i][c];
  const std::size_t k = polygons.front().size();
  if(std::all_of(polygons.begin(), polygons.end(), [k](const auto& p) { return p.size() == k; }))
  {
    py::array_t<std::int64_t> faces({py::ssize_t(polygons.size()), py::ssize_t(k)});
    for(std::size_t f = 0; f < polygons.size(); ++f)
      std::copy(polygons[f].begin(), polygons[f].end(), faces.mutable_data() + f * k);
    return {vertices, faces};
  }
  py::list faces;
  for(const auto& polygon : polygons)
  {
    py::array_t<std::int64_t> face(py::ssize_t(polygon.size()));
    std::copy(polygon.begin(), polygon.end(), face.mutable_data());
    faces.append(face);
  }
  return {vertices, faces};
}

// ------------------------------------------------------------------------------ the reports

// Every field of the package's reports, by its C++ name: the one place that follows them.
void bind_reports(py::module_& m)
{
  py::enum_<SMP::Error_code>(m, "ErrorCode", "The package's error codes (CGAL's Error_code).")
    .value("OK", SMP::OK)
    .value("ERROR_EMPTY_MESH", SMP::ERROR_EMPTY_MESH)
    .value("ERROR_NON_TRIANGULAR_MESH", SMP::ERROR_NON_TRIANGULAR_MESH)
    .value("ERROR_NO_TOPOLOGICAL_DISC", SMP::ERROR_NO_TOPOLOGICAL_DISC)
    .value("ERROR_NO_TOPOLOGICAL_BALL", SMP::ERROR_NO_TOPOLOGICAL_BALL)
    .value("ERROR_BORDER_TOO_SHORT", SMP::ERROR_BORDER_TOO_SHORT)
    .value("ERROR_NON_CONVEX_BORDER", SMP::ERROR_NON_CONVEX_BORDER)
    .value("ERROR_CANNOT_SOLVE_LINEAR_SYSTEM", SMP::ERROR_CANNOT_SOLVE_LINEAR_SYSTEM)
    .value("ERROR_NO_1_TO_1_MAPPING", SMP::ERROR_NO_1_TO_1_MAPPING)
    .value("ERROR_WRONG_PARAMETER", SMP::ERROR_WRONG_PARAMETER);

  py::enum_<SMP::Norm_preserving_solver_status>(m, "SolverStatus", "How the QP solver of a component ended.")
    .value("CONVERGED", SMP::NORM_PRESERVING_SOLVER_CONVERGED)
    .value("ITERATION_LIMIT", SMP::NORM_PRESERVING_SOLVER_ITERATION_LIMIT)
    .value("TIME_LIMIT", SMP::NORM_PRESERVING_SOLVER_TIME_LIMIT)
    .value("PRECISION_LIMIT", SMP::NORM_PRESERVING_SOLVER_PRECISION_LIMIT)
    .value("FAILED", SMP::NORM_PRESERVING_SOLVER_FAILED);

  using P = SMP::Norm_preserving_progress;
  py::class_<P>(m, "Progress", "Where a texture() call is, as its progress callback receives it.")
    .def_readonly("components", &P::components, "connected components of the mesh")
    .def_readonly("components_done", &P::components_done, "of those, the ones finished")
    .def_readonly("fraction", &P::fraction, "an estimate of the share of the work done, in [0, 1], never decreasing")
    .def_readonly("seconds", &P::seconds, "since the start of the call")
    .def("__repr__", [](const P& p) {
      return "Progress(fraction=" + std::to_string(p.fraction) + ", components_done=" + std::to_string(p.components_done) +
             "/" + std::to_string(p.components) + ", seconds=" + std::to_string(p.seconds) + ")";
    });

  using S = SMP::Norm_preserving_solve_report;
  py::class_<S>(m, "SolveReport", "What the QP solve of one component did (C++ Norm_preserving_solve_report).")
    .def_readonly("status", &S::status, "how the solve ended")
    .def_readonly("method", &S::method, "the solver and its setting")
    .def_readonly("has_statistics", &S::has_statistics, "whether iterations and kkt_residual are reported")
    .def_readonly("iterations", &S::iterations, "iterations of the solver")
    .def_readonly("kkt_residual", &S::kkt_residual, "largest residual of the optimality conditions (normalized QP)")
    .def_readonly("optimality_gap", &S::optimality_gap, "certified bound on the relative distance to the optimum")
    .def_readonly("assembly_seconds", &S::assembly_seconds, "setting up the linear algebra")
    .def_readonly("factorization_seconds", &S::factorization_seconds, "factorizations before iterating")
    .def_readonly("iteration_seconds", &S::iteration_seconds, "the rest of the solve")
    .def_readonly("message", &S::message, "why it stopped short of its tolerance (a limit), else empty")
    .def_readonly("interrupted", &S::interrupted, "whether the progress callback stopped it");

  using T = SMP::Norm_preserving_timings;
  py::class_<T>(m, "Timings", "Where the time of one component went, in seconds (the solve's own steps: SolveReport).")
    .def_readonly("extraction", &T::extraction, "copying the component, choosing the fixed pair, normalizing")
    .def_readonly("guess", &T::guess, "the initial guess, the similarity transform and the signs")
    .def_readonly("solve", &T::solve, "the QP solve")
    .def_readonly("sign_refinement", &T::sign_refinement, "the rounds of sign refinement")
    .def_readonly("euclidean_refinement", &T::euclidean_refinement, "the Euclidean refinement")
    .def_readonly("write_back", &T::write_back, "the rest: the final objective, the fit, the uvs");

  using C = SMP::Norm_preserving_report;
  py::class_<C>(m, "ComponentReport", "What the map of one connected component did (C++ Norm_preserving_report).")
    .def_readonly("status", &C::status, "the component's result")
    .def_readonly("message", &C::message, "the reason of a failure, else empty")
    .def_readonly("vertices", &C::vertices, "vertices of the component")
    .def_readonly("edges", &C::edges, "edges of the component, one QP residual each")
    .def_readonly("fixed_a", &C::fixed_a, "the first fixed vertex (an input index)")
    .def_readonly("fixed_b", &C::fixed_b, "the second fixed vertex (an input index)")
    .def_readonly("initial_objective", &C::initial_objective, "Eq. 4 at the transformed initial guess")
    .def_readonly("objective", &C::objective, "Eq. 3 at the solution of the QP, before the Euclidean refinement")
    .def_readonly("max_constraint_violation", &C::max_constraint_violation, "largest violation of a sign constraint")
    .def_readonly("active_constraints", &C::active_constraints, "sign constraints at equality")
    .def_readonly("constraints", &C::constraints, "sign constraints, two per edge")
    .def_readonly("solver", &C::solver, "the SolveReport of the QP solve (the first, before the refinements)")
    .def_readonly("sign_refinement_rounds", &C::sign_refinement_rounds, "rounds of sign refinement kept")
    .def_readonly("sign_refinement_objectives", &C::sign_refinement_objectives,
                  "Eq. 3 at the QP solution, then after each round kept")
    .def_readonly("euclidean_iterations", &C::euclidean_iterations, "steps of the Euclidean refinement")
    .def_readonly("euclidean_stress", &C::euclidean_stress,
                  "the Euclidean objective at the start of the refinement, then after each step")
    .def_readonly("seconds", &C::seconds, "wall-clock time of the component")
    .def_readonly("timings", &C::timings, "the same time, step by step");

  using D = SMP::Parameterization_distortion;
  py::class_<D>(m, "Distortion", "Distortion of a uv map over the faces whose vertices all have a uv (measure_distortion()).")
    .def_readonly("faces", &D::faces, "triangles measured (each face triangulated as the package does)")
    .def_readonly("edges", &D::edges, "edges measured")
    .def_readonly("scale", &D::scale, "the factor that best fits the uvs to the 3D edge lengths")
    .def_readonly("edge_length_error", &D::edge_length_error, "RMS relative Euclidean edge-length error")
    .def_readonly("l1_edge_length_error", &D::l1_edge_length_error, "RMS relative L1 edge-length error")
    .def_readonly("l1_objective", &D::l1_objective, "the paper's Eq. 3 at the best-fitting scale")
    .def_readonly("mean_angle_distortion", &D::mean_angle_distortion, "mean angle error, degrees")
    .def_readonly("max_angle_distortion", &D::max_angle_distortion, "largest angle error, degrees")
    .def_readonly("area_distortion", &D::area_distortion, "RMS of log(uv area / 3D area)")
    .def_readonly("l2_stretch", &D::l2_stretch, "Sander et al.'s L2 stretch (1 is ideal)")
    .def_readonly("linf_stretch", &D::linf_stretch, "Sander et al.'s L-infinity stretch (1 is ideal)")
    .def_readonly("flipped_faces", &D::flipped_faces, "faces oriented against most of the area")
    .def_readonly("flipped_area_fraction", &D::flipped_area_fraction, "their share of the 3D area")
    .def_readonly("degenerate_uv_faces", &D::degenerate_uv_faces, "faces of zero uv area");

  py::class_<Texture_report>(m, "Report", "What a texture() call did (C++ Texture_polygon_mesh_report), and its distortion.")
    .def_readonly("status", &Texture_report::status, "the call's result: OK, since a failure raises")
    .def_readonly("message", &Texture_report::message, "the reason of a failure: empty, since a failure raises")
    .def_readonly("components", &Texture_report::components, "connected components textured")
    .def_readonly("isolated_vertices", &Texture_report::isolated_vertices, "vertices on no face: their uv is NaN")
    .def_readonly("welded_vertices", &Texture_report::welded_vertices, "vertices given the uv of a coincident one")
    .def_readonly("repeated_corners", &Texture_report::repeated_corners, "face corners dropped as repeats of a vertex")
    .def_readonly("point_components", &Texture_report::point_components, "components of zero extent, mapped to a point")
    .def_readonly("objective", &Texture_report::objective, "sum of the components' Eq. 3 objectives")
    .def_readonly("optimality_gap", &Texture_report::optimality_gap, "the largest certified gap of the components")
    .def_readonly("reports", &Texture_report::reports, "one ComponentReport per component")
    .def_readonly("seconds", &Texture_report::seconds, "wall-clock time of the package's call")
    .def_readonly("interrupted", &Texture_report::interrupted, "whether the call was stopped: False, since that raises")
    .def_readonly("distortion", &Texture_report::distortion, "the Distortion of the uvs")
    .def("__repr__", [](const Texture_report& r) {
      return "Report(components=" + std::to_string(r.components) + ", objective=" + std::to_string(r.objective) +
             ", optimality_gap=" + std::to_string(r.optimality_gap) + ", seconds=" + std::to_string(r.seconds) + ")";
    });

  py::class_<Cut_report>(m, "CutReport", "What an lscm() or arap() call did.")
    .def_readonly("method", &Cut_report::method, "'lscm' or 'arap'")
    .def_readonly("components", &Cut_report::components, "connected components, each cut and mapped on its own")
    .def_readonly("seam_edges", &Cut_report::seam_edges, "edges cut by cut_to_disk(), over all components")
    .def_readonly("seam_length", &Cut_report::seam_length, "their total 3D length")
    .def_readonly("cut_seconds", &Cut_report::cut_seconds, "building the mesh, cutting and triangulating it")
    .def_readonly("seconds", &Cut_report::seconds, "the parameterizer's calls")
    .def_readonly("distortion", &Cut_report::distortion, "the Distortion of the map on the cut mesh")
    .def("__repr__", [](const Cut_report& r) {
      return "CutReport(method='" + r.method + "', components=" + std::to_string(r.components) +
             ", seam_edges=" + std::to_string(r.seam_edges) + ", seconds=" + std::to_string(r.seconds) + ")";
    });
}

} // namespace

PYBIND11_MODULE(norm_preserving, m)
{
  m.doc() = R"doc(Norm-preserving texture mapping (Lai & Cheng) on NumPy arrays.

Every vertex of any polygon soup gets one uv, with no cut and no seam:

    uv, report = norm_preserving.texture(vertices, faces)

vertices: an (n, 3) array of numbers; faces: an (m, k) integer array, or a sequence of index
sequences for polygons of mixed sizes. Also: measure_distortion(), CGAL's lscm() and arap() on
the mesh cut to a disk, read_mesh() and (but in the module of the Blender add-on's zip)
write_obj(). The caller's arrays are read, never
written. The user's guide: doc/manual.md, section 7 (Python).)doc";

  bind_reports(m);

  m.def("texture", &texture, py::arg("vertices"), py::arg("faces"), py::kw_only(), py::arg("guess") = "xy",
        py::arg("fit") = "uniform", py::arg("tiles") = std::make_pair(1, 1), py::arg("fixed_pair") = py::none(),
        py::arg("keep_coincident") = false, py::arg("refine_signs") = false, py::arg("refine_euclidean") = false,
        py::arg("quality") = "default", py::arg("tolerance") = py::none(), py::arg("time_limit") = py::none(),
        py::arg("progress") = py::none(),
        R"doc(Textures a polygon soup: one uv per vertex, no cut, no seam.

Any soup is taken as it is: closed or not, any genus, several components, non-manifold,
mis-oriented or non-orientable faces, polygons of any size (triangulated adding no vertex),
vertices at the same position (welded: they get one uv). Each component is mapped at one
common scale, the components are laid side by side and fitted into texture space.

Parameters
----------
vertices : (n, 3) array of numbers; float32 and float64 are read in place, others converted.
faces : (m, k) integer array (any integer dtype), or a sequence of index sequences.
guess : 'xy' (XY-MinMax), 'combination' or 'graph': the initial guess that sets the signs.
fit : 'uniform' ([0,1]^2, aspect kept), 'clamp' (each axis to [0,1]) or 'none' (mesh units).
tiles : (M, N): the texture repeats M times along u and N times along v.
fixed_pair : (a, b), two vertices of an edge held at its length; None: automatic.
keep_coincident : do not weld the vertices at the same position.
refine_signs : re-solve with the signs of the solution (at most 10 rounds).
refine_euclidean : then minimize the Euclidean edge-length error (at most 1000 steps).
quality : 'draft' (at most 2% above the optimum), 'default' or 'exact' (certified to 1e-9).
tolerance : the solver's tolerance; None: the quality's.
time_limit : seconds after which the solver returns its best point (its SolveReport.message
    says so); None: no limit.
progress : None, or a callable taking a Progress, called from the solver's threads with the
    GIL held; returning a false value other than None (False, 0, numpy.False_) stops the call
    (RuntimeError), an exception it raises stops the call and is raised again.

Returns
-------
(uv, report): uv an (n, 2) float64 array (NaN for a vertex on no face), report a Report.

Raises
------
TypeError: an array of the wrong kind (faces not integers, vertices not numbers).
ValueError: a wrong shape, no face, an index out of range, a non-finite coordinate on a face,
    a mesh of zero extent, a bad option or fixed pair; the message says which.
RuntimeError: the solver failed, or the progress callback returned a false value.
KeyboardInterrupt: Ctrl-C during the solve, which stops cleanly (nothing is returned).

The arrays are read in place while the GIL is released (other Python threads run during the
solve): no other thread may modify them until the call returns.)doc");

  m.def("measure_distortion", &measure_distortion, py::arg("vertices"), py::arg("faces"), py::arg("uv"),
        R"doc(Measures the distortion of a uv map of a polygon soup.

Parameters
----------
vertices : (n, 3) array of numbers.
faces : (m, k) integer array, or a sequence of index sequences (triangulated as texture() does).
uv : (n, 2) array, one uv per vertex; a vertex whose u is not finite has no uv, and the faces
    around it are not measured.

Returns
-------
Distortion: edge-length, angle and area errors, stretch, flipped faces.

Raises
------
TypeError, ValueError: as texture() does for the arrays.)doc");

  const char* const cut_doc = R"doc(

The mesh must be an oriented 2-manifold (CGAL's Surface_mesh holds it). Each connected
component is cut to a disk by the package's cut_to_disk() (not cut if it is one), its polygons
are then triangulated, and CGAL's parameterizer maps it in its own uv coordinates (components
may overlap). It cannot be interrupted: Ctrl-C takes effect when it returns.

Parameters
----------
vertices : (n, 3) array of numbers.
faces : (m, k) integer array, or a sequence of index sequences.

Returns
-------
(uv, report): uv per face corner, since a vertex on a cut has one uv on each side: an
(m, k, 2) float64 array (uv[f, c] is the uv of corner c of face f) when every face has k
corners, else a list of (k, 2) arrays, one per face; report a CutReport with the distortion.

Raises
------
TypeError, ValueError: as texture() does, and for a mesh that is not an oriented 2-manifold.
RuntimeError: the parameterizer failed.)doc";
  static const std::string lscm_doc = "CGAL's LSCM (least squares conformal maps) on the mesh cut to a disk." + std::string(cut_doc);
  m.def("lscm", [](const Array_like& vertices, const Array_like& faces) {
    return parameterize_cut<SMP::LSCM_parameterizer_3<Seam_mesh> >(vertices, faces, "lscm");
  }, py::arg("vertices"), py::arg("faces"), lscm_doc.c_str());
  static const std::string arap_doc = "CGAL's ARAP (as rigid as possible) on the mesh cut to a disk." + std::string(cut_doc);
  m.def("arap", [](const Array_like& vertices, const Array_like& faces) {
    return parameterize_cut<SMP::ARAP_parameterizer_3<Seam_mesh> >(vertices, faces, "arap");
  }, py::arg("vertices"), py::arg("faces"), arap_doc.c_str());

#ifndef NP_PYTHON_WITHOUT_PNG
  m.def("write_obj", &write_obj, py::arg("basename"), py::arg("vertices"), py::arg("faces"), py::arg("uv"),
        R"doc(Writes a textured OBJ with the command-line tool's writer: basename.obj (the vertices
and faces in their order, one vt per vertex), basename.mtl and a checkerboard basename.png, so
that any viewer shows the texture. All three or none: they are written into a scratch directory
beside them, then moved into place, replacing files of the same names.

Parameters
----------
basename : the path of the files, with or without .obj.
vertices : (n, 3) array of numbers, all finite.
faces : (m, k) integer array, or a sequence of index sequences (a face of two corners is a line).
uv : (n, 2) array, one uv per vertex, as texture() returns it; a vertex whose uv is not
    finite (a vertex on no face) is written at (0, 0), as the tool writes it.

Raises
------
TypeError, ValueError: as texture() does for the arrays; ValueError too for a non-finite
    coordinate (on a face or not), and a basename that names a directory.
OSError: the files cannot be written (nothing is).)doc");
#endif

  m.def("read_mesh", &read_mesh, py::arg("path"),
        R"doc(Reads a mesh file as the command-line tool does: OBJ (with its l lines: faces of two
corners) and PLY (any numeric type, ASCII or binary, triangle strips) with the tool's readers,
OFF, STL and GOCAD TS with CGAL's.

Parameters
----------
path : str or path-like.

Returns
-------
(vertices, faces): an (n, 3) float64 array, and an (m, k) int64 array when every face has k
corners, else a list of int64 arrays, one per face.

Raises
------
FileNotFoundError: no such file.
ValueError: the file cannot be read, or has no face; the message says why.)doc");
}
