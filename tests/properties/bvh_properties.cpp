// Properties of the hierarchies and their traversal, on generated mesh queries (FCL's meshes at
// FCL's poses, near contact and touching at vertices; procedural meshes with degenerate faces):
//  - the pair set does not depend on the volume type, build, split rule, update or descent, and
//    is brute force's, except pairs apart by less than the band that a volume test may prune;
//  - swapping the meshes transposes the pairs (up to pairs within the band: the other mesh
//    moves then, with other roundings);
//  - a first hit is a pair of the all-pairs set, and there is one exactly when that set is not
//    empty;
//  - every volume is conservative in exact arithmetic: each node's volume holds its triangles,
//    and each moved volume (both updates) holds the node's triangles as the leaf test sees
//    them moved.
#include <gtest/gtest.h>
#include <rapidcheck.h>

#include <algorithm>
#include <cmath>

#include "harness/judging/bands.h"
#include "harness/judging/features.h"
#include "harness/formats/input_json.h"
#include "harness/model/mesh_collide.h"
#include "harness/generation/mesh_poses.h"
#include "collide/procedural_mesh.h"
#include "oracle/exact/exact_meshes.h"
#include "oracle/exact/rational.h"
#include "properties/property.h"

namespace cc::test {
namespace {

using namespace harness;
using exact::QVec3;
using exact::rational;
using Pairs = std::vector<std::pair<std::uint32_t, std::uint32_t>>;

const double kBand = library_band(QueryKind::mesh_mesh).width;

std::vector<LibraryBvh> hierarchies() {
  std::vector<LibraryBvh> out;
  for (BvType bv : kAllBvTypes) {
    for (BuildStrategy s : {BuildStrategy::top_down, BuildStrategy::bottom_up, BuildStrategy::incremental,
                            BuildStrategy::lazy_top_down}) {
      LibraryBvh l;
      l.bv = bv, l.build.strategy = s;
      l.update = s == BuildStrategy::bottom_up ? BvUpdate::exact : BvUpdate::approximate;
      l.descent = s == BuildStrategy::incremental ? Descent::larger : Descent::first_model;
      out.push_back(l);
    }
    LibraryBvh l;  // a top-down variant per volume type: another split rule, a few per leaf
    l.bv = bv;
    l.build = {BuildStrategy::top_down, static_cast<SplitAxis>(static_cast<int>(bv) % 4),
               static_cast<SplitPoint>(static_cast<int>(bv) % 3), 1 + static_cast<int>(bv) % 4};
    out.push_back(l);
  }
  return out;
}

std::string describe(const LibraryBvh& l) {
  return std::string(to_string(l.bv)) + " " + std::string(to_string(l.build.strategy)) + " " +
         std::string(to_string(l.build.axis)) + " " + std::string(to_string(l.build.point)) + " leaf " +
         std::to_string(l.build.leaf_size) + " " + std::string(to_string(l.update)) + " " +
         std::string(to_string(l.descent));
}

// Each pair of `found` is in `all`, and each pair of `all` missing from `found` is apart by
// less than the band (exact margin in (-band, 0)).
void expect_brute_force_up_to_band(const Pairs& found, const Pairs& all, const ExactVerdict& v, const std::string& what) {
  for (const auto& p : found) {
    if (!std::binary_search(all.begin(), all.end(), p)) {
      RC_FAIL(what + ": pair (" + std::to_string(p.first) + ", " + std::to_string(p.second) + ") not brute force's");
    }
  }
  for (const auto& p : all) {
    if (std::binary_search(found.begin(), found.end(), p)) continue;
    const double margin = v.margin_of({p.first, p.second});
    if (!(margin < 0 && margin > -kBand)) {
      RC_FAIL(what + ": missed pair (" + std::to_string(p.first) + ", " + std::to_string(p.second) +
              ") at exact margin " + std::to_string(margin));
    }
  }
}

// The exact verdict on a generated mesh query, counted in `met`; inputs outside the library's
// domain, or that the reference cannot decide, are discarded.
ExactVerdict judged(const Input& input, Met& met) {
  RC_PRE(!exact::meshes_outside_domain(*meshes_of(input)));
  const ExactVerdict v = exact::judge_meshes(*meshes_of(input));
  RC_PRE(v.decided);
  met.count(features_of(input, v));
  return v;
}

TEST(BvhProperties, ThePairsAreBruteForcesWhateverTheHierarchy) {
  Met met;
  const std::string property = "every hierarchy finds brute force's pairs";
  const bool passed = check_property(property, QueryKind::mesh_mesh, 0, 40, met, [&](const Input& input) {
    const ExactVerdict v = judged(input, met);
    const MeshPair& m = *meshes_of(input);
    const Pairs all = collide_brute_force(*m.a.mesh, m.pose_a, *m.b.mesh, m.pose_b);
    for (const LibraryBvh& l : hierarchies()) {
      MeshPair with = m;
      with.library = l;
      expect_brute_force_up_to_band(library_collide(with, CollisionMode::all_pairs).pairs, all, v, describe(l));
    }
  });
  EXPECT_TRUE(passed);
  expect_met_the_boundary(property, QueryKind::mesh_mesh, met);
}

TEST(BvhProperties, LazyTreesAnswerAsTheEagerOnes) {
  Met met;
  const std::string property = "a lazy top-down tree answers as the eager one";
  const bool passed = check_property(property, QueryKind::mesh_mesh, 0, 40, met, [&](const Input& input) {
    const ExactVerdict v = judged(input, met);
    const MeshPair& m = *meshes_of(input);
    for (BvType bv : kAllBvTypes) {
      for (BvUpdate update : {BvUpdate::approximate, BvUpdate::exact}) {
        MeshPair eager = m, lazy = m;
        eager.library = m.library, eager.library.bv = bv, eager.library.update = update;
        eager.library.build.strategy = BuildStrategy::top_down;
        lazy.library = eager.library;
        lazy.library.build.strategy = BuildStrategy::lazy_top_down;
        for (CollisionMode mode : {CollisionMode::all_pairs, CollisionMode::first_hit}) {
          const CollisionResult e = library_collide(eager, mode), l = library_collide(lazy, mode);
          if (!moved_whole(bv)) {  // Aabb and k-DOP trees: the same nodes, the same walk
            RC_ASSERT(l.pairs == e.pairs);
            // (The lazy trees keep no hull points: their exact updates move every vertex.)
            RC_ASSERT(l.counters.bv_tests == e.counters.bv_tests);
            RC_ASSERT(l.counters.primitive_tests == e.counters.primitive_tests);
            RC_ASSERT(l.counters.bv_updates == e.counters.bv_updates);
          } else if (mode == CollisionMode::all_pairs) {  // lazily fitted volumes: up to the band
            Pairs differ;
            std::set_symmetric_difference(e.pairs.begin(), e.pairs.end(), l.pairs.begin(), l.pairs.end(),
                                          std::back_inserter(differ));
            for (const auto& p : differ) RC_ASSERT(std::fabs(v.margin_of({p.first, p.second})) < kBand);
          }
        }
      }
    }
  });
  EXPECT_TRUE(passed);
  expect_met_the_boundary(property, QueryKind::mesh_mesh, met);
}

TEST(BvhProperties, SwappingTheMeshesTransposesThePairs) {
  Met met;
  const std::string property = "swapping the meshes transposes the pairs";
  const bool passed = check_property(property, QueryKind::mesh_mesh, 0, 40, met, [&](const Input& input) {
    const ExactVerdict v = judged(input, met);
    const MeshPair& m = *meshes_of(input);
    MeshPair swapped = m;
    std::swap(swapped.a, swapped.b);
    std::swap(swapped.pose_a, swapped.pose_b);
    Pairs back;
    for (const auto& [b, a] : library_collide(swapped, CollisionMode::all_pairs).pairs) back.emplace_back(a, b);
    std::sort(back.begin(), back.end());
    const Pairs forward = library_collide(m, CollisionMode::all_pairs).pairs;
    Pairs differ;
    std::set_symmetric_difference(forward.begin(), forward.end(), back.begin(), back.end(), std::back_inserter(differ));
    for (const auto& p : differ) {
      const double margin = v.margin_of({p.first, p.second});
      RC_ASSERT(std::fabs(margin) < kBand);
    }
  });
  EXPECT_TRUE(passed);
  expect_met_the_boundary(property, QueryKind::mesh_mesh, met);
}

TEST(BvhProperties, AFirstHitIsOneOfAllThePairs) {
  Met met;
  const std::string property = "a first hit is one of all the pairs";
  const bool passed = check_property(property, QueryKind::mesh_mesh_first, 0, 150, met, [&](const Input& input) {
    judged(input, met);
    const MeshPair& m = *meshes_of(input);
    const Pairs first = library_collide(m, CollisionMode::first_hit).pairs;
    const Pairs all = library_collide(m, CollisionMode::all_pairs).pairs;
    RC_ASSERT(first.size() <= 1u);
    RC_ASSERT(first.empty() == all.empty());
    if (!first.empty()) RC_ASSERT(std::binary_search(all.begin(), all.end(), first[0]));
  });
  EXPECT_TRUE(passed);
  expect_met_the_boundary(property, QueryKind::mesh_mesh_first, met);
}

// Whether a volume holds a point, exactly. An OBB holds what projects onto each of its axes
// within its half extent of its centre's projection (as the separating-axis tests see it).
bool holds(const Aabb& b, const QVec3& p) {
  for (int i = 0; i < 3; ++i) {
    if (p[i] < rational(b.lo[i]) || p[i] > rational(b.hi[i])) return false;
  }
  return true;
}
bool holds(const Obb& b, const QVec3& p) {
  const QVec3 d = p - rational(b.center);
  for (int k = 0; k < 3; ++k) {
    if (abs(dot(rational(b.axes.col[k]), d)) > rational(b.half[k])) return false;
  }
  return true;
}
bool holds(const Sphere& b, const QVec3& p) {
  const QVec3 d = p - rational(b.center);
  return dot(d, d) <= rational(b.radius) * rational(b.radius);
}
template <int K>
bool holds(const Kdop<K>& d, const QVec3& p) {
  const auto dirs = kdop_directions<K>();
  for (int i = 0; i < K / 2; ++i) {
    const exact::Rational s = dirs[i].x * p.x + dirs[i].y * p.y + dirs[i].z * p.z;
    if (s < rational(d.lo[i]) || s > rational(d.hi[i])) return false;
  }
  return true;
}

struct Conservative {
  int flat = 0, degenerate = 0, cases = 0;
};

template <class BV>
void expect_conservative(const Mesh& mesh, const BuildOptions& build, const RigidTransform& t) {
  const Bvh<BV> bvh = build_bvh<BV>(mesh, build);
  for (std::size_t n = 0; n < bvh.nodes.size(); ++n) {
    const BvhNode<BV>& node = bvh.nodes[n];
    const BV moved[2] = {moved_volume(bvh, n, t, BvUpdate::approximate), moved_volume(bvh, n, t, BvUpdate::exact)};
    for (std::uint32_t s = node.first; s < node.first + node.count; ++s) {
      for (const Vec3& v : bvh.triangle(s).v) {
        if (!holds(node.bv, rational(v))) RC_FAIL("node " + std::to_string(n) + " does not hold its triangle in slot " + std::to_string(s));
        const QVec3 as_seen = rational(apply(t, v));  // moved as the leaf test moves it
        for (int u = 0; u < 2; ++u) {
          if (!holds(moved[u], as_seen)) {
            RC_FAIL("the " + std::string(u ? "exact" : "approximate") + " moved volume of node " + std::to_string(n) +
                    " does not hold its triangle in slot " + std::to_string(s));
          }
        }
      }
    }
  }
}

TEST(BvhProperties, EveryVolumeHoldsItsTrianglesExactly) {
  Conservative met;
  const bool passed = check_property_with_choices("every volume holds its triangles exactly", 60, [&](Choices& c) {
    ProceduralMesh recipe;
    recipe.shape = static_cast<ProceduralMesh::Shape>(c.draw(5));
    recipe.seed = c.draw(1000);
    recipe.resolution = 2 + static_cast<int>(c.draw(7));
    recipe.size = std::ldexp(1.0, static_cast<int>(c.draw(41)) - 20);
    recipe.thickness = c.chance(50) ? 0.0 : recipe.size * std::ldexp(1.0, -static_cast<int>(c.draw(40)));
    recipe.degenerate_percent = c.chance(40) ? static_cast<int>(c.draw(60)) : 0;
    const Mesh mesh = make_mesh(recipe);
    ++met.cases;
    met.flat += recipe.shape == ProceduralMesh::Shape::plate && recipe.thickness == 0;
    met.degenerate += recipe.degenerate_percent > 0;
    RigidTransform t = fcl_style_pose(c);
    t.translation = std::ldexp(1.0, static_cast<int>(c.draw(21)) - 10) * t.translation;
    BuildOptions build;
    build.strategy = static_cast<BuildStrategy>(c.draw(3));
    build.axis = static_cast<SplitAxis>(c.draw(4));
    build.point = static_cast<SplitPoint>(c.draw(3));
    build.leaf_size = 1 + static_cast<int>(c.draw(4));
    build.hull_points = c.chance(50);  // the exact update moves them, or else every vertex
    with_bv_type(kAllBvTypes[c.draw(std::size(kAllBvTypes))],
                 [&]<class BV>() { expect_conservative<BV>(mesh, build, t); });
  });
  EXPECT_TRUE(passed);
  EXPECT_GT(met.flat, met.cases / 20) << "flat meshes";
  EXPECT_GT(met.degenerate, met.cases / 5) << "meshes with degenerate faces";
}

}  // namespace
}  // namespace cc::test
