// Mesh files named by case files: where a path is looked for, and a cache of what was read.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "collide/mesh.h"

namespace cc::harness {

/// Where a mesh file named `as_written` in a case file in `case_dir` is: an absolute path as
/// it is; a relative one in case_dir, or else in the nearest folder above it that has it (so
/// "meshes/env.obj" is found from any folder under corpora/), or else relative to the current
/// directory. Nothing when none exists.
std::optional<std::filesystem::path> find_mesh_file(const std::string& as_written, const std::filesystem::path& case_dir);

/// The mesh in an OBJ file, read once per process (by canonical path) and shared afterwards.
/// Throws MeshFileError (see obj_file.h).
std::shared_ptr<const Mesh> load_mesh_file(const std::filesystem::path& path);

/// The canonical path of the file load_mesh_file read this very mesh from, in this process;
/// nothing for a mesh it did not read.
std::optional<std::filesystem::path> mesh_file_of(const Mesh& mesh);

/// The folder the campaign takes FCL's test meshes from: <corpora root>/meshes.
std::filesystem::path mesh_folder(const std::filesystem::path& corpora_root);

}  // namespace cc::harness
