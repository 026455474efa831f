#include "harness/judging/features.h"
#include "harness/model/kind_pieces.h"

namespace cc::harness {

Features features_of(const Input& input, const ExactVerdict& exact) {
  Features f = pieces_of(kind_of(input)).features(input);
  f.touching = exact.contract == Contract::in && exact.decided && exact.answer.hit && exact.margin == 0;
  return f;
}

bool parallel_applies(QueryKind kind) {
  return pieces_of(kind).parallel_applies;
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
