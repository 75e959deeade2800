// Writes a set of output files all or nothing, for the command-line tool and the Python module's
// write_obj(): each file into a new scratch directory beside them, then each moved into place
// (replacing files of the same names), so that no failure leaves a file of the set half-written
// or a set partly replaced.

#ifndef NP_EXAMPLES_OUTPUT_FILES_H
#define NP_EXAMPLES_OUTPUT_FILES_H

#include <cstddef>
#include <filesystem>
#include <fstream>
#include <functional>
#include <optional>
#include <string>
#include <system_error>
#include <vector>

namespace np_examples {

// One output file: its name, and how to write it at a path (false on failure).
struct Output_file
{
  std::string name;
  std::function<bool(const std::string& path)> write;
};

// The files of a set, in their directory, all named stem + a suffix; the first one the main one.
struct Output_files
{
  std::filesystem::path directory;
  std::string stem;
  std::vector<Output_file> files;
};

// Writes the file `path` of `bytes`; no bytes (an image libpng could not encode) is a failure.
inline bool write_bytes(const std::string& path, const std::vector<unsigned char>& bytes)
{
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
  return !bytes.empty() && bool(out);
}

// "out.obj, .mtl, .png, _uv.svg, _report.txt": the names of the files, for a message.
inline std::string file_list(const Output_files& files)
{
  std::string list;
  for(const Output_file& file : files.files)
    list += list.empty() ? file.name : ", " + file.name.substr(files.stem.size());
  return list;
}

// Why the files cannot be written, if that is known before writing them.
inline std::optional<std::string> output_problem(const Output_files& files)
{
  std::error_code ec;
  if(!std::filesystem::exists(files.directory, ec))
    return "no such directory: " + files.directory.string();
  if(!std::filesystem::is_directory(files.directory, ec))
    return "not a directory: " + files.directory.string();
  for(const Output_file& file : files.files)
    if(std::filesystem::is_directory(files.directory / file.name, ec))
      return (files.directory / file.name).string() + " is a directory";
  return std::nullopt;
}

// A directory this run created, removed with what it holds when it goes out of scope.
struct Scratch_directory
{
  std::filesystem::path path;
  Scratch_directory() = default;
  Scratch_directory(const Scratch_directory&) = delete;
  Scratch_directory& operator=(const Scratch_directory&) = delete;
  ~Scratch_directory()
  {
    std::error_code ec;
    if(!path.empty())
      std::filesystem::remove_all(path, ec);
  }
};

// Writes every file into a new scratch directory beside them (stem.partial, or stem.partial.1,
// ...: never one that exists), then moves them in place: on any failure nothing of this call is
// left behind, and the reason is returned. An exception of a writer leaves nothing either.
inline std::optional<std::string> write_outputs(const Output_files& files)
{
  namespace fs = std::filesystem;
  if(const std::optional<std::string> problem = output_problem(files))
    return problem;
  std::error_code ec;
  Scratch_directory scratch;
  for(int k = 0; scratch.path.empty(); ++k)
  {
    const fs::path candidate =
      files.directory / (files.stem + ".partial" + (k > 0 ? "." + std::to_string(k) : std::string()));
    if(fs::create_directory(candidate, ec))
      scratch.path = candidate;
    else if((ec && ec != std::errc::file_exists) || k == 100)
      return "cannot create a directory in " + files.directory.string() + (ec ? ": " + ec.message() : std::string());
  }
  for(const Output_file& file : files.files)
    if(!file.write((scratch.path / file.name).string()))
      return "cannot write " + (scratch.path / file.name).string();
  for(std::size_t k = 0; k < files.files.size(); ++k)
  {
    fs::rename(scratch.path / files.files[k].name, files.directory / files.files[k].name, ec);
    if(ec)
    {
      const std::string reason = "cannot move " + files.files[k].name + " into place: " + ec.message();
      for(std::size_t moved = 0; moved < k; ++moved)
        fs::remove(files.directory / files.files[moved].name, ec);
      return reason;
    }
  }
  return std::nullopt;
}

} // namespace np_examples

#endif
