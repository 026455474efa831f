// The library's certified error bounds, term by term, over generated cases (harness/judging/bound_coverage.h):
// no case's actual error exceeds the term that covers it or the whole bound (a failing case is
// shrunk), and every term is approached within 2^-8 by some case at its decision. A term no case
// comes near is a term no test checks: a generator that stopped reaching its regime fails here.
#include <gtest/gtest.h>
#include <rapidcheck.h>

#include <algorithm>

#include "collide/bound_records.h"
#include "harness/judging/bound_coverage.h"
#include "harness/formats/input_json.h"
#include "oracle/exact/exact_reference.h"
#include "properties/property.h"

namespace cc::test {
namespace {

using namespace harness;

// Cases per kind: enough for every term's regime to come up with the fixed seeds, and about a
// second or two each (a mesh case measures every vertex of both meshes).
int cases_for(QueryKind kind) {
  switch (kind) {
    case QueryKind::ray_aabb:
    case QueryKind::sphere_sphere: return 3000;
    case QueryKind::mesh_mesh: return 80;
    case QueryKind::ray_mesh: return 200;
    default: return 1000;
  }
}

class BoundCoverageProperty : public ::testing::TestWithParam<QueryKind> {};

TEST_P(BoundCoverageProperty, EveryTermIsApproachedAndNoneIsExceeded) {
  const QueryKind kind = GetParam();
  const exact::ExactRationalReference exact;
  const std::string property = std::string(name(kind)) + ": the bounds hold term by term";
  BoundCoverage coverage;
  Met met;
  const bool passed = check_property(property, kind, 0, cases_for(kind), met, [&](const Input& input) {
    const CaseCoverage c = coverage.add(input, exact);
    if (c.largest > 1) {
      RC_FAIL(c.where + ": an error " + std::to_string(c.largest) + " times its bound\n  inputs: " + input_to_json(input).dump());
    }
  }, &exact);
  EXPECT_TRUE(passed) << property;
  const QueryKind kinds[] = {kind};
  const auto rows = coverage.rows(kinds);
  std::cout << format_coverage(rows);
  for (const TermCoverage& row : rows) {
    EXPECT_TRUE(row.ok()) << row.test << " " << row.quantity << " " << row.term << ": closest approach " << row.closest
                          << ", largest " << row.largest << "\n  case: " << (row.largest > 1 ? row.largest_case : row.closest_case);
  }
}

std::vector<QueryKind> certified_kinds() {
  std::vector<QueryKind> kinds;
  for (const ExpectedTerm& e : expected_terms()) {
    if (std::find(kinds.begin(), kinds.end(), e.kind) == kinds.end()) kinds.push_back(e.kind);
  }
  return kinds;
}

INSTANTIATE_TEST_SUITE_P(EveryCertifiedQuery, BoundCoverageProperty, ::testing::ValuesIn(certified_kinds()),
                         [](const auto& p) { return std::string(name(p.param)); });

}  // namespace
}  // namespace cc::test
