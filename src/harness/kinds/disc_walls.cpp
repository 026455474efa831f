// The disc_walls kind: pieces of a maze (the sides of a cell, sharing their ends at its corners;
// corridors of nearly parallel walls; 3-4-5 diagonal walls; pillars) on a grid of 1/16 of a cell,
// with a disc touching a wall's side, an end, a pillar or a corner exactly (3-4-5 offsets), a
// point disc on a wall, or a few ULPs either way; generic walls with a disc slid to an exact margin
// of them; walls and discs at random. Units of a power of two from 2^-1000 to 2^480 or a generic
// one, grids far from the origin. Out of contract: NaN and infinities, a negative radius. The
// library's calls, and what its cases are.
#include "harness/kinds/disc_walls.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "collide/disc_walls.h"
#include "harness/generation/regimes.h"
#include "harness/judging/configurations.h"
#include "harness/judging/features.h"

namespace cc::harness {
namespace {

Vec2 operator+(const Vec2& a, const Vec2& b) { return {a.x + b.x, a.y + b.y}; }
Vec2 operator-(const Vec2& a, const Vec2& b) { return {a.x - b.x, a.y - b.y}; }
Vec2 operator*(double s, const Vec2& a) { return {s * a.x, s * a.y}; }
double dot(const Vec2& a, const Vec2& b) { return a.x * b.x + a.y * b.y; }
double cross(const Vec2& a, const Vec2& b) { return a.x * b.y - a.y * b.x; }
double max_abs(const Vec2& a) { return std::max(std::fabs(a.x), std::fabs(a.y)); }
bool finite(const Vec2& a) { return std::isfinite(a.x) && std::isfinite(a.y); }
bool pillar(const Wall& w) { return w.a == w.b; }
Vec2 direction(const Wall& w) { return w.b - w.a; }

// A generic double in [1, 2): 52 random bits; the simplest is 1.
double generic_unit(Choices& c) { return 1 + static_cast<double>(c.draw(std::uint64_t{1} << 52)) * 0x1p-52; }

// A generic direction in the plane (components up to 2 in magnitude, some 0; never zero).
Vec2 draw_direction_2d(ValueSource& v) {
  const Vec3 d = draw_direction(v);
  return d.x == 0 && d.y == 0 ? Vec2{1, 0} : Vec2{d.x, d.y};
}

// --- maze pieces on a grid --------------------------------------------------------------------
// A construction is made in grid units (a cell is 16 units; every coordinate a small integer or
// a quarter, so every distance that is meant to be exact is), then placed: x -> unit * (origin +
// x), exact for a unit that is a power of two (grids far from the origin) and for a generic unit of 44
// bits near it (its products with numbers of up to 9 bits, quarters of the grid included).

constexpr double kCell = 16;

struct Pythagorean {
  double a, b, c;  // a^2 + b^2 = c^2
};
constexpr Pythagorean kTriples[] = {{3, 4, 5}, {0, 1, 1}, {5, 12, 13}, {8, 15, 17}, {4, 3, 5}};

struct Grid {
  double unit = 1;
  Vec2 origin;  // in units
  Vec2 at(const Vec2& p) const { return {unit * (origin.x + p.x), unit * (origin.y + p.y)}; }
};

Grid draw_grid(ValueSource& v) {
  Choices& c = v.choices();
  Grid g;
  switch (c.draw(10)) {
    case 7: g.unit = std::ldexp(1.0, -static_cast<int>(100 + c.draw(900))); break;  // tiny: down to 2^-999
    case 8: g.unit = std::ldexp(1.0, static_cast<int>(100 + c.draw(370))); break;   // huge: up to 2^469
    case 9: {  // a generic unit stays near the origin
      const int exponent = v.small_int(20);
      g.unit = std::ldexp(1.0, exponent) * (1 + static_cast<double>(c.draw(std::uint64_t{1} << 43)) * 0x1p-43);
      return g;
    }
    default: g.unit = std::ldexp(1.0, v.small_int(20));
  }
  if (c.chance(40)) {  // far from the origin: up to 2^30 cells away (the huge units stay below 2^500)
    const double reach = std::ldexp(1.0, static_cast<int>(c.draw(g.unit > 0x1p400 ? 8 : 31)));
    for (int k = 0; k < 2; ++k) {
      const double cells = std::floor(reach * generic_unit(c) / 2);
      (k == 0 ? g.origin.x : g.origin.y) = kCell * cells * (c.chance(50) ? -1 : 1);
    }
  }
  return g;
}

// A sign, either way.
double sign(Choices& c) { return c.chance(50) ? -1.0 : 1.0; }

// The sides of a cell at (0, 0), each kept with probability 3/4 (at least one) and its ends in
// either order, sharing their ends at the corners as a maze's walls do; sometimes the next
// cell's floor too.
std::vector<Wall> cell_walls(Choices& c) {
  const Vec2 p00{0, 0}, p10{kCell, 0}, p01{0, kCell}, p11{kCell, kCell};
  const Wall sides[] = {{p00, p10}, {p01, p11}, {p00, p01}, {p10, p11}};
  std::vector<Wall> walls;
  for (const Wall& w : sides) {
    if (!c.chance(25)) walls.push_back(c.chance(50) ? w : Wall{w.b, w.a});
  }
  if (walls.empty()) walls.push_back(sides[c.draw(4)]);
  if (c.chance(30)) walls.push_back({p10, {2 * kCell, 0}});  // the next cell's floor, sharing an end
  return walls;
}

// The disc against a wall of `walls` (in grid units): touching its side (a point of it plus the
// radius along its normal), touching an end or a pillar (a 3-4-5 offset, outward), a point disc
// on the wall, or anywhere in the cell.
Disc disc_against(const std::vector<Wall>& walls, Choices& c) {
  const Wall& w = walls[c.draw(walls.size())];
  const Vec2 d = direction(w);
  const double length = std::max(std::fabs(d.x), std::fabs(d.y));
  switch (c.draw(5)) {
    case 0: {  // a side: a grid point of the wall, then the radius along its normal
      const bool axis = d.x == 0 || d.y == 0;
      const bool diagonal = 4 * std::fabs(d.x) == 3 * std::fabs(d.y) || 3 * std::fabs(d.x) == 4 * std::fabs(d.y);
      if (pillar(w) || !(axis || diagonal)) break;
      // An axis wall is `length` steps of 1, a 3-4-5 wall m steps of (3, 4) or (4, 3): the normal
      // of a step is 1 or 5 long, so the radius is k or 5k and the offset exact.
      const double steps = axis ? length : length / 4;
      const Vec2 step{d.x / steps, d.y / steps};
      const double k = static_cast<double>(1 + c.draw(axis ? 8 : 2));
      const Vec2 point = w.a + static_cast<double>(c.draw(static_cast<std::uint64_t>(steps) + 1)) * step;
      return {point + (sign(c) * k) * Vec2{-step.y, step.x}, axis ? k : 5 * k};
    }
    case 1: {  // an end, or a pillar: a 3-4-5 offset pointing away from the wall
      const Pythagorean t = kTriples[c.draw(std::size(kTriples))];
      const double s = static_cast<double>(1 + c.draw(2));
      const bool at_b = c.chance(50);
      const Vec2 end = at_b ? w.b : w.a, away = at_b ? d : Vec2{-d.x, -d.y};
      Vec2 offset{sign(c) * t.a * s, sign(c) * t.b * s};
      if (dot(offset, away) < 0) offset = Vec2{-offset.x, -offset.y};  // outward: the end is the nearest point
      return {end + offset, t.c * s};
    }
    case 2:  // a point disc on the wall
      return {w.a + (static_cast<double>(c.draw(5)) / 4) * d, 0};
    default:
      break;
  }
  // Anywhere in or around the cell, with a radius up to half a cell.
  return {{static_cast<double>(c.draw(33)) - 8, static_cast<double>(c.draw(33)) - 8}, static_cast<double>(c.draw(9))};
}

// A 3-4-5 diagonal wall (m steps of (3, 4), signs drawn) from a grid point, or a pillar.
Wall diagonal_or_pillar(Choices& c) {
  const Vec2 a{static_cast<double>(c.draw(17)), static_cast<double>(c.draw(17))};
  if (c.chance(30)) return {a, a};
  const double m = static_cast<double>(1 + c.draw(3));
  const Vec2 step = c.chance(50) ? Vec2{3, 4} : Vec2{4, 3};
  return {a, a + Vec2{sign(c) * m * step.x, sign(c) * m * step.y}};
}

// Two long walls along x, a corridor, the second tilted by 2^-8 to 2^-52 (nearly parallel).
std::vector<Wall> corridor(Choices& c) {
  const double length = 3 * kCell, width = static_cast<double>(4 + c.draw(13));
  const int shift = 8 + static_cast<int>(c.draw(45));
  const double tilt = std::ldexp(generic_unit(c), -shift);
  return {{{0, 0}, {length, 0}}, {{0, width}, {length, width + tilt}}};
}

DiscWallsInput maze_piece(ValueSource& v) {
  Choices& c = v.choices();
  DiscWallsInput in;
  switch (c.draw(4)) {
    case 0: in.walls = corridor(c); break;
    case 1: {
      in.walls = {diagonal_or_pillar(c)};
      if (c.chance(50)) in.walls.push_back(diagonal_or_pillar(c));
      break;
    }
    default: in.walls = cell_walls(c);
  }
  in.disc = disc_against(in.walls, c);
  const Grid g = draw_grid(v);
  for (Wall& w : in.walls) w = {g.at(w.a), g.at(w.b)};
  in.disc = {g.at(in.disc.center), g.unit * in.disc.radius};
  // A few ULPs either way of the construction.
  switch (c.draw(6)) {
    case 0: in.disc.center.x = v.nudge(in.disc.center.x); break;
    case 1: in.disc.center.y = v.nudge(in.disc.center.y); break;
    case 2: in.disc.radius = std::fabs(v.nudge(in.disc.radius)); break;
    default: break;
  }
  return in;
}

// --- at the bound -------------------------------------------------------------------------

// A generic wall (or a pillar, or with a nearly parallel or an end-sharing companion) far from
// the origin compared with its size, and a disc slid from a point of it to an exact margin in
// the regimes of the library's bounds: radii from 0 to 2^20 times the wall's length.
DiscWallsInput disc_at_the_bound(ValueSource& v, const GenerateOptions& options) {
  Choices& c = v.choices();
  const double size = draw_size(v);
  const Vec3 far = draw_far_offset(v, size);
  const Vec2 a = Vec2{v.coordinate(), v.coordinate()} + Vec2{far.x, far.y};
  const Wall wall{a, c.chance(15) ? a : a + size * draw_direction_2d(v)};
  std::vector<Wall> walls = {wall};
  if (c.chance(30) && !pillar(wall)) {
    const Vec2 d = direction(wall);
    if (c.chance(50)) {  // a corner
      walls.push_back(Wall{wall.b, wall.b + std::ldexp(1.0, v.small_int(4)) * Vec2{-d.y, d.x}});
    } else {  // nearly parallel
      const int shift = 8 + static_cast<int>(c.draw(45));
      walls.push_back(Wall{wall.a + Vec2{-d.y, d.x}, wall.b + Vec2{-d.y, d.x} + std::ldexp(generic_unit(c), -shift) * d});
    }
  }
  double r = 0;
  switch (c.draw(4)) {
    case 0: r = 0; break;
    case 1: r = size; break;
    case 2: {
      const int shift = static_cast<int>(c.draw(41));
      r = std::ldexp(size * generic_unit(c), -shift);
      break;
    }
    default: {
      const int shift = static_cast<int>(c.draw(21));
      r = std::ldexp(size * generic_unit(c), shift);
    }
  }
  const double along = c.chance(50) ? static_cast<double>(c.draw(3)) / 2 : generic_unit(c) - 1;
  const Vec2 start = wall.a + along * direction(wall);
  const Vec2 w = c.chance(50) && !pillar(wall) ? Vec2{-direction(wall).y, direction(wall).x} : draw_direction_2d(v);
  const double length = std::sqrt(dot(w, w));
  const auto placed = [&walls, &start, &w, r](double s) { return DiscWallsInput{{start + s * w, r}, walls}; };
  const double contact = r / length;
  const double s = place_at([&placed](double t) -> Input { return placed(t); }, 0, 2 * contact + 2 * size / length,
                            draw_margin_target(c), options, contact);
  return placed(s);
}

// --- at random ------------------------------------------------------------------------------

Vec2 draw_point(ValueSource& v) { return {v.coordinate(), v.coordinate()}; }

DiscWallsInput at_random(ValueSource& v) {
  Choices& c = v.choices();
  DiscWallsInput in;
  in.disc = {draw_point(v), v.length()};
  in.walls.resize(1 + c.draw(4));
  for (Wall& w : in.walls) {
    w.a = draw_point(v);
    w.b = c.chance(20) ? w.a : (c.chance(30) ? in.disc.center : draw_point(v));
  }
  return in;
}

// Every value times 2^e, when each stays exact (no value leaves the normal range or passes 2^480).
void rescale(DiscWallsInput& in, int e) {
  const auto fits = [e](double x) {
    const double y = std::ldexp(x, e);
    return x == 0 || !std::isfinite(x) || (std::fabs(y) >= 0x1p-1022 && std::fabs(y) <= 0x1p480);
  };
  bool ok = fits(in.disc.center.x) && fits(in.disc.center.y) && fits(in.disc.radius);
  for (const Wall& w : in.walls) ok = ok && fits(w.a.x) && fits(w.a.y) && fits(w.b.x) && fits(w.b.y);
  if (!ok) return;
  const auto scale = [e](Vec2& p) { p = {std::ldexp(p.x, e), std::ldexp(p.y, e)}; };
  scale(in.disc.center);
  in.disc.radius = std::ldexp(in.disc.radius, e);
  for (Wall& w : in.walls) scale(w.a), scale(w.b);
}

void leave_the_contract(DiscWallsInput& in, ValueSource& v) {
  Choices& c = v.choices();
  const double specials[] = {NAN, INFINITY, -INFINITY};
  const double special = specials[c.draw(3)];
  switch (c.draw(6)) {
    case 0: in.disc.center.x = special; break;
    case 1: in.disc.center.y = special; break;
    case 2: in.disc.radius = special; break;
    case 3:
    case 4: in.disc.radius = in.disc.radius > 0 ? -in.disc.radius : -1.0; break;  // a negative radius
    default: {
      Wall& w = in.walls[c.draw(in.walls.size())];
      (c.chance(50) ? w.a : w.b).y = special;
    }
  }
}

Answer walls_answer(const std::vector<std::uint32_t>& touched) {
  Answer a = Answer::of(!touched.empty());
  for (std::uint32_t i : touched) a.pairs.emplace_back(i, 0);
  return a;
}

constexpr std::string_view kConfigurations[] = {
    "touching",   "just apart",          "just overlapping",      "touching a side",       "touching at an end",
    "point disc", "pillar",              "walls sharing an end",  "nearly parallel walls", "far from the origin",
    "tiny scale", "huge scale"};

}  // namespace

Answer Query<DiscWallsInput>::ask(const DiscWallsInput& in) {
  return walls_answer(disc_walls(in.disc, in.walls, DiscWallsMethod::disc_against_walls));
}

const std::vector<Party<DiscWallsInput>>& Query<DiscWallsInput>::library_parties() {
  static const std::vector<Party<DiscWallsInput>> parties = {
      {"library.disc_walls(point_against_grown_walls)", band, [](const DiscWallsInput& in) {
         return answered(walls_answer(disc_walls(in.disc, in.walls, DiscWallsMethod::point_against_grown_walls)));
       }}};
  return parties;
}

DiscWallsInput Query<DiscWallsInput>::generate(ValueSource& v, const GenerateOptions& options) {
  Choices& c = v.choices();
  DiscWallsInput in;
  switch (c.draw(10)) {
    case 0:
    case 1:
    case 2: in = disc_at_the_bound(v, options); break;
    case 3: in = at_random(v); break;
    default: in = maze_piece(v);
  }
  if (c.chance(10)) rescale(in, (c.chance(50) ? -1 : 1) * static_cast<int>(100 + c.draw(300)));
  if (options.out_of_contract && c.chance(25)) leave_the_contract(in, v);
  return in;
}

void Query<DiscWallsInput>::touch(DiscWallsInput& in, ValueSource& v) {
  Choices& c = v.choices();
  std::vector<std::size_t> finite;  // the walls a disc can touch
  for (std::size_t i = 0; i < in.walls.size(); ++i) {
    const Wall& w = in.walls[i];
    if (std::isfinite(w.a.x) && std::isfinite(w.a.y) && std::isfinite(w.b.x) && std::isfinite(w.b.y)) finite.push_back(i);
  }
  if (finite.empty()) {
    in.walls.push_back({in.disc.center, in.disc.center});
    finite.push_back(in.walls.size() - 1);
  }
  const Wall& w = in.walls[finite[c.draw(finite.size())]];
  const bool at_a = c.chance(50);
  const Vec2 end = at_a ? w.a : w.b, away = at_a ? w.a - w.b : w.b - w.a;
  // Along an axis, on the side away from the other end (so that the end is the nearest point).
  const bool along_x = c.chance(50);
  const double side = along_x ? away.x : away.y;
  const double offset = (side > 0 ? 1.0 : side < 0 ? -1.0 : sign(c)) * in.disc.radius;
  in.disc.center = along_x ? Vec2{end.x + offset, end.y} : Vec2{end.x, end.y + offset};
}

Features Query<DiscWallsInput>::features(const DiscWallsInput& in) {
  Features f;
  f.degenerate = in.disc.radius == 0;
  for (std::size_t i = 0; i < in.walls.size(); ++i) {
    const Wall& w = in.walls[i];
    f.degenerate |= pillar(w);
    if (pillar(w)) continue;
    const Vec2 d = direction(w);
    f.parallel |= d.x == 0 || d.y == 0;
    for (std::size_t j = 0; j < i; ++j) {
      if (!pillar(in.walls[j]) && cross(d, direction(in.walls[j])) == 0) f.parallel = true;
    }
  }
  return f;
}

std::span<const std::string_view> Query<DiscWallsInput>::configurations() { return kConfigurations; }

void Query<DiscWallsInput>::recognise(const DiscWallsInput& in, Configurations& found) {
  found.margins();
  const ExactVerdict& exact = found.exact();
  const Vec2 c = in.disc.center;
  bool side = false, end = false, shared = false, nearly = false;
  double largest = max_abs(c), size = std::fabs(in.disc.radius);
  for (std::size_t i = 0; i < in.walls.size(); ++i) {
    const Wall& w = in.walls[i];
    largest = std::max({largest, max_abs(w.a), max_abs(w.b)});
    size = std::max(size, max_abs(direction(w)));
    if (exact.contract == Contract::in && exact.decided && exact.margin_of({static_cast<std::uint32_t>(i), 0}) == 0 &&
        std::binary_search(exact.answer.pairs.begin(), exact.answer.pairs.end(), FacePair{static_cast<std::uint32_t>(i), 0})) {
      // Exactly touching: at a side when the centre projects strictly between the ends (as computed).
      const bool between = !pillar(w) && dot(c - w.a, direction(w)) > 0 && dot(c - w.b, direction(w)) < 0;
      (between ? side : end) = true;
    }
    for (std::size_t j = 0; j < i; ++j) {
      const Wall& o = in.walls[j];
      shared |= !pillar(w) && !pillar(o) && (w.a == o.a || w.a == o.b || w.b == o.a || w.b == o.b);
      const Vec2 d = direction(w), e = direction(o);
      const double ld = std::sqrt(dot(d, d)), le = std::sqrt(dot(e, e));
      const double sine = ld > 0 && le > 0 ? std::fabs(cross(d, e)) / (ld * le) : 0;
      nearly |= sine > 0 && sine <= kNearlyParallel;
    }
  }
  found.add("touching a side", side);
  found.add("touching at an end", end);
  found.add("point disc", in.disc.radius == 0);
  found.add("pillar", std::any_of(in.walls.begin(), in.walls.end(), pillar));
  found.add("walls sharing an end", shared);
  found.add("nearly parallel walls", nearly);
  found.far(largest, size);
  const bool finite_case = finite(c) && std::isfinite(in.disc.radius) && std::isfinite(largest);
  found.add("tiny scale", finite_case && largest > 0 && largest < 0x1p-100);
  found.add("huge scale", finite_case && largest >= 0x1p100);
}

std::span<const BoundTerm> Query<DiscWallsInput>::bound_terms() { return {}; }

void Query<DiscWallsInput>::probe(const DiscWallsInput&, std::vector<bounds::Records>&) {}

}  // namespace cc::harness
