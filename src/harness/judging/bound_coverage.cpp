#include "harness/judging/bound_coverage.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

#include "collide/bound_records.h"
#include "harness/formats/input_json.h"
#include "harness/model/mesh_collide.h"
#include "harness/model/kind_pieces.h"

namespace cc::harness {
namespace {

// Every kind's terms, in the order of the kinds.
const std::vector<ExpectedTerm>& all_expected() {
  static const std::vector<ExpectedTerm> terms = [] {
    std::vector<ExpectedTerm> out;
    for (QueryKind kind : kAllQueryKinds) {
      for (const BoundTerm& t : pieces_of(kind).bound_terms()) out.push_back({kind, t.test, t.quantity, t.term});
    }
    return out;
  }();
  return terms;
}

// The same term, whichever kind measures it.
bool same_term(const TermCoverage& row, const ExpectedTerm& e) {
  return row.test == e.test && row.quantity == e.quantity && row.term == e.term;
}

bool is_total(std::string_view term) { return term == "total"; }

// error / term. A term's error counts beyond fp::subnormal_slack, which every total holds for
// results in the subnormal range (where a relative term may be 0).
double ratio(const TermError& e) {
  const double error = is_total(e.term) ? e.error : std::max(0.0, e.error - fp::subnormal_slack);
  if (error == 0) return 0;
  return e.bound > 0 ? error / e.bound : INFINITY;
}

TermCoverage row_of(std::string_view test, std::string_view quantity, std::string_view term) {
  TermCoverage row;
  row.test = test, row.quantity = quantity, row.term = term;
  return row;
}

}  // namespace

std::span<const ExpectedTerm> expected_terms() { return all_expected(); }

bool TermCoverage::ok() const {
  if (largest > 1) return false;
  return is_total(term) || closest >= kApproachFactor;
}

std::string_view test_of(QueryKind kind, std::string_view quantity) {
  for (const ExpectedTerm& e : all_expected()) {
    if (e.kind == kind && e.quantity == quantity) return e.test;
  }
  return name(kind);
}

std::vector<bounds::Records> probe_library(const Input& input) {
  std::vector<bounds::Records> out;
  pieces_of(kind_of(input)).probe(input, out);
  return out;
}

CaseCoverage BoundCoverage::add(const Input& input, const ExactReference& exact) {
  CaseCoverage added;
  const ExactVerdict verdict = exact.judge(input);
  if (verdict.contract != Contract::in || !verdict.decided) return added;
  added.measured = true;
  const QueryKind kind = kind_of(input);
  const bool near_boundary = std::fabs(verdict.margin) <= kNearBoundary;
  std::set<std::size_t> met;
  std::string json;  // the inputs, written when first needed
  const auto inputs = [&] {
    if (json.empty()) json = input_to_json(input).dump();
    return json;
  };
  for (const bounds::Records& records : probe_library(input)) {
    for (const TermError& e : exact.bound_errors(records)) {
      const std::string_view test = test_of(kind, e.family);
      auto it = std::find_if(rows_.begin(), rows_.end(), [&](const TermCoverage& row) {
        return row.test == test && row.quantity == e.family && row.term == e.term;
      });
      if (it == rows_.end()) {
        rows_.push_back(row_of(test, e.family, e.term));
        it = rows_.end() - 1;
      }
      const double r = ratio(e);
      if (r > it->largest) it->largest = r, it->largest_case = inputs();
      if (r > added.largest) added.largest = r, added.where = it->test + " " + it->quantity + " " + it->term;
      // A term's approach counts where its error could decide an answer; a total's, everywhere.
      // (The object bounds are containers whatever the query's answer.)
      if (!is_total(e.term) && !(e.decisive && (near_boundary || test == "object_bounds"))) continue;
      ++it->quantities;
      met.insert(static_cast<std::size_t>(it - rows_.begin()));
      if (r > it->closest) it->closest = r, it->closest_case = inputs();
    }
  }
  for (std::size_t i : met) ++rows_[i].cases;
  return added;
}

std::vector<TermCoverage> BoundCoverage::rows(std::span<const QueryKind> kinds) const {
  const auto wanted = [&](QueryKind k) { return kinds.empty() || std::find(kinds.begin(), kinds.end(), k) != kinds.end(); };
  std::vector<TermCoverage> out;
  for (const ExpectedTerm& e : all_expected()) {
    const bool listed = std::any_of(out.begin(), out.end(), [&](const TermCoverage& row) { return same_term(row, e); });
    if (!wanted(e.kind) || listed) continue;
    const auto it = std::find_if(rows_.begin(), rows_.end(), [&](const TermCoverage& row) { return same_term(row, e); });
    out.push_back(it != rows_.end() ? *it : row_of(e.test, e.quantity, e.term));
  }
  for (const TermCoverage& row : rows_) {
    const auto& all = all_expected();
    if (std::none_of(all.begin(), all.end(), [&](const ExpectedTerm& e) { return same_term(row, e); })) out.push_back(row);
  }
  return out;
}

std::string format_coverage(const std::vector<TermCoverage>& rows) {
  std::string out;
  char line[256];
  std::snprintf(line, sizeof line, "%-24s %-20s %-16s %10s %11s %8s  %s\n", "test", "quantity", "term", "closest",
                "quantities", "cases", "");
  out += line;
  for (const TermCoverage& row : rows) {
    std::string closest = "-";
    if (row.closest > 0 && std::isfinite(row.closest)) {
      std::snprintf(line, sizeof line, "2^%.1f", std::log2(row.closest));
      closest = line;
    } else if (row.closest > 0) {
      closest = "inf";
    }
    std::string note;
    if (row.largest > 1) {
      note = is_total(row.term) ? "EXCEEDED: the bound does not hold" : "EXCEEDED: the term does not cover its error";
    } else if (row.quantities == 0) {
      note = "not measured";
    } else if (!row.ok()) {
      note = "never approached within 2^-8";
    }
    std::snprintf(line, sizeof line, "%-24s %-20s %-16s %10s %11ld %8ld  %s\n", row.test.c_str(), row.quantity.c_str(),
                  row.term.c_str(), closest.c_str(), row.quantities, row.cases, note.c_str());
    out += line;
  }
  return out;
}

}  // namespace cc::harness
