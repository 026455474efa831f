#include "harness/shrinking/shrink.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <tuple>

#include "harness/generation/generate.h"
#include "harness/judging/evaluate.h"
#include "harness/formats/input_json.h"
#include "harness/formats/number_text.h"
#include "harness/model/library.h"
#include "harness/model/mesh_query.h"
#include "harness/shrinking/shrink_faces.h"
#include "oracle/exact/exact_reference.h"
#include "oracle/fcl/fcl_oracle.h"

namespace cc::harness {
namespace {

TEST(Complexity, OrdersZeroIntegersHalvesThenMantissaBits) {
  EXPECT_LT(complexity(0.0), complexity(-0.0));
  EXPECT_LT(complexity(-0.0), complexity(1.0));
  EXPECT_LT(complexity(1.0), complexity(-1.0));
  EXPECT_LT(complexity(2.0), complexity(3.0));
  EXPECT_LT(complexity(1000.0), complexity(0.5));
  EXPECT_LT(complexity(0.5), complexity(0.1));
  EXPECT_LT(complexity(0.75), complexity(0.1));
  EXPECT_LT(complexity(0x1p30), complexity(0.1));
  EXPECT_LT(complexity(0.1), complexity(NAN));
}

TEST(ComplexValues, CountsWhatIsNotASmallIntegerOrAHalf) {
  EXPECT_EQ(complex_values(SphereSphereInput{{{0, 1, -2}, 0.5}, {{1024, 0.25, 0.1}, 1e9}}), 3);
}

// An evaluation that only the exact reference and the library make, with a planted
// disagreement: a "second opinion" that says hit whenever the spheres' radii sum above 1.
Evaluation planted(const Input& in) {
  static const exact::ExactRationalReference exact;
  Evaluation e;
  e.library = ask_library(in);
  e.exact = exact.judge(in);
  const auto& s = std::get<SphereSphereInput>(in);
  e.opinions = {{"fcl.collide(Sphere,Sphere)", Opinion::Status::answered, {s.a.radius + s.b.radius > 1, {}, {}, {}}, ""}};
  restore_bands(e.opinions, fcl_oracle::FclSecondOpinion(), QueryKind::sphere_sphere);
  e.verdict = classify(QueryKind::sphere_sphere, e.library, e.exact, e.opinions);
  return e;
}

TEST(Shrink, KeepsTheDisagreementAndSimplifiesTheValues) {
  const Input start = SphereSphereInput{{{0.1234567, -7.5e3, 3.3}, 0.9876}, {{11.11, 0.2, 9.87e5}, 0.33}};
  const Evaluation e = planted(start);
  ASSERT_EQ(e.verdict.cls, CaseClass::oracle_defect);  // apart, but the planted party says hit
  const ShrinkResult r = shrink(start, e, planted);
  EXPECT_EQ(r.evaluation.verdict.cls, CaseClass::oracle_defect);
  EXPECT_EQ(complex_values(r.input), 0);
  const auto& s = std::get<SphereSphereInput>(r.input);
  EXPECT_GT(s.a.radius + s.b.radius, 1);  // still the planted disagreement
  EXPECT_LE(r.attempts, 4000);
}

// Keeping the signature, part by part: the planted evaluations below differ from the start's in
// one part of the signature only (the class, the exact answer, a party's standing, what it said,
// a party that was right), and only on about half of the candidates (by a hash of their inputs),
// so the shrinker can make progress on the others. It must reject every candidate that changes
// the part: the result keeps every part, compared part by part (not through signature_of).
enum class Part { cls, exact_hit, library_standing, library_said, party_standing, party_said, right_party };

Evaluation base_evaluation() {
  Evaluation e;
  e.library = {true, {}, {}, {}};
  e.exact.answer = {true, {}, {}, {}};
  e.exact.margin = 0x1p-45;
  e.opinions = {{"fcl.OBBd::overlap", Opinion::Status::answered, {false, {}, {}, {}}, ""},
                {"fcl.collide(Box,Box)", Opinion::Status::answered, {true, {}, {}, {}}, ""}};
  restore_bands(e.opinions, fcl_oracle::FclSecondOpinion(), QueryKind::obb_obb);
  e.verdict.cls = CaseClass::oracle_defect;
  e.verdict.parties = {{"library", Standing::within_band, ""},
                       {"fcl.OBBd::overlap", Standing::wrong, ""},
                       {"fcl.collide(Box,Box)", Standing::right, ""}};
  return e;
}

void change(Evaluation& e, Part part) {
  switch (part) {
    case Part::cls: e.verdict.cls = CaseClass::boundary; break;
    case Part::exact_hit: e.exact.answer.hit = false; break;
    case Part::library_standing: e.verdict.parties[0].standing = Standing::wrong; break;
    case Part::library_said: e.library.hit = false; break;
    case Part::party_standing: e.verdict.parties[1].standing = Standing::within_band; break;
    case Part::party_said: e.opinions[0].answer.hit = true; break;
    case Part::right_party: e.verdict.parties[2].standing = Standing::wrong; break;
  }
}

// Every part of the signature, written out here.
std::vector<std::string> parts_of(const Evaluation& e) {
  std::vector<std::string> out = {std::string(to_string(e.verdict.cls)), e.exact.answer.hit ? "exact hit" : "exact miss",
                                  e.library.hit ? "library hit" : "library miss"};
  for (std::size_t i = 0; i < e.verdict.parties.size(); ++i) {
    out.push_back(e.verdict.parties[i].party + " " + std::string(to_string(e.verdict.parties[i].standing)));
    if (i > 0) out.push_back(e.verdict.parties[i].party + (e.opinions[i - 1].answer.hit ? " hit" : " miss"));
  }
  return out;
}

TEST(Shrink, KeepsEveryPartOfTheSignature) {
  const Part parts[] = {Part::cls,           Part::exact_hit,      Part::library_standing, Part::library_said,
                        Part::party_standing, Part::party_said,    Part::right_party};
  for (QueryKind kind : {QueryKind::sphere_sphere, QueryKind::obb_obb, QueryKind::ray_aabb}) {
    for (Part part : parts) {
      for (std::uint64_t seed = 0; seed < 3; ++seed) {
        RandomChoices choices(seed * 7 + 1);
        const Input start = generate(kind, choices);
        int changed = 0;
        const Evaluator planted = [&](const Input& in) {
          Evaluation e = base_evaluation();
          if (std::hash<std::string>{}(input_to_json(in).dump()) % 2 == 0 && !(in == start)) {
            change(e, part);
            ++changed;
          }
          return e;
        };
        const ShrinkResult r = shrink(start, base_evaluation(), planted, 300, 20);
        const std::string what = std::string(name(kind)) + " part " + std::to_string(static_cast<int>(part)) +
                                 " seed " + std::to_string(seed);
        EXPECT_EQ(parts_of(r.evaluation), parts_of(base_evaluation())) << what;
        EXPECT_GT(changed, 0) << what << ": no candidate changed the part";
        EXPECT_GT(r.accepted, 0) << what << ": no candidate was kept";
      }
    }
  }
}

TEST(Shrink, RespectsTheAttemptBudget) {
  const Input start = SphereSphereInput{{{0.1234567, -7.5e3, 3.3}, 0.9876}, {{11.11, 0.2, 9.87e5}, 0.33}};
  EXPECT_LE(shrink(start, planted(start), planted, 5).attempts, 5);
}

// A planted disagreement on walls: a "second opinion" that is wrong whenever a wall starts at
// x = 7. The shrinker keeps that wall alone, and its x.
Evaluation planted_walls(const Input& in) {
  Evaluation e = base_evaluation();
  const auto& walls = std::get<DiscWallsInput>(in).walls;
  if (std::none_of(walls.begin(), walls.end(), [](const Wall& w) { return w.a.x == 7; })) e.verdict.cls = CaseClass::agree;
  return e;
}

// Out of time before the first attempt: nothing is tried, neither the lists nor the values, and
// the result says it ran out of time.
TEST(Shrink, RespectsTheTimeBudgetFromTheFirstAttempt) {
  DiscWallsInput start{{{0.3, 0.7}, 0.1}, {}};
  for (int i = 0; i < 11; ++i) start.walls.push_back({{i == 6 ? 7.0 : 0.1 * i, 1.5}, {2.5, 0.1 * i}});
  const ShrinkResult r = shrink(start, base_evaluation(), planted_walls, 4000, 0);
  EXPECT_EQ(r.attempts, 0);
  EXPECT_TRUE(r.out_of_time);
  EXPECT_EQ(std::get<DiscWallsInput>(r.input).walls.size(), 11u);
}

TEST(Shrink, ListsOfWallsLoseTheWallsThatDoNotMatter) {
  DiscWallsInput start{{{0.3, 0.7}, 0.1}, {}};
  for (int i = 0; i < 11; ++i) start.walls.push_back({{i == 6 ? 7.0 : 0.1 * i, 1.5}, {2.5, 0.1 * i}});
  const ShrinkResult r = shrink(start, base_evaluation(), planted_walls);
  const auto& walls = std::get<DiscWallsInput>(r.input).walls;
  ASSERT_EQ(walls.size(), 1u);
  EXPECT_EQ(walls[0].a.x, 7);
  EXPECT_EQ(complex_values(r.input), 0);
}

// A planted mesh disagreement: a "second opinion" that lists the exact pairs except those whose
// triangle of mesh a has a vertex above z = 0.25.
Evaluation planted_meshes(const Input& in) {
  static const exact::ExactRationalReference exact;
  Evaluation e;
  e.library = ask_library(in);
  e.exact = exact.judge(in);
  const MeshPair& m = *meshes_of(in);
  Answer said;
  for (const FacePair& p : e.exact.answer.pairs) {
    bool high = false;
    for (const Vec3& v : m.a.mesh->triangle(p.first).v) high = high || apply(m.pose_a, v).z > 0.25;
    if (!high) said.pairs.push_back(p);
  }
  said.hit = !said.pairs.empty();
  e.opinions = {{"fcl.BVHModel<OBBd>", Opinion::Status::answered, said, ""}};
  restore_bands(e.opinions, fcl_oracle::FclSecondOpinion(), QueryKind::mesh_mesh);
  e.verdict = classify(kind_of(in), e.library, e.exact, e.opinions);
  return e;
}

Input sphere_through_torus() {
  MeshPair m;
  m.a = procedural_mesh({ProceduralMesh::Shape::sphere, 3, 8, 1.0});
  m.b = procedural_mesh({ProceduralMesh::Shape::torus, 5, 8, 1.0});
  m.pose_b.translation = {0.7, 0.1, 0.3};
  return MeshMeshInput{m};
}

TEST(ShrinkFaces, DisputedFacesAreThoseOfPairsAPartyListsDifferently) {
  const Input in = sphere_through_torus();
  const Evaluation e = planted_meshes(in);
  ASSERT_EQ(e.verdict.cls, CaseClass::oracle_defect);
  const MeshPair& m = *meshes_of(in);
  const std::vector<std::uint32_t> a = disputed_faces(e, false, false);
  ASSERT_FALSE(a.empty());
  EXPECT_LT(a.size(), m.a.mesh->size());
  for (std::uint32_t f : a) {
    double top = -INFINITY;
    for (const Vec3& v : m.a.mesh->triangle(f).v) top = std::max(top, v.z);
    EXPECT_GT(top, 0.25) << "face " << f << " is not one the planted party drops";
  }
}

TEST(Shrink, AMeshCaseLosesFacesAndKeepsItsDisagreement) {
  const Input start = sphere_through_torus();
  const Evaluation e = planted_meshes(start);
  ASSERT_EQ(e.verdict.cls, CaseClass::oracle_defect);
  const ShrinkResult r = shrink(start, e, planted_meshes, 1500, 60);
  EXPECT_EQ(r.evaluation.verdict.cls, CaseClass::oracle_defect);
  const MeshPair& m = *meshes_of(r.input);
  EXPECT_EQ(m.a.source, MeshRef::Source::triangles);
  // Two pairs are the least: one the party drops, one it lists (the signature has it say hit).
  EXPECT_LE(m.a.mesh->size(), 2u);
  EXPECT_LE(m.b.mesh->size(), 2u);
  EXPECT_LT(complex_values(r.input), complex_values(start));
}

// Every signed permutation matrix in a case's JSON under `key` ("rotation": a pose's, which
// must stay proper; "axes": a box's), as its determinant and its text.
void simple_frames_in(const Json& j, const std::string& key, std::vector<std::pair<int, std::string>>& out) {
  if (j.is_object()) {
    for (auto it = j.begin(); it != j.end(); ++it) {
      if (it.key() == key && it.value().is_array() && it.value().size() == 3) {
        double m[3][3];
        bool simple = true;  // a signed permutation: one +-1 in each row and each column
        int row_ones[3] = {0, 0, 0}, column_ones[3] = {0, 0, 0};
        for (int r = 0; r < 3; ++r) {
          for (int c = 0; c < 3; ++c) {
            m[r][c] = *parse_double(it.value()[r][c].get<std::string>());
            simple &= m[r][c] == 0 || m[r][c] == 1 || m[r][c] == -1;
            row_ones[r] += m[r][c] != 0;
            column_ones[c] += m[r][c] != 0;
          }
        }
        for (int i = 0; i < 3; ++i) simple &= row_ones[i] == 1 && column_ones[i] == 1;
        const double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                           m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
        if (simple) out.emplace_back(static_cast<int>(det), it.value().dump());
      } else {
        simple_frames_in(it.value(), key, out);
      }
    }
  } else if (j.is_array()) {
    for (const Json& e : j) simple_frames_in(e, key, out);
  }
}

// The shrinker's candidate frames: a pose's rotation only ever becomes one of the 24 proper
// signed permutations (determinant +1: a reflection would turn a mesh inside out), and it tries
// every one of them; a box's axes may take all 48.
TEST(Shrink, CandidatePosesAreProperRotationsAndReachAllOfThem) {
  // Two one-triangle meshes, a turned about z by 30 degrees; a box pair with turned axes.
  const Json mesh_mesh = Json::parse(R"({
    "a": {"triangles": [[["0", "0", "0"], ["1", "0", "0"], ["0", "1", "0"]]]},
    "pose_a": {"rotation": [["0.8660254037844387", "-0.5", "0"], ["0.5", "0.8660254037844387", "0"], ["0", "0", "1"]],
               "translation": ["0.25", "0", "0"]},
    "b": {"triangles": [[["0", "0", "0"], ["0", "1", "0"], ["0", "0", "1"]]]},
    "pose_b": {"rotation": [["1", "0", "0"], ["0", "1", "0"], ["0", "0", "1"]], "translation": ["0.5", "0", "0"]},
    "library": {"bv": "obb", "build": "top_down", "split_axis": "longest_side", "split_point": "midpoint",
                "leaf_size": 1, "update": "approximate", "descent": "first_model"}})");
  for (const auto& [kind, key, expected] : {std::tuple{QueryKind::mesh_mesh, "rotation", 24},
                                            std::tuple{QueryKind::obb_obb, "axes", 48}}) {
    RandomChoices choices(3);
    const Input start = kind == QueryKind::mesh_mesh ? input_from_json(kind, mesh_mesh, "", ".") : generate(kind, choices);
    std::set<std::string> tried;
    int improper = 0;
    const Evaluator reject_all = [&](const Input& in) {
      std::vector<std::pair<int, std::string>> frames;
      simple_frames_in(input_to_json(in), key, frames);
      for (const auto& [det, text] : frames) {
        tried.insert(text);
        improper += det != 1;
      }
      Evaluation e = base_evaluation();
      e.verdict.cls = CaseClass::agree;  // never the same disagreement: every candidate is rejected
      return e;
    };
    (void)shrink(start, base_evaluation(), reject_all, 3000, 60);
    if (std::string(key) == "rotation") {
      EXPECT_EQ(improper, 0) << name(kind);
    }
    EXPECT_EQ(static_cast<int>(tried.size()), expected) << name(kind);
  }
}

}  // namespace
}  // namespace cc::harness
