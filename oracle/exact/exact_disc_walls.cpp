#include "oracle/exact/exact_disc_walls.h"

#include <algorithm>
#include <cmath>

namespace cc::exact {
namespace {

struct QVec2 {
  Rational x, y;
};

QVec2 rational(const Vec2& v) { return {exact::rational(v.x), exact::rational(v.y)}; }
Rational dot(const QVec2& a, const QVec2& b) { return a.x * b.x + a.y * b.y; }

}  // namespace

ExactDiscWall exact_disc_wall(const Disc& disc, const Wall& wall) {
  const QVec2 c = rational(disc.center), a = rational(wall.a), b = rational(wall.b);
  const QVec2 d{c.x - a.x, c.y - a.y}, w{b.x - a.x, b.y - a.y};
  const Rational ww = dot(w, w);
  Rational t = 0;
  if (sgn(ww) > 0) t = std::clamp(Rational(dot(d, w) / ww), Rational(0), Rational(1));
  const QVec2 gap{d.x - t * w.x, d.y - t * w.y};
  ExactDiscWall e;
  e.distance2 = dot(gap, gap);
  const Rational r = exact::rational(disc.radius);
  e.touches = e.distance2 <= r * r;
  e.scale = max_magnitude({disc.center.x, disc.center.y, wall.a.x, wall.a.y, wall.b.x, wall.b.y, disc.radius});
  if (e.scale > 0) e.margin = (disc.radius - std::sqrt(to_double(e.distance2))) / e.scale;
  return e;
}

bool disc_wall_answer_right(const ExactDiscWall& exact, const Disc& disc, bool says_touch, double band) {
  if (!says_touch) return !exact.touches;
  if (exact.touches) return true;
  const Rational reach = exact::rational(disc.radius) + exact::rational(band) * exact::rational(exact.scale);
  return exact.distance2 <= reach * reach;
}

}  // namespace cc::exact
