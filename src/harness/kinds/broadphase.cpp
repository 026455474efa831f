// Generator for broadphase: boxes on a coarse grid (so endpoints are often equal and boxes touch),
// zero-extent, identical and nested boxes, moving coherently frame to frame by small steps (and
// sometimes a few ULPs), added and removed between frames.
#include <cmath>

#include "harness/generation/shapes.h"

namespace cc::harness::detail {
namespace {

// A box with corners on the half-integer grid, often flat or a point, or drawn freely.
Aabb grid_box(ValueSource& v, const GenerateOptions& options) {
  Choices& c = v.choices();
  if (c.chance(20)) return draw_aabb(v, options);
  Aabb b;
  for (int k = 0; k < 3; ++k) {
    b.lo[k] = 0.5 * v.small_int(12);
    b.hi[k] = b.lo[k] + (c.chance(15) ? 0.0 : 0.5 * static_cast<double>(1 + c.draw(6)));
  }
  return b;
}

// A small coherent step: 0, a grid step, or a few ULPs.
Vec3 step(ValueSource& v) {
  Choices& c = v.choices();
  Vec3 d;
  for (int k = 0; k < 3; ++k) {
    const std::uint64_t kind = c.draw(10);
    d[k] = kind < 4 ? 0.0 : (kind < 8 ? 0.5 * v.small_int(2) : std::ldexp(v.small_int(3), -50));
  }
  return d;
}

}  // namespace

BroadphaseInput generate_broadphase(ValueSource& v, const GenerateOptions& options) {
  Choices& c = v.choices();
  const bool big = c.chance(5);
  const std::size_t n = big ? 40 + c.draw(80) : 2 + c.draw(24);
  const std::size_t frames = big ? 4 + c.draw(12) : 1 + c.draw(8);
  std::vector<Aabb> boxes;
  for (std::size_t i = 0; i < n; ++i) {
    if (!boxes.empty() && c.chance(15)) {
      boxes.push_back(boxes[c.draw(boxes.size())]);  // identical to another
    } else if (!boxes.empty() && c.chance(10)) {
      const Aabb& outer = boxes[c.draw(boxes.size())];  // inside another
      boxes.push_back({0.75 * outer.lo + 0.25 * outer.hi, 0.25 * outer.lo + 0.75 * outer.hi});
    } else {
      boxes.push_back(grid_box(v, options));
    }
  }
  shuffle(c, boxes);  // an identical or nested box may come before the box it copies
  // When each box is in the scene: from an added frame to a removed one (and maybe back).
  std::vector<std::size_t> added(n, 0), removed(n, frames), readded(n, frames);
  for (std::size_t i = 0; i < n; ++i) {
    if (frames > 1 && c.chance(20)) added[i] = c.draw(frames);
    if (frames > 1 && c.chance(20)) removed[i] = added[i] + 1 + c.draw(frames - added[i]);
    if (removed[i] < frames && c.chance(50)) readded[i] = removed[i] + c.draw(frames - removed[i]);
  }
  BroadphaseInput in;
  std::vector<Vec3> velocity(n);
  for (Vec3& d : velocity) d = step(v);
  for (std::size_t f = 0; f < frames; ++f) {
    auto& frame = in.frames.emplace_back();
    for (std::size_t i = 0; i < n; ++i) {
      const bool present = f >= added[i] && (f < removed[i] || f >= readded[i]);
      frame.push_back(present ? std::optional(boxes[i]) : std::nullopt);
      if (c.chance(10)) velocity[i] = step(v);  // a change of course now and then
      boxes[i] = {boxes[i].lo + velocity[i], boxes[i].hi + velocity[i]};
    }
  }
  if (options.out_of_contract && c.chance(10)) {
    auto& box = in.frames[c.draw(frames)][c.draw(n)];
    if (!box) box = Aabb{};
    box->lo[static_cast<int>(c.draw(3))] = c.chance(50) ? NAN : box->hi[0] + 1;
  }
  return in;
}

}  // namespace cc::harness::detail
