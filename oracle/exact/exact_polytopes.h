// What the units of the kinds on convex polytopes (boxes and triangles) share:
// their shapes for the exact separating-axis test of convex_sat.h, their domains and their
// verdicts. A box is the parallelepiped its matrix spans (its face normals are cross products of
// its columns), so the reference needs no orthonormality.
#pragma once

#include <optional>
#include <string>

#include "collide/obb.h"
#include "collide/triangle.h"
#include "oracle/exact/convex_sat.h"
#include "oracle/exact/triangle_sat.h"
#include "harness/model/oracle.h"

namespace cc::exact {

/// The range of binary exponents of the inputs' magnitude inside the library's contract.
constexpr int kObbMinExponent = -500, kObbMaxExponent = 500;
constexpr int kTriangleMinExponent = -300, kTriangleMaxExponent = 300;

/// The verdict of an exact separating-axis test on inputs of that magnitude.
harness::ExactVerdict verdict_of(const SatResult& r, double magnitude);
harness::ExactVerdict verdict_of(const TriangleSatVerdict& r, double magnitude);

/// The largest absolute coordinate of a shape.
double magnitude_of(const Triangle& t);
double magnitude_of(const Obb& b);
double magnitude_of(const Aabb& b);

/// The documented verdict for a box outside the domain (NaN, infinite, a negative extent).
std::optional<harness::ExactVerdict> obb_outside_domain(const Obb& b);

/// A box or a triangle as an exact shape named `name` in explanations.
ExactShape shape_of(const Obb& b, const std::string& name);
ExactShape shape_of(const Triangle& t, const std::string& name);

}  // namespace cc::exact
