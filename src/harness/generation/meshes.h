// Meshes for the generators (meshes.cpp): procedural recipes and the library's hierarchies.
#pragma once

#include "collide/procedural_mesh.h"
#include "harness/generation/choices.h"
#include "harness/model/mesh_query.h"

namespace cc::harness {

/// A hierarchy for the library: any volume, build and walk; with `few`, one of a few per volume
/// type (for FCL's big meshes, so that the campaign's workers build each once).
LibraryBvh draw_library(Choices& choices, bool few);
/// A procedural mesh of about the given size.
ProceduralMesh draw_recipe(Choices& choices, double size);

}  // namespace cc::harness
