#include "harness/judging/configurations.h"
#include "harness/model/kind_pieces.h"

namespace cc::harness {
namespace {

bool long_box(const Vec3& half) {
  double lo = INFINITY;
  for (int k = 0; k < 3; ++k) {
    if (half[k] > 0) lo = std::min(lo, half[k]);
  }
  return std::isfinite(lo) && max_abs(half) >= kFar * lo;
}

// Longest edge over height: 2^20 or more.
bool sliver(const Triangle& t) {
  const double area2 = length(normal(t)), e = longest_edge(t);
  return area2 > 0 && e * e >= kFar * area2;
}

}  // namespace

bool far_vertex_not_last(const Triangle& t, const Vec3& p) {
  const auto d = [&p](const Vec3& v) { return length(v - p); };
  return d(t.v[2]) < std::max(d(t.v[0]), d(t.v[1]));
}

void Configurations::add(std::string_view name, bool yes) {
  if (yes) names.push_back(name);
}

void Configurations::margins() {
  if (exact_.contract != Contract::in || !exact_.decided) return;
  add("touching", exact_.answer.hit && exact_.margin == 0);
  add("just apart", exact_.margin < 0 && exact_.margin >= -kJust);
  add("just overlapping", exact_.margin > 0 && exact_.margin <= kJust);
}

void Configurations::far(double largest, double size) { add("far from the origin", size > 0 && largest >= kFar * size); }

void Configurations::boxes(const Vec3& half) {
  add("flat box", zero_extents(half) == 1);
  add("segment box", zero_extents(half) == 2);
  add("point box", zero_extents(half) == 3);
  add("long box", long_box(half));
}

void Configurations::triangle(const Triangle& t) {
  add("segment triangle", is_segment(t));
  add("point triangle", is_point(t));
  add("sliver", sliver(t));
}

void Configurations::triangle_and_box(const Triangle& t, const Mat3& axes, const Vec3& c) {
  triangle(t);
  const Vec3 n = normal(t);
  bool in_plane = false, nearly_in_plane = false, nearly_along = false;
  for (const Vec3& a : axes.col) {
    in_plane |= parallel(n, a);
    nearly_in_plane |= nearly_parallel(n, a);
    for (int i = 0; i < 3; ++i) nearly_along |= nearly_parallel(edge(t, i), a);
  }
  add("in a face's plane", in_plane);
  add("nearly in a face's plane", nearly_in_plane);
  add("edge nearly parallel to an axis", nearly_along);
  add("far vertex not last", far_vertex_not_last(t, c));
}

void Configurations::axes_pair(const Mat3& a, const Mat3& b) {
  bool par = false, nearly = false;
  for (const Vec3& x : a.col) {
    for (const Vec3& y : b.col) par |= parallel(x, y), nearly |= nearly_parallel(x, y);
  }
  add("parallel axes", par);
  add("nearly parallel axes", nearly);
  add("frame at the tolerance", std::max(off_orthonormal(a), off_orthonormal(b)) >= kAtTheTolerance);
}

void Configurations::negative_parameters() {
  add("negative parameters",
      exact_.contract == Contract::in && exact_.answer.hit && !exact_.answer.params.empty() && exact_.answer.params[0] < 0);
}

std::vector<std::string_view> configurations_of(const Input& input, const ExactVerdict& exact) {
  Configurations found(exact);
  pieces_of(kind_of(input)).recognise(input, found);
  return std::move(found.names);
}

std::span<const std::string_view> expected_configurations(QueryKind kind) {
  return pieces_of(kind).configurations();
}

}  // namespace cc::harness
