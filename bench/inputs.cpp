#include "bench/inputs.h"

#include <cmath>
#include <cstdlib>
#include <random>
#include <span>
#include <string>

#include "collide/triangle_box.h"
#include "collide/triangle_triangle.h"
#include "harness/generation/rotation.h"

namespace cc::bench {
namespace {

using Rng = std::mt19937_64;

double uniform(Rng& rng, double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }
Vec3 uniform_vec(Rng& rng, double lo, double hi) { return {uniform(rng, lo, hi), uniform(rng, lo, hi), uniform(rng, lo, hi)}; }

Mat3 random_rotation(Rng& rng) {
  std::normal_distribution<double> n;
  return harness::from_quaternion(n(rng), n(rng), n(rng), n(rng));
}

Obb random_obb(Rng& rng, double region, double min_half, double max_half) {
  return {uniform_vec(rng, -region, region), uniform_vec(rng, min_half, max_half), random_rotation(rng)};
}

Triangle random_triangle(Rng& rng, double region, double reach) {
  const Vec3 c = uniform_vec(rng, -region, region);
  return {{c + uniform_vec(rng, -reach, reach), c + uniform_vec(rng, -reach, reach), c + uniform_vec(rng, -reach, reach)}};
}

// Where a shape is, and the same shape translated.
Vec3 center_of(const Aabb& b) { return 0.5 * (b.lo + b.hi); }
Vec3 center_of(const Sphere& s) { return s.center; }
Vec3 center_of(const Obb& b) { return b.center; }
Vec3 center_of(const Triangle& t) { return (1.0 / 3) * (t.v[0] + t.v[1] + t.v[2]); }
Vec3 center_of(const Cloud& c) {
  Vec3 sum;
  for (const Vec3& p : c) sum = sum + p;
  return (1.0 / static_cast<double>(c.size())) * sum;
}
Aabb moved(Aabb b, const Vec3& v) { return {b.lo + v, b.hi + v}; }
Sphere moved(Sphere s, const Vec3& v) { return {s.center + v, s.radius}; }
Obb moved(Obb b, const Vec3& v) { return {b.center + v, b.half, b.axes}; }
Triangle moved(Triangle t, const Vec3& v) { return {{t.v[0] + v, t.v[1] + v, t.v[2] + v}}; }
Cloud moved(Cloud c, const Vec3& v) {
  for (Vec3& p : c) p = p + v;
  return c;
}

// The near-contact mix: b moved along the line of centres to the library's first contact (see
// Mix). s = -1 puts b's centre on a's (the shapes overlap: both contain their centres); s grows
// until they part, then bisection down to adjacent doubles.
template <class A, class B, class Test>
void bring_to_contact(Pairs<A, B>& p, Test test) {
  for (std::size_t i = 0; i < p.a.size(); ++i) {
    Vec3 d = center_of(p.b[i]) - center_of(p.a[i]);
    if (max_abs(d) == 0) d = {1, 0, 0};
    const B start = p.b[i];
    const auto hit_at = [&](double s) { return test(p.a[i], moved(start, s * d)); };
    double lo = -1, hi = 1;
    if (!hit_at(lo)) continue;  // leave a pair that does not fit the recipe as it is
    for (int k = 0; k < 60 && hit_at(hi); ++k) hi *= 2;
    for (int k = 0; k < 200 && std::nextafter(lo, hi) != hi; ++k) {
      const double mid = lo + (hi - lo) / 2;
      (hit_at(mid) ? lo : hi) = mid;
    }
    p.b[i] = moved(start, (i % 2 == 0 ? lo : hi) * d);
  }
}

template <class A, class B, class Make, class Test>
Pairs<A, B> make_pairs(Mix mix, std::uint64_t stream, Make make, Test test) {
  Rng rng(seed() ^ (stream * 0x9E3779B97F4A7C15ull));
  Pairs<A, B> p;
  for (std::size_t i = 0; i < kPairs; ++i) {
    auto [a, b] = make(rng);
    p.a.push_back(a);
    p.b.push_back(b);
  }
  if (mix == Mix::near) bring_to_contact(p, test);
  return p;
}

template <int K>
bool clouds_overlap(const Cloud& a, const Cloud& b) {
  return test_kdop_kdop(fit_kdop<K>(a), fit_kdop<K>(b));
}

}  // namespace

std::uint64_t seed() {
  static const std::uint64_t s = [] {
    const char* text = std::getenv("CROSSCHECK_BENCH_SEED");
    return text ? std::strtoull(text, nullptr, 10) : std::uint64_t{1};
  }();
  return s;
}

std::string_view to_string(Mix m) { return m == Mix::mixed ? "mixed" : "near"; }

Pairs<Aabb, Aabb> aabb_pairs(Mix mix) {
  const auto make = [](Rng& rng) {
    const auto box = [&] {
      const Vec3 c = uniform_vec(rng, -1, 1), h = uniform_vec(rng, 0.1, 0.8);
      return Aabb{c - h, c + h};
    };
    const Aabb a = box();
    return std::pair{a, box()};
  };
  return make_pairs<Aabb, Aabb>(mix, 1, make, test_aabb_aabb);
}

Pairs<Sphere, Sphere> sphere_pairs(Mix mix) {
  const auto make = [](Rng& rng) {
    const Sphere a{uniform_vec(rng, -1, 1), uniform(rng, 0.1, 0.8)};
    return std::pair{a, Sphere{uniform_vec(rng, -1, 1), uniform(rng, 0.1, 0.8)}};
  };
  return make_pairs<Sphere, Sphere>(mix, 2, make, test_sphere_sphere);
}

Pairs<Obb, Obb> obb_pairs(Mix mix) {
  const auto make = [](Rng& rng) {
    const Obb a = random_obb(rng, 1, 0.1, 0.6);
    return std::pair{a, random_obb(rng, 1, 0.1, 0.6)};
  };
  return make_pairs<Obb, Obb>(mix, 3, make, test_obb_obb);
}

Pairs<Triangle, Obb> triangle_obb_pairs(Mix mix) {
  const auto make = [](Rng& rng) {
    const Triangle t = random_triangle(rng, 1, 0.6);
    return std::pair{t, random_obb(rng, 1, 0.1, 0.6)};
  };
  return make_pairs<Triangle, Obb>(mix, 4, make, test_triangle_obb);
}

Pairs<Triangle, Triangle> triangle_pairs(Mix mix) {
  const auto make = [](Rng& rng) {
    const Triangle a = random_triangle(rng, 0.8, 0.6);
    return std::pair{a, random_triangle(rng, 0.8, 0.6)};
  };
  return make_pairs<Triangle, Triangle>(mix, 5, make, test_triangle_triangle);
}

Pairs<Cloud, Cloud> cloud_pairs(Mix mix, int k) {
  const auto make = [](Rng& rng) {
    const auto cloud = [&] {
      const Vec3 c = uniform_vec(rng, -1, 1), h = uniform_vec(rng, 0.1, 0.6);
      Cloud points;
      for (std::size_t j = 0; j < kCloudPoints; ++j) {
        points.push_back({c.x + uniform(rng, -h.x, h.x), c.y + uniform(rng, -h.y, h.y), c.z + uniform(rng, -h.z, h.z)});
      }
      return points;
    };
    Cloud a = cloud();
    return std::pair{a, cloud()};
  };
  if (k == 16) return make_pairs<Cloud, Cloud>(mix, 6, make, clouds_overlap<16>);
  if (k == 24) return make_pairs<Cloud, Cloud>(mix, 6, make, clouds_overlap<24>);
  return make_pairs<Cloud, Cloud>(mix, 6, make, clouds_overlap<18>);
}

RayScene ray_scene() {
  Rng rng(seed() ^ 0x5EEDull);
  RayScene s;
  for (std::size_t i = 0; i < kBoxes; ++i) {
    const Vec3 c = uniform_vec(rng, -4, 4), h = uniform_vec(rng, 0.5, 1.5);
    s.boxes.push_back({c - h, c + h});
  }
  std::normal_distribution<double> n;
  for (std::size_t i = 0; i < kRays; ++i) {
    Vec3 dir{n(rng), n(rng), n(rng)};
    if (i % 16 == 15) dir[static_cast<int>(i / 16 % 3)] = 0;
    s.rays.push_back({uniform_vec(rng, -8, 8), dir, 0, INFINITY});
  }
  return s;
}

}  // namespace cc::bench
