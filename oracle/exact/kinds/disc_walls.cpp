// disc_walls in exact arithmetic: every wall on its own (exact_disc_walls.h): the squared distance
// from the disc's centre to the segment against the squared radius, and the wall's margin with
// its exact sign. The case's margin is the wall's nearest 0.
#include <algorithm>
#include <cmath>
#include <string>

#include "oracle/exact/domain.h"
#include "oracle/exact/exact_disc_walls.h"
#include "oracle/exact/explain.h"
#include "oracle/exact/judges.h"
#include "oracle/exact/rational.h"

namespace cc::exact {
namespace {

constexpr int kMaxExponent = 500;  // the library's domain: magnitudes up to 2^500

bool finite(const Wall& w) { return all_finite({w.a.x, w.a.y, w.b.x, w.b.y}); }

std::string point(const Vec2& p) {
  std::string s = "(";
  s.append(num(p.x)).append(", ").append(num(p.y)).append(")");
  return s;
}

// Where the segment's nearest point to c lies: an end, the side (the clamped projection
// parameter, exact), or the pillar.
std::string nearest_part(const ExactDiscWall& e) {
  if (e.pillar) return "pillar";
  if (sgn(e.t) == 0) return "end a";
  if (e.t == 1) return "end b";
  return "side, t = " + num(e.t);
}

}  // namespace

template <>
ExactVerdict judge(const harness::DiscWallsInput& in) {
  const Disc& disc = in.disc;
  if (!all_finite({disc.center.x, disc.center.y, disc.radius})) return documented(false, "NaN or infinite disc");
  if (disc.radius < 0) return documented(false, "negative radius");
  ExactVerdict v;
  v.unlisted_margin = -INFINITY;  // every wall is listed
  v.margin = -INFINITY;           // as far as no wall at all
  double magnitude = max_magnitude({disc.center.x, disc.center.y, disc.radius});
  for (std::uint32_t i = 0; i < in.walls.size(); ++i) {
    const Wall& w = in.walls[i];
    const harness::FacePair pair{i, 0};
    if (!finite(w)) {  // documented: a wall with a NaN or infinite end is never touched
      v.pair_margins.push_back({pair, -INFINITY});
      continue;
    }
    magnitude = std::max(magnitude, max_magnitude({w.a.x, w.a.y, w.b.x, w.b.y}));
    const ExactDiscWall e = exact_disc_wall(disc, w);
    const double margin = e.margin;
    if (e.touches) v.answer.pairs.push_back(pair);
    v.pair_margins.push_back({pair, margin});
    if (std::fabs(margin) < std::fabs(v.margin)) v.margin = margin;
  }
  v.answer.hit = !v.answer.pairs.empty();
  // Decided all the same beyond the library's range (the margins keep their exponents apart).
  if (magnitude > std::ldexp(1.0, kMaxExponent)) {
    return beyond_range(v, "a coordinate exceeds 2^" + std::to_string(kMaxExponent) + " in magnitude");
  }
  return v;
}

template <>
harness::Explanation explain(const harness::DiscWallsInput& in) {
  using harness::Explanation;
  const ExactVerdict v = judge(in);
  Explanation e;
  e.title = "walls (the squared distance from the centre to each segment, exact)";
  e.columns = {"wall", "a", "b", "nearest part", "r^2 - |c - wall|^2", "touches", "margin"};
  int deciding = -1;
  Rational deciding_slack;
  double deciding_size = 0;
  for (std::uint32_t i = 0; i < in.walls.size(); ++i) {
    const Wall& w = in.walls[i];
    const double margin = v.margin_of({i, 0});
    if (!finite(w)) {
      e.rows.push_back({std::to_string(i), point(w.a), point(w.b), "-", "-", "never (NaN or infinite end)", num(margin)});
      continue;
    }
    const ExactDiscWall x = exact_disc_wall(in.disc, w);
    const Rational& slack = x.slack;
    e.rows.push_back({std::to_string(i), point(w.a), point(w.b), nearest_part(x), num(slack),
                      x.touches ? "yes" : "no", num(margin)});
    if (deciding < 0 && margin == v.margin) {
      deciding = static_cast<int>(i);
      deciding_slack = slack;
      deciding_size = std::max(to_double(rational(in.disc.radius) * rational(in.disc.radius)), to_double(x.distance2));
    }
  }
  e.facts = {{"disc", "centre " + point(in.disc.center) + ", radius " + num(in.disc.radius)},
             {"walls", std::to_string(in.walls.size())},
             {"walls touched", std::to_string(v.answer.pairs.size())}};
  if (deciding < 0) {
    e.deciding = "no wall";
    return e;
  }
  e.deciding_row = deciding;
  e.deciding = "r^2 - |c - wall " + std::to_string(deciding) + "|^2, the wall nearest the boundary";
  e.deciding_value = to_double(deciding_slack);
  e.deciding_ulps = in_ulps(e.deciding_value, deciding_size);
  return e;
}

}  // namespace cc::exact
