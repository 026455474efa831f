// Meshes from Wavefront OBJ files, as FCL's test meshes and most modelling tools write them.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>

#include "collide/mesh.h"

namespace cc::harness {

/// A problem with a mesh file; what() reads "FILE:LINE: what is wrong" (or "FILE: ..." when no
/// line applies).
class MeshFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Reads an OBJ file: its `v` and `f` lines (polygons are triangulated; normals, texture
/// coordinates, groups and materials are ignored; a first line that is not OBJ, such as FCL's
/// "6540 2180" header, is skipped). tinyobjloader reads the structure. Its number parser is not
/// correctly rounded (one ULP off for 2676 of env.obj's 19620 coordinates) and reads "nan" as 0,
/// so every `v` line's three coordinates are read again with std::from_chars, which gives the
/// double nearest to the decimal text.
/// Throws MeshFileError for a folder, an unreadable file, a syntax error, a face that names a missing
/// vertex, a vertex with fewer than three coordinates or a NaN, infinite or out-of-range
/// coordinate, and a file without triangles.
Mesh read_obj_file(const std::filesystem::path& path);
/// The same for an OBJ file's text; `path` names it in errors.
Mesh read_obj_text(const std::string& text, const std::filesystem::path& path);

}  // namespace cc::harness
