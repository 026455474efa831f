// broadphase in exact arithmetic: brute force over every pair of every frame, with closed-box
// overlap decided by comparisons of the given bounds (exact in floating point).
#include <algorithm>
#include <cmath>

#include "oracle/exact/domain.h"
#include "oracle/exact/explain.h"
#include "oracle/exact/judges.h"

namespace cc::exact {
namespace {

bool valid(const Aabb& b) {
  for (int k = 0; k < 3; ++k) {
    if (!(b.lo[k] <= b.hi[k])) return false;  // also NaN
  }
  return true;
}

bool overlap(const Aabb& a, const Aabb& b) {
  for (int k = 0; k < 3; ++k) {
    if (a.lo[k] > b.hi[k] || b.lo[k] > a.hi[k]) return false;
  }
  return true;
}

// How far two boxes are from touching: the least overlap over the axes (>= 0), or minus the
// largest gap. Differences of doubles are 0 exactly when the bounds are equal.
double signed_overlap(const Aabb& a, const Aabb& b) {
  double least = INFINITY, gap = 0;
  for (int k = 0; k < 3; ++k) {
    const double overlap = std::min(a.hi[k], b.hi[k]) - std::max(a.lo[k], b.lo[k]);
    least = std::min(least, overlap);
    gap = std::min(gap, overlap);
  }
  return gap < 0 ? gap : least;
}

}  // namespace

template <>
ExactVerdict judge(const harness::BroadphaseInput& in) {
  double magnitude = 0;
  for (std::size_t f = 0; f < in.frames.size(); ++f) {
    for (std::size_t i = 0; i < in.frames[f].size(); ++i) {
      const auto& box = in.frames[f][i];
      if (!box) continue;
      if (!valid(*box)) {
        return documented(false, "box " + std::to_string(i) + " in frame " + std::to_string(f) +
                                     " has lo > hi or NaN: add() and move() reject it");
      }
      magnitude = std::max({magnitude, max_abs(box->lo), max_abs(box->hi)});
    }
  }
  const double scale = scale_of(std::isfinite(magnitude) ? magnitude : 0x1p1023);
  ExactVerdict v;
  v.margin = -INFINITY;
  for (const auto& frame : in.frames) {
    auto& pairs = v.answer.frames.emplace_back();
    for (std::size_t i = 0; i < frame.size(); ++i) {
      if (!frame[i]) continue;
      for (std::size_t j = i + 1; j < frame.size(); ++j) {
        if (!frame[j]) continue;
        const double s = signed_overlap(*frame[i], *frame[j]);
        if (overlap(*frame[i], *frame[j])) pairs.emplace_back(static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j));
        const double margin = std::isfinite(s) ? s / scale : s;
        if (std::fabs(margin) < std::fabs(v.margin) || std::isnan(margin)) v.margin = margin;
      }
    }
    v.answer.hit |= !pairs.empty();
  }
  if (std::isinf(v.margin)) v.margin = v.margin > 0 ? 1 : -1;  // no pair, or only unbounded ones
  return v;
}

// Per frame: the boxes present, the overlapping pairs, and the pair nearest to touching.
template <>
harness::Explanation explain(const harness::BroadphaseInput& in) {
  using harness::Explanation;
  const harness::ExactVerdict v = judge(in);
  Explanation e;
  e.title = "boxes per frame (closed-box overlap by comparisons of the bounds)";
  if (v.contract != harness::Contract::in) {
    e.deciding = v.note;
    return e;
  }
  e.columns = {"frame", "boxes", "overlapping pairs", "pairs"};
  for (std::size_t f = 0; f < in.frames.size(); ++f) {
    std::size_t present = 0;
    for (const auto& box : in.frames[f]) present += box.has_value();
    std::string listed;
    for (std::size_t i = 0; i < v.answer.frames[f].size() && i < 8; ++i) {
      const auto& [a, b] = v.answer.frames[f][i];
      listed.append("(").append(std::to_string(a)).append(", ").append(std::to_string(b)).append(") ");
    }
    if (v.answer.frames[f].size() > 8) listed.append("...");
    e.rows.push_back({std::to_string(f), std::to_string(present), std::to_string(v.answer.frames[f].size()), listed});
  }
  e.deciding = "the pair nearest to touching, over all frames (overlap > 0, gap < 0, relative to the scale)";
  e.deciding_value = v.margin;
  return e;
}

}  // namespace cc::exact
