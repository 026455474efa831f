// crosscheck shrink FILE [-o OUT]: the simplest case that shows the same disagreement.
#include <cstdio>

#include "harness/shrinking/shrink.h"
#include "harness/shrinking/signature.h"
#include "harness/model/subject.h"
#include "tool/cases.h"
#include "tool/commands.h"
#include "tool/subject_option.h"
#include "tool/flag_checks.h"

namespace cc::tool {
namespace {

struct ShrinkArgs {
  std::string file;
  std::string out;
  int attempts = 4000;
  double seconds = 60;
  std::string subject;
};

int run(const ShrinkArgs& args) {
  put_subject_under_test(args.subject, kPartyTimeLimit);
  const auto c = read_case_or_report(args.file);
  if (!c || !subject_fits_case(*c, args.file, "shrink")) return kExitBadInput;
  if (!harness::library_answers(harness::kind_of(c->input))) {
    std::fprintf(stderr, "crosscheck shrink: %s: the subject does not answer %s\n", args.file.c_str(),
                 std::string(name(harness::kind_of(c->input))).c_str());
    return kExitBadInput;
  }
  const harness::Evaluation start = evaluate_surviving_crashes(c->input);
  // Candidates run in a child first: one that crashes an oracle is rejected, not fatal.
  const harness::ShrinkResult r = harness::shrink(c->input, start, evaluate_surviving_crashes, args.attempts, args.seconds,
                                                     std::filesystem::path(args.file).parent_path());
  std::printf("%s: %s\n  %d values not small integers or halves before, %d after; %d of %d attempts kept\n",
              args.file.c_str(), harness::signature_of(harness::kind_of(c->input), start).c_str(),
              harness::complex_values(c->input), harness::complex_values(r.input), r.accepted, r.attempts);
  harness::Provenance provenance{"shrink", c->provenance.seed, c->provenance.case_index, args.file};
  const harness::Case shrunk = case_of(r.input, r.evaluation, provenance, c->note);
  // The output: beside the input or in the directory given (named by the shrunk case's hash, so
  // that two findings that shrink to the same case are stored once), or the file given.
  std::filesystem::path out = args.out.empty() ? std::filesystem::path(args.file).parent_path() : std::filesystem::path(args.out);
  if (args.out.empty() || std::filesystem::is_directory(out) || args.out.back() == '/') out /= harness::case_file_name(r.input);
  try {
    const auto written = harness::write_new_case_file(out, shrunk);
    if (!written) {
      std::printf("  %s exists already: not overwritten\n", out.string().c_str());
      return args.out.empty() ? 0 : kExitBadInput;
    }
    out = *written;  // the next free name when another case had this one
  } catch (const harness::CaseFileError& e) {
    std::fprintf(stderr, "crosscheck shrink: %s\n", e.what());
    return kExitBadInput;
  }
  std::printf("  written to %s\n  inputs: %s\n", out.string().c_str(), harness::input_to_json(r.input).dump().c_str());
  return 0;
}

}  // namespace

void add_shrink_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<ShrinkArgs>();
  auto* cmd = app.add_subcommand("shrink", "Minimise a case file, keeping its kind, class and disagreement");
  cmd->add_option("file", args->file, "The case file")->required();
  cmd->add_option("-o,--out", args->out,
                  "A file, or a directory (ending in /) for a file named by the shrunk case's hash (default: beside it)")
      ->check(CLI::Validator(
          [](std::string& out) {
            std::error_code ec;  // a path that cannot be looked at is refused below, with why
            const bool folder = (!out.empty() && out.back() == '/') || std::filesystem::is_directory(out, ec);
            return folder ? unwritable_folder(out) : unwritable_file(out);
          },
          "FILE or FOLDER/ (writable)"));
  cmd->add_option("--attempts", args->attempts, "Evaluations to try at most")->capture_default_str()->check(whole_in(1, 10000000));
  cmd->add_option("--seconds", args->seconds, "Time to spend at most")->capture_default_str()->check(finite_above(0, 1e6));
  add_subject_option(cmd, args->subject);
  cmd->callback([args, &exit_code] { exit_code = run(*args); });
}

}  // namespace cc::tool
