// Shrinking two placed meshes by their faces, before the values: the meshes become lists of
// triangles, first only those named by a pair the parties dispute, then fewer by delta debugging
// (drop halves, then quarters, ... of what is left, while the case keeps its signature).
#pragma once

#include <functional>
#include <string>

#include "harness/formats/input_json.h"
#include "harness/judging/evaluate.h"

namespace cc::harness {

/// Tries a candidate document; on success the caller's current document becomes it.
using Attempt = std::function<bool(const Json&)>;

/// Drops faces of `meshes` (at `pointer` in the document `current`; the case's evaluation is
/// `start`, its answers a first hit or all pairs) through `attempt`, which updates `current`.
/// True if any face was dropped (the meshes are then written as "triangles").
bool shrink_faces(const Json& current, const std::string& pointer, const MeshPair& meshes, bool first_hit,
                  const Evaluation& start, const Attempt& attempt);

/// The faces of mesh a (`second` false) or b named by a pair that some party lists and the
/// exact reference does not, or the other way round (for a first hit: a pair it names that is
/// not exact, or every exact pair when it names none); failing that, by the exact pair nearest
/// contact. Sorted, without repeats.
std::vector<std::uint32_t> disputed_faces(const Evaluation& e, bool first_hit, bool second);

}  // namespace cc::harness
