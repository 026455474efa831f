#include "fuzz/fuzz_target.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "fuzz/impl_bug_groups.h"
#include "harness/judging/disagreement.h"
#include "harness/judging/evaluate.h"
#include "harness/formats/fuzz_record.h"
#include "harness/formats/input_json.h"
#include "harness/model/subject.h"
#include "harness/processes/subject_process.h"
#include "oracle/exact/exact_reference.h"
#include "oracle/peers/peer_opinions.h"

namespace cc::fuzz {
namespace {

using namespace harness;

std::uint64_t fnv1a(const std::uint8_t* data, std::size_t size) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (std::size_t i = 0; i < size; ++i) h = (h ^ data[i]) * 0x100000001b3ULL;
  return h;
}

// Keeps a finding's input bytes, named by class and hash (the same input is kept once).
void keep(QueryKind kind, CaseClass cls, const std::uint8_t* data, std::size_t size) {
  const char* dir = std::getenv("CROSSCHECK_FUZZ_FINDINGS");
  if (dir == nullptr) return;
  const auto folder = std::filesystem::path(dir) / std::string(name(kind));
  std::error_code ec;
  std::filesystem::create_directories(folder, ec);
  char file[64];
  std::snprintf(file, sizeof file, "%s-%016llx", std::string(to_string(cls)).c_str(),
                static_cast<unsigned long long>(fnv1a(data, size)));
  std::ofstream(folder / file, std::ios::binary).write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
}

}  // namespace

namespace {

// The library under test: crosscheck's own, or the subject CROSSCHECK_SUBJECT names
// (include/crosscheck/subject.h), put under test at the first input and asked in a child process
// of the target's (processes/subject_process.h: its crash, exit or hang is an impl_bug, each call
// limited to 20 s); a path that is no subject ends the run (exit 2). Kinds the subject does not answer are not fuzzed (every input returns
// at once).
void put_subject_under_test_once() {
  static const bool done = [] {
    if (const char* path = std::getenv("CROSSCHECK_SUBJECT"); path != nullptr && *path != '\0') {
      try {
        put_under_test(load_subject(path, 20));
      } catch (const std::exception& e) {
        std::fprintf(stderr, "CROSSCHECK_SUBJECT: %s\n", e.what());
        std::exit(2);
      }
    }
    return true;
  }();
  (void)done;
}

}  // namespace

int test_one_input(QueryKind kind, const std::uint8_t* data, std::size_t size) {
  put_subject_under_test_once();
  if (!library_answers(kind)) return 0;
  static const exact::ExactRationalReference exact;
  static const peers::PeerOpinions second;
  const Input input = decode_record(kind, {data, size});
  const Evaluation e = evaluate(input, exact, &second);
  switch (e.verdict.cls) {
    case CaseClass::impl_bug:
      std::fprintf(stderr, "impl_bug %s:\n", std::string(name(kind)).c_str());
      for (const PartyStanding& p : e.verdict.parties) {  // the library, or one of its own parties
        if (p.standing == Standing::wrong || p.standing == Standing::failed) {
          std::fprintf(stderr, "  %s: %s\n", p.party.c_str(), p.why.c_str());
        }
      }
      std::fprintf(stderr, "  inputs: %s\n", input_to_json(input).dump().c_str());
      if (const auto d = disagreement_of(kind, e)) abort_in_group(kind, d->what);
      std::abort();
    case CaseClass::oracle_defect:
    case CaseClass::oracle_crash:
    case CaseClass::undecided: keep(kind, e.verdict.cls, data, size); break;
    default: break;
  }
  return 0;
}

}  // namespace cc::fuzz
