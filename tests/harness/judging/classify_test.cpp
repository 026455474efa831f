#include "harness/judging/classify.h"

#include <gtest/gtest.h>

#include <cmath>

#include "harness/judging/bands.h"
#include "oracle/fcl/fcl_oracle.h"

namespace cc::harness {
namespace {

ExactVerdict exact(bool hit, double margin, std::vector<double> params = {}) {
  ExactVerdict v;
  v.answer = {hit, std::move(params), {}, {}};
  v.margin = margin;
  return v;
}

const fcl_oracle::FclSecondOpinion kFcl;
const std::string kObb = "fcl.OBBd::overlap";

// A party's band, as its oracle declares it.
Band band_of(QueryKind kind, const std::string& party) {
  for (const PartyBand& p : kFcl.parties(kind)) {
    if (p.party == party) return p.band;
  }
  throw std::out_of_range("no party " + party);
}

// What an obb_obb party said.
Opinion said(const std::string& party, bool hit) {
  return {party, Opinion::Status::answered, {hit, {}, {}, {}}, "", band_of(QueryKind::obb_obb, party)};
}

TEST(Classify, AgreeWhenEveryPartyMatches) {
  EXPECT_EQ(classify(QueryKind::obb_obb, {true, {}, {}, {}}, exact(true, 0.1), {said(kObb, true)}).cls, CaseClass::agree);
}

TEST(Classify, ALibraryMissForTouchingShapesIsAnImplBug) {
  const Verdict v = classify(QueryKind::obb_obb, {false, {}, {}, {}}, exact(true, 0), {said(kObb, true)});
  EXPECT_EQ(v.cls, CaseClass::impl_bug);
  EXPECT_EQ(v.parties[0].standing, Standing::wrong);
}

TEST(Classify, ALibraryHitJustApartIsBoundary) {
  EXPECT_EQ(classify(QueryKind::obb_obb, {true, {}, {}, {}}, exact(false, -0x1p-45), {said(kObb, false)}).cls,
            CaseClass::boundary);
  EXPECT_EQ(classify(QueryKind::obb_obb, {true, {}, {}, {}}, exact(false, -0x1p-30), {said(kObb, false)}).cls,
            CaseClass::impl_bug);
  // aabb_aabb has no band at all.
  EXPECT_EQ(classify(QueryKind::aabb_aabb, {true, {}, {}, {}}, exact(false, -0x1p-60), {}).cls, CaseClass::impl_bug);
}

TEST(Classify, ASecondOpinionWrongBeyondItsBandIsAnOracleDefect) {
  EXPECT_EQ(classify(QueryKind::obb_obb, {true, {}, {}, {}}, exact(true, 0.1), {said(kObb, false)}).cls,
            CaseClass::oracle_defect);
  EXPECT_EQ(classify(QueryKind::obb_obb, {true, {}, {}, {}}, exact(true, 0x1p-30), {said(kObb, false)}).cls,
            CaseClass::boundary);
  // The library wrong and FCL wrong: the library's bug comes first.
  EXPECT_EQ(classify(QueryKind::obb_obb, {false, {}, {}, {}}, exact(true, 0.1), {said(kObb, false)}).cls,
            CaseClass::impl_bug);
}

TEST(Classify, FailedAndInapplicableOpinions) {
  const Opinion failed{kObb, Opinion::Status::failed, {}, "did not return"};
  EXPECT_EQ(classify(QueryKind::obb_obb, {true, {}, {}, {}}, exact(true, 0.1), {failed}).cls, CaseClass::oracle_crash);
  const Opinion na{"libccd.GJK", Opinion::Status::not_applicable, {}, "a ray"};
  EXPECT_EQ(classify(QueryKind::ray_aabb, {true, {1, 2}, {}, {}}, exact(true, 0.1, {1, 2}), {na}).cls, CaseClass::agree);
}

TEST(Classify, ALibraryPartyWithoutParametersIsJudgedOnItsHitAlone) {
  const Opinion batched{"library.test_ray_aabbs", Opinion::Status::answered, {true, {}, {}, {}}, ""};
  EXPECT_EQ(classify(QueryKind::ray_aabb, {true, {1, 2}, {}, {}}, exact(true, 0.1, {1, 2}), {batched}).cls,
            CaseClass::agree);
  const Opinion misses{"library.test_ray_aabbs", Opinion::Status::answered, {false, {}, {}, {}}, ""};
  EXPECT_EQ(classify(QueryKind::ray_aabb, {true, {1, 2}, {}, {}}, exact(true, 0, {1, 2}), {misses}).cls,
            CaseClass::impl_bug);
  const Opinion wrong_t{"library.test_ray_aabbs", Opinion::Status::answered, {true, {1, 2.001}, {}, {}}, ""};
  EXPECT_EQ(classify(QueryKind::ray_aabb, {true, {1, 2}, {}, {}}, exact(true, 0.1, {1, 2}), {wrong_t}).cls,
            CaseClass::impl_bug);
  const Opinion failed{"library.test_ray_aabbs", Opinion::Status::failed, {}, "the avx2 kernel says hit"};
  EXPECT_EQ(classify(QueryKind::ray_aabb, {true, {1, 2}, {}, {}}, exact(true, 0.1, {1, 2}), {failed}).cls,
            CaseClass::impl_bug);
}

TEST(Classify, RayParametersMustBeWithinTheirBand) {
  EXPECT_EQ(classify(QueryKind::ray_aabb, {true, {1, 2}, {}, {}}, exact(true, 0.1, {1, 2 + 0x1p-51}), {}).cls,
            CaseClass::agree);
  EXPECT_EQ(classify(QueryKind::ray_aabb, {true, {1, 2}, {}, {}}, exact(true, 0.1, {1, 2.001}), {}).cls,
            CaseClass::impl_bug);
}

TEST(Classify, OutOfContractChecksTheDocumentedAnswerOnly) {
  ExactVerdict documented = exact(false, NAN);
  documented.contract = Contract::documented;
  documented.note = "NaN input";
  EXPECT_EQ(classify(QueryKind::obb_obb, {false, {}, {}, {}}, documented, {said(kObb, true)}).cls, CaseClass::out_of_contract);
  EXPECT_EQ(classify(QueryKind::obb_obb, {true, {}, {}, {}}, documented, {}).cls, CaseClass::impl_bug);
  ExactVerdict unspecified = exact(false, NAN);
  unspecified.contract = Contract::unspecified;
  EXPECT_EQ(classify(QueryKind::obb_obb, {true, {}, {}, {}}, unspecified, {}).cls, CaseClass::out_of_contract);
  ExactVerdict undecided = exact(false, 0);
  undecided.decided = false;
  EXPECT_EQ(classify(QueryKind::obb_obb, {true, {}, {}, {}}, undecided, {}).cls, CaseClass::undecided);
}

// Out of contract the library is not judged, but the second opinions are still heard: with no
// exact verdict, one that answers otherwise than the library documents "differs"; beyond the
// library's range, where the reference decided, each is judged by its band.
TEST(Classify, OutOfContractStillHearsTheSecondOpinions) {
  ExactVerdict documented = exact(false, NAN);
  documented.contract = Contract::documented;
  documented.note = "NaN input";
  const Verdict nan = classify(QueryKind::obb_obb, {false, {}, {}, {}}, documented, {said(kObb, true)});
  EXPECT_EQ(nan.cls, CaseClass::out_of_contract);
  ASSERT_EQ(nan.parties.size(), 2u);
  EXPECT_EQ(nan.parties[1].standing, Standing::differs);
  EXPECT_NE(nan.parties[1].why.find("says hit where the library documents miss (NaN input)"), std::string::npos);
  EXPECT_EQ(classify(QueryKind::obb_obb, {false, {}, {}, {}}, documented, {said(kObb, false)}).parties[1].standing,
            Standing::right);

  ExactVerdict beyond = exact(true, 0.25);
  beyond.contract = Contract::unspecified;
  beyond.note = "every coordinate is below 2^-500 in magnitude";
  const Verdict judged = classify(QueryKind::obb_obb, {false, {}, {}, {}}, beyond, {said(kObb, false)});
  EXPECT_EQ(judged.cls, CaseClass::out_of_contract);  // the library's miss is not judged
  EXPECT_EQ(judged.parties[0].standing, Standing::right);
  EXPECT_EQ(judged.parties[1].standing, Standing::wrong);

  ExactVerdict none = exact(false, NAN);
  none.contract = Contract::unspecified;
  none.decided = false;
  const Verdict unheard = classify(QueryKind::obb_obb, {false, {}, {}, {}}, none, {said(kObb, true)});
  EXPECT_EQ(unheard.parties[1].standing, Standing::not_applicable);
  EXPECT_NE(unheard.parties[1].why.find("says hit; no exact verdict"), std::string::npos);
}

TEST(CaseClass, NamesRoundTrip) {
  for (CaseClass c : kAllClasses) EXPECT_EQ(case_class_named(to_string(c)), c);
  EXPECT_FALSE(case_class_named("bug").has_value());
}

// A ray parameter exactly at the band's bound is right and one ulp further is wrong, on both
// sides (the bound 2^-50 |e| + 2^-1060 is a double plus a term no double fits in, for these e).
TEST(Classify, RayParametersOneUlpPastTheBandAreWrong) {
  for (double e : {1.0, 0.75, -3.0, 1e-300, 12345.678, 0.0}) {
    const double reach = 0x1p-50 * std::fabs(e);
    const double sides[2] = {e + reach, e - reach};  // stepped inward below when the sum rounded outward
    for (int side = 0; side < 2; ++side) {
      double at = sides[side];
      const double toward = side == 0 ? INFINITY : -INFINITY;
      if (e == 0) at = side == 0 ? 0x1p-1060 : -0x1p-1060;
      if (std::fabs(at - e) > reach && e != 0) at = std::nextafter(at, -toward);
      const ExactVerdict v = exact(true, 0.1, {0, e});
      EXPECT_EQ(classify(QueryKind::ray_aabb, {true, {0, at}, {}, {}}, v, {}).cls, CaseClass::agree) << e << " " << at;
      EXPECT_EQ(classify(QueryKind::ray_aabb, {true, {0, std::nextafter(at, toward)}, {}, {}}, v, {}).cls, CaseClass::impl_bug)
          << e << " " << std::nextafter(at, toward);
    }
  }
}

// The margins: for every query kind and every party's band, a disagreement exactly at the band's
// width is within it and one ulp further is wrong; a conservative party missing touching shapes
// is wrong. (Exact bands: any disagreement is wrong.)
TEST(Classify, MarginsOneUlpPastTheBandAreWrong) {
  int checked = 0;
  const auto bands = all_bands(kFcl);
  for (const auto& [name_of_band, band] : bands) {
    const bool library = name_of_band.starts_with("library ");
    // The library's band on its own kind; a second opinion's on a kind it answers.
    std::vector<QueryKind> kinds;
    for (QueryKind kind : kAllQueryKinds) {
      if (library && name_of_band == "library " + std::string(name(kind))) kinds.push_back(kind);
    }
    if (!library) kinds.push_back(name_of_band.starts_with("fcl.BVHModel") ? QueryKind::mesh_mesh : QueryKind::obb_obb);
    for (QueryKind kind : kinds) {
      if (kind == QueryKind::broadphase) continue;  // judged by exact comparisons of boxes, not margins
      ++checked;
      const bool meshes = judged_of(kind) == Judged::all_pairs || judged_of(kind) == Judged::first_pair;
      const std::string party = library ? "library" : name_of_band;
      // The verdict: apart (or, for pairs, a pair apart) at margin m; the party says hit there.
      const auto standing_at = [&](double m, bool says_hit, bool exact_hit) {
        ExactVerdict v;
        v.answer.hit = exact_hit;
        v.margin = m;
        Answer said{says_hit, {}, {}, {}};
        if (meshes) {
          const FacePair pair{1, 2};
          v.pair_margins = {{pair, m}};
          v.unlisted_margin = -1;
          if (exact_hit) v.answer.pairs = {pair};
          if (says_hit) said.pairs = {pair};
        }
        if (library) return classify(kind, said, v, {}).parties[0].standing;
        Answer right{exact_hit, {}, v.answer.pairs, {}};
        return classify(kind, right, v, {{party, Opinion::Status::answered, said, "", band}}).parties[1].standing;
      };
      const std::string what = party + " on " + std::string(name(kind));
      const double w = band.width;
      switch (band.sides) {
        case BandSides::exact:
          EXPECT_EQ(standing_at(-0x1p-1074, true, false), Standing::wrong) << what;
          EXPECT_EQ(standing_at(0, false, true), Standing::wrong) << what;
          break;
        case BandSides::conservative:
          EXPECT_EQ(standing_at(-w, true, false), Standing::within_band) << what;
          EXPECT_EQ(standing_at(std::nextafter(-w, -1.0), true, false), Standing::wrong) << what;
          EXPECT_EQ(standing_at(0, false, true), Standing::wrong) << what << ": a miss of touching shapes";
          EXPECT_EQ(standing_at(-0x1p-1074, false, false), Standing::right) << what;
          break;
        case BandSides::two_sided:
          EXPECT_EQ(standing_at(-w, true, false), Standing::within_band) << what;
          EXPECT_EQ(standing_at(std::nextafter(-w, -1.0), true, false), Standing::wrong) << what;
          EXPECT_EQ(standing_at(w, false, true), Standing::within_band) << what;
          EXPECT_EQ(standing_at(std::nextafter(w, 1.0), false, true), Standing::wrong) << what;
          break;
      }
    }
  }
  EXPECT_EQ(checked, static_cast<int>(bands.size()) - 1);  // every band but broadphase's
}

}  // namespace
}  // namespace cc::harness
