// obb_obb, tri_aabb, tri_obb and tri_tri in exact arithmetic, through the exact separating-axis
// test of convex_sat.h. A box is the parallelepiped its matrix spans (its face normals are
// cross products of its columns), so the reference needs no orthonormality.
#include "oracle/exact/convex_sat.h"
#include "oracle/exact/domain.h"
#include "oracle/exact/judges.h"

namespace cc::exact {
namespace {

constexpr int kObbMinExponent = -500, kObbMaxExponent = 500;
constexpr int kTriangleMinExponent = -300, kTriangleMaxExponent = 300;

ExactVerdict verdict_of(const SatResult& r, double magnitude) {
  ExactVerdict v;
  v.answer.hit = r.hit;
  v.margin = r.margin / scale_of(magnitude);
  return v;
}

double magnitude_of(const Triangle& t) { return std::max({max_abs(t.v[0]), max_abs(t.v[1]), max_abs(t.v[2])}); }
double magnitude_of(const Obb& b) { return std::max(max_abs(b.center), max_abs(b.half)); }
double magnitude_of(const Aabb& b) { return std::max(max_abs(b.lo), max_abs(b.hi)); }

std::optional<ExactVerdict> obb_outside_domain(const Obb& b) {
  if (!all_finite(b)) return documented(false, "NaN or infinite input");
  if (b.half.x < 0 || b.half.y < 0 || b.half.z < 0) return documented(false, "negative half extent");
  return std::nullopt;
}

ExactShape shape_of(const Obb& b, const std::string& name) { return parallelepiped_shape(b.center, b.half, b.axes, name); }
ExactShape shape_of(const Triangle& t, const std::string& name) { return triangle_shape(t.v[0], t.v[1], t.v[2], name); }

}  // namespace

std::optional<std::pair<ExactShape, ExactShape>> polytopes_of(const harness::Input& input) {
  if (const auto* in = std::get_if<harness::ObbObbInput>(&input)) return std::pair{shape_of(in->a, "A"), shape_of(in->b, "B")};
  if (const auto* in = std::get_if<harness::TriAabbInput>(&input)) {
    return std::pair{box_shape(in->box.lo, in->box.hi, "B"), shape_of(in->tri, "T")};
  }
  if (const auto* in = std::get_if<harness::TriObbInput>(&input)) return std::pair{shape_of(in->box, "B"), shape_of(in->tri, "T")};
  if (const auto* in = std::get_if<harness::TriTriInput>(&input)) return std::pair{shape_of(in->a, "A"), shape_of(in->b, "B")};
  return std::nullopt;
}

ExactVerdict judge(const harness::ObbObbInput& in) {
  for (const Obb* b : {&in.a, &in.b}) {
    if (auto out = obb_outside_domain(*b)) return *out;
  }
  const double magnitude = std::max(magnitude_of(in.a), magnitude_of(in.b));
  if (auto why = scale_outside(magnitude, kObbMinExponent, kObbMaxExponent)) return unspecified(*why);
  for (const Obb* b : {&in.a, &in.b}) {
    if (auto why = not_orthonormal(b->axes)) return unspecified(*why);
  }
  return verdict_of(exact_sat(shape_of(in.a, "A"), shape_of(in.b, "B")), magnitude);
}

ExactVerdict judge(const harness::TriAabbInput& in) {
  if (!all_finite(in.tri) || !all_finite({in.box.lo.x, in.box.lo.y, in.box.lo.z, in.box.hi.x, in.box.hi.y, in.box.hi.z})) {
    return documented(false, "NaN or infinite input");
  }
  for (int k = 0; k < 3; ++k) {
    if (in.box.lo[k] > in.box.hi[k]) return documented(false, "inverted box");
  }
  const double magnitude = std::max(magnitude_of(in.tri), magnitude_of(in.box));
  if (auto why = scale_outside(magnitude, kTriangleMinExponent, kTriangleMaxExponent)) return unspecified(*why);
  return verdict_of(exact_sat(box_shape(in.box.lo, in.box.hi, "B"), shape_of(in.tri, "T")), magnitude);
}

ExactVerdict judge(const harness::TriObbInput& in) {
  if (!all_finite(in.tri)) return documented(false, "NaN or infinite input");
  if (auto out = obb_outside_domain(in.box)) return *out;
  const double magnitude = std::max(magnitude_of(in.tri), magnitude_of(in.box));
  if (auto why = scale_outside(magnitude, kTriangleMinExponent, kTriangleMaxExponent)) return unspecified(*why);
  if (auto why = not_orthonormal(in.box.axes)) return unspecified(*why);
  return verdict_of(exact_sat(shape_of(in.box, "B"), shape_of(in.tri, "T")), magnitude);
}

ExactVerdict judge(const harness::TriTriInput& in) {
  if (!all_finite(in.a) || !all_finite(in.b)) return documented(false, "NaN or infinite input");
  const double magnitude = std::max(magnitude_of(in.a), magnitude_of(in.b));
  if (auto why = scale_outside(magnitude, kTriangleMinExponent, kTriangleMaxExponent)) return unspecified(*why);
  return verdict_of(exact_sat(shape_of(in.a, "A"), shape_of(in.b, "B")), magnitude);
}

}  // namespace cc::exact
