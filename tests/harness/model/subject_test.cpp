// Subjects: loading one (the Bullet example), the ways a library is refused (missing, no version
// symbol, another version, no kind), asking one through ask_library, and a subject that
// crashes, hangs or answers neither 0 nor 1 in a campaign: findings, never the end of the run.
#include "harness/model/subject.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "harness/judging/evaluate.h"
#include "harness/model/library.h"
#include "harness/model/mesh_query.h"
#include "harness/processes/campaign.h"
#include "oracle/exact/exact_reference.h"

namespace cc::harness {
namespace {

std::string test_subject(const char* name) {
  return std::string(CROSSCHECK_SUBJECTS_DIR) + "/libtest_subject_" + name + ".so";
}

// The message load() throws for the path.
std::string refusal(const std::string& path) {
  try {
    Subject::load(path);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "(loaded)";
}

// No second opinion: the subject against the exact reference alone.
class NoSecondOpinion final : public SecondOpinion {
 public:
  std::vector<Opinion> opinions(const Input&) const override { return {}; }
  std::vector<PartyBand> parties(QueryKind) const override { return {}; }
};

// Puts a subject under test for the test's scope.
struct UnderTest {
  explicit UnderTest(std::shared_ptr<const Subject> s) { put_under_test(std::move(s)); }
  ~UnderTest() { put_under_test(nullptr); }
};

TEST(Subject, TheBulletExampleAnswersTheKindsItExports) {
  const auto bullet = Subject::load(CROSSCHECK_BULLET_SUBJECT);
  for (QueryKind kind : {QueryKind::ray_aabb, QueryKind::sphere_sphere, QueryKind::aabb_aabb, QueryKind::obb_obb,
                         QueryKind::tri_aabb, QueryKind::tri_obb, QueryKind::moving_obb, QueryKind::ray_mesh,
                         QueryKind::mesh_mesh, QueryKind::mesh_mesh_first, QueryKind::broadphase}) {
    EXPECT_TRUE(bullet->answers(kind)) << name(kind);
  }
  for (QueryKind kind : {QueryKind::tri_tri, QueryKind::kdop_kdop, QueryKind::disc_walls}) {
    EXPECT_FALSE(bullet->answers(kind)) << name(kind);
  }
  const Aabb unit{{0, 0, 0}, {1, 1, 1}};
  EXPECT_TRUE(bullet->ask(AabbAabbInput{unit, {{1, 0, 0}, {2, 1, 1}}}).hit);
  EXPECT_FALSE(bullet->ask(AabbAabbInput{unit, {{1.5, 0, 0}, {2, 1, 1}}}).hit);
  EXPECT_TRUE(bullet->ask(SphereSphereInput{{{0, 0, 0}, 1}, {{1.5, 0, 0}, 1}}).hit);
  EXPECT_FALSE(bullet->ask(RayAabbInput{{{-1, 2.5, 0.5}, {1, 0, 0}, 0, 3}, unit}).hit);
  EXPECT_THROW(bullet->ask(TriTriInput{}), std::runtime_error);
}

TEST(Subject, TheMeshKindsHandTheMeshesOverAndNameTheFaces) {
  const auto bullet = Subject::load(CROSSCHECK_BULLET_SUBJECT);
  Mesh two;  // face 0 in the plane z = 2, face 1 in z = 1, legs x, y in [0, 4]
  two.vertices = {{0, 0, 2}, {4, 0, 2}, {0, 4, 2}, {0, 0, 1}, {4, 0, 1}, {0, 4, 1}};
  two.faces = {{0, 1, 2}, {3, 4, 5}};
  const Answer up = bullet->ask(RayMeshInput{triangles_mesh(two), {{1, 1, 0}, {0, 0, 1}, 0, INFINITY}, {}});
  EXPECT_TRUE(up.hit);
  EXPECT_EQ(up.pairs, (std::vector<FacePair>{{1, 0}}));  // the nearer face
  EXPECT_FALSE(bullet->ask(RayMeshInput{triangles_mesh(two), {{5, 5, 0}, {0, 0, 1}, 0, INFINITY}, {}}).hit);
  Mesh stick;  // a triangle standing through face 0 only
  stick.vertices = {{1, 1, 1.5}, {1, 1, 3}, {1.5, 1, 3}};
  stick.faces = {{0, 1, 2}};
  MeshPair pair{triangles_mesh(two), triangles_mesh(stick), {}, {}, {}};
  EXPECT_EQ(bullet->ask(MeshMeshInput{pair}).pairs, (std::vector<FacePair>{{0, 0}}));
  EXPECT_EQ(bullet->ask(MeshMeshFirstInput{pair}).pairs, (std::vector<FacePair>{{0, 0}}));
  pair.pose_b.translation = {0, 0, 5};
  EXPECT_FALSE(bullet->ask(MeshMeshInput{pair}).hit);
}

TEST(Subject, BoxFramesGoOverFrameByFrame) {
  const auto bullet = Subject::load(CROSSCHECK_BULLET_SUBJECT);
  const Aabb unit{{0, 0, 0}, {1, 1, 1}};
  BroadphaseInput in;
  in.frames = {{unit, Aabb{{2, 0, 0}, {3, 1, 1}}},
               {unit, Aabb{{1, 0, 0}, {2, 1, 1}}, Aabb{{0.5, 0.5, 0.5}, {0.6, 0.6, 0.6}}},
               {std::nullopt, Aabb{{1, 0, 0}, {2, 1, 1}}, Aabb{{0.5, 0.5, 0.5}, {0.6, 0.6, 0.6}}}};
  const Answer a = bullet->ask(in);
  EXPECT_TRUE(a.hit);
  EXPECT_EQ(a.frames, (std::vector<std::vector<FacePair>>{{}, {{0, 1}, {0, 2}}, {}}));
}

TEST(Subject, AskLibraryAsksTheSubjectUnderTestAndNoAlternative) {
  const Aabb unit{{0, 0, 0}, {1, 1, 1}};
  const RayAabbInput touching_end{{{-1, 0.5, 0.5}, {1, 0, 0}, 0, 1}, unit};  // Bullet's open range: a miss
  EXPECT_TRUE(ask_library(touching_end).hit);
  EXPECT_FALSE(library_alternatives(touching_end).empty());
  {
    const UnderTest bullet(Subject::load(CROSSCHECK_BULLET_SUBJECT));
    EXPECT_FALSE(ask_library(touching_end).hit);
    EXPECT_TRUE(library_alternatives(touching_end).empty());
  }
  EXPECT_EQ(subject_under_test(), nullptr);
  EXPECT_TRUE(ask_library(touching_end).hit);
}

TEST(Subject, ALibraryThatIsNoSubjectIsRefusedWithTheReason) {
  EXPECT_NE(refusal("/nonexistent/libmine.so").find("cannot be loaded"), std::string::npos);
  EXPECT_NE(refusal(test_subject("no_version")).find("exports no crosscheck_subject_version"), std::string::npos);
  EXPECT_NE(refusal(test_subject("wrong_version")).find("interface version 2, this crosscheck takes version 1"),
            std::string::npos);
  EXPECT_NE(refusal(test_subject("no_kind")).find("exports no crosscheck_<kind>"), std::string::npos);
  EXPECT_EQ(refusal(test_subject("misbehaving")), "(loaded)");
}

TEST(Subject, AnAnswerThatIsNeitherZeroNorOneThrowsAndIsAFailure) {
  const auto subject = Subject::load(test_subject("misbehaving"));
  const SphereSphereInput spheres{{{0, 0, 0}, 1}, {{1, 0, 0}, 1}};
  EXPECT_THROW(subject->ask(spheres), std::runtime_error);
  const UnderTest misbehaving(subject);
  const Evaluation e = evaluate(spheres, exact::ExactRationalReference(), nullptr);
  EXPECT_EQ(e.verdict.cls, CaseClass::impl_bug);
  ASSERT_FALSE(e.verdict.parties.empty());
  EXPECT_EQ(e.verdict.parties[0].standing, Standing::failed);
  EXPECT_NE(e.library_failure.find("returned 7"), std::string::npos) << e.library_failure;
}

TEST(Subject, ACrashOrAHangInASubjectIsAFindingNotTheEndOfTheCampaign) {
  const UnderTest misbehaving(Subject::load(test_subject("misbehaving")));
  CampaignOptions options;
  options.kinds = {QueryKind::aabb_aabb};
  options.workers = 2;
  options.seconds = 3;
  options.case_timeout_seconds = 0.3;
  const Oracles oracles{[] { return std::make_unique<exact::ExactRationalReference>(); },
                        [] { return std::make_unique<NoSecondOpinion>(); }};
  const CampaignResult r = run_campaign(options, oracles);
  int crashes = 0, hangs = 0;
  for (const Finding& f : r.findings) {
    if (f.crash.empty()) continue;
    EXPECT_EQ(f.evaluation.verdict.cls, CaseClass::impl_bug) << f.crash;
    const double x = std::get<AabbAabbInput>(f.input).a.lo.x;
    (f.crash.find("hung") != std::string::npos ? hangs : crashes) += 1;
    EXPECT_TRUE(x == 0.25 || x == 0.75) << f.crash;
  }
  EXPECT_GT(crashes, 0);
  EXPECT_GT(hangs, 0);
  EXPECT_GT(r.tallies.at(QueryKind::aabb_aabb).cases, 1000u);
}

}  // namespace
}  // namespace cc::harness
