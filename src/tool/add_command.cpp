// crosscheck add QUERY INPUTS --note TEXT: stores a hand-written case, with the three answers
// computed now, as corpora/QUERY/<hash>.json. INPUTS is the JSON itself, a file holding it, or
// "-" for standard input.
#include <cstdio>
#include <fstream>
#include <iostream>
#include <iterator>
#include <optional>

#include "harness/formats/json_text.h"
#include "oracle/exact/exact_reference.h"
#include "tool/cases.h"
#include "tool/commands.h"
#include "tool/flag_checks.h"

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
  // The inputs inline (JSON starts with { or [), from standard input ("-"), or from a file.
  const std::size_t first = args.inputs.find_first_not_of(" \t\r\n");
  const bool inline_json = first != std::string::npos && (args.inputs[first] == '{' || args.inputs[first] == '[');
  const std::string source = inline_json ? "inputs" : args.inputs == "-" ? "standard input" : args.inputs;
  std::string text = args.inputs;
  if (!inline_json) {
    std::ifstream file;
    if (args.inputs != "-") {
      if (std::filesystem::is_directory(args.inputs)) {
        std::fprintf(stderr, "crosscheck add: %s is a folder, not a file of inputs\n", source.c_str());
        return kExitBadInput;
      }
      file.open(args.inputs, std::ios::binary);
      if (!file) {
        std::fprintf(stderr, "crosscheck add: %s: cannot read the file (inputs are JSON, \"-\" or a file)\n", source.c_str());
        return kExitBadInput;
      }
    }
    std::istream& in = args.inputs == "-" ? std::cin : file;
    text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  harness::Input input;
  try {
    // Mesh files are found as they will be from the stored case: from its folder, or above it.
    input = harness::input_from_json(*kind, harness::parse_json_text(text), "",
                                     std::filesystem::path(args.corpora) / args.query);
  } catch (const harness::JsonTextError& e) {
    std::fprintf(stderr, "crosscheck add: %s: %s: %s\n", harness::printable(source).c_str(), e.place().c_str(),
                 harness::printable(e.what()).c_str());
    return kExitBadInput;
  } catch (const harness::FormatError& e) {
    // The pointer names the file's own keys: shown as safely as the rest.
    std::fprintf(stderr, "crosscheck add: %s%s: %s\n", harness::printable(source).c_str(), harness::printable(e.pointer()).c_str(),
                 harness::printable(e.what()).c_str());
    return kExitBadInput;
  }
  const harness::Evaluation e = evaluate_surviving_crashes(input);
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
  cmd->add_option("query", args->query, "The query kind")->required()->check(query_kind_name());
  cmd->add_option("inputs", args->inputs, "The inputs as JSON, in the layout of a case file's \"inputs\": inline, a file holding it, or - for "
                  "standard input")->required();
  cmd->add_option("--note", args->note, "A one-line note: what the case shows")->required();
  cmd->add_option("--corpora", args->corpora, "The corpus root")->capture_default_str()->check(writable_folder());
  cmd->callback([args, &exit_code] { exit_code = run(*args); });
}

}  // namespace cc::tool
