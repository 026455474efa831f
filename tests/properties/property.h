// Running a property over generated queries with RapidCheck.
//
// A property draws a vector of choices from RapidCheck and replays it through the harness's
// generator, so RapidCheck's shrinking (toward zeros) moves a counterexample toward simple
// values. Seeds are fixed per property and printed; RC_PARAMS (e.g. "seed=42 max_success=5000")
// overrides them.
#pragma once

#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "harness/judging/features.h"
#include "harness/generation/generate.h"

namespace cc::test {

/// How often a property met each kind of configuration (counted over every case it ran).
struct Met {
  int cases = 0, touching = 0, parallel = 0, degenerate = 0;
  std::map<std::string_view, int> configurations;  // harness/judging/configurations.h
  void count(const harness::Features& f);
  void count(const std::vector<std::string_view>& names);
};

/// Runs `body` on generated queries of one kind; true if it never failed. `met` collects the
/// features the body reports. The options are drawn per case: out of contract with the given
/// percentage. With `exact`, the generators place their bound-reaching constructions at exact
/// margins (GenerateOptions::exact).
bool check_property(const std::string& name, harness::QueryKind kind, int out_of_contract_percent, int cases,
                    Met& met, const std::function<void(const harness::Input&)>& body,
                    const harness::ExactReference* exact = nullptr);

/// The same for a body that makes its own input from the choices.
bool check_property_with_choices(const std::string& name, int cases,
                                 const std::function<void(harness::Choices&)>& body);

/// Expects that a property met touching, parallel (where that applies to its kind) and
/// degenerate configurations at least once.
void expect_met_the_boundary(const std::string& name, harness::QueryKind kind, const Met& met);

/// Expects that a property met every configuration the generators of its kind are meant to make
/// (harness::expected_configurations) at least once, and prints how often it met each.
void expect_met_every_configuration(const std::string& name, harness::QueryKind kind, const Met& met);

}  // namespace cc::test
