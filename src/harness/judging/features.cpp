#include "harness/judging/features.h"

namespace cc::harness {

Features features_of(const Input& input, const ExactVerdict& exact) {
  Features f = std::visit([]<class In>(const In& in) { return Query<In>::features(in); }, input);
  f.touching = exact.contract == Contract::in && exact.decided && exact.answer.hit && exact.margin == 0;
  return f;
}

bool parallel_applies(QueryKind kind) {
  return with_kind(kind, []<class In>() { return Query<In>::parallel_applies; });
}

Features obb_pair_features(const Obb& a, const Obb& b) {
  Features f;
  for (const Vec3& x : a.axes.col) {
    for (const Vec3& y : b.axes.col) f.parallel |= parallel(x, y);
  }
  f.degenerate = a.half.x == 0 || a.half.y == 0 || a.half.z == 0 || b.half.x == 0 || b.half.y == 0 || b.half.z == 0;
  return f;
}

}  // namespace cc::harness
