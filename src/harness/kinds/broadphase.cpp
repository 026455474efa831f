// The broadphase kind: boxes on a coarse grid (so endpoints are often equal and boxes touch),
// zero-extent, identical and nested boxes, moving coherently frame to frame by small steps (and
// sometimes a few ULPs), added and removed between frames. The library's sweeps, and what its
// cases are.
#include "harness/kinds/broadphase.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

#include "collide/box_pairs.h"
#include "collide/column_sweep.h"
#include "collide/sweep_and_prune.h"
#include "harness/generation/shapes.h"
#include "harness/generation/touch.h"
#include "harness/judging/configurations.h"
#include "harness/judging/features.h"

namespace cc::harness {
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

std::vector<FacePair> slot_pairs(const std::vector<ObjectPair>& pairs, const std::vector<std::uint32_t>& slot_of) {
  std::vector<FacePair> out;
  for (const auto& [a, b] : pairs) out.push_back(std::minmax(slot_of[a], slot_of[b]));
  std::sort(out.begin(), out.end());
  return out;
}

// A broadphase (ColumnSweep, SweepAndPrune) over the frames: boxes added, moved and removed as
// the slots say. A box outside the domain makes add() or move() throw: the documented answer is
// then no hit.
template <class Sweep>
Answer incremental(const BroadphaseInput& in) {
  Answer a;
  try {
    Sweep broadphase;
    std::map<std::size_t, ObjectId> id_of;   // slot -> id of its box
    std::vector<std::uint32_t> slot_of;      // id -> slot
    for (const auto& frame : in.frames) {
      for (std::size_t i = 0; i < frame.size(); ++i) {
        const auto it = id_of.find(i);
        if (frame[i] && it == id_of.end()) {
          id_of[i] = broadphase.add(*frame[i]);
          slot_of.push_back(static_cast<std::uint32_t>(i));
        } else if (frame[i]) {
          broadphase.move(it->second, *frame[i]);
        } else if (it != id_of.end()) {
          broadphase.remove(it->second);
          id_of.erase(it);
        }
      }
      broadphase.update();
      a.frames.push_back(slot_pairs(broadphase.pairs(), slot_of));
      a.hit |= !a.frames.back().empty();
    }
  } catch (const std::invalid_argument&) {
    return {};
  }
  return a;
}

Answer full_sorts(const BroadphaseInput& in) {
  Answer a;
  for (const auto& frame : in.frames) {
    std::vector<Aabb> boxes;
    std::vector<std::uint32_t> slot_of;
    for (std::size_t i = 0; i < frame.size(); ++i) {
      if (!frame[i]) continue;
      boxes.push_back(*frame[i]);
      slot_of.push_back(static_cast<std::uint32_t>(i));
    }
    a.frames.push_back(slot_pairs(sort_and_sweep(boxes), slot_of));
    a.hit |= !a.frames.back().empty();
  }
  return a;
}

constexpr std::string_view kConfigurations[] = {"touching",   "identical",          "flat box", "added and removed",
                                                "many boxes", "one box at a time"};

}  // namespace

Answer Query<BroadphaseInput>::ask(const BroadphaseInput& in) { return incremental<ColumnSweep>(in); }

const std::vector<Party<BroadphaseInput>>& Query<BroadphaseInput>::library_parties() {
  static const std::vector<Party<BroadphaseInput>> parties = {
      {"library.sweep_and_prune", band, [](const BroadphaseInput& in) { return answered(incremental<SweepAndPrune>(in)); }},
      {"library.sort_and_sweep", band, [](const BroadphaseInput& in) { return answered(full_sorts(in)); }}};
  return parties;
}

