// disc_walls's second opinion from Chipmunk: cpShapesCollide on a cpCircleShape (the disc: its
// radius, the centre as its offset) and a cpSegmentShape of radius 0 per wall (the walls are
// segments of no thickness), both on one static body at the origin (its transform the identity,
// which maps every finite point to itself exactly), no neighbours set (so no end cap is
// rejected); the wall is touched when the contact set's count is > 0. Chipmunk's test is static,
// as the kind's question is: the disc against each wall where it stands, nothing swept.
//
// Band, read from cpCollision.c (CircleToSegment, which cpCollide picks for a circle and a
// segment; cpShapesCollide only copies its contacts): t = clamp01(w . (c - a) / |w|^2), w = b - a,
// the nearest point q = a + t w, and a contact when |q - c|^2 < (r + 0)^2; no slop or epsilon.
// Strictly less: a disc touching a wall exactly, and a point disc (radius 0) anywhere, is a miss
// for Chipmunk, a difference of meaning at margin 0. Rounding, with S the wall's scale (the
// largest |coordinate| of the centre and the wall, or the radius) and u = 2^-53: w and c - a
// carry 2uS per component, so t is off by at most 4u |c - a| / |w| + 5u |t| (t clamped the same
// way beyond [-1, 2]), which moves q along the wall by at most 4u |c - a| + 10u |w| <= 40uS and,
// since q stays on the wall, only lengthens |q - c|, by at most as much; a + t w rounds by 5uS
// per component (7uS); q - c, the sum of squares and r^2 add about 3u of the distance and the
// radius. About 50uS either way: the band is 2^-46 (128u) two-sided. No product is scaled: where
// the squares underflow (scales below about 2^-511) the test compares rounded zeros (a disc
// overlapping a wall is missed, a wall whose |w|^2 is 0 is taken at an end), a defect of
// Chipmunk's beyond any band; within the kind's domain (2^500) none overflows. NaN or infinite
// inputs and a negative radius are not asked.
#include <chipmunk/chipmunk.h>

#include <cmath>
#include <cstdint>
#include <memory>

#include "oracle/chipmunk/parties.h"

namespace cc::chipmunk_oracle {
namespace {

struct BodyFree {
  void operator()(cpBody* b) const { cpBodyFree(b); }
};
struct ShapeFree {
  void operator()(cpShape* s) const { cpShapeFree(s); }
};
using Body = std::unique_ptr<cpBody, BodyFree>;
using Shape = std::unique_ptr<cpShape, ShapeFree>;

bool finite(const Vec2& p) { return std::isfinite(p.x) && std::isfinite(p.y); }
cpVect to_cp(const Vec2& p) { return cpv(p.x, p.y); }

Opinion collide_disc_walls(const harness::DiscWallsInput& in) {
  if (!(in.disc.radius >= 0 && std::isfinite(in.disc.radius) && finite(in.disc.center))) {
    return not_applicable("a negative, NaN or infinite radius or centre");
  }
  for (const Wall& w : in.walls) {
    if (!finite(w.a) || !finite(w.b)) return not_applicable("a wall with a NaN or infinite end");
  }
  const Body body(cpBodyNewStatic());
  const Shape disc(cpCircleShapeNew(body.get(), in.disc.radius, to_cp(in.disc.center)));
  cpShapeCacheBB(disc.get());  // places the shape by its body: centre as given
  harness::Answer answer;
  for (std::uint32_t i = 0; i < in.walls.size(); ++i) {
    const Shape wall(cpSegmentShapeNew(body.get(), to_cp(in.walls[i].a), to_cp(in.walls[i].b), 0));
    cpShapeCacheBB(wall.get());
    if (cpShapesCollide(disc.get(), wall.get()).count > 0) answer.pairs.emplace_back(i, 0);
  }
  answer.hit = !answer.pairs.empty();
  return answered(answer);
}

}  // namespace

template <>
const std::vector<Party<harness::DiscWallsInput>>& chipmunk_parties() {
  static const std::vector<Party<harness::DiscWallsInput>> parties = {chipmunk_party<harness::DiscWallsInput>(
      "chipmunk.cpShapesCollide(cpCircleShape,cpSegmentShape)",
      {0x1p-46, BandSides::two_sided, 0,
       "CircleToSegment: the clamped projection t, q = a + t w and |q - c|^2 < r^2 strictly, no epsilon: about "
       "50u of the scale (t's error moves q along the wall by 40u at most); touching is a miss"},
      collide_disc_walls)};
  return parties;
}

}  // namespace cc::chipmunk_oracle
