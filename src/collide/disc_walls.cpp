#include "collide/disc_walls.h"

#include <algorithm>
#include <cmath>

#include "collide/fp.h"

namespace cc {
namespace {

using fp::u;

Vec2 operator-(const Vec2& a, const Vec2& b) { return {a.x - b.x, a.y - b.y}; }
double dot(const Vec2& a, const Vec2& b) { return a.x * b.x + a.y * b.y; }
double abs_dot(const Vec2& a, const Vec2& b) { return std::fabs(a.x * b.x) + std::fabs(a.y * b.y); }
double max_abs(const Vec2& a) { return std::max(std::fabs(a.x), std::fabs(a.y)); }
bool finite(const Vec2& a) { return fp::finite(a.x) && fp::finite(a.y); }
Vec2 scaled(const Vec2& a, int e) { return {fp::scale2(a.x, e), fp::scale2(a.y, e)}; }

// The differences both methods start from, each rounded once (relatively, or exact), then
// scaled by powers of two (exactly): d = c - a, e = c - b and r with the largest in [1, 2), and
// the wall's direction w = b - a with its largest component in [1, 2) (the tests below are
// homogeneous in w). The ends are taken in lexicographic order, so that swapping them changes
// nothing.
struct Frame {
  Vec2 d, e, w;
  double r;
  bool point_wall;  // a == b
};

Frame frame(const Vec2& c, double radius, const Wall& wall) {
  const bool ordered = wall.a.x < wall.b.x || (wall.a.x == wall.b.x && wall.a.y <= wall.b.y);
  const Vec2& a = ordered ? wall.a : wall.b;
  const Vec2& b = ordered ? wall.b : wall.a;
  Frame f{c - a, c - b, b - a, radius, a == b};
  const double m = std::max({max_abs(f.d), max_abs(f.e), std::fabs(radius)});
  if (m > 0 && std::isfinite(m)) {
    const int k = fp::exponent_of(m);
    f.d = scaled(f.d, -k), f.e = scaled(f.e, -k), f.r = fp::scale2(radius, -k);
  }
  const double mw = max_abs(f.w);
  if (mw > 0 && std::isfinite(mw)) f.w = scaled(f.w, -fp::exponent_of(mw));
  return f;
}

bool in_contract(const Vec2& c, double radius, const Wall& wall) {
  return finite(c) && finite(wall.a) && finite(wall.b) && fp::finite(radius) && radius >= 0;
}

// Each bound below covers the rounding of the differences (u each), of the products and sums,
// and of the final comparison's subtraction, with a factor of 2 to spare; subnormal_slack
// covers squares and products that underflow (relative to the scaled largest value, 1).

// |v| <= r, compared as squares: |v . v - r^2| errs by at most 6u (v . v + r^2).
bool within_squared(const Vec2& v, double r) {
  const double vv = dot(v, v), rr = r * r;
  return vv - rr <= 16 * u * (vv + rr) + fp::subnormal_slack;
}

// The centre projects between the ends: d . w >= 0 >= e . w (each product errs by 3u).
bool between_ends(const Vec2& d, const Vec2& e, const Vec2& w) {
  return dot(d, w) >= -(8 * u * abs_dot(d, w) + fp::subnormal_slack) &&
         dot(e, w) <= 8 * u * abs_dot(e, w) + fp::subnormal_slack;
}

// The line through the wall within r of the centre: |cross(w, d)| <= r |w|, compared as lengths
// (as squares the bound would have to cover the cross product's error squared, which lets a
// small disc reach a line sqrt(u) of the scale away). With P = |w_x d_y| + |w_y d_x|, the cross
// product of the rounded differences errs by at most 5u P, and r |w| by 4u of it.
bool line_within(const Vec2& d, const Vec2& w, double r) {
  const double cross = std::fabs(w.x * d.y - w.y * d.x);
  const double p = std::fabs(w.x * d.y) + std::fabs(w.y * d.x);
  const double reach = r * std::sqrt(dot(w, w));
  return cross - reach <= 16 * u * (p + reach) + fp::subnormal_slack;
}

// |v| <= r by a square root: sqrt(v . v) errs by 3u of it, and by 2^-537 when v . v underflows.
bool within_length(const Vec2& v, double r) {
  const double length = std::sqrt(dot(v, v));
  return length - r <= 8 * u * (length + r) + 0x1p-536;
}

// The grown wall's band: |n . d| <= r between the ends, with t = w / |w| and n = (-t_y, t_x)
// as computed (each component within 5u of the exact unit vectors).
bool within_band(const Vec2& d, const Vec2& e, const Vec2& w, double r) {
  const double length = std::sqrt(dot(w, w));
  const Vec2 t{w.x / length, w.y / length}, n{-t.y, t.x};
  const bool between = dot(d, t) >= -(16 * u * abs_dot(d, t) + fp::subnormal_slack) &&
                       dot(e, t) <= 16 * u * abs_dot(e, t) + fp::subnormal_slack;
  return between && std::fabs(dot(n, d)) - r <= 16 * u * (abs_dot(n, d) + r) + fp::subnormal_slack;
}

}  // namespace

bool test_disc_wall(const Disc& disc, const Wall& wall) {
  const Frame f = frame(disc.center, disc.radius, wall);
  const bool hit = within_squared(f.d, f.r) || within_squared(f.e, f.r) ||
                   (!f.point_wall && between_ends(f.d, f.e, f.w) && line_within(f.d, f.w, f.r));
  return hit && in_contract(disc.center, disc.radius, wall);  // out of contract: false
}

bool test_point_grown_wall(const Vec2& center, double radius, const Wall& wall) {
  const Frame f = frame(center, radius, wall);
  const bool hit = within_length(f.d, f.r) || within_length(f.e, f.r) || (!f.point_wall && within_band(f.d, f.e, f.w, f.r));
  return hit && in_contract(center, radius, wall);
}

std::vector<std::uint32_t> disc_walls(const Disc& disc, std::span<const Wall> walls, DiscWallsMethod method) {
  std::vector<std::uint32_t> touched;
  for (std::size_t i = 0; i < walls.size(); ++i) {
    const bool hit = method == DiscWallsMethod::disc_against_walls ? test_disc_wall(disc, walls[i])
                                                                    : test_point_grown_wall(disc.center, disc.radius, walls[i]);
    if (hit) touched.push_back(static_cast<std::uint32_t>(i));
  }
  return touched;
}

}  // namespace cc
