// exact_sat for two triangles in integers: the same hit, rank and margin as exact_sat on the
// rationals, bit for bit, on pairs that cross, touch (a shared vertex, a vertex on a face, edges
// meeting, coplanar overlap), lie apart by a little or a lot, are degenerate (segments, points:
// ranks 2, 1 and 0) and are placed by rotations near and far from the origin, with coordinates
// from 2^-60 to 2^60.
#include "oracle/exact/triangle_sat.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "oracle/exact/convex_sat.h"
#include "oracle/exact/rational.h"
#include "rotations.h"

namespace cc::exact {
namespace {

QVec3 placed_exactly(const RigidTransform& pose, const Vec3& v) {
  QVec3 out;
  for (int i = 0; i < 3; ++i) out[i] = dot(rational(pose.rotation.row(i)), rational(v)) + rational(pose.translation[i]);
  return out;
}

QVec3 rational_point(const DyadicPoint& p) {
  QVec3 q;
  for (int i = 0; i < 3; ++i) {
    q[i] = Rational(p.c[i]);
    if (p.exponent >= 0) {
      mpq_mul_2exp(q[i].get_mpq_t(), q[i].get_mpq_t(), static_cast<unsigned long>(p.exponent));
    } else {
      mpq_div_2exp(q[i].get_mpq_t(), q[i].get_mpq_t(), static_cast<unsigned long>(-p.exponent));
    }
  }
  return q;
}

using test::rotation;

TEST(PlacedDyadic, IsThePlacedPointExactly) {
  std::mt19937_64 random(1);
  std::uniform_real_distribution<double> uniform(-1, 1);
  for (int trial = 0; trial < 500; ++trial) {
    const double scale = std::ldexp(1.0, static_cast<int>(trial % 121) - 60);
    const Vec3 v{scale * uniform(random), trial % 5 ? scale * uniform(random) : 0.0, scale * uniform(random)};
    const RigidTransform pose{rotation(uniform(random), uniform(random), uniform(random)),
                              {std::ldexp(uniform(random), static_cast<int>(trial % 81) - 40), 0, 1}};
    const DyadicPoint p = placed_dyadic(pose, v);
    const QVec3 q = rational_point(p), expected = placed_exactly(pose, v);
    for (int i = 0; i < 3; ++i) ASSERT_EQ(q[i], expected[i]) << "trial " << trial;
  }
  const DyadicPoint origin = placed_dyadic(RigidTransform{}, {0, 0, 0});
  for (const mpz_class& c : origin.c) EXPECT_EQ(sgn(c), 0);
}

struct Tally {
  int cases = 0, hits = 0, touching = 0, apart = 0, flat = 0, collinear = 0;
};

// Compares one pair both ways; the integer test answers for ranks 3 and 2 only.
void compare(const Triangle& a, const RigidTransform& pa, const Triangle& b, const RigidTransform& pb, Tally& t,
             int trial) {
  std::array<DyadicPoint, 3> da, db;
  std::array<QVec3, 3> qa, qb;
  for (int k = 0; k < 3; ++k) {
    da[k] = placed_dyadic(pa, a.v[k]), db[k] = placed_dyadic(pb, b.v[k]);
    qa[k] = placed_exactly(pa, a.v[k]), qb[k] = placed_exactly(pb, b.v[k]);
  }
  const SatResult expected = exact_sat(rational_triangle_shape(qa[0], qa[1], qa[2], "A"),
                                       rational_triangle_shape(qb[0], qb[1], qb[2], "B"));
  thread_local TriangleSat sat;
  const auto r = sat({&da[0], &da[1], &da[2]}, {&db[0], &db[1], &db[2]});
  ++t.cases;
  if (expected.rank <= 1) {
    ASSERT_FALSE(r.has_value()) << "trial " << trial;
    ++t.collinear;
    return;
  }
  ASSERT_TRUE(r.has_value()) << "trial " << trial;
  ASSERT_EQ(r->rank, expected.rank) << "trial " << trial;
  ASSERT_EQ(r->hit, expected.hit) << "trial " << trial;
  ASSERT_EQ(r->margin, expected.margin) << "trial " << trial << ": " << r->margin << " against " << expected.margin;
  t.hits += expected.hit;
  t.touching += expected.hit && expected.rank == 3 && expected.margin == 0;
  t.apart += !expected.hit;
  t.flat += expected.rank == 2;
}

// triangle_pair_sat on the triangles as given: exact_sat's hit, rank and margin, whatever path.
void compare_as_given(const Triangle& a, const Triangle& b, int trial) {
  const SatResult expected =
      exact_sat(triangle_shape(a.v[0], a.v[1], a.v[2], "A"), triangle_shape(b.v[0], b.v[1], b.v[2], "B"));
  const TriangleSatVerdict direct = triangle_pair_sat(a, b);
  ASSERT_EQ(direct.rank, expected.rank) << "trial " << trial;
  ASSERT_EQ(direct.hit, expected.hit) << "trial " << trial;
  ASSERT_EQ(direct.margin, expected.margin) << "trial " << trial;
}

TEST(TriangleSat, AgreesWithExactSatBitForBit) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> uniform(-1, 1);
  const auto point = [&] { return Vec3{uniform(random), uniform(random), uniform(random)}; };
  // Small integers: exact touching and coplanar configurations survive an exact pose.
  const auto grid = [&] {
    return Vec3{std::round(3 * uniform(random)), std::round(3 * uniform(random)), std::round(3 * uniform(random))};
  };
  Tally t;
  for (int trial = 0; trial < 4000; ++trial) {
    Triangle a, b;
    const bool on_grid = trial % 2 == 0;
    for (int k = 0; k < 3; ++k) a.v[k] = on_grid ? grid() : point(), b.v[k] = on_grid ? grid() : point();
    switch (trial % 8) {
      case 1: b.v[0] = a.v[1]; break;                                   // a shared vertex
      case 2: b.v[0] = 0.25 * a.v[0] + 0.25 * a.v[1] + 0.5 * a.v[2]; break;  // a vertex on a's face
      case 3: b.v[2] = b.v[1]; break;                                   // a segment
      case 4: a.v[1] = a.v[2] = a.v[0]; break;                          // a point
      case 5:                                                            // coplanar
        for (int k = 0; k < 3; ++k) a.v[k].z = b.v[k].z = 0;
        break;
      case 6:  // segments and points on one line (exactly, on the grid): collinear directions
        a.v[2] = a.v[1];
        b.v[0] = a.v[0] + 0.5 * (a.v[1] - a.v[0]);
        b.v[1] = b.v[2] = a.v[0] + 2.0 * (a.v[1] - a.v[0]);
        break;
      case 7: {  // b lifted off a along a's normal by a small power of two
        const Vec3 n = cross(a.v[1] - a.v[0], a.v[2] - a.v[0]);
        const double lift = std::ldexp(1.0, -static_cast<int>(trial % 50));
        for (int k = 0; k < 3; ++k) b.v[k] = a.v[k] + lift * n + 0.1 * (b.v[k] - a.v[k]);
        break;
      }
      default: break;
    }
    const double size = std::ldexp(1.0, static_cast<int>(trial % 41) - 20);
    for (int k = 0; k < 3; ++k) a.v[k] = size * a.v[k], b.v[k] = size * b.v[k];
    RigidTransform pa, pb;
    if (trial % 3 != 0) {
      pa.rotation = rotation(uniform(random), uniform(random), uniform(random));
      pb.rotation = trial % 3 == 1 ? pa.rotation : rotation(uniform(random), uniform(random), uniform(random));
    }
    const double far = std::ldexp(1.0, static_cast<int>(trial % 61) - 20);
    pa.translation = far * point();
    pb.translation = trial % 4 ? pa.translation : far * point();
    compare(a, pa, b, pb, t, trial);
    compare_as_given(a, b, trial);
    if (HasFatalFailure()) return;
  }
  std::cout << "triangle_sat: " << t.cases << " pairs: " << t.hits << " hits (" << t.touching << " touching), "
            << t.apart << " apart, " << t.flat << " coplanar, " << t.collinear << " collinear or points" << std::endl;
  EXPECT_GT(t.touching, 100);
  EXPECT_GT(t.hits - t.touching, 200);
  EXPECT_GT(t.apart, 500);
  EXPECT_GT(t.flat, 100);
  EXPECT_GT(t.collinear, 50);
}

}  // namespace
}  // namespace cc::exact
