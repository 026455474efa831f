// The peers as one: FCL's parties, then Bullet's, then ODE's, then Chipmunk's, in the order their
// opinions come.
#include "oracle/peers/peer_opinions.h"

#include <gtest/gtest.h>

namespace cc::peers {
namespace {

TEST(PeerOpinions, FclsPartiesThenBulletsThenOdesThenChipmunksInTheOrderOfTheOpinions) {
  const PeerOpinions peers;
  const fcl_oracle::FclSecondOpinion fcl;
  const bullet_oracle::BulletSecondOpinion bullet;
  const ode_oracle::OdeSecondOpinion ode;
  const chipmunk_oracle::ChipmunkSecondOpinion chipmunk;
  for (harness::QueryKind kind : harness::kAllQueryKinds) {
    const harness::Input input = harness::with_kind(kind, []<class In>() { return harness::Input(In{}); });
    const auto parties = peers.parties(kind);
    std::vector<harness::PartyBand> expected = fcl.parties(kind);
    for (const auto& p : bullet.parties(kind)) expected.push_back(p);
    for (const auto& p : ode.parties(kind)) expected.push_back(p);
    for (const auto& p : chipmunk.parties(kind)) expected.push_back(p);
    ASSERT_EQ(parties.size(), expected.size()) << name(kind);
    for (std::size_t i = 0; i < parties.size(); ++i) EXPECT_EQ(parties[i].party, expected[i].party) << name(kind);
    if (harness::meshes_of(input) != nullptr || kind == harness::QueryKind::broadphase ||
        kind == harness::QueryKind::ray_mesh) {
      continue;  // empty inputs (the mesh kinds' without their meshes): asked in their own tests
    }
    const auto opinions = peers.opinions(input);
    ASSERT_EQ(opinions.size(), parties.size()) << name(kind);
    for (std::size_t i = 0; i < parties.size(); ++i) EXPECT_EQ(opinions[i].party, parties[i].party) << name(kind);
  }
}

}  // namespace
}  // namespace cc::peers
