// The exact time window of moving boxes: ExactWindow::restrict keeps the times t in the window
// at which |p + t s| <= r, checked against that definition at times on a grid and at the
// window's ends and just beyond them. moving_axes gives the candidate axes of the boxes as
// parallelepipeds and their p, s and r, checked against those definitions in rationals on the
// moving_obb generator's boxes (flat, rotated, touching, at every scale).
#include "oracle/exact/exact_sweep.h"

#include <gtest/gtest.h>

#include <random>

#include "harness/generation/choices.h"
#include "harness/generation/generate.h"

namespace cc::exact {
namespace {

Rational fraction(long k, long n) {
  Rational q(k, n);
  q.canonicalize();
  return q;
}

TEST(ExactWindow, RestrictKeepsTheTimesOfItsDefinition) {
  std::mt19937_64 rng(11);
  const auto small = [&](long range) { return static_cast<long>(rng() % static_cast<std::uint64_t>(2 * range + 1)) - range; };
  int hits = 0, misses = 0;
  for (int round = 0; round < 3000; ++round) {
    // One to three axes, at rates that are 0 a third of the time; radii 0 now and then.
    struct Axis {
      Rational p, s, r;
    };
    std::vector<Axis> axes;
    for (long k = 1 + small(1) + 1; k > 0; --k) {
      axes.push_back({fraction(small(12), 1 + (round % 4)), round % 3 == 0 ? Rational(0) : fraction(small(12), 1 + (round % 5)),
                      fraction(std::labs(small(6)) * (round % 7 != 0), 2)});
    }
    ExactWindow w;
    for (const Axis& a : axes) w.restrict(a.p, a.s, a.r);
    const auto inside = [&](const Rational& t) {
      if (t < 0 || t > 1) return false;
      for (const Axis& a : axes) {
        if (abs(a.p + t * a.s) > a.r) return false;
      }
      return true;
    };
    std::vector<Rational> times;
    for (long j = -8; j <= 72; ++j) times.push_back(fraction(j, 64));
    const Rational eps = fraction(1, 1000000);
    if (w.hit()) {
      times.insert(times.end(), {w.first, w.last, w.first - eps, w.last + eps, (w.first + w.last) / 2});
      EXPECT_TRUE(inside(w.first) && inside(w.last)) << "round " << round;
      EXPECT_FALSE(inside(w.first - eps)) << "round " << round << ": the window starts late";
      EXPECT_FALSE(inside(w.last + eps)) << "round " << round << ": the window ends early";
      ++hits;
    } else {
      ++misses;
    }
    for (const Rational& t : times) {
      EXPECT_EQ(w.hit() && w.first <= t && t <= w.last, inside(t)) << "round " << round << " t = " << t.get_str();
    }
  }
  EXPECT_GT(hits, 300);
  EXPECT_GT(misses, 300);
}

TEST(MovingAxes, AreTheParallelepipedsCandidateAxesWithTheirOffsetsRatesAndRadii) {
  int spanning = 0, flat = 0;
  for (std::uint64_t seed = 0; seed < 3000; ++seed) {
    harness::RandomChoices choices(seed);
    const auto in = std::get<harness::MovingObbInput>(harness::generate(harness::QueryKind::moving_obb, choices));
    bool finite_boxes = true;
    for (const MovingObb* m : {&in.a, &in.b}) {
      finite_boxes = finite_boxes && finite(m->box.center) && finite(m->box.half) && finite(m->box.axes) &&
                     finite(m->velocity) && m->box.half.x >= 0 && m->box.half.y >= 0 && m->box.half.z >= 0;
    }
    if (!finite_boxes) continue;
    const ExactShape sa = parallelepiped_shape(in.a.box.center, in.a.box.half, in.a.box.axes, "A");
    const ExactShape sb = parallelepiped_shape(in.b.box.center, in.b.box.half, in.b.box.axes, "B");
    const std::vector<CandidateAxis> expected = candidate_axes_for_any_offset(sa, sb);
    const std::vector<MovingAxis> got = moving_axes(in.a, in.b);
    ASSERT_EQ(got.size(), expected.size()) << "seed " << seed;
    const QVec3 d = sb.center - sa.center, w = rational(in.b.velocity) - rational(in.a.velocity);
    for (std::size_t i = 0; i < got.size(); ++i) {
      const CandidateAxis& c = expected[i];
      ASSERT_EQ(got[i].axis.name, c.name) << "seed " << seed;
      for (int k = 0; k < 3; ++k) ASSERT_EQ(got[i].axis.axis[k], c.axis[k]) << "seed " << seed;
      ASSERT_EQ(got[i].axis.conditioning.m, c.conditioning.m) << "seed " << seed;
      ASSERT_EQ(got[i].axis.conditioning.e, c.conditioning.e) << "seed " << seed;
      Rational r = 0;
      for (const ExactShape* s : {&sa, &sb}) {
        for (const QVec3& h : s->half_edges) r += abs(dot(c.axis, h));
      }
      ASSERT_EQ(got[i].p, dot(c.axis, d)) << "seed " << seed << " axis " << c.name;
      ASSERT_EQ(got[i].s, dot(c.axis, w)) << "seed " << seed << " axis " << c.name;
      ASSERT_EQ(got[i].r, r) << "seed " << seed << " axis " << c.name;
    }
    (sa.directions.size() + sb.directions.size() == 6 ? spanning : flat) += 1;
  }
  EXPECT_GT(spanning, 1000);
  EXPECT_GT(flat, 50);  // flat boxes: fewer directions, down to the points' candidate axes
}

}  // namespace
}  // namespace cc::exact
