#include "harness/judging/bands.h"

#include <gtest/gtest.h>

#include "harness/processes/campaign.h"
#include "oracle/fcl/fcl_oracle.h"

namespace cc::harness {
namespace {

// Each party's band comes with its opinions: the one its oracle declares for it, said why.
TEST(Bands, EverySecondOpinionCarriesItsPartysBand) {
  const fcl_oracle::FclSecondOpinion fcl;
  for (QueryKind kind : kAllQueryKinds) {
    const std::vector<PartyBand> parties = fcl.parties(kind);
    for (const PartyBand& p : parties) EXPECT_FALSE(p.band.why.empty()) << p.party;
    const Input in = campaign_case(1, kind, 0, 0);
    const std::vector<Opinion> opinions = fcl.opinions(in);
    ASSERT_EQ(opinions.size(), parties.size()) << name(kind);
    for (std::size_t i = 0; i < parties.size(); ++i) {
      EXPECT_EQ(opinions[i].party, parties[i].party);
      ASSERT_TRUE(opinions[i].band.has_value()) << parties[i].party;
      EXPECT_EQ(opinions[i].band->width, parties[i].band.width) << parties[i].party;
      EXPECT_EQ(opinions[i].band->sides, parties[i].band.sides) << parties[i].party;
    }
  }
}

// Primitive tests round outward; a mesh query moves one mesh into the other's frame in
// floating point first, which can part touching triangles, so its band is two-sided.
TEST(Bands, TheLibraryIsExactOrConservativeOnPrimitives) {
  for (QueryKind kind : kAllQueryKinds) {
    const Band b = library_band(kind);
    const bool two_meshes = kind == QueryKind::mesh_mesh || kind == QueryKind::mesh_mesh_first;
    EXPECT_EQ(b.sides == BandSides::two_sided, two_meshes) << name(kind);
    EXPECT_LE(b.width, 0x1p-40) << name(kind);
    EXPECT_FALSE(b.why.empty());
  }
  EXPECT_EQ(library_band(QueryKind::aabb_aabb).sides, BandSides::exact);
}

// A party answering several kinds: listed once when its band is the same for each, and once per
// band, with the kinds of each, when they differ (none is left out).
class TwoBands : public SecondOpinion {
 public:
  std::vector<Opinion> opinions(const Input&) const override { return {}; }
  std::vector<PartyBand> parties(QueryKind kind) const override {
    const Band narrow{0x1p-46, BandSides::two_sided, 0, "narrow"}, wide{0x1p-40, BandSides::two_sided, 0, "wide"};
    switch (kind) {
      case QueryKind::aabb_aabb: return {{"peer.boxes", narrow}, {"peer.same", narrow}};
      case QueryKind::obb_obb: return {{"peer.boxes", wide}, {"peer.same", narrow}};
      case QueryKind::tri_obb: return {{"peer.boxes", wide}};
      default: return {};
    }
  }
};

TEST(Bands, APartyWithDifferentBandsPerKindIsListedWithEach) {
  const auto rows = all_bands(TwoBands());
  std::vector<std::pair<std::string, double>> peers;
  for (const auto& [row, band] : rows) {
    if (row.starts_with("peer.")) peers.emplace_back(row, band.width);
  }
  const std::vector<std::pair<std::string, double>> expected = {
      {"peer.boxes (aabb_aabb)", 0x1p-46}, {"peer.same", 0x1p-46}, {"peer.boxes (obb_obb, tri_obb)", 0x1p-40}};
  EXPECT_EQ(peers, expected);
}

}  // namespace
}  // namespace cc::harness