BroadphaseInput Query<BroadphaseInput>::generate(ValueSource& v, const GenerateOptions& options) {
  Choices& c = v.choices();
  const bool big = c.chance(5);
  // Now and then a relay: box i in frame i alone, no two boxes ever in the scene together,
  // wherever they lie (and a frame or two with none at the end).
  const bool relay = !big && c.chance(5);
  const std::size_t n = big ? 40 + c.draw(80) : 2 + c.draw(relay ? 6 : 24);
  const std::size_t frames = big ? 4 + c.draw(12) : relay ? n + c.draw(3) : 1 + c.draw(8);
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
    if (relay) {
      added[i] = i, removed[i] = i + 1;
      continue;
    }
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

void Query<BroadphaseInput>::touch(BroadphaseInput& in, ValueSource& v) {
  Choices& c = v.choices();
  if (in.frames.empty()) return;
  std::vector<std::vector<std::size_t>> present(in.frames.size());  // per frame, its slots that hold a box
  std::vector<std::size_t> frames;                                  // the frames with two boxes or more
  for (std::size_t f = 0; f < in.frames.size(); ++f) {
    for (std::size_t i = 0; i < in.frames[f].size(); ++i) {
      if (in.frames[f][i]) present[f].push_back(i);
    }
    if (present[f].size() >= 2) frames.push_back(f);
  }
  if (frames.empty()) {  // no frame has two boxes: one gets a second, against one it has
    const std::size_t f = c.draw(in.frames.size());
    auto& frame = in.frames[f];
    if (frame.size() < 2) {
      for (auto& other : in.frames) other.resize(2);  // every frame has the same slots
    }
    if (present[f].empty()) {  // an empty frame: a unit box to start from
      frame[0] = Aabb{{0, 0, 0}, {1, 1, 1}};
      present[f] = {0};
    }
    const std::size_t held = present[f][0], empty = held == 0 ? 1 : 0;
    frame[empty] = frame[held];
    put_face_to_face(*frame[held], *frame[empty], c);
    return;
  }
  const std::size_t f = frames[c.draw(frames.size())];
  auto& frame = in.frames[f];
  const std::vector<std::size_t>& boxes = present[f];
  const std::size_t i = c.draw(boxes.size()), j = (i + 1 + c.draw(boxes.size() - 1)) % boxes.size();
  put_face_to_face(*frame[boxes[i]], *frame[boxes[j]], c);
}

Features Query<BroadphaseInput>::features(const BroadphaseInput& in) {
  Features f;
  for (const auto& frame : in.frames) {
    for (std::size_t i = 0; i < frame.size(); ++i) {
      if (!frame[i]) continue;
      f.degenerate |= zero_extent(*frame[i]);
      for (std::size_t j = i + 1; j < frame.size() && !(f.parallel && f.degenerate); ++j) {
        if (!frame[j]) continue;
        f.degenerate |= *frame[i] == *frame[j];
        for (int k = 0; k < 3; ++k) f.parallel |= frame[i]->lo[k] == frame[j]->hi[k] || frame[i]->hi[k] == frame[j]->lo[k];
      }
    }
  }
  return f;
}

std::span<const std::string_view> Query<BroadphaseInput>::configurations() { return kConfigurations; }

void Query<BroadphaseInput>::recognise(const BroadphaseInput& in, Configurations& found) {
  bool touching = false, identical = false, flat = false, added_and_removed = false, one_at_a_time = in.frames.size() > 1;
  const std::size_t slots = in.frames.empty() ? 0 : in.frames[0].size();
  for (std::size_t i = 0; i < slots; ++i) {
    bool present = false, absent = false;
    for (const auto& frame : in.frames) (frame[i] ? present : absent) = true;
    added_and_removed |= present && absent;
  }
  for (const auto& frame : in.frames) {
    one_at_a_time &= std::ranges::count_if(frame, [](const auto& box) { return box.has_value(); }) <= 1;
    for (std::size_t i = 0; i < frame.size(); ++i) {
      if (!frame[i]) continue;
      flat |= zero_extents(frame[i]->hi - frame[i]->lo) > 0;
      for (std::size_t j = i + 1; j < frame.size(); ++j) {
        if (!frame[j]) continue;
        identical |= *frame[i] == *frame[j];
        for (int k = 0; k < 3; ++k) {
          touching |= (frame[i]->lo[k] == frame[j]->hi[k] || frame[i]->hi[k] == frame[j]->lo[k]) &&
                      test_aabb_aabb(*frame[i], *frame[j]);
        }
      }
    }
  }
  found.add("touching", touching);
  found.add("identical", identical);
  found.add("flat box", flat);
  found.add("added and removed", added_and_removed);
  found.add("many boxes", slots >= 40);
  found.add("one box at a time", one_at_a_time);
}

std::span<const BoundTerm> Query<BroadphaseInput>::bound_terms() { return {}; }

void Query<BroadphaseInput>::probe(const BroadphaseInput&, std::vector<bounds::Records>&) {}

}  // namespace cc::harness
