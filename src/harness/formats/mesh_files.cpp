#include "harness/formats/mesh_files.h"

#include <map>

#include "harness/formats/obj_file.h"

namespace cc::harness {

std::optional<std::filesystem::path> find_mesh_file(const std::string& as_written, const std::filesystem::path& case_dir) {
  const std::filesystem::path given(as_written);
  if (given.is_absolute()) return std::filesystem::exists(given) ? std::optional(given) : std::nullopt;
  std::error_code ec;
  // The real folders above the case (".." and symbolic links resolved), not the path as written.
  std::filesystem::path dir = std::filesystem::weakly_canonical(case_dir.empty() ? std::filesystem::path(".") : case_dir, ec);
  if (ec) dir = std::filesystem::absolute(case_dir, ec);
  for (int depth = 0; depth < 64 && !dir.empty(); ++depth) {
    if (std::filesystem::exists(dir / given)) return (dir / given).lexically_normal();
    if (dir == dir.parent_path()) break;
    dir = dir.parent_path();
  }
  if (std::filesystem::exists(given)) return given;
  return std::nullopt;
}

namespace {

std::map<std::filesystem::path, std::shared_ptr<const Mesh>>& loaded_meshes() {
  static std::map<std::filesystem::path, std::shared_ptr<const Mesh>> cache;
  return cache;
}

}  // namespace

std::shared_ptr<const Mesh> load_mesh_file(const std::filesystem::path& path) {
  auto& cache = loaded_meshes();
  std::error_code ec;
  const std::filesystem::path key = std::filesystem::weakly_canonical(path, ec);
  if (auto it = cache.find(key); it != cache.end()) return it->second;
  auto mesh = std::make_shared<const Mesh>(read_obj_file(path));
  cache.emplace(key, mesh);
  return mesh;
}

std::optional<std::filesystem::path> mesh_file_of(const Mesh& mesh) {
  for (const auto& [path, loaded] : loaded_meshes()) {
    if (loaded.get() == &mesh) return path;
  }
  return std::nullopt;
}

std::filesystem::path mesh_folder(const std::filesystem::path& corpora_root) { return corpora_root / "meshes"; }

}  // namespace cc::harness
