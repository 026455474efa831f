#include "properties/property.h"

#include <gtest/gtest.h>
#include <rapidcheck.h>
#include "test_paths.h"
#include "harness/judging/configurations.h"

#include <cstdlib>
#include <iostream>

namespace cc::test {
namespace {

constexpr std::size_t kChoices = 256;

rc::detail::TestParams params_for(const std::string& name, int cases) {
  if (std::getenv("RC_PARAMS") != nullptr) return rc::detail::configuration().testParams;
  rc::detail::TestParams params;
  params.seed = std::hash<std::string>{}(name) % 1000000007ULL;  // fixed for each property
  params.maxSuccess = cases;
  return params;
}

bool run(const std::string& name, int cases, const std::function<void()>& property) {
  const rc::detail::TestParams params = params_for(name, cases);
  std::cout << "property \"" << name << "\": seed " << params.seed << ", " << params.maxSuccess
            << " cases (RC_PARAMS overrides)" << std::endl;
  rc::detail::TestMetadata metadata;
  metadata.id = name;
  metadata.description = name;
  const auto result = rc::detail::checkProperty(rc::detail::toProperty(property), metadata, params);
  rc::detail::printResultMessage(result, std::cout);
  std::cout << std::endl;
  return result.template is<rc::detail::SuccessResult>();
}

}  // namespace

void Met::count(const harness::Features& f) {
  ++cases;
  touching += f.touching;
  parallel += f.parallel;
  degenerate += f.degenerate;
  RC_TAG(f.touching ? "touching" : "-", f.parallel ? "parallel" : "-", f.degenerate ? "degenerate" : "-");
}

void Met::count(const std::vector<std::string_view>& names) {
  for (std::string_view n : names) ++configurations[n];
}

bool check_property(const std::string& name, harness::QueryKind kind, int out_of_contract_percent, int cases,
                    Met& met, const std::function<void(const harness::Input&)>& body,
                    const harness::ExactReference* exact) {
  (void)met;
  return run(name, cases, [&] {
    const auto choices = *rc::gen::container<std::vector<std::uint64_t>>(kChoices, rc::gen::arbitrary<std::uint64_t>());
    harness::ReplayChoices replay(choices);
    harness::GenerateOptions options;
    options.mesh_folder = fcl_mesh_folder();
    options.exact = exact;
    options.out_of_contract = replay.chance(out_of_contract_percent);
    body(harness::generate(kind, replay, options));
  });
}

bool check_property_with_choices(const std::string& name, int cases,
                                 const std::function<void(harness::Choices&)>& body) {
  return run(name, cases, [&] {
    const auto choices = *rc::gen::container<std::vector<std::uint64_t>>(kChoices, rc::gen::arbitrary<std::uint64_t>());
    harness::ReplayChoices replay(choices);
    body(replay);
  });
}

void expect_met_the_boundary(const std::string& name, harness::QueryKind kind, const Met& met) {
  std::cout << name << ": " << met.cases << " cases, " << met.touching << " touching, " << met.parallel
            << " parallel, " << met.degenerate << " degenerate" << std::endl;
  EXPECT_GT(met.touching, 0) << name << " never met touching shapes";
  if (harness::parallel_applies(kind)) {
    EXPECT_GT(met.parallel, 0) << name << " never met a parallel configuration";
  }
  EXPECT_GT(met.degenerate, 0) << name << " never met a degenerate shape";
}

void expect_met_every_configuration(const std::string& name, harness::QueryKind kind, const Met& met) {
  std::cout << name << ", configurations met:";
  for (std::string_view c : harness::expected_configurations(kind)) {
    const auto it = met.configurations.find(c);
    const int n = it == met.configurations.end() ? 0 : it->second;
    std::cout << " " << c << " " << n << ";";
    EXPECT_GT(n, 0) << name << " never met the configuration \"" << c << "\"";
  }
  std::cout << std::endl;
}

}  // namespace cc::test
