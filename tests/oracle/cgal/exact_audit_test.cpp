// The audit of one case: which kinds CGAL answers, what is compared and what is skipped, and that
// an exact verdict altered where it is compared is a disagreement.
#include "oracle/cgal/exact_audit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <regex>
#include <set>
#include <string>
#include <functional>
#include <initializer_list>
#include <utility>
#include <vector>

#include "collide/moving_box.h"
#include "harness/model/mesh_query.h"
#include "oracle/exact/exact_reference.h"

namespace cc::cgal {
namespace {

using namespace harness;

// The exact reference with its verdicts altered, to see that the audit notices.
class AlteredReference : public ExactReference {
 public:
  explicit AlteredReference(std::function<void(ExactVerdict&)> alter) : alter_(std::move(alter)) {}
  ExactVerdict judge(const Input& input) const override {
    ExactVerdict v = reference_.judge(input);
    alter_(v);
    return v;
  }
  Explanation explain(const Input& input) const override { return reference_.explain(input); }
  std::vector<TermError> bound_errors(const bounds::Records& records) const override {
    return reference_.bound_errors(records);
  }

 private:
  exact::ExactRationalReference reference_;
  std::function<void(ExactVerdict&)> alter_;
};

// The tetrahedron x, y, z >= 0, x + y + z <= 1, and a box B whose least x + y is 1 (x_low + 0.5):
// the 18-DOPs touch on the slab (1, 1, 0) alone (cgal_audit_test.cpp works the slabs out).
KdopKdopInput tetrahedron_and_box(double x_low) {
  return {18, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {{x_low, 0.5, 0.25}, {0.625, 0.875, 0.5}}};
}

// Two parallel right triangles, face 0 in the plane z = 2 and face 1 in z = 1, each with the legs
// x, y in [0, 4] (cgal_audit_test.cpp works the rays out).
RayMeshInput ray_on_two_faces(Ray ray) {
  Mesh mesh;
  mesh.vertices = {{0, 0, 2}, {4, 0, 2}, {0, 4, 2}, {0, 0, 1}, {4, 0, 1}, {0, 4, 1}};
  mesh.faces = {{0, 1, 2}, {3, 4, 5}};
  return {triangles_mesh(mesh), ray, {}};
}

TEST(ExactAudit, AnswersTheKindsMadeOfTwoShapesItExpresses) {
  for (QueryKind kind : {QueryKind::ray_aabb, QueryKind::sphere_sphere, QueryKind::aabb_aabb, QueryKind::tri_aabb,
                         QueryKind::tri_obb, QueryKind::tri_tri, QueryKind::obb_obb, QueryKind::kdop_kdop,
                         QueryKind::ray_mesh, QueryKind::disc_walls, QueryKind::tri_tri_distance,
                         QueryKind::sphere_sphere_distance, QueryKind::sphere_obb_distance, QueryKind::obb_obb_distance,
                         QueryKind::tri_obb_distance, QueryKind::mesh_mesh, QueryKind::mesh_mesh_first,
                         QueryKind::mesh_mesh_distance}) {
    EXPECT_TRUE(answers(kind)) << name(kind);
  }
  for (QueryKind kind : {QueryKind::broadphase, QueryKind::moving_obb}) {
    EXPECT_FALSE(answers(kind)) << name(kind);
    EXPECT_FALSE(cgal_answer(with_kind(kind, []<class In>() { return Input(In{}); })).has_value()) << name(kind);
  }
}

// The manual's table of the kinds audited (docs/exact-audit.md, rows "| `kind` ..." or
// "| `kind`, `kind` ...") names exactly the kinds CGAL answers: a kind that joins or leaves the
// audit changes the page too.
TEST(ExactAudit, TheManualListsExactlyTheKindsAudited) {
  std::ifstream page(std::string(CROSSCHECK_SOURCE_DIR) + "/docs/exact-audit.md");
  ASSERT_TRUE(page) << "docs/exact-audit.md";
  std::set<std::string> listed;
  const std::regex row("^\\| (`[a-z_]+`(, `[a-z_]+`)*) \\|.*"), word("`([a-z_]+)`");
  for (std::string line; std::getline(page, line);) {
    std::smatch m;
    if (!std::regex_match(line, m, row)) continue;
    const std::string cell = m[1];
    for (auto it = std::sregex_iterator(cell.begin(), cell.end(), word); it != std::sregex_iterator(); ++it) {
      listed.insert((*it)[1]);
    }
  }
  for (QueryKind kind : kAllQueryKinds) {
    EXPECT_EQ(listed.count(std::string(name(kind))), answers(kind) ? 1u : 0u)
        << name(kind) << (answers(kind) ? " is audited but not in" : " is not audited but in")
        << " the table of docs/exact-audit.md";
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

// Boxes apart, touching and overlapping, flat ones, turned ones with nearly parallel edges:
// CGAL's signed distance (its hull of the Minkowski difference, its triangle distances) is the
// reference's, rounded down alike.
TEST(ExactAudit, BoxDistancesAgreeWithCgals) {
  const exact::ExactRationalReference reference;
  const Mat3 turned = Mat3::from_columns({0.6, 0.8, 0}, {-0.8, 0.6, 0}, {0, 0, 1});
  const Obb cube{{0, 0, 0}, {1, 1, 1}, Mat3::identity()};
  const ObbObbDistanceInput cases[] = {
      {cube, {{3.5, 0.25, -0.5}, {1, 1, 1}, Mat3::identity()}},  {cube, {{2, 0.5, 0.5}, {1, 1, 1}, Mat3::identity()}},
      {cube, {{1.5, 0.2, 0}, {1, 1, 1}, Mat3::identity()}},      {cube, {{2.1, 1.9, 0.3}, {0.5, 1, 2}, turned}},
      {cube, {{0.5, 0.25, 0}, {1, 0.5, 0.25}, turned}},          {cube, {{0.5, 0, 0}, {0, 0, 1}, Mat3::identity()}},
      {{{0, 0, 0}, {1, 1, 0}, Mat3::identity()}, {{0.5, 0.5, 0}, {1, 1, 0}, Mat3::identity()}}};
  for (const ObbObbDistanceInput& in : cases) {
    const Audit a = audit_case(in, reference);
    EXPECT_EQ(a.outcome, AuditOutcome::agree) << a.why;
    ASSERT_TRUE(a.cgal.distance_down.has_value());
  }
}

// Triangles and boxes apart, touching and overlapping (a vertex in a face, a corner through the
// triangle, a triangle cutting the box), a segment and a flat box: CGAL's signed distance is the
// reference's, rounded down alike.
TEST(ExactAudit, TriangleBoxDistancesAgreeWithCgals) {
  const exact::ExactRationalReference reference;
  const Mat3 turned = Mat3::from_columns({0.6, 0.8, 0}, {-0.8, 0.6, 0}, {0, 0, 1});
  const Obb cube{{0, 0, 0}, {1, 1, 1}, Mat3::identity()};
  const auto tri = [](const Vec3& a, const Vec3& b, const Vec3& c) { return Triangle{{a, b, c}}; };
  const TriObbDistanceInput cases[] = {
      {tri({0.25, 0.5, 1.75}, {3, 3, 5}, {-2, 2, 6}), cube},
      {tri({0, 0, 1}, {3, 0, 3}, {0, 3, 3}), cube},
      {tri({0.25, 0.25, 0.875}, {4, 1, 6}, {1, 4, 6}), cube},
      {tri({-5, -5, 0.25}, {5, -5, 0.25}, {0, 5, 0.25}), cube},
      {tri({3, 1, -1}, {-1, 3, -1}, {-1, -1, 3}), {{0, 0, 0}, {0.5, 1, 2}, turned}},
      {tri({-3, 0, 0.5}, {3, 0, 0.5}, {3, 0, 0.5}), cube},
      {tri({0, 0, 0.5}, {2, 0, 0.5}, {0, 2, 0.5}), {{0.5, 0.5, 0.5}, {1, 1, 0}, Mat3::identity()}}};
  for (const TriObbDistanceInput& in : cases) {
    const Audit a = audit_case(in, reference);
    EXPECT_EQ(a.outcome, AuditOutcome::agree) << a.why;
    ASSERT_TRUE(a.cgal.distance_down.has_value());
  }
}

TEST(ExactAudit, OutOfContractIsNotCompared) {
  const exact::ExactRationalReference reference;
  EXPECT_EQ(audit_case(SphereSphereInput{{{NAN, 0, 0}, 1}, {{0, 0, 0}, 1}}, reference).outcome,
            AuditOutcome::out_of_contract);
  EXPECT_EQ(audit_case(AabbAabbInput{{{0, 0, 0}, {INFINITY, 1, 1}}, {{0, 0, 0}, {1, 1, 1}}}, reference).outcome,
            AuditOutcome::out_of_contract);
}

TEST(ExactAudit, KdopsTouchingOnOneSlabAgreeSlabBySlab) {
  const exact::ExactRationalReference reference;
  const Audit a = audit_case(tetrahedron_and_box(0.5), reference);
  EXPECT_EQ(a.outcome, AuditOutcome::agree) << a.why;
  EXPECT_TRUE(a.touching());
  EXPECT_EQ(a.cgal.slab_signs, (std::vector<int>{1, 1, 1, 0, 1, 1, 1, 1, 1}));
  const Audit apart = audit_case(tetrahedron_and_box(std::nextafter(0.5, 1.0)), reference);
  EXPECT_EQ(apart.outcome, AuditOutcome::agree) << apart.why;
  EXPECT_FALSE(apart.exact.answer.hit);
  EXPECT_LT(apart.exact.margin, 0);
}

TEST(ExactAudit, AKdopMarginOfTheWrongSignIsADisagreement) {
  // Apart by 2^-53 on one slab: a margin rounded to 0 would call it touching.
  const AlteredReference rounded_to_zero([](ExactVerdict& v) { v.margin = 0; });
  const Audit a = audit_case(tetrahedron_and_box(std::nextafter(0.5, 1.0)), rounded_to_zero);
  EXPECT_EQ(a.outcome, AuditOutcome::disagree);
  EXPECT_NE(a.why.find("margin"), std::string::npos) << a.why;
}

TEST(ExactAudit, RaysOnAMeshAgreeOnTheFacesAndTheFirstT) {
  const exact::ExactRationalReference reference;
  constexpr double inf = INFINITY;
  for (const Ray& ray : {Ray{{1, 1, 0}, {0, 0, 3}, 0, inf},                          // both faces, t = 1/3
                         Ray{{3, 3, 3}, {-1, -1, -1}, 0, inf},                       // grazing face 0's edge
                         Ray{{std::nextafter(3.0, 4.0), 3, 3}, {-1, -1, -1}, 0, inf},  // one ulp past it
                         Ray{{-2, 1, 1}, {3, 0, 0}, -inf, inf},                      // in face 1's plane
                         Ray{{1, 1, 1}, {0, 0, 0}, 0.5, inf},                        // a point on face 1
                         Ray{{2, 2, 2}, {0, 0, 0}, -inf, inf},                       // on face 0's edge, t = -inf
                         Ray{{1, 1, 0}, {0, 0, 1}, 0, 1},                            // ending on face 1
                         Ray{{1, 1, 0}, {0, 0, 1}, 0, std::nextafter(1.0, 0.0)},     // one ulp short
                         Ray{{1, 1, 5}, {0, 0, -0x1p-1000}, 0, inf},                 // t = 3 * 2^1000
                         Ray{{1, 1, 5}, {0, 0, -0x1p-1074}, 0, inf}}) {              // t beyond the doubles
    const Audit a = audit_case(ray_on_two_faces(ray), reference);
    EXPECT_EQ(a.outcome, AuditOutcome::agree) << a.why << " on " << ray.origin.x << " " << ray.dir.z;
  }
  const Audit both = audit_case(ray_on_two_faces({{1, 1, 0}, {0, 0, 3}, 0, inf}), reference);
  EXPECT_EQ(both.cgal.faces, (std::vector<std::uint32_t>{0, 1}));
  EXPECT_EQ(both.exact.answer.params, std::vector<double>{1.0 / 3});
}

TEST(ExactAudit, ARayFirstTOneUlpOffOrAFaceLeftOutIsADisagreement) {
  // Up through both faces at speed 3: the exact first t is 1/3, between 1.0 / 3 and the next double.
  const RayMeshInput in = ray_on_two_faces({{1, 1, 0}, {0, 0, 3}, 0, INFINITY});
  const AlteredReference later([](ExactVerdict& v) {  // still one of the two doubles, but its range ends later
    v.answer.params[0] = std::nextafter(v.answer.params[0], 1.0);
    v.param_ranges[0].second = std::nextafter(v.param_ranges[0].second, 1.0);
  });
  const AlteredReference earlier([](ExactVerdict& v) { v.answer.params[0] = std::nextafter(v.answer.params[0], 0.0); });
  const AlteredReference one_face([](ExactVerdict& v) { v.answer.pairs.pop_back(); });
  for (const ExactReference* altered : std::initializer_list<const ExactReference*>{&later, &earlier, &one_face}) {
    const Audit a = audit_case(in, *altered);
    EXPECT_EQ(a.outcome, AuditOutcome::disagree);
    EXPECT_FALSE(a.why.empty());
  }
  EXPECT_NE(audit_case(in, one_face).why.find("faces"), std::string::npos);
}

// Two unit squares in z = 0 as two triangles each, b placed by the pose.
MeshPair two_squares(const RigidTransform& pose_b) {
  Mesh mesh;
  mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  mesh.faces = {{0, 1, 2}, {0, 2, 3}};
  return {triangles_mesh(mesh), triangles_mesh(mesh), {Mat3::identity(), {0, 0, 0}}, pose_b, {}};
}

// Squares crossing, sharing an edge, turned over each other and apart: CGAL's pairs of faces that
// meet are the reference's, all of them, and its distance the reference's, rounded down alike;
// a pair left out or a distance one ulp off is a disagreement.
TEST(ExactAudit, TwoMeshesAgreeOnThePairsThatMeetAndTheirDistance) {
  const exact::ExactRationalReference reference;
  const Mat3 stand = Mat3::from_columns({1, 0, 0}, {0, 0, 1}, {0, -1, 0});
  const Mat3 turned = Mat3::from_columns({0.6, 0.8, 0}, {-0.8, 0.6, 0}, {0, 0, 1});
  const MeshPair crossing = two_squares({stand, {0, 0.5, -0.5}}), shared_edge = two_squares({Mat3::identity(), {0, 1, 0}}),
                 over = two_squares({turned, {0.1, 0.2, 0x1p-40}}), beside = two_squares({turned, {3, 4.5, 1}});
  for (const MeshPair& m : {crossing, shared_edge, over, beside}) {
    for (const Input& in : {Input{MeshMeshInput{m}}, Input{MeshMeshFirstInput{m}}, Input{MeshMeshDistanceInput{m}}}) {
      const Audit a = audit_case(in, reference);
      EXPECT_EQ(a.outcome, AuditOutcome::agree) << name(kind_of(in)) << ": " << a.why;
    }
  }
  EXPECT_EQ(audit_case(MeshMeshInput{crossing}, reference).cgal.pairs,
            (std::vector<FacePair>{{0, 0}, {0, 1}, {1, 0}, {1, 1}}));
  EXPECT_EQ(audit_case(MeshMeshDistanceInput{over}, reference).cgal.distance_down, 0x1p-40);

  const AlteredReference one_pair_less([](ExactVerdict& v) { v.answer.pairs.pop_back(); });
  const Audit fewer = audit_case(MeshMeshInput{crossing}, one_pair_less);
  EXPECT_EQ(fewer.outcome, AuditOutcome::disagree);
  EXPECT_NE(fewer.why.find("pairs"), std::string::npos) << fewer.why;
  const AlteredReference nearer([](ExactVerdict& v) { v.answer.params[0] = std::nextafter(v.answer.params[0], 0.0); });
  const Audit off = audit_case(MeshMeshDistanceInput{beside}, nearer);
  EXPECT_EQ(off.outcome, AuditOutcome::disagree);
  EXPECT_NE(off.why.find("distance"), std::string::npos) << off.why;
}

TEST(ExactAudit, ADiscAgainstWallsAgreesWallByWall) {
  const exact::ExactRationalReference reference;
  // Touching the side of wall 0 exactly, 3-4-5 from the end of wall 1 exactly, apart from the
  // pillar 2; wall 3 has a NaN end (never touched).
  const DiscWallsInput in{{{2, 0.3125}, 0.3125},
                          {{{0, 0}, {4, 0}}, {{2.1875, 0.5625}, {9, 9}}, {{5, 5}, {5, 5}}, {{NAN, 0}, {2, 0.3125}}}};
  const Audit a = audit_case(in, reference);
  EXPECT_EQ(a.outcome, AuditOutcome::agree) << a.why;
  EXPECT_TRUE(a.touching());
  EXPECT_EQ(a.cgal.faces, (std::vector<std::uint32_t>{0, 1}));
  const AlteredReference one_wall([](ExactVerdict& v) { v.answer.pairs.pop_back(); });
  const Audit b = audit_case(in, one_wall);
  EXPECT_EQ(b.outcome, AuditOutcome::disagree);
  EXPECT_NE(b.why.find("faces"), std::string::npos) << b.why;
}

TEST(ExactAudit, AKindCgalDoesNotAnswerIsRefused) {
  const exact::ExactRationalReference reference;
  const MovingObb box = moving_obb(Aabb{{0, 0, 0}, {1, 1, 1}}, {1, 0, 0});
  EXPECT_THROW(audit_case(MovingObbInput{box, box}, reference), std::invalid_argument);
}

}  // namespace
}  // namespace cc::cgal

namespace cc::cgal {
namespace {

using namespace harness;

// The corners of two triangles' intersection, as CGAL constructs them, against the exact
// reference's: a tiny segment where a's edge in b's plane crosses b's edges, and a hexagon.
TEST(ExactAuditCorners, TheSameCornersAgreeAndAMovedOneDoesNot) {
  const exact::ExactRationalReference exact;
  const TriTriIntersectionInput tiny{{{Vec3{1, 1.0078125, 1.125}, Vec3{1, 0.9921874999999999, -0.8749999999999999},
                                       Vec3{0, 0, 0.9999999999999999}}},
                                     {{Vec3{1, 0.9999999999999999, 0.12500000000000014},
                                       Vec3{1, 1.9999999999999998, -0.7499999999999998}, Vec3{1, 0, 1}}}};
  const TriTriIntersectionInput star{{{Vec3{0, 0, 0}, Vec3{6, 0, 0}, Vec3{3, 6, 0}}},
                                     {{Vec3{0, 4, 0}, Vec3{3, -2, 0}, Vec3{6, 4, 0}}}};
  for (const TriTriIntersectionInput& in : {tiny, star}) {
    const Audit a = audit_case(Input{in}, exact);
    EXPECT_EQ(a.outcome, AuditOutcome::agree) << a.why;
    // Moved by more than the bracket's ulp (a bracket holds two doubles: a corner one ulp off may
    // still match one of its neighbour's).
    const AlteredReference moved([](ExactVerdict& v) { v.answer.params[2] += 0x1p-20; });
    EXPECT_EQ(audit_case(Input{in}, moved).outcome, AuditOutcome::disagree);
  }
}

}  // namespace
}  // namespace cc::cgal
