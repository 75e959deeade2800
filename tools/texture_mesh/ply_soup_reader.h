// PLY files as polygon soups, for the command-line tool and the Python module (soup_reader.h):
// every PLY file is read here. (CGAL 5.5's reader skips or refuses the triangle strips of many of
// Stanford's scans, reads a missing coordinate as 0 and crashes on integer coordinates.)
//
// The vertices are the items of an element named `vertex` (or `vertices`), their position the
// first single properties named x, y and z, of any numeric type. A face element is any other
// element with a list of integers named `vertex_indices` or `vertex_index` (or, in an element
// named face, faces or tristrips, with a single list of integers, whatever its name); the lists
// of `tristrips` are triangle strips, every other one a polygon. Every other element and
// property is read and skipped.
//
// ASCII and binary files of both byte orders are read on any host, each value by its declared
// type: an ASCII integer must be an integer in the range of its type, an ASCII float is rounded
// to float as a binary one is stored (so that ASCII and binary copies of one file give the same
// doubles), and a binary value is assembled from its bytes in the file's byte order.

#ifndef NP_EXAMPLES_PLY_SOUP_READER_H
#define NP_EXAMPLES_PLY_SOUP_READER_H

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace np_examples {

enum class Ply_type { NONE, INT8, UINT8, INT16, UINT16, INT32, UINT32, FLOAT32, FLOAT64 };

// The type of a PLY type name (both spellings: `uchar` and `uint8`), or NONE.
inline Ply_type ply_type_named(const std::string& name)
{
  static const struct { const char* name; Ply_type type; } names[] = {
    {"char", Ply_type::INT8},     {"int8", Ply_type::INT8},       {"uchar", Ply_type::UINT8},
    {"uint8", Ply_type::UINT8},   {"short", Ply_type::INT16},     {"int16", Ply_type::INT16},
    {"ushort", Ply_type::UINT16}, {"uint16", Ply_type::UINT16},   {"int", Ply_type::INT32},
    {"int32", Ply_type::INT32},   {"uint", Ply_type::UINT32},     {"uint32", Ply_type::UINT32},
    {"float", Ply_type::FLOAT32}, {"float32", Ply_type::FLOAT32}, {"double", Ply_type::FLOAT64},
    {"float64", Ply_type::FLOAT64}};
  for(const auto& n : names)
    if(name == n.name)
      return n.type;
  return Ply_type::NONE;
}

inline int ply_type_size(Ply_type type)
{
  switch(type)
  {
    case Ply_type::INT8: case Ply_type::UINT8: return 1;
    case Ply_type::INT16: case Ply_type::UINT16: return 2;
    case Ply_type::INT32: case Ply_type::UINT32: case Ply_type::FLOAT32: return 4;
    case Ply_type::FLOAT64: return 8;
    default: return 0;
  }
}

inline bool is_ply_integer_type(Ply_type type)
{
  return type != Ply_type::NONE && type != Ply_type::FLOAT32 && type != Ply_type::FLOAT64;
}

// The smallest and largest values of an integer type.
inline std::int64_t ply_type_min(Ply_type type)
{
  switch(type)
  {
    case Ply_type::INT8: return INT8_MIN;
    case Ply_type::INT16: return INT16_MIN;
    case Ply_type::INT32: return INT32_MIN;
    default: return 0;
  }
}
inline std::int64_t ply_type_max(Ply_type type)
{
  switch(type)
  {
    case Ply_type::INT8: return INT8_MAX;
    case Ply_type::UINT8: return UINT8_MAX;
    case Ply_type::INT16: return INT16_MAX;
    case Ply_type::UINT16: return UINT16_MAX;
    case Ply_type::INT32: return INT32_MAX;
    default: return UINT32_MAX;
  }
}

// What a property is to the reader, resolved once from the header.
enum class Ply_role { SKIPPED, X, Y, Z, INDICES };

struct Ply_property
{
  std::string name;
  std::string type_name, count_type_name; // as declared (for messages)
  Ply_type type = Ply_type::NONE;          // of the value, or of a list's items
  Ply_type count_type = Ply_type::NONE;    // of a list's length; NONE for a single value
  Ply_role role = Ply_role::SKIPPED;
  bool is_list() const { return count_type != Ply_type::NONE; }
};

struct Ply_element
{
  std::string name;
  std::size_t count = 0;
  std::vector<Ply_property> properties;
  bool vertices = false; // the element of the vertices
  bool strips = false;   // a face element of triangle strips
  bool faces = false;    // a face element (of polygons or strips)
};

struct Ply_header
{
  std::string format; // ascii, binary_little_endian or binary_big_endian
  std::vector<Ply_element> elements;
};

inline bool is_ply_vertex_element(const Ply_element& element)
{
  return element.name == "vertex" || element.name == "vertices";
}

// The position in `element` of its list of vertex indices (see the top of this file), or -1 if
// it is not a face element.
inline int ply_index_list(const Ply_element& element)
{
  if(is_ply_vertex_element(element))
    return -1;
  int only = -1, integer_lists = 0;
  for(std::size_t k = 0; k < element.properties.size(); ++k)
  {
    const Ply_property& p = element.properties[k];
    if(!p.is_list() || !is_ply_integer_type(p.type))
      continue;
    if(p.name == "vertex_indices" || p.name == "vertex_index")
      return int(k);
    only = int(k);
    ++integer_lists;
  }
  const bool named_for_faces = element.name == "face" || element.name == "faces" || element.name == "tristrips";
  return named_for_faces && integer_lists == 1 ? only : -1;
}

// Gives each element and property its role; returns what is missing, if anything (a vertex
// element without x, y or z).
inline std::optional<std::string> resolve_ply_roles(Ply_header& header)
{
  for(Ply_element& element : header.elements)
  {
    element.vertices = is_ply_vertex_element(element);
    if(element.vertices)
    {
      const Ply_role roles[3] = {Ply_role::X, Ply_role::Y, Ply_role::Z};
      for(int axis = 0; axis < 3; ++axis)
      {
        const std::string name(1, char('x' + axis));
        const auto p = std::find_if(element.properties.begin(), element.properties.end(),
                                    [&](const Ply_property& q) { return !q.is_list() && q.name == name; });
        if(p == element.properties.end())
          return "its vertices have no " + name + " coordinate";
        p->role = roles[axis];
      }
      continue;
    }
    const int list = ply_index_list(element);
    if(list >= 0)
    {
      element.faces = true;
      element.strips = element.name == "tristrips";
      element.properties[std::size_t(list)].role = Ply_role::INDICES;
    }
  }
  return std::nullopt;
}

inline bool has_ply_face_element(const Ply_header& header)
{
  return std::any_of(header.elements.begin(), header.elements.end(), [](const Ply_element& e) { return e.faces; });
}

// "vertex, tristrips and edge elements", "a vertex element": the elements, for a message.
inline std::string ply_element_names(const Ply_header& header)
{
  if(header.elements.empty())
    return "no element";
  if(header.elements.size() == 1)
    return "a " + header.elements.front().name + " element";
  std::string names;
  for(std::size_t k = 0; k < header.elements.size(); ++k)
    names += (k == 0 ? "" : k + 1 == header.elements.size() ? " and " : ", ") + header.elements[k].name;
  return names + " elements";
}

// Reads the header of the PLY file `text` into `header`, its roles resolved, and sets `data` to
// the first byte after it; returns what is wrong with it, if anything.
inline std::optional<std::string> read_ply_header(const std::string& text, Ply_header& header, std::size_t& data)
{
  std::size_t at = 0;
  auto next_line = [&](std::string& line) {
    if(at >= text.size())
      return false;
    const std::size_t end = std::min(text.find('\n', at), text.size());
    line = text.substr(at, end - at);
    at = end + 1;
    return true;
  };
  std::string line, keyword;
  if(!next_line(line) || !(std::istringstream(line) >> keyword) || keyword != "ply")
    return std::string("it does not start with \"ply\"");
  for(std::size_t number = 2; next_line(line); ++number)
  {
    std::istringstream words(line);
    if(!(words >> keyword) || keyword == "comment" || keyword == "obj_info")
      continue;
    const std::string where = "header line " + std::to_string(number) + ": ";
    std::string rest;
    if(keyword == "end_header")
    {
      if(header.format.empty())
        return std::string("its header has no format line");
      data = std::min(at, text.size());
      return resolve_ply_roles(header);
    }
    if(keyword == "format")
    {
      if(!(words >> header.format) ||
         (header.format != "ascii" && header.format != "binary_little_endian" && header.format != "binary_big_endian"))
        return where + "unknown format \"" + header.format + "\"";
    }
    else if(keyword == "element")
    {
      Ply_element element;
      std::string count;
      if(!(words >> element.name >> count) || words >> rest)
        return where + "an element needs a name and a count";
      char* end = nullptr;
      errno = 0;
      const unsigned long long n = std::strtoull(count.c_str(), &end, 10);
      if(!std::isdigit(static_cast<unsigned char>(count[0])) || *end != '\0' || errno == ERANGE ||
         n > std::numeric_limits<std::size_t>::max())
        return where + "the count of element " + element.name + " is not a count: " + count;
      element.count = std::size_t(n);
      header.elements.push_back(element);
    }
    else if(keyword == "property")
    {
      if(header.elements.empty())
        return std::string("a property is declared before any element");
      Ply_property property;
      std::string& count_type = property.count_type_name;
      if(!(words >> property.type_name))
        return where + "a property needs a type and a name";
      if(property.type_name == "list" && !(words >> count_type >> property.type_name))
        return where + "a list needs the types of its length and of its items";
      if(!(words >> property.name) || words >> rest)
        return where + "a property needs a type and a name";
      property.type = ply_type_named(property.type_name);
      if(property.type == Ply_type::NONE)
        return where + "unknown type \"" + property.type_name + "\"";
      if(!count_type.empty())
      {
        property.count_type = ply_type_named(count_type);
        if(property.count_type == Ply_type::NONE)
          return where + "unknown type \"" + count_type + "\"";
        if(!is_ply_integer_type(property.count_type))
          return where + "the length of a list must be an integer";
      }
      header.elements.back().properties.push_back(property);
    }
    else
      return where + "unknown keyword \"" + keyword + "\"";
  }
  return std::string("its header has no end_header line");
}

// Reads the values of a PLY file's data, each by its type, from the text in memory.
class Ply_value_reader
{
public:
  enum Status { OK, END, NOT_OF_TYPE, OUT_OF_RANGE };

  Ply_value_reader(const std::string& text, std::size_t data, const std::string& format)
    : m_at(text.c_str() + std::min(data, text.size())), m_end(text.c_str() + text.size()), m_ascii(format == "ascii"),
      m_big_endian(format == "binary_big_endian")
  {
  }

  // An integer of the integer type `type`.
  Status integer(Ply_type type, std::int64_t& value)
  {
    if(m_ascii)
    {
      if(!next_word())
        return END;
      char* end = nullptr;
      errno = 0;
      const long long number = std::strtoll(m_word, &end, 10);
      if(end == m_word || end != m_word_end)
        return NOT_OF_TYPE;
      if(errno == ERANGE || number < ply_type_min(type) || number > ply_type_max(type))
        return OUT_OF_RANGE;
      value = number;
      return OK;
    }
    const int size = ply_type_size(type);
    std::uint64_t bits = 0;
    if(!bytes(size, bits))
      return END;
    value = std::int64_t(bits);
    if(ply_type_min(type) < 0 && (bits >> (8 * size - 1)) != 0) // the sign bit of a signed type
      value -= std::int64_t(1) << (8 * size);
    return OK;
  }

  // A value of any type, as a double (every PLY value is one exactly).
  Status number(Ply_type type, double& value)
  {
    if(is_ply_integer_type(type))
    {
      std::int64_t integer_value = 0;
      const Status status = integer(type, integer_value);
      value = double(integer_value);
      return status;
    }
    if(m_ascii)
    {
      if(!next_word())
        return END;
      char* end = nullptr;
      errno = 0;
      value = type == Ply_type::FLOAT32 ? double(std::strtof(m_word, &end)) : std::strtod(m_word, &end);
      if(end == m_word || end != m_word_end)
        return NOT_OF_TYPE;
      if(errno == ERANGE && !std::isfinite(value)) // an overflow; an underflow is a small number
        return OUT_OF_RANGE;
      return OK;
    }
    std::uint64_t bits = 0;
    if(!bytes(ply_type_size(type), bits))
      return END;
    if(type == Ply_type::FLOAT32)
    {
      const std::uint32_t bits32 = std::uint32_t(bits);
      float f;
      std::memcpy(&f, &bits32, sizeof f);
      value = f;
    }
    else
      std::memcpy(&value, &bits, sizeof value);
    return OK;
  }

  // The ASCII word last read, for a message.
  std::string word() const { return std::string(m_word, m_word_end); }

private:
  static bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f'; }

  // The next whitespace-separated word, [m_word, m_word_end); followed by a blank or the
  // text's terminating '\0', which ends strtod()'s scan.
  bool next_word()
  {
    while(m_at < m_end && is_space(*m_at))
      ++m_at;
    if(m_at == m_end)
      return false;
    m_word = m_at;
    while(m_at < m_end && !is_space(*m_at))
      ++m_at;
    m_word_end = m_at;
    return true;
  }

  // `size` bytes as an unsigned integer, in the file's byte order.
  bool bytes(int size, std::uint64_t& bits)
  {
    if(m_end - m_at < size)
    {
      m_at = m_end;
      return false;
    }
    const unsigned char* b = reinterpret_cast<const unsigned char*>(m_at);
    for(int k = 0; k < size; ++k)
      bits |= std::uint64_t(b[k]) << (8 * (m_big_endian ? size - 1 - k : k));
    m_at += size;
    return true;
  }

  const char* m_at;
  const char* const m_end;
  const bool m_ascii, m_big_endian;
  const char* m_word = "";
  const char* m_word_end = m_word;
};

// Appends the triangles of the strip `strip` to `polygons`: each three vertices in a row are a
// triangle, every second one reversed so that all keep the strip's orientation; the triangles
// with a repeated vertex, which strips use to join their pieces, are skipped.
template <typename PolygonRange>
void append_strip_triangles(const std::vector<std::size_t>& strip, PolygonRange& polygons)
{
  for(std::size_t k = 0; k + 2 < strip.size(); ++k)
  {
    const std::size_t a = strip[k + (k % 2)], b = strip[k + 1 - (k % 2)], c = strip[k + 2];
    if(a != b && b != c && a != c)
      polygons.push_back({a, b, c});
  }
}

// Reads the data of the PLY file `text`, which starts at `data` and is described by `header`
// (read_ply_header()): appends the vertices to `points` (constructed from three doubles) and the
// faces of every face element to `polygons` (vectors of indices); returns what is wrong, if
// anything. A face element's negative index is refused, but in a strip, where -1 starts a new
// strip.
template <typename PointRange, typename PolygonRange>
std::optional<std::string> read_ply_data(const std::string& text, std::size_t data, const Ply_header& header,
                                         PointRange& points, PolygonRange& polygons)
{
  typedef typename PointRange::value_type Point;
  Ply_value_reader values(text, data, header.format);
  std::vector<std::size_t> indices;
  for(const Ply_element& element : header.elements)
  {
    if(element.properties.empty()) // no data, whatever the count
      continue;
    for(std::size_t item = 0; item < element.count; ++item)
    {
      // Where a value is, for a message.
      auto where = [&](const Ply_property& p) {
        return "element " + element.name + ", item " + std::to_string(item + 1) + " of " + std::to_string(element.count) +
               ", property " + p.name + ": ";
      };
      // Why the value of type `type_name` cannot be read.
      auto wrong = [&](Ply_value_reader::Status status, const std::string& type_name) {
        if(status == Ply_value_reader::END)
          return std::string("the data ends");
        return "'" + values.word() + "' is " +
               (status == Ply_value_reader::OUT_OF_RANGE ? "out of the range of type " : "not a value of type ") + type_name;
      };
      double xyz[3] = {0, 0, 0};
      for(const Ply_property& p : element.properties)
      {
        if(!p.is_list())
        {
          double value = 0;
          const Ply_value_reader::Status status = values.number(p.type, value);
          if(status != Ply_value_reader::OK)
            return where(p) + wrong(status, p.type_name);
          if(p.role == Ply_role::X) xyz[0] = value;
          else if(p.role == Ply_role::Y) xyz[1] = value;
          else if(p.role == Ply_role::Z) xyz[2] = value;
          continue;
        }
        std::int64_t length = 0;
        Ply_value_reader::Status status = values.integer(p.count_type, length);
        if(status != Ply_value_reader::OK)
          return where(p) + wrong(status, p.count_type_name);
        if(length < 0)
          return where(p) + "the length " + std::to_string(length) + " is negative";
        const bool index_list = p.role == Ply_role::INDICES;
        indices.clear();
        for(std::int64_t k = 0; k < length; ++k)
        {
          if(!index_list)
          {
            double skipped;
            status = values.number(p.type, skipped);
            if(status != Ply_value_reader::OK)
              return where(p) + wrong(status, p.type_name);
            continue;
          }
          std::int64_t index = 0;
          status = values.integer(p.type, index);
          if(status != Ply_value_reader::OK)
            return where(p) + wrong(status, p.type_name);
          if(element.strips && index == -1)
          {
            append_strip_triangles(indices, polygons);
            indices.clear();
          }
          else if(index < 0)
            return where(p) + std::to_string(index) + " is not a vertex index";
          else
            indices.push_back(std::size_t(index));
        }
        if(index_list && element.strips)
          append_strip_triangles(indices, polygons);
        else if(index_list)
          polygons.emplace_back(indices.begin(), indices.end());
      }
      if(element.vertices)
        points.push_back(Point(xyz[0], xyz[1], xyz[2]));
    }
  }
  return std::nullopt;
}

} // namespace np_examples

#endif
