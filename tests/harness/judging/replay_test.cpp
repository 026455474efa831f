// Replaying a case compares every party's whole answer with the record: each test changes one
// part of an evaluation by the least that can change (one ulp, a pair written the other way
// round, a frame's pairs swapped with the next frame's) and requires a line that names it.
#include "harness/judging/replay.h"

#include <gtest/gtest.h>

#include <cmath>

namespace cc::harness {
namespace {

// A recorded ray_mesh-like case with parameters, pairs and frames in every answer, and its
// replay, the same for now.
struct Recorded {
  Case c;
  Evaluation now;
};

Recorded recorded() {
  Recorded r;
  r.c.input = RayAabbInput{};
  const Answer answer{true, {1.5, 2.5}, {{1, 2}, {3, 4}}, {{{0, 1}}, {{1, 2}}}};
  r.c.library = answer;
  r.c.exact.answer = answer;
  r.c.exact.margin = 0.25;
  r.c.opinions = {{"library.test_ray_aabbs", Opinion::Status::answered, answer, ""},
                  {"libccd.GJK", Opinion::Status::answered, {true, {}, {}, {}}, ""},
                  {"libccd.MPR", Opinion::Status::not_applicable, {}, "a ray of infinite length"}};
  r.c.cls = CaseClass::agree;
  r.now.library = r.c.library;
  r.now.exact = r.c.exact;
  r.now.opinions = r.c.opinions;
  r.now.verdict.cls = CaseClass::agree;
  r.now.verdict.parties = {{"library", Standing::right, ""}};
  return r;
}

// The lines of a replay in which one part changed: exactly one, naming `what`.
void expect_one_change_naming(const Recorded& r, const std::string& what) {
  const std::vector<std::string> lines = replay_changes(r.c, r.now);
  ASSERT_EQ(lines.size(), 1u) << what << ": " << (lines.empty() ? "no change reported" : lines[0]);
  EXPECT_NE(lines[0].find(what), std::string::npos) << lines[0];
}

TEST(ReplayChanges, NoneWhenTheReplayIsTheRecord) { EXPECT_TRUE(replay_changes(recorded().c, recorded().now).empty()); }

TEST(ReplayChanges, EveryPartOfTheLibrarysAnswer) {
  Recorded r = recorded();
  r.now.library.params[1] = std::nextafter(2.5, 3.0);
  expect_one_change_naming(r, "the library's answer changed");
  r = recorded();
  std::swap(r.now.library.params[0], r.now.library.params[1]);
  expect_one_change_naming(r, "the library's answer changed");
  r = recorded();
  r.now.library.pairs[0] = {2, 1};
  expect_one_change_naming(r, "the library's answer changed");
  r = recorded();
  std::swap(r.now.library.frames[0], r.now.library.frames[1]);
  expect_one_change_naming(r, "the library's answer changed");
  r = recorded();
  r.now.library.params[0] = -0.0;
  r.c.library.params[0] = 0.0;
  expect_one_change_naming(r, "the library's answer changed");  // bit for bit: -0 is not 0
}

TEST(ReplayChanges, TheExactVerdict) {
  Recorded r = recorded();
  r.now.exact.answer.params[0] = std::nextafter(1.5, 0.0);
  expect_one_change_naming(r, "the exact reference's answer changed");
  r = recorded();
  r.now.exact.answer.pairs = {{3, 4}, {1, 2}};
  expect_one_change_naming(r, "the exact reference's answer changed");
  r = recorded();
  r.now.exact.margin = std::nextafter(0.25, 1.0);
  expect_one_change_naming(r, "the exact margin changed");
  r = recorded();
  r.now.exact.contract = Contract::documented;
  expect_one_change_naming(r, "the exact reference changed");
  r = recorded();
  r.now.exact.decided = false;
  expect_one_change_naming(r, "the exact reference changed");
}

TEST(ReplayChanges, EveryPartyWholeAndByName) {
  Recorded r = recorded();
  r.now.opinions[0].answer.params[1] = std::nextafter(2.5, 0.0);
  expect_one_change_naming(r, "library.test_ray_aabbs changed its behaviour");
  r = recorded();
  r.now.opinions[0].answer.frames[1] = {{2, 1}};
  expect_one_change_naming(r, "library.test_ray_aabbs changed its behaviour");
  r = recorded();
  r.now.opinions[1].answer.hit = false;
  expect_one_change_naming(r, "libccd.GJK changed its behaviour");
  r = recorded();
  r.now.opinions[1].status = Opinion::Status::failed;
  expect_one_change_naming(r, "libccd.GJK changed its behaviour");
  r = recorded();
  r.now.opinions[2].status = Opinion::Status::answered;
  expect_one_change_naming(r, "libccd.MPR changed its behaviour");
  r = recorded();
  std::swap(r.now.opinions[0], r.now.opinions[1]);  // the order does not matter, the names do
  EXPECT_TRUE(replay_changes(r.c, r.now).empty());
  r = recorded();
  r.now.opinions.pop_back();
  expect_one_change_naming(r, "libccd.MPR no longer answers");
  r = recorded();
  r.now.opinions.push_back({"library.new_party", Opinion::Status::answered, {false, {}, {}, {}}, ""});
  expect_one_change_naming(r, "library.new_party is not in the record");
}

TEST(ReplayChanges, TheClassAndAWrongLibrary) {
  Recorded r = recorded();
  r.now.verdict.cls = CaseClass::boundary;
  expect_one_change_naming(r, "class changed: recorded agree, now boundary");
  r = recorded();
  r.now.verdict.parties[0] = {"library", Standing::wrong, "says miss"};
  expect_one_change_naming(r, "the library is wrong: says miss");
}

// A case kept as an impl_bug (a subject's finding) replayed with the same wrong answer, or the
// same failure, is unchanged; another answer, another failure, or a library now right is a change.
TEST(ReplayChanges, AKnownBugWithTheSameAnswerIsUnchanged) {
  Recorded r = recorded();
  r.c.cls = r.now.verdict.cls = CaseClass::impl_bug;
  r.now.verdict.parties = {{"library", Standing::wrong, "a touch missed"}};
  EXPECT_TRUE(replay_changes(r.c, r.now).empty());
  r.now.library.hit = false;
  const std::vector<std::string> lines = replay_changes(r.c, r.now);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_NE(lines[0].find("the library is wrong"), std::string::npos) << lines[0];
  EXPECT_NE(lines[1].find("the library's answer changed"), std::string::npos) << lines[1];

  r = recorded();
  r.c.cls = r.now.verdict.cls = CaseClass::impl_bug;
  r.c.library_failure = r.now.library_failure = "exited with status 0";
  r.now.verdict.parties = {{"library", Standing::failed, "exited with status 0"}};
  EXPECT_TRUE(replay_changes(r.c, r.now).empty());
  r.now.library_failure = "was killed by signal 6 (Aborted)";
  expect_one_change_naming(r, "recorded failed: exited with status 0, now failed: was killed by signal 6");

  r = recorded();
  r.c.cls = CaseClass::impl_bug;  // recorded wrong, right now: the class changed
  expect_one_change_naming(r, "class changed: recorded impl_bug, now agree");
}

// Whether a call returns within its time limit depends on the machine and its load: a time-out
// on either side is no change, nor is the class that changed with it; anything else still is.
TEST(ReplayChanges, ATimeOutOnEitherSideIsNoChange) {
  Recorded r = recorded();
  r.now.opinions[1].status = Opinion::Status::timed_out;
  r.now.verdict.cls = CaseClass::oracle_crash;
  EXPECT_TRUE(replay_changes(r.c, r.now).empty());
  r = recorded();
  r.c.opinions[1].status = Opinion::Status::timed_out;
  r.c.opinions[1].answer = {};
  r.c.cls = CaseClass::oracle_crash;
  EXPECT_TRUE(replay_changes(r.c, r.now).empty());
  r = recorded();
  r.c.library_failure = "timed out: hung for more than 2 s in the library";
  r.c.cls = CaseClass::impl_bug;
  EXPECT_TRUE(replay_changes(r.c, r.now).empty());
  // A failure that is no time-out is still a change, and so is another party's answer.
  r = recorded();
  r.now.opinions[1].status = Opinion::Status::failed;
  r.now.verdict.cls = CaseClass::oracle_crash;
  EXPECT_EQ(replay_changes(r.c, r.now).size(), 2u);
  r = recorded();
  r.now.opinions[1].status = Opinion::Status::timed_out;
  r.now.opinions[0].answer.params[0] = 1.25;
  expect_one_change_naming(r, "library.test_ray_aabbs changed its behaviour");
}

}  // namespace
}  // namespace cc::harness
