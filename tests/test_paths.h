// Where tests find the project's files, whatever the directory they run in.
#pragma once

#include <filesystem>

namespace cc::test {

/// FCL's test meshes in the source tree (the campaign's default mesh folder).
inline std::filesystem::path fcl_mesh_folder() { return std::filesystem::path(CROSSCHECK_SOURCE_DIR) / "corpora" / "meshes"; }

/// A folder below the corpus root, from which case files' "meshes/env.obj" is found.
inline std::filesystem::path corpus_case_folder() { return std::filesystem::path(CROSSCHECK_SOURCE_DIR) / "corpora" / "mesh_mesh"; }

}  // namespace cc::test
