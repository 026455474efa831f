// The kdop_kdop kind: clusters of points, sets sharing a point or repeating the other, sets
// shifted to touch on one slab (exactly when the sums are), clusters far from the origin where
// projections cancel; every direction set. The library's call, and what its cases are.
#include "harness/kinds/kdop_kdop.h"

#include <cmath>

#include "collide/kdop.h"
#include "collide/kdop_bound.h"
#include "collide/record_sink.h"
#include "harness/generation/regimes.h"
#include "harness/generation/shapes.h"
#include "harness/judging/configurations.h"
#include "harness/judging/features.h"

namespace cc::harness {
namespace {

constexpr int kKs[] = {18, 6, 14, 16, 24, 26};

// Two point sets at an exact margin in the regimes of fit_kdop's bound: clusters far from the
// origin compared with their spread (where 2- and 3-term projections cancel), spreads up to 2^40
// apart; b slid from a's centre along a slab's direction or any.
KdopKdopInput kdops_at_the_bound(ValueSource& v, const GenerateOptions& options) {
  Choices& c = v.choices();
  KdopKdopInput in;
  in.k = kKs[c.draw(6)];
  const double size = draw_size(v);
  const Vec3 offset = draw_far_offset(v, size);
  const Vec3 center = v.point() + offset;
  const auto cluster = [&](double spread) {
    std::vector<Vec3> points;
    const auto n = 1 + c.draw(6);
    for (std::uint64_t i = 0; i < n; ++i) {
      const Vec3 direction = draw_direction(v);
      points.push_back(center + std::ldexp(spread, -static_cast<int>(c.draw(41))) * direction);
    }
    return points;
  };
  in.a = cluster(size);
  const std::vector<Vec3> b = cluster(std::ldexp(size, v.small_int(20)));
  const auto dirs = kdop_directions(in.k);
  Vec3 w = draw_direction(v);
  if (c.chance(60)) {
    const KdopDirection d = dirs[c.draw(dirs.size())];
    w = {static_cast<double>(d.x), static_cast<double>(d.y), static_cast<double>(d.z)};
  }
  double reach = 0;
  for (const Vec3& p : in.a) reach = std::max(reach, std::fabs(dot(p - center, w)));
  for (const Vec3& p : b) reach = std::max(reach, std::fabs(dot(p - center, w)));
  const auto placed = [&in, &b, &w](double s) {
    KdopKdopInput out = in;
    for (const Vec3& p : b) out.b.push_back(p + s * w);
    return out;
  };
  const double contact = 2 * reach / dot(w, w);
  const double s = place_at([&placed](double t) -> Input { return placed(t); }, 0, 2 * contact + 1 / std::sqrt(dot(w, w)),
                            draw_margin_target(c), options, contact);
  KdopKdopInput out = placed(s);
  shuffle(c, out.a);
  shuffle(c, out.b);
  return out;
}

// B's points moved so that the k-DOPs touch on one slab (with `nudged`, a few ULPs off).
void shift_to_touch(KdopKdopInput& in, ValueSource& v, bool nudged) {
  const auto dirs = kdop_directions(in.k);  // never empty: k is one of the six, from every source
  if (in.a.empty() || in.b.empty()) return;
  const KdopDirection d = dirs[v.choices().draw(dirs.size())];
  const Vec3 dir{static_cast<double>(d.x), static_cast<double>(d.y), static_cast<double>(d.z)};
  // B's point least along the direction moved onto A's point most along it: the slabs along the
  // direction touch there, and every other slab of both holds that point. Each point of B is put
  // at its offset from that point, so that B's old place (however far) adds no rounding.
  const auto along = [&dir](const Vec3& p, const Vec3& q) { return dot(dir, p) < dot(dir, q); };
  Vec3 target = *std::max_element(in.a.begin(), in.a.end(), along);
  const Vec3 b_least = *std::min_element(in.b.begin(), in.b.end(), along);
  const int axis = d.x != 0 ? 0 : (d.y != 0 ? 1 : 2);
  if (nudged) target[axis] = v.nudge(target[axis]);  // a few ULPs into A or away from it
  for (Vec3& p : in.b) p = target + (p - b_least);
}

template <int K>
bool kdops_overlap(const KdopKdopInput& in) {
  return test_kdop_kdop(fit_kdop<K>(in.a), fit_kdop<K>(in.b));
}

template <int K>
void fit_both(const KdopKdopInput& in, bounds::Records& r) {
  fit_kdop<K>(in.a, r);
  fit_kdop<K>(in.b, r);
}

constexpr std::string_view kConfigurations[] = {
    "touching", "just apart", "just overlapping", "single point", "cancelling projection", "far from the origin",
    "k = 6",    "k = 14",     "k = 16",           "k = 18",       "k = 24",                "k = 26"};

constexpr BoundTerm kBoundTerms[] = {{"fit_kdop", "projection", "pad"}, {"fit_kdop", "projection", "total"}};

}  // namespace

Answer Query<KdopKdopInput>::ask(const KdopKdopInput& in) {
  switch (in.k) {
    case 6: return Answer::of(kdops_overlap<6>(in));
    case 14: return Answer::of(kdops_overlap<14>(in));
    case 16: return Answer::of(kdops_overlap<16>(in));
    case 18: return Answer::of(kdops_overlap<18>(in));
    case 24: return Answer::of(kdops_overlap<24>(in));
    case 26: return Answer::of(kdops_overlap<26>(in));
  }
  return {};  // no such direction set: never generated, rejected when read
}

KdopKdopInput Query<KdopKdopInput>::generate(ValueSource& v, const GenerateOptions& options) {
  if (v.choices().chance(35)) return kdops_at_the_bound(v, options);
  KdopKdopInput in;
  in.k = kKs[v.choices().draw(6)];
  const Vec3 center = v.point();
  const auto cluster = [&](std::vector<Vec3>& points) {
    const auto n = 1 + v.choices().draw(5);
    for (std::uint64_t i = 0; i < n; ++i) points.push_back(v.choices().chance(40) ? center + v.point() : v.point());
  };
  cluster(in.a);
  switch (v.choices().draw(4)) {
    case 0: cluster(in.b); break;
    case 1: {  // share a point of A, or repeat A
      in.b.push_back(in.a[v.choices().draw(in.a.size())]);
      if (v.choices().chance(50)) in.b = in.a;
      break;
    }
    default:  // B shifted so that its k-DOP touches A's on one slab (exact when the sums are)
      cluster(in.b);
      shift_to_touch(in, v, v.choices().chance(25));
  }
  shuffle(v.choices(), in.a);
  shuffle(v.choices(), in.b);
  return in;
}

void Query<KdopKdopInput>::touch(KdopKdopInput& in, ValueSource& v) { shift_to_touch(in, v, false); }

Features Query<KdopKdopInput>::features(const KdopKdopInput& in) {
  Features f;
  for (const KdopDirection& d : kdop_directions(in.k)) {
    const Vec3 dir{static_cast<double>(d.x), static_cast<double>(d.y), static_cast<double>(d.z)};
    for (const Vec3& p : in.a) {
      for (const Vec3& q : in.b) f.parallel |= dot(dir, p) == dot(dir, q);
    }
  }
  const auto single = [](const std::vector<Vec3>& s) {
    for (const Vec3& p : s) {
      if (!(p == s.front())) return false;
    }
    return true;
  };
  f.degenerate = single(in.a) || single(in.b);
  return f;
}

std::span<const std::string_view> Query<KdopKdopInput>::configurations() { return kConfigurations; }

void Query<KdopKdopInput>::recognise(const KdopKdopInput& in, Configurations& found) {
  found.margins();
  const auto single = [](const std::vector<Vec3>& s) {
    return !s.empty() && std::all_of(s.begin(), s.end(), [&s](const Vec3& p) { return p == s.front(); });
  };
  found.add("single point", single(in.a) || single(in.b));
  bool cancels = false;
  double largest = 0, lo = INFINITY, hi = -INFINITY;
  for (const std::vector<Vec3>* set : {&in.a, &in.b}) {
    for (const Vec3& p : *set) {
      largest = std::max(largest, max_abs(p));
      lo = std::min(lo, p.x), hi = std::max(hi, p.x);
      for (const KdopDirection& d : kdop_directions(in.k)) {
        const double m = std::fabs(d.x * p.x) + std::fabs(d.y * p.y) + std::fabs(d.z * p.z);
        const double s = d.x * p.x + d.y * p.y + d.z * p.z;
        cancels |= (d.x != 0) + (d.y != 0) + (d.z != 0) > 1 && m > 0 && std::fabs(s) <= kNearlyParallel * m;
      }
    }
  }
  found.add("cancelling projection", cancels);
  found.far(largest, hi - lo);
  static constexpr std::string_view kNames[] = {"k = 6", "k = 14", "k = 16", "k = 18", "k = 24", "k = 26"};
  static constexpr int kSets[] = {6, 14, 16, 18, 24, 26};
  for (int i = 0; i < 6; ++i) found.add(kNames[i], in.k == kSets[i]);
}

std::span<const BoundTerm> Query<KdopKdopInput>::bound_terms() { return kBoundTerms; }

void Query<KdopKdopInput>::probe(const KdopKdopInput& in, std::vector<bounds::Records>& records) {
  bounds::Records& r = bounds::next_call(records);
  switch (in.k) {
    case 6: return fit_both<6>(in, r);
    case 14: return fit_both<14>(in, r);
    case 16: return fit_both<16>(in, r);
    case 18: return fit_both<18>(in, r);
    case 24: return fit_both<24>(in, r);
    case 26: return fit_both<26>(in, r);
  }
}

bool Query<KdopKdopInput>::admits(const KdopKdopInput& in, Relation relation) {
  if (relation == Relation::permute_axes && in.k == 16) return false;
  return !(relation == Relation::flip_axis && (in.k == 16 || in.k == 24));
}

}  // namespace cc::harness
