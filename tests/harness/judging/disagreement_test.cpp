#include "harness/judging/disagreement.h"

#include <gtest/gtest.h>

#include <set>

namespace cc::harness {
namespace {

// A case judged by hand: the exact answer and margin, what the library said, and each party's
// standing (the library first, then one per opinion, which says `opinion_hit`).
Evaluation judged(bool exact_hit, double margin, bool library_hit, std::vector<PartyStanding> parties,
                  CaseClass cls = CaseClass::impl_bug, bool opinion_hit = false) {
  Evaluation e;
  e.exact.answer.hit = exact_hit;
  e.exact.margin = margin;
  e.library.hit = library_hit;
  for (std::size_t i = 1; i < parties.size(); ++i) {
    e.opinions.push_back({parties[i].party, Opinion::Status::answered, Answer::of(opinion_hit), "", std::nullopt});
  }
  e.verdict = {cls, std::move(parties)};
  return e;
}

const PartyStanding kRight{"library", Standing::right, ""};
const PartyStanding kWrong{"library", Standing::wrong, "why"};

TEST(Disagreement, AMissIsOfATouchWhereTheMarginIsZeroElseOfAHit) {
  EXPECT_EQ(disagreement_of(QueryKind::tri_tri, judged(true, 0, false, {kWrong}))->what, Disagreement::missed_touch);
  EXPECT_EQ(disagreement_of(QueryKind::tri_tri, judged(true, 1e-300, false, {kWrong}))->what, Disagreement::missed_hit);
  EXPECT_EQ(disagreement_of(QueryKind::tri_tri, judged(false, -1e-300, true, {kWrong}))->what, Disagreement::false_hit);
}

TEST(Disagreement, WhereTheHitAgreesWhatCameWithItIsNamedByHowTheKindIsJudged) {
  const auto with_hit = [](QueryKind kind) { return disagreement_of(kind, judged(true, 0.5, true, {kWrong}))->what; };
  EXPECT_EQ(with_hit(QueryKind::ray_aabb), Disagreement::wrong_first_hit);
  EXPECT_EQ(with_hit(QueryKind::moving_obb), Disagreement::wrong_first_hit);
  EXPECT_EQ(with_hit(QueryKind::mesh_mesh), Disagreement::wrong_pairs);
  EXPECT_EQ(with_hit(QueryKind::mesh_mesh_first), Disagreement::wrong_pairs);
  EXPECT_EQ(with_hit(QueryKind::broadphase), Disagreement::wrong_pairs);
  EXPECT_EQ(with_hit(QueryKind::tri_tri_intersection), Disagreement::wrong_corners);
  EXPECT_EQ(with_hit(QueryKind::tri_tri_distance), Disagreement::wrong_distance);
  EXPECT_EQ(with_hit(QueryKind::mesh_mesh_distance), Disagreement::wrong_distance);
}

TEST(Disagreement, APartyThatFailedFailedWhateverItSaid) {
  const auto e = judged(true, 0, true, {{"library", Standing::failed, "crashed (SIGSEGV)"}});
  EXPECT_EQ(disagreement_of(QueryKind::aabb_aabb, e)->what, Disagreement::failed);
  EXPECT_EQ(group_of(QueryKind::aabb_aabb, e), "aabb_aabb.failed");
}

TEST(Disagreement, AnImplBugIsTheLibrarysEvenWhereAPeerIsWrongBeforeItsOwnOtherWay) {
  const auto e = judged(true, 0, true,
                        {kRight, {"fcl.OBBd::overlap", Standing::wrong, "miss"}, {"library.batched", Standing::wrong, "miss"}},
                        CaseClass::impl_bug, false);
  const auto d = disagreement_of(QueryKind::obb_obb, e);
  ASSERT_TRUE(d);
  EXPECT_EQ(d->party, "library.batched");
  EXPECT_EQ(d->what, Disagreement::missed_touch);  // what library.batched said (miss), not the library's hit
}

TEST(Disagreement, AnOracleDefectIsTheFirstWrongPeers) {
  const auto e = judged(false, -0.25, false,
                        {kRight, {"fcl.OBBd::overlap", Standing::right, ""}, {"bullet.box_box", Standing::wrong, "hit"}},
                        CaseClass::oracle_defect, true);
  const auto d = disagreement_of(QueryKind::obb_obb, e);
  ASSERT_TRUE(d);
  EXPECT_EQ(d->party, "bullet.box_box");
  EXPECT_EQ(group_name(QueryKind::obb_obb, d->what), "obb_obb.false_hit");
}

TEST(Disagreement, NoPartyWrongIsNoDisagreement) {
  EXPECT_FALSE(disagreement_of(QueryKind::sphere_sphere, judged(true, 0, true, {kRight}, CaseClass::agree)));
  EXPECT_FALSE(disagreement_of(QueryKind::sphere_sphere,
                               judged(true, 0, false, {{"library", Standing::within_band, "near"}}, CaseClass::boundary)));
  EXPECT_EQ(group_of(QueryKind::sphere_sphere, judged(true, 0, true, {kRight}, CaseClass::agree)), "-");
}

TEST(Disagreement, EveryClassHasItsOwnName) {
  std::set<std::string> names;
#define CC_NAME_OF(d, ...) names.insert(std::string(to_string(Disagreement::d)));
  CC_FOR_EACH_DISAGREEMENT(CC_NAME_OF)
#undef CC_NAME_OF
  EXPECT_EQ(names.size(), 8u);
  EXPECT_FALSE(names.contains("?"));
}

}  // namespace
}  // namespace cc::harness
