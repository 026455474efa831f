// Shrinking a case by the elements of its lists, before its values: a broadphase case loses
// boxes (a slot in every frame) and frames, a ray_mesh case the faces of its mesh (which is then
// written as triangles), by delta debugging: drop halves, then quarters, ... of what is left,
// while the case keeps its signature.
#pragma once

#include "harness/shrinking/shrink_faces.h"

namespace cc::harness {

/// Drops what it can through `attempt` (which updates the caller's current document to the
/// candidate it accepts). True if anything was dropped. Other kinds: nothing.
bool shrink_lists(const Json& current, const Input& input, const Attempt& attempt);

}  // namespace cc::harness
