// Bounding spheres in exact arithmetic (GMP rationals): fit_sphere holds every point and
// merge_spheres both balls, on point sets of every scale from 2^-1000 to 2^450, coincident,
// collinear, coplanar, far from the origin, and on balls nested, almost nested and apart.
#include "collide/sphere_fit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "oracle/exact/rational.h"
#include "test_random.h"

namespace cc {
namespace {

using exact::QVec3;
using exact::Rational;
using exact::rational;

bool holds(const Sphere& s, const Vec3& p) {
  const QVec3 d = rational(p) - rational(s.center);
  return dot(d, d) <= rational(s.radius) * rational(s.radius);
}

// Whether m holds b: |c_m - c_b| + r_b <= r_m, that is r_m - r_b >= 0 and |c_m - c_b|^2 <= (r_m - r_b)^2.
bool holds(const Sphere& m, const Sphere& b) {
  const Rational slack = rational(m.radius) - rational(b.radius);
  const QVec3 d = rational(m.center) - rational(b.center);
  return slack >= 0 && dot(d, d) <= slack * slack;
}
using test::Random;

// Points of one of several shapes at a random scale and offset.
std::vector<Vec3> points(Random& random) {
  const double scale = std::ldexp(1.0, random.below(1450) - 1000);
  const double far = random.below(3) == 0 ? std::ldexp(scale, random.below(40)) : 0;
  const int shape = random.below(4);  // general, coplanar, collinear, coincident
  std::vector<Vec3> out;
  const int count = 1 + random.below(24);
  const Vec3 origin{far, -far, 0.5 * far};
  for (int i = 0; i < count; ++i) {
    Vec3 p{random.between(-1, 1), random.between(-1, 1), random.between(-1, 1)};
    if (shape == 1) p.z = 0.25;
    if (shape == 2) p = {p.x, 2 * p.x, -p.x};
    if (shape == 3) p = {0.5, 0.5, 0.5};
    out.push_back(origin + scale * p);
  }
  return out;
}

TEST(FitSphereExactly, HoldsEveryPointAtEveryScale) {
  Random random(7);
  int checked = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const std::vector<Vec3> p = points(random);
    const Sphere s = fit_sphere(p);
    for (const Vec3& v : p) {
      ASSERT_TRUE(holds(s, v)) << "trial " << trial;
      ++checked;
    }
  }
  EXPECT_GT(checked, 30000);
}

TEST(MergeSpheresExactly, HoldsBothBallsNestedAlmostNestedAndApart) {
  Random random(11);
  for (int trial = 0; trial < 3000; ++trial) {
    const double scale = std::ldexp(1.0, random.below(1400) - 900);
    const Sphere a{scale * Vec3{random.between(-1, 1), random.between(-1, 1), random.between(-1, 1)},
                   scale * random.between(0, 1)};
    Sphere b{scale * Vec3{random.between(-1, 1), random.between(-1, 1), random.between(-1, 1)},
             scale * random.between(0, 1)};
    if (random.below(3) == 0) {
      // b inside a, touching a's surface from inside up to a few ulps either way.
      b.center = a.center + Vec3{0.5 * a.radius, 0, 0};
      b.radius = 0.5 * a.radius;
      for (int k = random.below(5) - 2; k != 0; k += k > 0 ? -1 : 1) {
        b.radius = std::nextafter(b.radius, k > 0 ? INFINITY : 0.0);
      }
    }
    const Sphere m = merge_spheres(a, b);
    ASSERT_TRUE(holds(m, a)) << "trial " << trial;
    ASSERT_TRUE(holds(m, b)) << "trial " << trial;
  }
}

}  // namespace
}  // namespace cc
