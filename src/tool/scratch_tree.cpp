#include "tool/scratch_tree.h"

#include <set>
#include <stdexcept>
#include <string>

#include "tool/mutant_catalogue.h"

namespace cc::tool {
namespace {

namespace fs = std::filesystem;

bool left_out(const fs::path& relative) {
  const std::string s = relative.generic_string();
  return s == "build" || s == ".git" || s == "corpora/new";
}

// Every regular file under root (relative paths), not descending into the parts left out.
std::set<fs::path> files_under(const fs::path& root) {
  std::set<fs::path> out;
  if (!fs::exists(root)) return out;
  for (auto it = fs::recursive_directory_iterator(root); it != fs::recursive_directory_iterator(); ++it) {
    const fs::path relative = fs::relative(it->path(), root);
    if (it->is_directory() && left_out(relative)) {
      it.disable_recursion_pending();
      continue;
    }
    if (it->is_regular_file()) out.insert(relative);
  }
  return out;
}

}  // namespace

SyncCounts sync_tree(const fs::path& source_in, const fs::path& copy_in) {
  const fs::path source = fs::weakly_canonical(source_in), copy = fs::weakly_canonical(copy_in);
  const fs::path inside = copy.lexically_relative(source);
  if (!inside.empty() && *inside.begin() != ".." && !left_out(*inside.begin()) &&
      inside.generic_string().rfind("corpora/new", 0) != 0) {
    throw std::runtime_error(copy.string() + ": a scratch copy inside the source tree must be under its build/");
  }
  SyncCounts counts;
  const std::set<fs::path> wanted = files_under(source);
  for (const fs::path& relative : wanted) {
    const fs::path from = source / relative, to = copy / relative;
    if (!fs::exists(to)) {
      fs::create_directories(to.parent_path());
      fs::copy_file(from, to);
      fs::last_write_time(to, fs::last_write_time(from));
      fs::permissions(to, fs::status(from).permissions());
      ++counts.created;
      continue;
    }
    if (fs::file_size(from) == fs::file_size(to)) {
      if (read_text(from) == read_text(to)) continue;
    }
    write_text(to, read_text(from));  // a new modification time: rebuilt from its new content
    fs::permissions(to, fs::status(from).permissions());
    ++counts.updated;
  }
  for (const fs::path& relative : files_under(copy)) {
    if (!wanted.count(relative)) {
      fs::remove(copy / relative);
      ++counts.removed;
    }
  }
  return counts;
}

}  // namespace cc::tool
