// Meshes for the generators: procedural recipes and the library's hierarchies.
#include "harness/generation/meshes.h"

#include <cmath>
#include <tuple>
#include <utility>

namespace cc::harness {

// Any hierarchy; for FCL's meshes (`few`), one of a few per volume type, so that the campaign's
// workers build each once and reuse it over thousands of poses.
LibraryBvh draw_library(Choices& c, bool few) {
  LibraryBvh l;
  l.bv = kAllBvTypes[c.draw(std::size(kAllBvTypes))];
  l.build.strategy = static_cast<BuildStrategy>(c.draw(4));
  if (few) {
    constexpr std::pair<SplitAxis, SplitPoint> kRules[] = {{SplitAxis::longest_side, SplitPoint::midpoint},
                                                           {SplitAxis::splatter, SplitPoint::mean},
                                                           {SplitAxis::min_sum, SplitPoint::median}};
    std::tie(l.build.axis, l.build.point) = kRules[c.draw(3)];
    l.build.leaf_size = l.bv == BvType::obb ? 1 : 4;
  } else {
    l.build.axis = static_cast<SplitAxis>(c.draw(4));
    l.build.point = static_cast<SplitPoint>(c.draw(3));
    l.build.leaf_size = 1 + static_cast<int>(c.draw(4));
  }
  constexpr BvUpdate kUpdates[] = {BvUpdate::approximate, BvUpdate::exact, BvUpdate::hill_climbing};
  l.update = kUpdates[c.draw(3)];
  l.descent = c.chance(50) ? Descent::larger : Descent::first_model;
  return l;
}

ProceduralMesh draw_recipe(Choices& c, double size) {
  ProceduralMesh r;
  r.shape = static_cast<ProceduralMesh::Shape>(c.draw(5));
  r.seed = c.draw(1000);
  r.resolution = 2 + static_cast<int>(c.draw(10));
  r.size = size;
  r.thickness = c.chance(50) ? 0.0 : size * std::ldexp(1.0, -static_cast<int>(c.draw(30)));
  r.degenerate_percent = c.chance(30) ? static_cast<int>(c.draw(40)) : 0;
  return r;
}

}  // namespace cc::harness
