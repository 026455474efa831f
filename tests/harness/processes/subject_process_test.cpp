// Subjects in child processes: loading one (the Bullet example) and what it records, the ways a
// library is refused (missing, no version symbol, another version, no kind, a constructor that
// aborts or exits, a version function that hangs), asking one through ask_library, and each
// hostile subject's fault (exit with status 0 or 3, abort, a crash, a hang, printing, closing or
// writing descriptors, an answer that is neither 0 nor 1) as that call's failure: the caller
// goes on, its own descriptors intact, and the next call is answered. In a campaign, a subject
// that exits or prints on every call leaves the run going to its time, every case a finding;
// asked afresh, a subject answers in a new server with no history.
#include "harness/processes/subject_process.h"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "harness/formats/mesh_files.h"
#include "harness/judging/evaluate.h"
#include "harness/model/library.h"
#include "harness/model/mesh_query.h"
#include "harness/model/subject_binding.h"
#include "harness/processes/campaign.h"
#include "oracle/exact/exact_reference.h"

namespace cc::harness {
namespace {

std::string test_subject(const std::string& name) {
  return std::string(CROSSCHECK_SUBJECTS_DIR) + "/libtest_subject_" + name + ".so";
}

// The message load_subject throws for the path.
std::string refusal(const std::string& path, double load_seconds = kSubjectLoadSeconds) {
  try {
    load_subject(path, 5, load_seconds);
  } catch (const SubjectLoadError& e) {
    return e.what();
  }
  return "(loaded)";
}

// What the subject's call fails with; "(answered)" when it answers.
std::string failure(const Subject& subject, const Input& input) {
  try {
    subject.ask(input);
  } catch (const SubjectFailure& e) {
    return e.what();
  }
  return "(answered)";
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

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

const Aabb kUnit{{0, 0, 0}, {1, 1, 1}};
const AabbAabbInput kTouching{kUnit, {{1, 0, 0}, {2, 1, 1}}};

TEST(SubjectProcess, TheBulletExampleAnswersTheKindsItExportsAndIsNamedByItsHash) {
  const auto bullet = load_subject(CROSSCHECK_BULLET_SUBJECT, 20);
  for (QueryKind kind : {QueryKind::ray_aabb, QueryKind::sphere_sphere, QueryKind::aabb_aabb, QueryKind::obb_obb,
                         QueryKind::tri_aabb, QueryKind::tri_obb, QueryKind::moving_obb, QueryKind::ray_mesh,
                         QueryKind::mesh_mesh, QueryKind::mesh_mesh_first, QueryKind::broadphase,
                         QueryKind::tri_tri_distance, QueryKind::sphere_sphere_distance, QueryKind::sphere_obb_distance,
                         QueryKind::obb_obb_distance, QueryKind::tri_obb_distance, QueryKind::mesh_mesh_distance}) {
    EXPECT_TRUE(bullet->answers(kind)) << name(kind);
  }
  for (QueryKind kind : {QueryKind::tri_tri, QueryKind::kdop_kdop, QueryKind::disc_walls}) {
    EXPECT_FALSE(bullet->answers(kind)) << name(kind);
  }
  EXPECT_EQ(bullet->identity().file, "libcrosscheck_bullet_subject.so");
  EXPECT_EQ(bullet->identity().version, 1);
  EXPECT_EQ(bullet->identity().sha256.size(), 64u);
  EXPECT_EQ(bullet->identity().kinds.size(), 17u);
  EXPECT_TRUE(bullet->ask(kTouching).hit);
  EXPECT_FALSE(bullet->ask(AabbAabbInput{kUnit, {{1.5, 0, 0}, {2, 1, 1}}}).hit);
  EXPECT_TRUE(bullet->ask(SphereSphereInput{{{0, 0, 0}, 1}, {{1.5, 0, 0}, 1}}).hit);
  EXPECT_FALSE(bullet->ask(RayAabbInput{{{-1, 2.5, 0.5}, {1, 0, 0}, 0, 3}, kUnit}).hit);
  EXPECT_THROW(bullet->ask(TriTriInput{}), std::logic_error);
  // A distance: balls of radii 1 and 2 with centres 5 apart, 2 apart; the bounds its tolerance
  // (2^-9) times the largest magnitude, 4.
  const Answer d = bullet->ask(SphereSphereDistanceInput{{{0, 0, 0}, 1}, {{3, 4, 0}, 2}});
  ASSERT_EQ(d.params.size(), 9u);
  EXPECT_FALSE(d.hit);
  EXPECT_NEAR(d.params[0], 2, 1e-9);
  EXPECT_NEAR(d.params[1], 0.6, 1e-9);  // on_a: a's point toward b
  EXPECT_NEAR(d.params[4], 1.8, 1e-9);  // on_b: b's point toward a
  EXPECT_EQ(d.params[7], 0x1p-9 * 4);
  EXPECT_EQ(d.params[8], 0x1p-9 * 4);
  EXPECT_TRUE(bullet->ask(SphereObbDistanceInput{{{0, 0, 0.5}, 1}, {{0, 0, 0}, {1, 1, 1}, Mat3::identity()}}).hit);
  // Two unit cubes 1.5 apart along x.
  const Answer boxes =
      bullet->ask(ObbObbDistanceInput{{{0, 0, 0}, {1, 1, 1}, Mat3::identity()}, {{3.5, 0, 0}, {1, 1, 1}, Mat3::identity()}});
  EXPECT_FALSE(boxes.hit);
  EXPECT_NEAR(boxes.params.at(0), 1.5, 1e-9);
  // A triangle whose lowest vertex is 0.75 above a unit cube.
  const Triangle above{{Vec3{0.25, 0.5, 1.75}, Vec3{3, 3, 5}, Vec3{-2, 2, 6}}};
  const Answer triangle_box = bullet->ask(TriObbDistanceInput{above, {{0, 0, 0}, {1, 1, 1}, Mat3::identity()}});
  EXPECT_FALSE(triangle_box.hit);
  EXPECT_NEAR(triangle_box.params.at(0), 0.75, 1e-9);
}

TEST(SubjectProcess, TheOdeExampleAnswersTheKindsItExports) {
  const auto ode = load_subject(CROSSCHECK_ODE_SUBJECT, 20);
  EXPECT_EQ(ode->identity().kinds,
            (std::vector<std::string>{"ray_aabb", "sphere_sphere", "aabb_aabb", "obb_obb", "tri_tri", "mesh_mesh",
                                      "mesh_mesh_first", "broadphase", "ray_mesh"}));
  EXPECT_TRUE(ode->ask(AabbAabbInput{kUnit, {{0.5, 0.5, 0.5}, {2, 2, 2}}}).hit);
  EXPECT_FALSE(ode->ask(AabbAabbInput{kUnit, {{1.5, 0, 0}, {2, 1, 1}}}).hit);
  EXPECT_TRUE(ode->ask(SphereSphereInput{{{0, 0, 0}, 1}, {{1.5, 0, 0}, 1}}).hit);
  EXPECT_FALSE(ode->ask(SphereSphereInput{{{0, 0, 0}, 1}, {{2.5, 0, 0}, 1}}).hit);
  EXPECT_TRUE(ode->ask(RayAabbInput{{{-1, 0.5, 0.5}, {1, 0, 0}, 0, 3}, kUnit}).hit);
  EXPECT_FALSE(ode->ask(RayAabbInput{{{-1, 2.5, 0.5}, {1, 0, 0}, 0, 3}, kUnit}).hit);
}

TEST(SubjectProcess, TheMeshKindsHandTheMeshesOverAndNameTheFaces) {
  const auto bullet = load_subject(CROSSCHECK_BULLET_SUBJECT, 20);
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
  // Their distance: the stick's lowest point (1, 1, 6.5) is 4.5 above face 0.
  const Answer apart = bullet->ask(MeshMeshDistanceInput{pair});
  EXPECT_FALSE(apart.hit);
  ASSERT_EQ(apart.params.size(), 9u);
  EXPECT_NEAR(apart.params[0], 4.5, 1e-9);
  EXPECT_NEAR(apart.params[3], 2, 1e-9);    // on face 0 (z = 2)
  EXPECT_NEAR(apart.params[6], 6.5, 1e-9);  // the stick's lowest vertex
  pair.pose_b.translation = {0, 0, 0};
  EXPECT_TRUE(bullet->ask(MeshMeshDistanceInput{pair}).hit);  // through face 0: 0 apart
  // A stick through face 1 alone: the pair names each mesh's own face, the other way round when
  // the meshes (of two faces and of one) change sides, so meshes handed over swapped would show.
  Mesh low;
  low.vertices = {{1, 1, 0.5}, {1, 1, 1.5}, {1.5, 1, 1.5}};
  low.faces = {{0, 1, 2}};
  EXPECT_EQ(bullet->ask(MeshMeshInput{MeshPair{triangles_mesh(two), triangles_mesh(low), {}, {}, {}}}).pairs,
            (std::vector<FacePair>{{1, 0}}));
  EXPECT_EQ(bullet->ask(MeshMeshInput{MeshPair{triangles_mesh(low), triangles_mesh(two), {}, {}, {}}}).pairs,
            (std::vector<FacePair>{{0, 1}}));
}

TEST(SubjectProcess, AMeshFileIsReadFromWhereTheCallerReadItWhateverTheServersFolder) {
  const auto bullet = load_subject(CROSSCHECK_BULLET_SUBJECT, 20);
  MeshRef env;
  env.source = MeshRef::Source::file;
  env.file = "meshes/env.obj";  // as a case names it, found from the case's folder
  env.mesh = load_mesh_file(std::string(CROSSCHECK_SOURCE_DIR) + "/corpora/meshes/env.obj");
  const Vec3 c = env.mesh->vertices.front();
  const RayMeshInput in{env, {{c.x, c.y, c.z - 1000}, {0, 0, 1}, 0, INFINITY}, {}};
  // The same answer, to the face, as the subject gives when opened here.
  EXPECT_EQ(bullet->ask(in), SubjectBinding::open(CROSSCHECK_BULLET_SUBJECT).ask(in));
}

TEST(SubjectProcess, AskLibraryAsksTheSubjectUnderTestAndNoAlternative) {
  const RayAabbInput touching_end{{{-1, 0.5, 0.5}, {1, 0, 0}, 0, 1}, kUnit};  // Bullet's open range: a miss
  EXPECT_TRUE(ask_library(touching_end).hit);
  EXPECT_FALSE(library_alternatives(touching_end).empty());
  {
    const UnderTest bullet(load_subject(CROSSCHECK_BULLET_SUBJECT, 20));
    EXPECT_FALSE(ask_library(touching_end).hit);
    EXPECT_TRUE(library_alternatives(touching_end).empty());
  }
  EXPECT_EQ(subject_under_test(), nullptr);
  EXPECT_TRUE(ask_library(touching_end).hit);
}

TEST(SubjectProcess, ALibraryThatIsNoSubjectIsRefusedWithTheReason) {
  EXPECT_TRUE(contains(refusal("/nonexistent/libmine.so"), "cannot be loaded"));
  EXPECT_TRUE(contains(refusal(test_subject("no_version")), "exports no crosscheck_subject_version"));
  EXPECT_TRUE(contains(refusal(test_subject("wrong_version")), "interface version 2, this crosscheck takes version 1"));
  EXPECT_TRUE(contains(refusal(test_subject("no_kind")), "exports no crosscheck_<kind>"));
  EXPECT_TRUE(contains(refusal(test_subject("no_tolerance")),
                       "exports crosscheck_sphere_sphere_distance but no crosscheck_distance_tolerance()"));
  EXPECT_EQ(refusal(test_subject("misbehaving")), "(loaded)");
}

TEST(SubjectProcess, ALoadThatCrashesExitsOrHangsIsRefusedInOneLineNamingTheFile) {
  const std::string aborts = test_subject("hostile_load_aborts");
  EXPECT_EQ(refusal(aborts), aborts + ": killed by signal 6 (Aborted) while being loaded (in its constructors or "
                                      "crosscheck_subject_version), in a child process");
  const std::string exits = test_subject("hostile_load_exits");
  EXPECT_TRUE(contains(refusal(exits), exits + ": exited with status 0 while being loaded")) << refusal(exits);
  const std::string hangs = test_subject("hostile_load_hangs");
  const auto start = std::chrono::steady_clock::now();
  EXPECT_TRUE(contains(refusal(hangs, 0.5), hangs + ": hung (still running after 0.5 s) while being loaded"));
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5);
}

TEST(SubjectProcess, EachFaultIsThatCallsFailureAndTheNextCallIsAnsweredAgain) {
  // The caller's own descriptors: a pipe it holds must survive whatever the subject closes.
  int mine[2];
  ASSERT_EQ(::pipe(mine), 0);
  const std::pair<std::string, std::string> faults[] = {
      {"exits", "exited with status 0"},
      {"exits_nonzero", "exited with status 3"},
      {"aborts", "was killed by signal 6 (Aborted)"},
      {"prints", "wrote to standard output: \"checking boxes at 0 ?\""},
      {"closes_fds", "closed file descriptor 3 (crosscheck's questions), which it does not own"},
      {"writes_fds", "wrote to file descriptor 4 (its answers to crosscheck), which it does not own"},
  };
  for (const auto& [fault, what] : faults) {
    const auto subject = load_subject(test_subject("hostile_" + fault), 5);
    for (int call = 0; call < 2; ++call) EXPECT_EQ(failure(*subject, kTouching), what) << fault << ", call " << call;
  }
  EXPECT_EQ(::write(mine[1], "ok", 2), 2);
  char back[2] = {};
  EXPECT_EQ(::read(mine[0], back, 2), 2);
  ::close(mine[0]), ::close(mine[1]);

  const auto misbehaving = load_subject(test_subject("misbehaving"), 0.3);
  EXPECT_TRUE(contains(failure(*misbehaving, AabbAabbInput{{{0.25, 0, 0}, {1, 1, 1}}, kUnit}), "killed by signal 11"));
  EXPECT_EQ(failure(*misbehaving, AabbAabbInput{{{0.75, 0, 0}, {1, 1, 1}}, kUnit}), "timed out: ran past its time limit of 0.3 s");
  EXPECT_TRUE(contains(failure(*misbehaving, SphereSphereInput{{{0, 0, 0}, 1}, {{1, 0, 0}, 1}}), "returned 7"));
  EXPECT_EQ(failure(*misbehaving, kTouching), "(answered)");
  EXPECT_TRUE(misbehaving->ask(kTouching).hit);
  // Its crosscheck_tri_tri_intersection is no function of the interface: never looked up.
  EXPECT_FALSE(misbehaving->answers(QueryKind::tri_tri_intersection));
  EXPECT_EQ(misbehaving->identity().kinds, (std::vector<std::string>{"sphere_sphere", "aabb_aabb"}));
}

// A subject whose answers depend on its process's history (right on its first 100 calls,
// touching boxes a miss after) is right again once asked afresh: a new server, no history.
TEST(SubjectProcess, AskingAfreshStartsAServerWithNoHistory) {
  const UnderTest later(load_subject(test_subject("hostile_wrong_later"), 5));
  for (int call = 1; call <= 100; ++call) ASSERT_TRUE(ask_library(kTouching).hit) << "call " << call;
  EXPECT_FALSE(ask_library(kTouching).hit);
  ask_subject_afresh();
  EXPECT_TRUE(ask_library(kTouching).hit);
  EXPECT_TRUE(ask_library(kTouching).hit);
  ask_subject_afresh();  // twice in a row: no server to end the second time
  ask_subject_afresh();
  EXPECT_TRUE(ask_library(kTouching).hit);
}

TEST(SubjectProcess, AFailureIsTheLibrarysInThatCaseAnImplBug) {
  const UnderTest misbehaving(load_subject(test_subject("misbehaving"), 5));
  const Evaluation e = evaluate(SphereSphereInput{{{0, 0, 0}, 1}, {{1, 0, 0}, 1}}, exact::ExactRationalReference(), nullptr);
  EXPECT_EQ(e.verdict.cls, CaseClass::impl_bug);
  ASSERT_FALSE(e.verdict.parties.empty());
  EXPECT_EQ(e.verdict.parties[0].standing, Standing::failed);
  EXPECT_TRUE(contains(e.library_failure, "returned 7")) << e.library_failure;
}

CampaignResult aabb_campaign(double seconds) {
  CampaignOptions options;
  options.kinds = {QueryKind::aabb_aabb};
  options.workers = 2;
  options.seconds = seconds;
  options.case_timeout_seconds = 0.3;
  options.mesh_folder = std::string(CROSSCHECK_SOURCE_DIR) + "/corpora/meshes";
  const Oracles oracles{[] { return std::make_unique<exact::ExactRationalReference>(); },
                        [] { return std::make_unique<NoSecondOpinion>(); }};
  return run_campaign(options, oracles);
}

TEST(SubjectProcess, ASubjectThatExitsOnEveryCallLeavesTheCampaignGoingToItsTime) {
  const UnderTest exits(load_subject(test_subject("hostile_exits"), 0.3));
  const CampaignResult r = aabb_campaign(2);
  EXPECT_GT(r.seconds, 1.9);
  const KindTally& t = r.tallies.at(QueryKind::aabb_aabb);
  EXPECT_GT(t.cases, 20u);
  EXPECT_EQ(t.count(CaseClass::impl_bug), t.cases);  // every case, each a finding
  ASSERT_EQ(r.findings.size(), t.cases);
  for (const Finding& f : r.findings) {
    EXPECT_TRUE(f.crash.empty()) << f.crash;  // the worker lived on
    EXPECT_EQ(f.evaluation.library_failure, "exited with status 0");
  }
  EXPECT_TRUE(r.problems.empty());
}

TEST(SubjectProcess, ASubjectThatCrashesOrHangsOnSomeCasesIsAFindingOnThoseAlone) {
  const UnderTest misbehaving(load_subject(test_subject("misbehaving"), 0.3));
  const CampaignResult r = aabb_campaign(3);
  int crashes = 0, hangs = 0;
  for (const Finding& f : r.findings) {
    if (f.evaluation.library_failure.empty()) continue;
    EXPECT_EQ(f.evaluation.verdict.cls, CaseClass::impl_bug) << f.evaluation.library_failure;
    const double x = std::get<AabbAabbInput>(f.input).a.lo.x;
    (contains(f.evaluation.library_failure, "time limit") ? hangs : crashes) += 1;
    EXPECT_TRUE(x == 0.25 || x == 0.75) << f.evaluation.library_failure;
  }
  EXPECT_GT(crashes, 0);
  EXPECT_GT(hangs, 0);
  EXPECT_GT(r.tallies.at(QueryKind::aabb_aabb).cases, 1000u);
}

TEST(SubjectProcess, WhatASubjectPrintsIsCountedWithItsFirstLineNotShownRaw) {
  const UnderTest prints(load_subject(test_subject("hostile_prints"), 0.3));
  const CampaignResult r = aabb_campaign(1);
  EXPECT_GT(r.noisy_cases, 0u);
  EXPECT_EQ(r.noisy_cases, r.tallies.at(QueryKind::aabb_aabb).cases);
  EXPECT_TRUE(contains(r.first_noise, "the subject's standard output: checking boxes at")) << r.first_noise;
}

}  // namespace
}  // namespace cc::harness
