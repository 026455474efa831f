// The Chipmunk adapter: its one party, a disc against wall segments, touching (a miss for
// Chipmunk: its test is strict), apart by one ULP, overlapping by 2^-40 (which single precision
// would not see), at an end, on a pillar, several walls named in order, inputs it is not asked,
// a tiny scale where its squares underflow; its parties for every kind; an abort inside a call.
#include "oracle/chipmunk/chipmunk_oracle.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <map>
#include <string>

#include "harness/model/party.h"
#include "oracle/chipmunk/chipmunk_call.h"

namespace cc::chipmunk_oracle {
namespace {

using harness::Opinion;

constexpr const char* kParty = "chipmunk.cpShapesCollide(cpCircleShape,cpSegmentShape)";
const Wall kFloor{{-1, 0}, {1, 0}};

Opinion ask(const Disc& disc, std::vector<Wall> walls) {
  std::map<std::string, Opinion> out;
  for (Opinion& o : ChipmunkSecondOpinion().opinions(harness::DiscWallsInput{disc, std::move(walls)})) out[o.party] = o;
  return out.at(kParty);
}

bool hit(const Opinion& o) {
  EXPECT_EQ(o.status, Opinion::Status::answered) << o.party << ": " << o.detail;
  EXPECT_EQ(o.answer.hit, !o.answer.pairs.empty());
  return o.answer.hit;
}

TEST(ChipmunkSecondOpinion, ADiscOverlappingApartAndTouchingAWallsSide) {
  EXPECT_TRUE(hit(ask({{0, 0.5}, 1}, {kFloor})));
  EXPECT_TRUE(hit(ask({{0, 1 - 0x1p-40}, 1}, {kFloor})));  // overlapping by 2^-40: double precision
  EXPECT_FALSE(hit(ask({{0, 1}, 1}, {kFloor})));           // touching: |q - c|^2 < r^2 is strict
  EXPECT_FALSE(hit(ask({{0, std::nextafter(1.0, 2.0)}, 1}, {kFloor})));
  EXPECT_FALSE(hit(ask({{0, 3}, 1}, {kFloor})));
  EXPECT_FALSE(hit(ask({{0, 0}, 0}, {kFloor})));  // a point disc on the wall: strict, a miss
}

TEST(ChipmunkSecondOpinion, ADiscAtAWallsEndAndAtAPillar) {
  const Wall wall{{0, 0}, {8, 0}};
  EXPECT_FALSE(hit(ask({{-3, 4}, 5}, {wall})));  // touching the end a (3-4-5)
  EXPECT_TRUE(hit(ask({{-3, 4}, std::nextafter(5.0, 6.0)}, {wall})));
  EXPECT_TRUE(hit(ask({{11, -4}, std::nextafter(5.0, 6.0)}, {wall})));  // beyond the end b
  const Wall pillar{{3, 4}, {3, 4}};                                       // 0/0 projects to an end
  EXPECT_TRUE(hit(ask({{0, 0}, std::nextafter(5.0, 6.0)}, {pillar})));
  EXPECT_FALSE(hit(ask({{0, 0}, 5}, {pillar})));
  EXPECT_TRUE(hit(ask({{3, 4}, 1}, {pillar})));  // the centre on the pillar
}

TEST(ChipmunkSecondOpinion, TheWallsTouchedAreNamedInOrder) {
  const Opinion o = ask({{0, 0.5}, 1}, {{{5, 5}, {6, 6}}, kFloor, {{-1, 1.25}, {1, 1.25}}, {{0, -2}, {0, 2}}});
  ASSERT_TRUE(hit(o));
  EXPECT_EQ(o.answer.pairs, (std::vector<harness::FacePair>{{1, 0}, {2, 0}, {3, 0}}));
  EXPECT_FALSE(hit(ask({{0, 0.5}, 1}, {})));
}

TEST(ChipmunkSecondOpinion, InputsItIsNotAsked) {
  EXPECT_EQ(ask({{0, 0}, -1}, {kFloor}).status, Opinion::Status::not_applicable);
  EXPECT_EQ(ask({{NAN, 0}, 1}, {kFloor}).status, Opinion::Status::not_applicable);
  EXPECT_EQ(ask({{0, 0}, INFINITY}, {kFloor}).status, Opinion::Status::not_applicable);
  EXPECT_EQ(ask({{0, 0}, 1}, {kFloor, {{0, 0}, {INFINITY, 0}}}).status, Opinion::Status::not_applicable);
}

TEST(ChipmunkSecondOpinion, AtATinyScaleItsSquaresUnderflow) {
  // Overlapping by half the radius at the scale 2^-600: |q - c|^2 and r^2 both round to 0, and
  // 0 < 0 is false. A defect of Chipmunk's beyond its band (it scales nothing), kept as such.
  EXPECT_FALSE(hit(ask({{0, 0x1p-601}, 0x1p-600}, {{{-0x1p-600, 0}, {0x1p-600, 0}}})));
  EXPECT_TRUE(hit(ask({{0, 0x1p-1}, 1}, {kFloor})));  // the same at scale 1
}

TEST(ChipmunkSecondOpinion, OnePartyForTheDiscAndNoneForTheOtherKinds) {
  const ChipmunkSecondOpinion chipmunk;
  for (harness::QueryKind kind : harness::kAllQueryKinds) {
    const auto parties = chipmunk.parties(kind);
    const auto opinions = chipmunk.opinions(harness::with_kind(kind, []<class In>() { return harness::Input(In{}); }));
    ASSERT_EQ(opinions.size(), parties.size()) << name(kind);
    if (kind != harness::QueryKind::disc_walls) {
      EXPECT_TRUE(parties.empty()) << name(kind);
      continue;
    }
    ASSERT_EQ(parties.size(), 1u);
    EXPECT_EQ(parties[0].party, kParty);
    EXPECT_EQ(parties[0].band.sides, harness::BandSides::two_sided);
    EXPECT_EQ(parties[0].band.width, 0x1p-46);
    EXPECT_EQ(opinions[0].party, kParty);
    EXPECT_EQ(opinions[0].status, Opinion::Status::answered);  // no walls: a miss
  }
}

TEST(ChipmunkSecondOpinion, AnAbortInsideACallIsAFailedOpinion) {
  // A failed Chipmunk assertion prints its message and aborts: the guard jumps out of the call,
  // and the opinion is failed.
  const Opinion o = chipmunk_call([]() -> Opinion { std::abort(); });
  EXPECT_EQ(o.status, Opinion::Status::failed);
  EXPECT_EQ(chipmunk_call([] { return harness::answered(true); }).status, Opinion::Status::answered);
}

TEST(ChipmunkSecondOpinion, ItsVersionIsTheHeadersAndTheLibrarys) {
  EXPECT_EQ(chipmunk_version(), "7.0.3");
  EXPECT_EQ(chipmunk_library_version(), chipmunk_version());
}

}  // namespace
}  // namespace cc::chipmunk_oracle
