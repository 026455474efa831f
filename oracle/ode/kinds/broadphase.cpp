// broadphase's second opinions from ODE: two of its spaces, dSweepAndPruneSpace and dHashSpace
// (default levels 2^-3 to 2^10), driven frame by frame as a user drives them (a geom added when a
// box appears, moved every frame, destroyed when the box goes, then dSpaceCollide), every pair
// its near callback receives recorded. Each box is a geom of a user class (dCreateGeomClass)
// whose AABB is the box as given and whose aabb_test, which the spaces call before the near
// callback, compares its box with the other's AABB, closed; the class has no narrow phase.
// dHashSpace compares the AABBs (closed) of geoms sharing a cell of the grid and tests every
// geom too large for it against all; dSweepAndPruneSpace sorts the boxes' lower bounds on its
// first axis rounded to float and compares the other two axes in double, so a pair apart by less
// than float rounding on the first axis reaches the callback, and aabb_test drops it. The band is
// exact: what this asks is whether a space misses an overlapping pair. Boxes with NaN or
// inverted bounds are not asked; nor, for dHashSpace, coordinates of magnitude 2^27 or more
// (its cells of 2^-3 are counted in ints). dHashSpace puts a box in cells of size 2^level, level
// its largest extent's exponent, by floor(bound * 2^-level), and looks for boxes of larger
// levels in the cells that contain its own; for a subnormal bound the product underflows
// differently at each level (-5e-324 / 2 is -0, cell 0; -5e-324 / 1 is in cell -1), so a pair of
// overlapping boxes of different levels can be missed: a defect of ODE's (a two-box case in
// corpora/broadphase).
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "oracle/ode/convert.h"
#include "oracle/ode/parties.h"

namespace cc::ode_oracle {
namespace {

enum class SpaceKind { sweep_and_prune, hash };

// The user class's data: the box and its slot.
struct BoxData {
  double bounds[6];  // ODE's order: lo x, hi x, lo y, hi y, lo z, hi z
  std::uint32_t slot;
};

BoxData& data_of(dGeomID g) { return *static_cast<BoxData*>(dGeomGetClassData(g)); }

void box_aabb(dGeomID g, dReal aabb[6]) { std::copy_n(data_of(g).bounds, 6, aabb); }

int box_aabb_test(dGeomID g, dGeomID, dReal other[6]) {
  const double* b = data_of(g).bounds;
  for (int k = 0; k < 3; ++k) {
    if (b[2 * k] > other[2 * k + 1] || other[2 * k] > b[2 * k + 1]) return 0;
  }
  return 1;
}

dColliderFn* no_collider(int) { return nullptr; }

int box_class() {
  static const int number = [] {
    dGeomClass c{};
    c.bytes = static_cast<int>(sizeof(BoxData));
    c.collider = no_collider;
    c.aabb = box_aabb;
    c.aabb_test = box_aabb_test;
    return dCreateGeomClass(&c);
  }();
  return number;
}

void set_box(dGeomID g, const Aabb& box) {
  BoxData& d = data_of(g);
  for (int k = 0; k < 3; ++k) d.bounds[2 * k] = box.lo[k], d.bounds[2 * k + 1] = box.hi[k];
  dGeomSetPosition(g, 0, 0, 0);  // marks the geom moved: its AABB is asked again
}

void record_pair(void* data, dGeomID a, dGeomID b) {
  auto* pairs = static_cast<std::vector<harness::FacePair>*>(data);
  pairs->push_back(std::minmax(data_of(a).slot, data_of(b).slot));
}

Opinion run_space(SpaceKind kind, const harness::BroadphaseInput& in) {
  for (const auto& frame : in.frames) {
    for (const auto& box : frame) {
      for (int k = 0; box && k < 3; ++k) {
        if (!(box->lo[k] <= box->hi[k])) return not_applicable("a box with NaN or inverted bounds");
        if (kind == SpaceKind::hash && !(std::fabs(box->lo[k]) < 0x1p27 && std::fabs(box->hi[k]) < 0x1p27) &&
            !(std::isinf(box->lo[k]) || std::isinf(box->hi[k]))) {
          return not_applicable("a coordinate beyond dHashSpace's integer cells (2^27)");
        }
      }
    }
  }
  const Space space(kind == SpaceKind::hash ? dHashSpaceCreate(nullptr)
                                            : dSweepAndPruneSpaceCreate(nullptr, dSAP_AXES_XYZ));
  dSpaceSetCleanup(space.get(), 0);  // the geoms are destroyed here
  const int klass = box_class();
  std::vector<Geom> geoms;
  Opinion o = answered(false);
  for (const auto& frame : in.frames) {
    geoms.resize(std::max(geoms.size(), frame.size()));
    for (std::size_t i = 0; i < geoms.size(); ++i) {
      const bool present = i < frame.size() && frame[i].has_value();
      if (present && !geoms[i]) {
        geoms[i].reset(dCreateGeom(klass));
        data_of(geoms[i].get()).slot = static_cast<std::uint32_t>(i);
        set_box(geoms[i].get(), *frame[i]);
        dSpaceAdd(space.get(), geoms[i].get());
      } else if (present) {
        set_box(geoms[i].get(), *frame[i]);
      } else if (geoms[i]) {
        dSpaceRemove(space.get(), geoms[i].get());
        geoms[i].reset();
      }
    }
    std::vector<harness::FacePair> pairs;
    dSpaceCollide(space.get(), &pairs, record_pair);
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
    o.answer.hit |= !pairs.empty();
    o.answer.frames.push_back(std::move(pairs));
  }
  for (Geom& g : geoms) {
    if (g) dSpaceRemove(space.get(), g.get());
  }
  return o;
}

}  // namespace

template <>
const std::vector<Party<harness::BroadphaseInput>>& ode_parties() {
  constexpr Band kBand{0, BandSides::exact, 0,
                       "pairs passed by the geoms' aabb_test on the given bounds: a missed pair is wrong"};
  static const std::vector<Party<harness::BroadphaseInput>> parties = {
      ode_party<harness::BroadphaseInput>(
          "ode.dSweepAndPruneSpace", kBand,
          [](const harness::BroadphaseInput& in) { return run_space(SpaceKind::sweep_and_prune, in); }),
      ode_party<harness::BroadphaseInput>(
          "ode.dHashSpace", kBand, [](const harness::BroadphaseInput& in) { return run_space(SpaceKind::hash, in); })};
  return parties;
}

}  // namespace cc::ode_oracle
