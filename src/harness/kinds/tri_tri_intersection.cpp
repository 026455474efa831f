// The tri_tri_intersection kind: tri_tri's cases (touching at vertices and edges, coplanar and
// nearly coplanar pairs, slivers and degenerate triangles at the bound), and two of its own: a
// triangle crossing another's plane at a grazing angle (2^-4 to 2^-45), where the corners are
// ill-conditioned, and coplanar triangles of integer points on a tilted plane, which meet in
// polygons of up to six corners with vertices on edges and edges along edges. The library's call,
// and what its cases are.
#include "harness/kinds/tri_tri_intersection.h"

#include <algorithm>
#include <cmath>

#include "collide/triangle_intersection.h"
#include "harness/generation/regimes.h"
#include "harness/generation/rotation.h"
#include "harness/generation/triangles.h"
#include "harness/judging/configurations.h"
#include "harness/kinds/tri_tri.h"

namespace cc::harness {
namespace {

// b crossing the plane of a at a grazing angle: its vertices about a's plane, tilted out of it
// by 2^-4 to 2^-45 of a's size, one side against the other two.
TriTriIntersectionInput grazing(ValueSource& v) {
  Choices& c = v.choices();
  const double size = draw_size(v);
  const Mat3 frame = draw_rotation(v);
  const Vec3 at = v.point();
  const Vec3 u = size * frame.col[0], w = size * frame.col[1], n = size * frame.col[2];
  const auto in_plane = [&](double s, double t) { return at + s * u + t * w; };
  const auto unit = [&c] { return static_cast<double>(c.draw(33)) / 16 - 1; };  // -1 .. 1 by 1/16
  TriTriIntersectionInput in;
  in.a = {{in_plane(unit(), unit()), in_plane(unit(), unit()), in_plane(unit(), unit())}};
  const double tilt = std::ldexp(1.0, -4 - static_cast<int>(c.draw(42)));
  for (int i = 0; i < 3; ++i) in.b.v[i] = in_plane(unit(), unit()) + (i == 0 ? tilt : -tilt) * n;
  shuffle_vertices(c, in.b);
  if (c.chance(50)) std::swap(in.a, in.b);
  return in;
}

// Two triangles of integer points on the plane z = k - p x - q y, in a unit of 2^e: polygons,
// vertices on edges, edges along edges, shared vertices.
TriTriIntersectionInput coplanar_polygons(ValueSource& v) {
  Choices& c = v.choices();
  const double p = static_cast<double>(c.draw(5)) - 2, q = static_cast<double>(c.draw(5)) - 2, k = static_cast<double>(c.draw(9)) - 4;
  const int e = static_cast<int>(c.draw(41)) - 20;
  const int axis = static_cast<int>(c.draw(3));  // which coordinate the plane gives
  TriTriIntersectionInput in;
  for (Triangle* t : {&in.a, &in.b}) {
    for (Vec3& vertex : t->v) {
      const double x = static_cast<double>(c.draw(13)) - 6, y = static_cast<double>(c.draw(13)) - 6;
      Vec3 point;
      point[(axis + 1) % 3] = std::ldexp(x, e);
      point[(axis + 2) % 3] = std::ldexp(y, e);
      point[axis] = std::ldexp(k - p * x - q * y, e);
      vertex = point;
    }
  }
  if (c.chance(20)) in.b.v[0] = in.a.v[c.draw(3)];
  return in;
}

constexpr std::string_view kConfigurations[] = {
    "touching", "just apart", "just overlapping", "segment triangle", "point triangle", "sliver", "meet at a point",
    "meet along a segment", "meet in a polygon", "coplanar", "nearly coplanar", "ill-conditioned corner",
    "far from the origin"};

}  // namespace

Answer Query<TriTriIntersectionInput>::ask(const TriTriIntersectionInput& in) {
  const TriangleIntersection r = intersect_triangles(in.a, in.b);
  Answer answer = Answer::of(!r.empty());
  for (int i = 0; i < r.count; ++i) {
    for (int k = 0; k < 3; ++k) answer.params.push_back(r.points[static_cast<std::size_t>(i)][k]);
  }
  return answer;
}

TriTriIntersectionInput Query<TriTriIntersectionInput>::generate(ValueSource& v, const GenerateOptions& options) {
  // Out of contract (NaN, infinities, beyond 2^300), the two-triangle generator's cases only.
  switch (options.out_of_contract ? 2 : v.choices().draw(5)) {
    case 0: return grazing(v);
    case 1: return coplanar_polygons(v);
    default: {
      const TriTriInput in = Query<TriTriInput>::generate(v, options);
      return {in.a, in.b};
    }
  }
}

void Query<TriTriIntersectionInput>::touch(TriTriIntersectionInput& in, ValueSource& v) {
  TriTriInput pair{in.a, in.b};
  Query<TriTriInput>::touch(pair, v);
  in = {pair.a, pair.b};
}

Features Query<TriTriIntersectionInput>::features(const TriTriIntersectionInput& in) {
  return Query<TriTriInput>::features({in.a, in.b});
}

std::span<const std::string_view> Query<TriTriIntersectionInput>::configurations() { return kConfigurations; }

void Query<TriTriIntersectionInput>::recognise(const TriTriIntersectionInput& in, Configurations& found) {
  found.margins();
  found.triangle(in.a), found.triangle(in.b);
  const std::size_t corners = found.exact().answer.params.size() / 3;
  found.add("meet at a point", corners == 1);
  found.add("meet along a segment", corners == 2);
  found.add("meet in a polygon", corners >= 3);
  found.add("coplanar", coplanar(in.a, in.b));
  found.add("nearly coplanar", nearly_parallel(normal(in.a), normal(in.b)));
  const double largest = std::max(max_coordinate(in.a), max_coordinate(in.b));
  // A corner's tolerance over 2^-34 of the scale: a condition number over 2^10.
  found.add("ill-conditioned corner", found.exact().corner_tolerance > 0x1p-34 * largest);
  found.far(largest, std::max(longest_edge(in.a), longest_edge(in.b)));
}

std::span<const BoundTerm> Query<TriTriIntersectionInput>::bound_terms() { return {}; }

void Query<TriTriIntersectionInput>::probe(const TriTriIntersectionInput&, std::vector<bounds::Records>&) {}

}  // namespace cc::harness
