#include "oracle/exact/exact_polytopes.h"

#include <algorithm>

#include "oracle/exact/domain.h"

namespace cc::exact {

using harness::ExactVerdict;

ExactVerdict verdict_of(const SatResult& r, double magnitude) {
  return verdict_of(TriangleSatVerdict{r.hit, r.rank, r.margin}, magnitude);
}

ExactVerdict verdict_of(const TriangleSatVerdict& r, double magnitude) {
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

}  // namespace cc::exact
