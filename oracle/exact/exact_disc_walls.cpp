#include "oracle/exact/exact_disc_walls.h"

#include <algorithm>
#include <cmath>

#include "oracle/exact/domain.h"

namespace cc::exact {
namespace {

struct QVec2 {
  Rational x, y;
};

QVec2 rational(const Vec2& v) { return {exact::rational(v.x), exact::rational(v.y)}; }
Rational dot(const QVec2& a, const QVec2& b) { return a.x * b.x + a.y * b.y; }

// r - |c - wall| over the scale, computed as (r^2 - |c - wall|^2) / (r + |c - wall|) with
// exponents kept apart and the exact sign, so that it is 0 only for a wall the disc touches.
double wall_margin(const ExactDiscWall& e, double radius) {
  const Rational& slack = e.slack;
  if (sgn(slack) == 0) return 0;
  const Magnitude reach = Magnitude::of(exact::rational(radius)) + sqrt(Magnitude::of(e.distance2));
  const Magnitude scale = Magnitude::of(exact::rational(scale_of(e.scale)));
  return signed_margin((Magnitude::of(slack) / reach / scale).to_double(), sgn(slack));
}

}  // namespace

ExactDiscWall exact_disc_wall(const Disc& disc, const Wall& wall) {
  const QVec2 c = rational(disc.center), a = rational(wall.a), b = rational(wall.b);
  const QVec2 d{c.x - a.x, c.y - a.y}, w{b.x - a.x, b.y - a.y};
  const Rational ww = dot(w, w);
  ExactDiscWall e;
  e.pillar = sgn(ww) == 0;
  if (!e.pillar) e.t = std::clamp(Rational(dot(d, w) / ww), Rational(0), Rational(1));
  const Rational& t = e.t;
  const QVec2 gap{d.x - t * w.x, d.y - t * w.y};
  e.distance2 = dot(gap, gap);
  const Rational r = exact::rational(disc.radius);
  e.slack = r * r - e.distance2;
  e.touches = sgn(e.slack) >= 0;
  e.scale = max_magnitude({disc.center.x, disc.center.y, wall.a.x, wall.a.y, wall.b.x, wall.b.y, disc.radius});
  e.margin = wall_margin(e, disc.radius);
  return e;
}

bool disc_wall_answer_right(const ExactDiscWall& exact, const Disc& disc, bool says_touch, double band) {
  if (!says_touch) return !exact.touches;
  if (exact.touches) return true;
  const Rational reach = exact::rational(disc.radius) + exact::rational(band) * exact::rational(exact.scale);
  return exact.distance2 <= reach * reach;
}

}  // namespace cc::exact
