// The tri_tri_distance kind: tri_tri's cases (touching at vertices and edges, crossing, coplanar
// and nearly coplanar pairs, slivers and degenerate triangles at the bound, far from the origin),
// and pairs built around a closest pair of features at a drawn gap (0, 2^0 down to 2^-60 of their
// size, or crossing by as much): parallel faces and parallel edges (closest pairs not unique),
// a vertex over a face, crossing edges, a segment or point triangle over a face; scaled by 2^-300
// to 2^300. The library's call, and what its cases are.
#include "harness/kinds/tri_tri_distance.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "collide/record_sink.h"
#include "collide/triangle_distance.h"
#include "collide/triangle_distance_bound.h"
#include "harness/generation/gaps.h"
#include "harness/generation/regimes.h"
#include "harness/generation/rotation.h"
#include "harness/generation/triangles.h"
#include "harness/judging/configurations.h"
#include "harness/kinds/tri_tri.h"
#include "harness/kinds/separation_answer.h"

namespace cc::harness {
namespace {

// A plane of a drawn frame through a drawn point: s, t along its first two axes and h along the
// third, in units of a drawn size.
struct Plane {
  Vec3 at, u, w, n;
  Vec3 operator()(double s, double t, double h) const { return at + s * u + t * w + h * n; }
};

Plane draw_plane(ValueSource& v) {
  const double size = draw_size(v);
  const Mat3 frame = draw_rotation(v);
  return {v.point(), size * frame.col[0], size * frame.col[1], size * frame.col[2]};
}

// Two triangles whose closest features are drawn: a in the plane h = 0, b at the gap above it.
TriTriDistanceInput closest_features(ValueSource& v) {
  Choices& c = v.choices();
  const Plane p = draw_plane(v);
  const double gap = draw_gap(c);
  const auto unit = [&c] { return static_cast<double>(c.draw(33)) / 16 - 1; };  // -1 .. 1 by 1/16
  TriTriDistanceInput in;
  switch (c.draw(5)) {
    case 0:  // parallel faces, their projections overlapping: closest pairs not unique
      in.a = {{p(-1, -1, 0), p(1, -1, 0), p(-1, 1, 0)}};
      in.b = {{p(unit(), unit(), gap), p(unit(), unit(), gap), p(unit(), unit(), gap)}};
      break;
    case 1:  // a vertex of b over the face of a, b's other vertices farther up
      in.a = {{p(-1, -1, 0), p(1, -1, 0), p(-1, 1, 0)}};
      in.b = {{p(-0.5, -0.5, gap), p(unit(), unit(), gap + 1), p(unit(), unit(), gap + 0.5)}};
      break;
    case 2:  // an edge of a under a crossing edge of b, the third vertices away from each other
      in.a = {{p(-1, 0, 0), p(1, 0, 0), p(unit(), unit(), -1)}};
      in.b = {{p(0, -1, gap), p(0, 1, gap), p(unit(), unit(), gap + 1)}};
      break;
    case 3:  // parallel edges overlapping along their length: closest pairs not unique
      in.a = {{p(-1, 0, 0), p(1, 0, 0), p(unit(), unit(), -1)}};
      in.b = {{p(-0.5, 0, gap), p(1.5, 0, gap), p(unit(), unit(), gap + 1)}};
      break;
    default: {  // a segment or a point over the face of a
      in.a = {{p(-1, -1, 0), p(1, -1, 0), p(-1, 1, 0)}};
      const Vec3 q = p(-0.5, -0.5, gap);
      in.b = {{q, c.chance(50) ? q : p(unit(), unit(), gap + 1), q}};
    }
  }
  shuffle_vertices(c, in.a);
  shuffle_vertices(c, in.b);
  return in;
}

// The bounds of the answer: the distance's whole bound (certified after the fact: no term of its
// own), the witnesses' rounding and whole bound.
constexpr BoundTerm kBoundTerms[] = {{"distance_triangle_triangle", "signed distance", "total"},
                                     {"distance_triangle_triangle", "witness", "rounding"},
                                     {"distance_triangle_triangle", "witness", "total"}};

constexpr std::string_view kConfigurations[] = {
    "touching", "just apart", "just overlapping", "apart", "segment triangle", "point triangle", "sliver",
    "parallel faces", "parallel edges", "tiny", "huge", "far from the origin"};

}  // namespace

Answer Query<TriTriDistanceInput>::ask(const TriTriDistanceInput& in) {
  return separation_answer(distance_triangle_triangle(in.a, in.b));
}

TriTriDistanceInput Query<TriTriDistanceInput>::generate(ValueSource& v, const GenerateOptions& options) {
  // Out of contract (NaN, infinities, beyond 2^300), the two-triangle generator's cases only.
  TriTriDistanceInput in;
  if (options.out_of_contract || v.choices().chance(40)) {
    const TriTriInput pair = Query<TriTriInput>::generate(v, options);
    in = {pair.a, pair.b};
  } else {
    in = closest_features(v);
  }
  if (!options.out_of_contract && v.choices().chance(30)) {
    Triangle &a = in.a, &b = in.b;
    scale_by_a_power_of_two(v.choices(), {&a.v[0].x, &a.v[0].y, &a.v[0].z, &a.v[1].x, &a.v[1].y, &a.v[1].z, &a.v[2].x,
                                          &a.v[2].y, &a.v[2].z, &b.v[0].x, &b.v[0].y, &b.v[0].z, &b.v[1].x, &b.v[1].y,
                                          &b.v[1].z, &b.v[2].x, &b.v[2].y, &b.v[2].z});
  }
  if (v.choices().chance(50)) std::swap(in.a, in.b);
  return in;
}

void Query<TriTriDistanceInput>::touch(TriTriDistanceInput& in, ValueSource& v) {
  TriTriInput pair{in.a, in.b};
  Query<TriTriInput>::touch(pair, v);
  in = {pair.a, pair.b};
}

Features Query<TriTriDistanceInput>::features(const TriTriDistanceInput& in) {
  return Query<TriTriInput>::features({in.a, in.b});
}

std::span<const std::string_view> Query<TriTriDistanceInput>::configurations() { return kConfigurations; }

void Query<TriTriDistanceInput>::recognise(const TriTriDistanceInput& in, Configurations& found) {
  found.margins();
  const ExactVerdict& exact = found.exact();
  found.add("apart", exact.contract == Contract::in && exact.decided && exact.margin < -kJust);
  found.triangle(in.a), found.triangle(in.b);
  found.add("parallel faces", parallel(normal(in.a), normal(in.b)) && !coplanar(in.a, in.b));
  found.add("parallel edges", parallel_edges(in.a, in.b));
  const double largest = std::max(max_coordinate(in.a), max_coordinate(in.b));
  found.add("tiny", largest > 0 && largest < 0x1p-200);
  found.add("huge", largest > 0x1p200);
  found.far(largest, std::max(longest_edge(in.a), longest_edge(in.b)));
}

std::span<const BoundTerm> Query<TriTriDistanceInput>::bound_terms() { return kBoundTerms; }

void Query<TriTriDistanceInput>::probe(const TriTriDistanceInput& in, std::vector<bounds::Records>& records) {
  distance_triangle_triangle(in.a, in.b, bounds::next_call(records));
}

}  // namespace cc::harness
