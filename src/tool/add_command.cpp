// crosscheck add QUERY INPUTS --note TEXT: stores a hand-written case, with the three answers
// computed now, as corpora/QUERY/<hash>.json.
#include <cstdio>
#include <optional>

#include "oracle/exact/exact_reference.h"
#include "tool/cases.h"
#include "tool/commands.h"

namespace cc::tool {
namespace {

struct AddArgs {
  std::string query;
  std::string inputs;
  std::string note;
  std::string corpora = "corpora";
};

int run(const AddArgs& args) {
  const auto kind = harness::query_kind_named(args.query);
  if (!kind) {
    std::fprintf(stderr, "crosscheck add: unknown query \"%s\"\n", args.query.c_str());
    return kExitBadInput;
  }
  harness::Input input;
  try {
    // Mesh files are found as they will be from the stored case: from its folder, or above it.
    input = harness::input_from_json(*kind, harness::Json::parse(args.inputs), "",
                                     std::filesystem::path(args.corpora) / args.query);
  } catch (const harness::Json::parse_error& e) {
    std::fprintf(stderr, "crosscheck add: inputs: %s\n", e.what());
    return kExitBadInput;
  } catch (const harness::FormatError& e) {
    std::fprintf(stderr, "crosscheck add: inputs%s: %s\n", e.pointer().c_str(), e.what());
    return kExitBadInput;
  }
  const harness::Evaluation e = evaluate_with_oracles(input);
  const harness::Case c = case_of(input, e, harness::Provenance{}, args.note);
  const auto path = std::filesystem::path(args.corpora) / args.query / harness::case_file_name(input);
  std::optional<std::filesystem::path> written;
  try {
    written = harness::write_new_case_file(path, c);
    if (!written) {
      std::fprintf(stderr, "crosscheck add: %s exists already: not overwritten\n", path.string().c_str());
      return kExitBadInput;
    }
  } catch (const harness::CaseFileError& err) {
    std::fprintf(stderr, "crosscheck add: %s\n", err.what());
    return kExitBadInput;
  }
  const exact::ExactRationalReference exact;
  std::printf("%s\n", triage_text(written->string(), c, e, exact.explain(input)).c_str());
  return 0;
}

}  // namespace

void add_add_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<AddArgs>();
  auto* cmd = app.add_subcommand("add", "Store a hand-written case with its answers computed now");
  cmd->add_option("query", args->query, "The query kind")->required();
  cmd->add_option("inputs", args->inputs, "The inputs as JSON, in the layout of a case file's \"inputs\"")->required();
  cmd->add_option("--note", args->note, "A one-line note: what the case shows")->required();
  cmd->add_option("--corpora", args->corpora, "The corpus root")->capture_default_str();
  cmd->callback([args, &exit_code] { exit_code = run(*args); });
}

}  // namespace cc::tool
