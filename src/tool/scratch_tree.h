// Scratch copies of the source tree, kept in step with it file by file so that builds in them
// stay incremental.
#pragma once

#include <filesystem>

namespace cc::tool {

/// What sync_tree changed.
struct SyncCounts {
  int created = 0, updated = 0, removed = 0;
};

/// Makes `copy` hold the same files as `source`, leaving out the top-level build/ and .git/ and
/// corpora/new/. A file new in the copy keeps the source's modification time (so a fresh copy
/// looks as old as its source); a file whose content differs is rewritten and gets the current
/// time (newer than any build output made from its old content); an identical file is not
/// touched; a file the source no longer has is removed. Throws std::runtime_error naming the
/// file on failure, or when `copy` lies inside `source` outside the parts left out.
SyncCounts sync_tree(const std::filesystem::path& source, const std::filesystem::path& copy);

}  // namespace cc::tool
