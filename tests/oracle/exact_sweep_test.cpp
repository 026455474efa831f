// The exact time window of moving boxes: ExactWindow::restrict keeps the times t in the window
// at which |p + t s| <= r, checked against that definition at times on a grid and at the
// window's ends and just beyond them.
#include "oracle/exact/exact_sweep.h"

#include <gtest/gtest.h>

#include <random>

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

}  // namespace
}  // namespace cc::exact
