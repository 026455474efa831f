// crosscheck replay DIR...: re-answers every stored case and reports each change (see
// harness/judging/replay.h): the library now wrong, any party's whole answer or the exact verdict
// otherwise than recorded, a party gone or new, or the class changing. Exit 1 on any change (ctest's corpus label runs this), 2 on bad input.
#include <cstdio>

#include "harness/judging/replay.h"
#include "oracle/exact/exact_reference.h"
#include "harness/model/subject.h"
#include "tool/cases.h"
#include "tool/commands.h"
#include "tool/subject_option.h"

namespace cc::tool {
namespace {

using namespace harness;

struct ReplayArgs {
  std::vector<std::string> dirs;
  bool quiet = false;
  bool accept = false;
  std::string subject;
};

int run(const ReplayArgs& args) {
  std::vector<std::filesystem::path> roots(args.dirs.begin(), args.dirs.end());
  for (const auto& r : roots) {
    if (!std::filesystem::exists(r)) {
      std::fprintf(stderr, "crosscheck replay: %s: no such file or directory\n", r.string().c_str());
      return kExitBadInput;
    }
  }
  if (args.accept && !args.subject.empty()) {
    std::fprintf(stderr, "crosscheck replay: --accept records crosscheck's own answers: not with --subject\n");
    return kExitBadInput;
  }
  put_subject_under_test(args.subject, kPartyTimeLimit);
  const exact::ExactRationalReference exact;
  const std::vector<std::filesystem::path> files = case_files_under(roots);
  if (files.empty()) {
    std::string given;
    for (const std::string& d : args.dirs) given += (given.empty() ? "" : ", ") + d;
    std::fprintf(stderr, "crosscheck replay: no case files (*.json) in %s\n", given.c_str());
    return kExitBadInput;
  }
  int cases = 0, changed = 0, bad = 0, skipped = 0, needs_subject = 0;
  for (const auto& file : files) {
    const auto c = read_case_or_report(file);
    if (!c) {
      ++bad;
      continue;
    }
    if (!subject_fits_case(*c, file.string(), "replay")) {
      ++needs_subject;
      continue;
    }
    if (!library_answers(kind_of(c->input))) {
      ++skipped;
      if (!args.quiet) std::printf("skipped  %s  (the subject does not answer %s)\n", file.string().c_str(), std::string(name(kind_of(c->input))).c_str());
      continue;
    }
    ++cases;
    const Evaluation now = evaluate_surviving_crashes(c->input);
    const std::vector<std::string> what = replay_changes(*c, now);
    if (what.empty()) {
      if (!args.quiet) std::printf("ok       %s  %s\n", file.string().c_str(), std::string(to_string(c->cls)).c_str());
      continue;
    }
    if (args.accept && now.verdict.parties[0].standing != Standing::wrong) {
      // Explicitly asked: record today's answers, keeping the note and the provenance.
      Case updated = case_of(c->input, now, c->provenance, c->note);
      replace_case_file(file, updated);  // the new file written whole, then renamed over the old
      std::printf("ACCEPTED %s\n", file.string().c_str());
      for (const std::string& w : what) std::printf("  - %s\n", w.c_str());
      continue;
    }
    ++changed;
    std::printf("CHANGED  %s\n", file.string().c_str());
    for (const std::string& w : what) std::printf("  - %s\n", w.c_str());
    std::printf("%s\n", triage_text(file.string(), *c, now, exact.explain(c->input)).c_str());
  }
  std::printf("%d cases replayed: %d unchanged, %d changed%s%s%s\n", cases, cases - changed, changed,
              bad ? (", " + std::to_string(bad) + " unreadable").c_str() : "",
              skipped ? (", " + std::to_string(skipped) + " skipped (kinds the subject does not answer)").c_str() : "",
              needs_subject ? (", " + std::to_string(needs_subject) + " not replayed (found with a subject: give --subject)").c_str() : "");
  if (bad || needs_subject) return kExitBadInput;
  return changed ? kExitFound : 0;
}

}  // namespace

void add_replay_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<ReplayArgs>();
  auto* cmd = app.add_subcommand("replay", "Re-answer stored cases and report every change of class or behaviour");
  cmd->add_option("dirs", args->dirs, "Directories (searched recursively) or case files")->required();
  cmd->add_flag("-q,--quiet", args->quiet, "Print only the cases that changed");
  cmd->add_flag("--accept", args->accept,
                "Rewrite changed cases with today's answers (keeping note and provenance), unless the library is wrong");
  add_subject_option(cmd, args->subject);
  cmd->callback([args, &exit_code] { exit_code = run(*args); });
}

}  // namespace cc::tool
