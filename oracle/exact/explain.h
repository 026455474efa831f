// What the kinds' explanations (their units' explain<In>, judges.h) share.
#pragma once

#include <string>

#include "harness/model/explanation.h"
#include "harness/model/mesh_query.h"
#include "oracle/exact/convex_sat.h"
#include "oracle/exact/rational.h"

namespace cc::exact {

/// A number as the tables print it (10 significant digits), an interval, a vector.
std::string num(double x);
std::string num(const Rational& q);
std::string interval(double lo, double hi);
std::string vec(const Vec3& v);

/// How many ULPs of `magnitude` the value is (0 for a zero or non-finite magnitude).
double in_ulps(double value, double magnitude);

/// Two convex polytopes' separating-axis candidates, each with its exact and floating-point gap,
/// and the one that decides.
harness::Explanation explain_polytopes(const ExactShape& a, const ExactShape& b);

/// Two placed meshes: the pair of triangles nearest the boundary, explained as two polytopes.
harness::Explanation explain_meshes(const harness::MeshPair& m);

}  // namespace cc::exact
