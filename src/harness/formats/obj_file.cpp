#include "harness/formats/obj_file.h"

#include <tiny_obj_loader.h>

#include <charconv>
#include <cmath>
#include <sstream>

#include "harness/formats/input_file.h"
#include "harness/formats/printable.h"

namespace cc::harness {
namespace {

// Every message is printable: a token of the file may hold a NUL or an escape.
[[noreturn]] void fail(const std::filesystem::path& path, const std::string& what) {
  throw MeshFileError(printable(path.string() + ": " + what));
}
[[noreturn]] void fail(const std::filesystem::path& path, std::size_t line, const std::string& what) {
  throw MeshFileError(printable(path.string() + ":" + std::to_string(line) + ": " + what));
}

// tinyobjloader's messages end in newlines and name lines as "(line 6.)"; one line of text.
std::string one_line(std::string message) {
  while (!message.empty() && (message.back() == '\n' || message.back() == ' ')) message.pop_back();
  for (char& c : message) c = c == '\n' ? ' ' : c;
  return message;
}

// A coordinate as std::from_chars reads it (a leading '+' allowed, as strtod allows it).
double coordinate(const std::filesystem::path& path, std::size_t line, const std::string& token) {
  const bool plus = token.size() > 1 && token[0] == '+' && token[1] != '+' && token[1] != '-';
  const char* begin = token.data() + (plus ? 1 : 0);
  const char* end = token.data() + token.size();
  double x = 0;
  const auto [ptr, ec] = std::from_chars(begin, end, x);
  if (ec == std::errc::result_out_of_range) fail(path, line, "coordinate \"" + token + "\" is out of range");
  if (ec != std::errc() || ptr != end) fail(path, line, "\"" + token + "\" is not a number");
  if (!std::isfinite(x)) fail(path, line, "coordinate \"" + token + "\" is not finite");
  return x;
}

// One pass over the file: the coordinates of every `v` line, read exactly, in file order; and
// every `f` line checked to name at least three vertices, each within the file's `v` lines
// (1-based; a negative index counts back from the last vertex read so far). tinyobjloader
// checks indices only after the whole file, naming its last line; this names the face's own.
std::vector<Vec3> exact_vertices(const std::filesystem::path& path, const std::string& text) {
  std::vector<Vec3> out;
  std::vector<std::pair<std::size_t, long>> ahead;  // faces naming a vertex not read yet: line, index
  std::istringstream lines(text);
  std::string line;
  for (std::size_t number = 1; std::getline(lines, line); ++number) {
    std::istringstream tokens(line);
    std::string keyword;
    if (!(tokens >> keyword)) continue;
    if (keyword == "v") {
      Vec3 p;
      for (int k = 0; k < 3; ++k) {
        std::string token;
        if (!(tokens >> token)) fail(path, number, "a vertex needs three coordinates");
        p[k] = coordinate(path, number, token);
      }
      out.push_back(p);
    } else if (keyword == "f") {
      int corners = 0;
      for (std::string token; tokens >> token; ++corners) {
        const std::string index_text = token.substr(0, token.find('/'));
        long index = 0;
        const auto [ptr, ec] = std::from_chars(index_text.data(), index_text.data() + index_text.size(), index);
        if (ec != std::errc() || ptr != index_text.data() + index_text.size()) {
          fail(path, number, "\"" + token + "\" is not a vertex index");
        }
        if (index == 0 || (index < 0 && static_cast<std::size_t>(-index) > out.size())) {
          fail(path, number, "the face names vertex " + index_text + ", but " + std::to_string(out.size()) +
                                 " vertices come before this line");
        }
        if (index > 0 && static_cast<std::size_t>(index) > out.size()) ahead.emplace_back(number, index);
      }
      if (corners < 3) fail(path, number, "a face needs three vertices, this one has " + std::to_string(corners));
    }
  }
  for (const auto& [number, index] : ahead) {
    if (static_cast<std::size_t>(index) > out.size()) {
      fail(path, number, "the face names vertex " + std::to_string(index) + ", but the file has " +
                             std::to_string(out.size()) + " vertices");
    }
  }
  return out;
}

}  // namespace

Mesh read_obj_file(const std::filesystem::path& path) {
  std::string text;
  try {
    text = read_input_file(path, kMaxMeshFileBytes, "mesh file");
  } catch (const InputFileError& e) {
    fail(path, e.what());
  }
  return read_obj_text(text, path);
}

Mesh read_obj_text(const std::string& with_mark, const std::filesystem::path& path) {
  // A UTF-8 byte-order mark before the first line is no part of it.
  const std::string text = with_mark.starts_with("\xEF\xBB\xBF") ? with_mark.substr(3) : with_mark;
  const std::vector<Vec3> vertices = exact_vertices(path, text);

  tinyobj::ObjReaderConfig config;
  config.triangulate = true;
  config.vertex_color = false;
  tinyobj::ObjReader reader;
  if (!reader.ParseFromString(text, "", config)) fail(path, one_line(reader.Error()));
  if (const std::string warning = one_line(reader.Warning()); !warning.empty() &&
      (warning.find("out of bounds") != std::string::npos || warning.find("invalid") != std::string::npos)) {
    fail(path, warning);
  }

  Mesh mesh;
  mesh.vertices = vertices;
  if (mesh.vertices.size() * 3 != reader.GetAttrib().vertices.size()) {
    fail(path, "tinyobjloader read " + std::to_string(reader.GetAttrib().vertices.size() / 3) + " vertices, the file has " +
                   std::to_string(mesh.vertices.size()) + " `v` lines");
  }
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    const auto& indices = shape.mesh.indices;
    for (std::size_t i = 0; i + 2 < indices.size(); i += 3) {
      std::array<std::uint32_t, 3> face{};
      for (int k = 0; k < 3; ++k) {
        const int index = indices[i + k].vertex_index;
        if (index < 0 || static_cast<std::size_t>(index) >= mesh.vertices.size()) {
          fail(path, "face " + std::to_string(mesh.faces.size() + 1) + " of shape \"" + shape.name +
                         "\" names vertex " + std::to_string(index + 1) + " of " + std::to_string(mesh.vertices.size()));
        }
        face[k] = static_cast<std::uint32_t>(index);
      }
      mesh.faces.push_back(face);
    }
  }
  if (mesh.faces.empty()) fail(path, "no triangles (an empty file, or no `f` lines)");
  return mesh;
}

}  // namespace cc::harness
