#include "harness/judging/classify.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "harness/judging/bands.h"
#include "harness/judging/hull_distance.h"
#include "harness/model/subject.h"
#include "harness/model/kind_pieces.h"

namespace cc::harness {

double ExactVerdict::margin_of(const FacePair& pair) const {
  const auto it = std::lower_bound(pair_margins.begin(), pair_margins.end(), pair,
                                   [](const PairMargin& m, const FacePair& p) { return m.pair < p; });
  return it != pair_margins.end() && it->pair == pair ? it->margin : unlisted_margin;
}

std::string_view to_string(Standing s) {
  switch (s) {
    case Standing::right: return "right";
    case Standing::within_band: return "within band";
    case Standing::wrong: return "wrong";
    case Standing::not_applicable: return "n/a";
    case Standing::failed: return "failed";
    case Standing::differs: return "differs";
  }
  return "?";
}

namespace {

std::string describe(bool says_hit, const ExactVerdict& exact) {
  std::ostringstream s;
  s << "says " << (says_hit ? "hit" : "miss") << ", exact " << (exact.answer.hit ? "hit" : "miss") << " at margin "
    << exact.margin;
  return s.str();
}

// Parameters (ray t) within the band's relative width of the exact ones.
bool params_agree(const Band& band, const Answer& said, const Answer& exact) {
  if (said.params.size() != exact.params.size()) return false;
  for (std::size_t i = 0; i < said.params.size(); ++i) {
    const double a = said.params[i], e = exact.params[i];
    if (a == e) continue;  // also equal infinities
    if (!(std::fabs(a - e) <= band.param_width * std::fabs(e) + 0x1p-1060)) return false;
  }
  return true;
}

std::string pair_text(const FacePair& p) {
  std::ostringstream s;
  s << '(' << p.first << ", " << p.second << ')';
  return s.str();
}

// Mesh queries: every pair where the party and the exact answer differ is judged on its own
// margin. all_pairs: the pairs in one set and not the other. first_hit: the pair found must
// collide; a miss must leave only pairs within the band.
PartyStanding judge_pairs(std::string party, const Band& band, const Answer& said, const ExactVerdict& exact,
                          bool first_hit) {
  struct Difference {
    FacePair pair;
    bool says_hit;
  };
  std::vector<Difference> differences;
  const auto& truth = exact.answer.pairs;
  const auto collides = [&](const FacePair& p) { return std::binary_search(truth.begin(), truth.end(), p); };
  if (!first_hit) {
    std::vector<FacePair> only_said, only_exact;
    std::set_difference(said.pairs.begin(), said.pairs.end(), truth.begin(), truth.end(), std::back_inserter(only_said));
    std::set_difference(truth.begin(), truth.end(), said.pairs.begin(), said.pairs.end(), std::back_inserter(only_exact));
    for (const FacePair& p : only_said) differences.push_back({p, true});
    for (const FacePair& p : only_exact) differences.push_back({p, false});
  } else if (said.hit) {
    if (said.pairs.empty()) return {std::move(party), Standing::wrong, "says hit without naming a pair"};
    if (!collides(said.pairs[0])) differences.push_back({said.pairs[0], true});
  } else {
    for (const FacePair& p : truth) differences.push_back({p, false});
  }
  PartyStanding standing{std::move(party), Standing::right, ""};
  int wrong = 0, in_band = 0;
  std::string first_wrong, first_in_band;
  for (const Difference& d : differences) {
    const double m = exact.margin_of(d.pair);
    std::ostringstream s;
    s << "says " << pair_text(d.pair) << (d.says_hit ? " collides" : " does not collide") << ", exact "
      << (d.says_hit ? "apart" : "colliding") << " at margin " << m;
    if (within_band(band, d.says_hit, m)) {
      if (in_band++ == 0) first_in_band = s.str();
    } else if (wrong++ == 0) {
      first_wrong = s.str();
    }
  }
  const auto more = [](int n) {
    std::ostringstream s;
    if (n > 1) s << " (and " << n - 1 << " more pairs)";
    return s.str();
  };
  if (wrong > 0) {
    standing.standing = Standing::wrong;
    standing.why = first_wrong + more(wrong);
  } else if (in_band > 0) {
    standing.standing = Standing::within_band;
    standing.why = first_in_band + more(in_band);
  }
  return standing;
}

// Pairs over frames: every pair of every frame where the party and the exact answer differ; the
// truth is exact comparisons of the given bounds, so within a band only if the band allows.
PartyStanding judge_frames(std::string party, const Band& band, const Answer& said, const ExactVerdict& exact) {
  PartyStanding standing{std::move(party), Standing::right, ""};
  const auto& truth = exact.answer.frames;
  if (said.frames.size() != truth.size()) {
    standing.standing = Standing::wrong;
    standing.why = "answers " + std::to_string(said.frames.size()) + " frames of " + std::to_string(truth.size());
    return standing;
  }
  int differing = 0;
  std::string first;
  for (std::size_t f = 0; f < truth.size(); ++f) {
    std::vector<FacePair> only_said, only_exact;
    std::set_difference(said.frames[f].begin(), said.frames[f].end(), truth[f].begin(), truth[f].end(),
                        std::back_inserter(only_said));
    std::set_difference(truth[f].begin(), truth[f].end(), said.frames[f].begin(), said.frames[f].end(),
                        std::back_inserter(only_exact));
    if (differing == 0 && !(only_said.empty() && only_exact.empty())) {
      const bool says = !only_said.empty();
      first = "frame " + std::to_string(f) + ": says boxes " + pair_text(says ? only_said[0] : only_exact[0]) +
              (says ? " overlap, exact apart" : " are apart, exact overlapping");
    }
    differing += static_cast<int>(only_said.size() + only_exact.size());
  }
  if (differing > 0) {
    standing.standing = band.sides == BandSides::exact ? Standing::wrong : Standing::within_band;
    standing.why = first + (differing > 1 ? " (and " + std::to_string(differing - 1) + " more pairs)" : "");
  }
  return standing;
}

// A hit's parameters against the ranges of the exact verdict, or within the band's relative
// width of the exact parameters. Nothing when they agree, or when the party gives none (the
// batched ray test, any hit): it is judged on its hit alone. Else why not.
std::optional<std::string> params_wrong(const Band& band, const Answer& said, const ExactVerdict& exact) {
  const auto& ranges = exact.param_ranges;
  if (said.params.empty()) return std::nullopt;
  bool wrong = false;
  if (!ranges.empty()) {
    wrong = said.params.size() != ranges.size();
    for (std::size_t i = 0; !wrong && i < ranges.size(); ++i) {
      wrong = !(ranges[i].first <= said.params[i] && said.params[i] <= ranges[i].second);
    }
  } else {
    if (band.param_width <= 0) return std::nullopt;
    wrong = !params_agree(band, said, exact.answer);
  }
  if (!wrong) return std::nullopt;
  std::ostringstream s;
  s.precision(17);
  s << "parameters differ:";
  for (double v : said.params) s << ' ' << v;
  if (ranges.empty()) {
    s << " vs exact";
    for (double v : exact.answer.params) s << ' ' << v;
  } else {
    s << " outside";
    for (const auto& [lo, hi] : ranges) s << " [" << lo << ", " << hi << ']';
  }
  return s.str();
}

std::vector<Vec3> points_of(const std::vector<double>& params) {
  std::vector<Vec3> points;
  for (std::size_t i = 0; i + 2 < params.size(); i += 3) points.push_back({params[i], params[i + 1], params[i + 2]});
  return points;
}

// The corners of an intersection against the exact ones, within the verdict's tolerance both ways.
// Nothing when they agree, or when the party gives none (judged on its hit alone). Else why not.
std::optional<std::string> corners_wrong(const Answer& said, const ExactVerdict& exact) {
  if (said.params.empty()) return std::nullopt;
  std::ostringstream s;
  s.precision(17);
  if (said.params.size() % 3 != 0) {
    s << "gives " << said.params.size() << " corner coordinates, not three per corner";
    return s.str();
  }
  const double d = hull_distance(points_of(said.params), points_of(exact.answer.params));
  if (d <= exact.corner_tolerance) return std::nullopt;
  s << "corners";
  for (double v : said.params) s << ' ' << v;
  s << " are " << d << " from the exact ones";
  for (double v : exact.answer.params) s << ' ' << v;
  s << " (tolerance " << exact.corner_tolerance << ')';
  return s.str();
}

// A distance and its closest pair, each within the bounds the party certified with them (a
// distance query of the library gives them after the pair) or else within the party's band of
// the inputs' scale, decided in exact arithmetic by the reference. A party may give the distance
// alone (its points are not on the shapes, as FCL's signed distance through contacts). The hit
// follows from the distance (0 or less where the shapes meet) and is not judged apart from it,
// but for a party that gives no distance where it finds the shapes meeting.
PartyStanding judge_distance(std::string party, const Band& band, const Answer& said, const ExactVerdict& exact) {
  PartyStanding p{std::move(party), Standing::right, ""};
  if (said.params.empty()) {  // "in collision", with no distance (FCL's unsigned distance): the hit alone
    if (said.hit != exact.answer.hit) {
      p.standing = within_band(band, said.hit, exact.margin) ? Standing::within_band : Standing::wrong;
      p.why = describe(said.hit, exact);
    }
    return p;
  }
  std::ostringstream s;
  s.precision(17);
  const std::vector<double>& q = said.params;
  if (q.size() != 1 && q.size() != 7 && q.size() != 9) {
    s << "gives " << q.size() << " numbers, not a distance (and two points, and two bounds)";
  } else if (!exact.check_distance) {
    throw std::invalid_argument("the exact verdict of a distance query has no check_distance");
  } else {
    const bool certified = q.size() == 9;
    DistanceClaim claim{q[0], q.size() > 1, {}, {}, certified ? q[7] : band.param_width * exact.scale,
                        certified ? q[8] : band.param_width * exact.scale};
    if (claim.witnessed) claim.on_a = {q[1], q[2], q[3]}, claim.on_b = {q[4], q[5], q[6]};
    if (auto why = exact.check_distance(claim)) {
      s << *why << " (" << (certified ? "its own bounds " : "its band's ") << claim.distance_tolerance << " and "
        << claim.point_tolerance << ')';
    }
  }
  if (!s.str().empty()) {
    p.standing = Standing::wrong;
    p.why = s.str();
  }
  return p;
}

PartyStanding judge_party(std::string party, const Band& band, const Answer& said, const ExactVerdict& exact,
                          Judged judged) {
  if (judged == Judged::frames) return judge_frames(std::move(party), band, said, exact);
  if (judged == Judged::distance) return judge_distance(std::move(party), band, said, exact);
  PartyStanding p{std::move(party), Standing::right, ""};
  if (judged == Judged::all_pairs || judged == Judged::first_pair) {
    p = judge_pairs(std::move(p.party), band, said, exact, judged == Judged::first_pair);
  } else if (said.hit != exact.answer.hit) {
    p.standing = within_band(band, said.hit, exact.margin) ? Standing::within_band : Standing::wrong;
    p.why = describe(said.hit, exact);
  }
  if (p.standing != Standing::wrong && said.hit && exact.answer.hit) {
    if (auto why = judged == Judged::corners ? corners_wrong(said, exact) : params_wrong(band, said, exact)) {
      p.standing = Standing::wrong;
      p.why = *why;
    }
  }
  return p;
}

}  // namespace

Judged judged_of(QueryKind kind) {
  return pieces_of(kind).judged;
}

Verdict classify(QueryKind kind, const Answer& library, const ExactVerdict& exact, const std::vector<Opinion>& opinions) {
  return classify(library_band(kind), judged_of(kind), library, exact, opinions);
}

Verdict classify(const Band& band_of_library, Judged judged, const Answer& library, const ExactVerdict& exact,
                 const std::vector<Opinion>& opinions) {
  Verdict v;
  if (exact.contract != Contract::in) {
    PartyStanding lib{"library", Standing::right, exact.note};
    // The documented answer is crosscheck's own library's; a subject under test documents its own.
    if (exact.contract == Contract::documented && library.hit != exact.answer.hit && subject_under_test() == nullptr) {
      lib.standing = Standing::wrong;
      lib.why = "breaks its documented answer (" + std::string(exact.answer.hit ? "hit" : "miss") + ") for: " + exact.note;
    }
    v.parties.push_back(lib);
    v.cls = lib.standing == Standing::wrong ? CaseClass::impl_bug : CaseClass::out_of_contract;
    // The second opinions are still heard: judged when the reference decided the exact answer
    // (finite inputs beyond the library's range), else compared with the documented answer.
    for (const Opinion& o : opinions) {
      if (is_library_party(o.party) || o.status == Opinion::Status::not_applicable) {
        v.parties.push_back({o.party, Standing::not_applicable, o.detail.empty() ? exact.note : o.detail});
      } else if (o.status == Opinion::Status::failed || o.status == Opinion::Status::timed_out) {
        v.parties.push_back({o.party, Standing::failed, o.detail});
      } else if (exact.contract == Contract::unspecified && exact.decided && o.band) {
        Band band = *o.band;
        band.param_width = 0;
        Answer said = o.answer;
        said.params.clear();
        // Out of the domain only the hit is heard, a distance's too.
        v.parties.push_back(judge_party(o.party, band, said, exact, judged == Judged::distance ? Judged::hit : judged));
      } else if (exact.contract == Contract::documented && o.answer.hit != exact.answer.hit) {
        v.parties.push_back({o.party, Standing::differs,
                             std::string("says ") + (o.answer.hit ? "hit" : "miss") + " where the library documents " +
                                 (exact.answer.hit ? "hit" : "miss") + " (" + exact.note + "); no exact verdict"});
      } else if (exact.contract == Contract::documented) {
        v.parties.push_back({o.party, Standing::right, ""});
      } else {
        v.parties.push_back({o.party, Standing::not_applicable,
                             std::string("says ") + (o.answer.hit ? "hit" : "miss") + "; no exact verdict (" + exact.note + ")"});
      }
    }
    return v;
  }
  if (!exact.decided) {
    v.parties.push_back({"library", Standing::not_applicable, exact.note});
    v.cls = CaseClass::undecided;
    return v;
  }

  v.parties.push_back(judge_party("library", band_of_library, library, exact, judged));
  bool any_wrong = false, library_wrong = false, any_failed = false, any_band = v.parties[0].standing == Standing::within_band;
  for (const Opinion& o : opinions) {
    if (o.status == Opinion::Status::not_applicable) {
      v.parties.push_back({o.party, Standing::not_applicable, o.detail});
      continue;
    }
    if (o.status == Opinion::Status::failed || o.status == Opinion::Status::timed_out) {
      v.parties.push_back({o.party, Standing::failed, o.detail});
      (is_library_party(o.party) ? library_wrong : any_failed) = true;  // the library's own failure is a bug
      continue;
    }
    const bool own = is_library_party(o.party);
    if (!own && !o.band) throw std::invalid_argument("the opinion of " + o.party + " carries no band");
    Band band = own ? band_of_library : *o.band;
    Answer said = o.answer;
    if (!own && judged != Judged::distance) {  // second opinions give no parameters, but distances
      band.param_width = 0;
      said.params.clear();
    }
    v.parties.push_back(judge_party(o.party, band, said, exact, judged));
    const bool wrong = v.parties.back().standing == Standing::wrong;
    (own ? library_wrong : any_wrong) |= wrong;
    any_band |= v.parties.back().standing == Standing::within_band;
  }
  if (v.parties[0].standing == Standing::wrong || library_wrong) {
    v.cls = CaseClass::impl_bug;
  } else if (any_failed) {
    v.cls = CaseClass::oracle_crash;
  } else if (any_wrong) {
    v.cls = CaseClass::oracle_defect;
  } else if (any_band) {
    v.cls = CaseClass::boundary;
  } else {
    v.cls = CaseClass::agree;
  }
  return v;
}

}  // namespace cc::harness
