// Shrinking a case by the elements of its lists, before its values, by delta debugging (drop
// halves, then quarters, ... of what is left, while the case keeps its signature): boxes over
// frames lose boxes (a slot in every frame), then frames; a mesh loses faces (and is then
// written as triangles); a list of parts (a maze's walls) loses parts.
#pragma once

#include <string>

#include "harness/model/parts.h"
#include "harness/shrinking/shrink_faces.h"

namespace cc::harness {

/// Drops boxes, then frames, of the frames at `pointer` in the document `current`, through
/// `attempt` (which updates `current` to the candidate it accepts). True if any was dropped.
bool shrink_box_frames(const Json& current, const std::string& pointer, const BoxFrames& frames, const Attempt& attempt);

/// Drops parts of the list of `size` parts at `pointer` likewise (at least one stays). True if
/// any was dropped.
bool shrink_list(const Json& current, const std::string& pointer, std::size_t size, const Attempt& attempt);

/// Drops faces of the mesh at `pointer` likewise. True if any was dropped.
bool shrink_mesh_faces(const Json& current, const std::string& pointer, const MeshRef& mesh, const Attempt& attempt);

}  // namespace cc::harness
