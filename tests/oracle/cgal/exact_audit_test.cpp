// The audit of one case: which kinds CGAL answers, what is compared and what is skipped.
#include "oracle/cgal/exact_audit.h"

#include <gtest/gtest.h>

#include <cmath>

#include "oracle/exact/exact_reference.h"

namespace cc::cgal {
namespace {

using namespace harness;

TEST(ExactAudit, AnswersTheKindsMadeOfTwoShapesItExpresses) {
  for (QueryKind kind : {QueryKind::ray_aabb, QueryKind::sphere_sphere, QueryKind::aabb_aabb, QueryKind::tri_aabb,
                         QueryKind::tri_obb, QueryKind::tri_tri, QueryKind::obb_obb}) {
    EXPECT_TRUE(answers(kind)) << name(kind);
  }
  for (QueryKind kind : {QueryKind::kdop_kdop, QueryKind::mesh_mesh, QueryKind::mesh_mesh_first,
                         QueryKind::broadphase, QueryKind::ray_mesh, QueryKind::moving_obb}) {
    EXPECT_FALSE(answers(kind)) << name(kind);
    EXPECT_FALSE(cgal_answer(with_kind(kind, []<class In>() { return Input(In{}); })).has_value()) << name(kind);
  }
}

TEST(ExactAudit, TouchingSpheresAgreeAtMarginZero) {
  const exact::ExactRationalReference reference;
  const Audit a = audit_case(SphereSphereInput{{{0, 0, 0}, 1}, {{3, 0, 0}, 2}}, reference);
  EXPECT_EQ(a.outcome, AuditOutcome::agree);
  EXPECT_TRUE(a.touching());
  EXPECT_EQ(a.cgal.margin_sign, 0);
}

TEST(ExactAudit, AMarginThatUnderflowsKeepsItsSign) {
  // (r_a + r_b)^2 - |c_a - c_b|^2 = 2 * 13.5 * 5e-324 + (5e-324)^2 > 0: overlapping, not touching,
  // although the margin is far below the smallest double.
  const exact::ExactRationalReference reference;
  const Audit a = audit_case(SphereSphereInput{{{0, 0, 0}, 13.5}, {{13.5, 0, 0}, 5e-324}}, reference);
  EXPECT_EQ(a.outcome, AuditOutcome::agree) << a.why;
  EXPECT_FALSE(a.touching());
  EXPECT_GT(a.exact.margin, 0);
}

TEST(ExactAudit, OutOfContractIsNotCompared) {
  const exact::ExactRationalReference reference;
  EXPECT_EQ(audit_case(SphereSphereInput{{{NAN, 0, 0}, 1}, {{0, 0, 0}, 1}}, reference).outcome,
            AuditOutcome::out_of_contract);
  EXPECT_EQ(audit_case(AabbAabbInput{{{0, 0, 0}, {INFINITY, 1, 1}}, {{0, 0, 0}, {1, 1, 1}}}, reference).outcome,
            AuditOutcome::out_of_contract);
}

TEST(ExactAudit, AKindCgalDoesNotAnswerIsRefused) {
  const exact::ExactRationalReference reference;
  EXPECT_THROW(audit_case(KdopKdopInput{18, {{0, 0, 0}}, {{0, 0, 0}}}, reference), std::invalid_argument);
}

}  // namespace
}  // namespace cc::cgal
