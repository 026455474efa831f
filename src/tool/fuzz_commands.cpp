// crosscheck fuzz-seeds: the seed corpora of the fuzz targets, corpora/<query>/seed/: every case
// file of that query as a record (but those on which a peer crashes), and generated cases.
// crosscheck fuzz-case QUERY FILE...: fuzz inputs as case files (unshrunk; `crosscheck shrink`
// minimises them), each answered as every command answers a case (tool/cases.h), so that a crash
// is recorded, not suffered.

#include <cstdio>
#include <fstream>
#include <iterator>

#include "harness/processes/campaign.h"
#include "harness/formats/fuzz_record.h"
#include "harness/judging/disagreement.h"
#include "harness/shrinking/signature.h"
#include "harness/model/subject.h"
#include "tool/cases.h"
#include "tool/commands.h"
#include "tool/subject_option.h"
#include "tool/flag_checks.h"

namespace cc::tool {
namespace {

using namespace harness;

std::string hex(const std::vector<std::uint8_t>& bytes) {
  std::string s;
  char b[3];
  for (std::uint8_t x : bytes) {
    std::snprintf(b, sizeof b, "%02x", x);
    s += b;
  }
  return s;
}

std::string name_of_bytes(const std::vector<std::uint8_t>& bytes) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (std::uint8_t x : bytes) h = (h ^ x) * 0x100000001b3ULL;
  char name[24];
  std::snprintf(name, sizeof name, "%016llx", static_cast<unsigned long long>(h));
  return name;
}

struct SeedArgs {
  std::string corpora = "corpora";
  int generated = 200;
};

int run_seeds(const SeedArgs& args) {
  for (QueryKind kind : kAllQueryKinds) {
    const auto dir = std::filesystem::path(args.corpora) / std::string(name(kind));
    const auto seeds = dir / "seed";
    std::filesystem::create_directories(seeds);
    std::vector<Input> inputs;
    if (std::filesystem::is_directory(dir)) {
      for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        if (entry.path().extension() != ".json") continue;
        const auto c = read_case_or_report(entry.path());
        if (!c) return kExitBadInput;
        // A case that crashes a peer would end every fuzzing run at its first seed.
        if (c->cls != CaseClass::oracle_crash) inputs.push_back(c->input);
      }
    }
    for (int i = 0; i < args.generated; ++i) inputs.push_back(campaign_case(1, kind, static_cast<std::uint64_t>(i), 10));
    int written = 0;
    for (const Input& in : inputs) {
      const std::vector<std::uint8_t> bytes = encode_record(in);
      const auto path = seeds / name_of_bytes(bytes);
      if (std::filesystem::exists(path)) continue;
      std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
      ++written;
    }
    std::printf("%s: %d new seeds in %s\n", std::string(name(kind)).c_str(), written, seeds.string().c_str());
  }
  return 0;
}

struct FuzzCaseArgs {
  std::string query;
  std::vector<std::string> files;
  std::string out = "corpora/new";
  std::string subject;
};

int run_fuzz_case(const FuzzCaseArgs& args) {
  const auto kind = query_kind_named(args.query);
  if (!kind) {
    std::fprintf(stderr, "crosscheck fuzz-case: unknown query \"%s\"\n", args.query.c_str());
    return kExitBadInput;
  }
  put_subject_under_test(args.subject, kPartyTimeLimit);
  if (!harness::library_answers(*kind)) {
    std::fprintf(stderr, "crosscheck fuzz-case: --subject: it does not answer %s\n", args.query.c_str());
    return kExitBadInput;
  }
  for (const std::string& file : args.files) {
    std::ifstream in(file, std::ios::binary);
    if (!in) {
      std::fprintf(stderr, "crosscheck fuzz-case: %s: cannot read the file\n", file.c_str());
      return kExitBadInput;
    }
    const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const Input input = decode_record(*kind, bytes);
    const Provenance provenance{"fuzz", std::nullopt, std::nullopt, hex(bytes)};
    const auto path = std::filesystem::path(args.out) / args.query / case_file_name(input);
    const std::string note = "untriaged: from fuzz input " + std::filesystem::path(file).filename().string();
    // Every party answers in a child (a crash is recorded, not suffered); a case file that
    // cannot be written is bad input.
    const Evaluation e = evaluate_surviving_crashes(input);
    try {
      write_new_case_file(path, case_of(input, e, provenance, note));
    } catch (const CaseFileError& error) {
      std::fprintf(stderr, "crosscheck fuzz-case: %s\n", printable(error.what()).c_str());
      return kExitBadInput;
    }
    const std::string what = std::string(to_string(e.verdict.cls)) + " " + path.string() + " " + group_of(*kind, e) +
                             " " + finding_key(input, e);
    // The input, its class, its case file, the group of its disagreement (the fuzz target's abort
    // function's, or "-") and the kind of finding it is (for grouping).
    std::printf("%s %s\n", file.c_str(), what.c_str());
  }
  return 0;
}

}  // namespace

void add_fuzz_commands(CLI::App& app, int& exit_code) {
  auto seeds = std::make_shared<SeedArgs>();
  auto* s = app.add_subcommand("fuzz-seeds", "Write the fuzz targets' seed corpora (corpora/<query>/seed/)");
  s->add_option("--corpora", seeds->corpora, "The corpus root")->capture_default_str()->check(CLI::ExistingDirectory);
  s->add_option("--generated", seeds->generated, "Generated cases per query")->capture_default_str()->check(whole_in(0, 1000000));
  s->callback([seeds, &exit_code] { exit_code = run_seeds(*seeds); });

  auto cases = std::make_shared<FuzzCaseArgs>();
  auto* c = app.add_subcommand("fuzz-case", "Turn fuzz inputs (records) into case files, classifying each");
  c->add_option("query", cases->query, "The query kind of the fuzz target")->required()->check(query_kind_name());
  c->add_option("files", cases->files, "Fuzz inputs (files)")->required()->check(CLI::ExistingFile);
  c->add_option("--out", cases->out, "Where the case files go")->capture_default_str()->check(writable_folder());
  add_subject_option(c, cases->subject);
  c->callback([cases, &exit_code] { exit_code = run_fuzz_case(*cases); });
}

}  // namespace cc::tool
