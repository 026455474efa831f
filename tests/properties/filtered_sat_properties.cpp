// The filtered separating-axis test gives exact_sat's hit, rank and margin bit for bit on what
// the generators of tri_aabb, tri_obb and obb_obb make: touching at exact margins, parallel
// faces and edges, flat boxes, degenerate triangles, every scale. Each property also checks
// that it met both of the filter's outcomes (decided with a few axes taken exactly, and handed to
// exact_sat whole) and that the filter takes few of the up to 15 axes exactly: the one that
// gives the margin, and those near the decision.
#include <gtest/gtest.h>
#include <rapidcheck.h>

#include <bit>
#include <cstdio>
#include <cstdint>

#include "harness/formats/input_json.h"
#include "oracle/exact/exact_reference.h"
#include "oracle/exact/filtered_sat.h"
#include "properties/property.h"

namespace cc::test {
namespace {

using namespace harness;
using exact::SatInput;

bool finite(const SatInput& s) {
  if (const auto* t = std::get_if<Triangle>(&s)) {
    for (const Vec3& v : t->v) {
      if (!cc::finite(v)) return false;
    }
    return true;
  }
  if (const auto* b = std::get_if<Obb>(&s)) {
    return cc::finite(b->center) && cc::finite(b->half) && b->half.x >= 0 && b->half.y >= 0 && b->half.z >= 0 &&
           cc::finite(b->axes.col[0]) && cc::finite(b->axes.col[1]) && cc::finite(b->axes.col[2]);
  }
  const Aabb& box = std::get<Aabb>(s);
  return cc::finite(box.lo) && cc::finite(box.hi) && box.lo.x <= box.hi.x && box.lo.y <= box.hi.y && box.lo.z <= box.hi.z;
}

// The two shapes of a case in exact_sat's order (the box first), or nothing out of the domain.
std::optional<std::pair<SatInput, SatInput>> shapes_of(const Input& in) {
  std::pair<SatInput, SatInput> p;
  if (const auto* c = std::get_if<TriAabbInput>(&in)) p = {c->box, c->tri};
  if (const auto* c = std::get_if<TriObbInput>(&in)) p = {c->box, c->tri};
  if (const auto* c = std::get_if<ObbObbInput>(&in)) p = {c->a, c->b};
  if (!finite(p.first) || !finite(p.second)) return std::nullopt;
  return p;
}

void check_kind(QueryKind kind, int cases) {
  const exact::ExactRationalReference reference;
  Met met;
  const exact::SatFilterCounts before = exact::sat_filter_counts();
  long touching = 0;
  const bool passed = check_property(std::string(name(kind)) + ": the filtered SAT is exact_sat", kind, 10, cases, met,
                                     [&](const Input& in) {
    const auto shapes = shapes_of(in);
    if (!shapes) return;
    met.count(features_of(in, reference.judge(in)));
    const exact::TriangleSatVerdict got = exact::sat_verdict(shapes->first, shapes->second);
    const exact::SatResult expected =
        exact::exact_sat(exact::exact_shape(shapes->first, "A"), exact::exact_shape(shapes->second, "B"));
    touching += expected.hit && expected.rank == 3 && expected.margin == 0;
    if (got.hit != expected.hit || got.rank != expected.rank ||
        std::bit_cast<std::uint64_t>(got.margin) != std::bit_cast<std::uint64_t>(expected.margin)) {
      RC_FAIL(input_to_json(in).dump() + ": filtered hit " + std::to_string(got.hit) + " rank " + std::to_string(got.rank) +
              " margin " + std::to_string(got.margin) + ", exact_sat hit " + std::to_string(expected.hit) + " rank " +
              std::to_string(expected.rank) + " margin " + std::to_string(expected.margin));
    }
  });
  EXPECT_TRUE(passed);
  const exact::SatFilterCounts after = exact::sat_filter_counts();
  const long filtered = after.filtered - before.filtered, whole = after.whole - before.whole;
  // Decided by the filter for most cases; every outcome met.
  EXPECT_GT(filtered, 2 * whole) << name(kind);
  EXPECT_GT(whole, 0) << name(kind) << ": never handed to exact_sat whole";
  const double axes_per_case = static_cast<double>(after.exact_axes - before.exact_axes) / static_cast<double>(filtered);
  std::printf("%s: %ld cases filtered, %ld whole, %.2f axes taken exactly per filtered case\n", std::string(name(kind)).c_str(),
              filtered, whole, axes_per_case);
  EXPECT_GE(axes_per_case, 1.0) << name(kind) << ": most margins need their axis taken exactly";
  EXPECT_LT(axes_per_case, 4.0) << name(kind);  // of up to 15: the margin's, ties, gaps near 0
  EXPECT_GT(touching, 0) << name(kind) << ": never met shapes that touch";
  expect_met_the_boundary(std::string(name(kind)) + ": the filtered SAT is exact_sat", kind, met);
}

TEST(FilteredSat, IsExactSatOnBoxesAndTriangles) { check_kind(QueryKind::tri_aabb, 1500); }
TEST(FilteredSat, IsExactSatOnBoxesAndRotatedTriangles) { check_kind(QueryKind::tri_obb, 1500); }
TEST(FilteredSat, IsExactSatOnPairsOfBoxes) { check_kind(QueryKind::obb_obb, 1500); }

}  // namespace
}  // namespace cc::test
