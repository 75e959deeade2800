// The uvs of an OBJ file: its vt lines in order, as the command-line tool writes them (one per
// vertex, printed to round-trip), for the tests that compare them bit for bit with a call's.

#ifndef NP_TEST_OBJ_UVS_H
#define NP_TEST_OBJ_UVS_H

#include <array>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace np_test {

/// The (u, v) of every vt line of the OBJ file `path`, in order; empty if it cannot be read.
inline std::vector<std::array<double, 2> > read_obj_uvs(const std::string& path)
{
  std::vector<std::array<double, 2> > uvs;
  std::ifstream in(path);
  for(std::string line; std::getline(in, line);)
    if(line.compare(0, 3, "vt ") == 0)
    {
      std::istringstream words(line.substr(3));
      std::array<double, 2> uv = {0, 0};
      words >> uv[0] >> uv[1];
      uvs.push_back(uv);
    }
  return uvs;
}

} // namespace np_test

#endif
