// The aabb_aabb kind: boxes touching on 1 to 3 axes (a face, an edge, a corner) exactly or a few
// ULPs off, identical boxes, a point of one box's boundary as the other; the library's call, and
// what its cases are.
#include "harness/kinds/aabb_aabb.h"

#include <tuple>
#include <utility>

#include "harness/generation/shapes.h"
#include "harness/generation/touch.h"
#include "harness/judging/configurations.h"
#include "harness/judging/features.h"

namespace cc::harness {
namespace {

// Places [lo, hi] on one axis relative to [a_lo, a_hi]: touching above or below, overlapping,
// or (with `nudged`) a few ULPs away from touching.
std::pair<double, double> place_on_axis(ValueSource& v, double a_lo, double a_hi, bool touch, bool nudged) {
  const double len = v.length();
  if (touch) {
    if (v.choices().chance(50)) {
      const double lo = nudged ? v.nudge(a_hi) : a_hi;
      return {lo, lo + len};
    }
    const double hi = nudged ? v.nudge(a_lo) : a_lo;
    return {hi - len, hi};
  }
  const double anchors[] = {a_lo, a_hi, 0.5 * (a_lo + a_hi)};
  const double lo = anchors[v.choices().draw(3)] - (v.choices().chance(50) ? 0.0 : len);
  return {lo, lo + v.length()};
}

constexpr std::string_view kConfigurations[] = {"touching", "flat box", "point box", "identical"};

}  // namespace

Answer Query<AabbAabbInput>::ask(const AabbAabbInput& in) { return Answer::of(test_aabb_aabb(in.a, in.b)); }

AabbAabbInput Query<AabbAabbInput>::generate(ValueSource& v, const GenerateOptions& options) {
  AabbAabbInput in;
  in.a = draw_aabb(v, options);
  switch (v.choices().draw(5)) {
    case 0: in.b = draw_aabb(v, options); break;
    case 1:
    case 2: {  // touching on 1 to 3 axes (face, edge, corner), exactly or a few ULPs off
      const bool nudged = v.choices().chance(30);
      const auto touching = 1 + v.choices().draw(3);
      const auto first = v.choices().draw(3);
      for (std::uint64_t i = 0; i < 3; ++i) {
        const int k = static_cast<int>((first + i) % 3);
        std::tie(in.b.lo[k], in.b.hi[k]) = place_on_axis(v, in.a.lo[k], in.a.hi[k], i < touching, nudged);
      }
      break;
    }
    case 3: in.b = in.a; break;
    default: {  // a point of A's boundary, or a point nudged off it
      const Vec3 p = draw_boundary_point(v, in.a);
      in.b = {p, p};
      if (v.choices().chance(50)) {
        const int k = static_cast<int>(v.choices().draw(3));
        in.b.lo[k] = in.b.hi[k] = v.nudge(p[k]);
      }
    }
  }
  if (v.choices().chance(50)) std::swap(in.a, in.b);
  return in;
}

void Query<AabbAabbInput>::touch(AabbAabbInput& in, ValueSource& v) { put_face_to_face(in.a, in.b, v.choices()); }

Features Query<AabbAabbInput>::features(const AabbAabbInput& in) {
  Features f;
  for (int k = 0; k < 3; ++k) {
    f.parallel |= in.a.lo[k] == in.b.hi[k] || in.a.hi[k] == in.b.lo[k] || in.a.lo[k] == in.b.lo[k] ||
                  in.a.hi[k] == in.b.hi[k];
  }
  f.degenerate = zero_extent(in.a) || zero_extent(in.b);
  return f;
}

std::span<const std::string_view> Query<AabbAabbInput>::configurations() { return kConfigurations; }

void Query<AabbAabbInput>::recognise(const AabbAabbInput& in, Configurations& found) {
  found.margins();
  found.add("flat box", zero_extents(in.a.hi - in.a.lo) > 0 || zero_extents(in.b.hi - in.b.lo) > 0);
  found.add("point box", zero_extents(in.a.hi - in.a.lo) == 3 || zero_extents(in.b.hi - in.b.lo) == 3);
  found.add("identical", in.a == in.b);
}

std::span<const BoundTerm> Query<AabbAabbInput>::bound_terms() { return {}; }

void Query<AabbAabbInput>::probe(const AabbAabbInput&, std::vector<bounds::Records>&) {}

}  // namespace cc::harness
