// The peers as one: FCL's parties, then Bullet's, in the order their opinions come.
#include "oracle/peers/peer_opinions.h"

#include <gtest/gtest.h>

namespace cc::peers {
namespace {

TEST(PeerOpinions, FclsPartiesThenBulletsInTheOrderOfTheOpinions) {
  const PeerOpinions peers;
  const fcl_oracle::FclSecondOpinion fcl;
  const bullet_oracle::BulletSecondOpinion bullet;
  for (harness::QueryKind kind : harness::kAllQueryKinds) {
    const harness::Input input = harness::with_kind(kind, []<class In>() { return harness::Input(In{}); });
    const auto parties = peers.parties(kind);
    const auto from_fcl = fcl.parties(kind), from_bullet = bullet.parties(kind);
    ASSERT_EQ(parties.size(), from_fcl.size() + from_bullet.size()) << name(kind);
    for (std::size_t i = 0; i < parties.size(); ++i) {
      const std::string expected = i < from_fcl.size() ? from_fcl[i].party : from_bullet[i - from_fcl.size()].party;
      EXPECT_EQ(parties[i].party, expected) << name(kind);
    }
    if (kind == harness::QueryKind::mesh_mesh || kind == harness::QueryKind::mesh_mesh_first ||
        kind == harness::QueryKind::broadphase || kind == harness::QueryKind::ray_mesh) {
      continue;  // empty inputs: asked in their own tests
    }
    const auto opinions = peers.opinions(input);
    ASSERT_EQ(opinions.size(), parties.size()) << name(kind);
    for (std::size_t i = 0; i < parties.size(); ++i) EXPECT_EQ(opinions[i].party, parties[i].party) << name(kind);
  }
}

}  // namespace
}  // namespace cc::peers
