#include "tool/subject_option.h"

#include <cstdio>
#include <map>
#include <memory>

#include "harness/model/subject.h"
#include "harness/processes/subject_process.h"
#include "tool/cases.h"

namespace cc::tool {
namespace {

// Each path tried once per process.
std::shared_ptr<harness::Subject> loaded(const std::string& path) {
  static std::map<std::string, std::shared_ptr<harness::Subject>> subjects;
  auto& subject = subjects[path];
  if (!subject) subject = harness::load_subject(path, kPartyTimeLimit);
  return subject;
}

std::string identity_text(const harness::SubjectIdentity& s) {
  return s.file + " (interface version " + std::to_string(s.version) + ", sha256 " + s.sha256.substr(0, 16) + "...)";
}

}  // namespace

void add_subject_option(CLI::App* cmd, std::string& path) {
  cmd->add_option("--subject", path,
                  "A shared library to put under test instead of crosscheck's own (include/crosscheck/subject.h); "
                  "default: $" + std::string(kSubjectVariable))
      ->envname(kSubjectVariable)
      ->check(CLI::Validator(
          [](std::string& text) -> std::string {
            try {
              loaded(text);
              return {};
            } catch (const std::exception& e) {
              return e.what();
            }
          },
          "SUBJECT.so"));
}

void put_subject_under_test(const std::string& path, double call_seconds) {
  if (path.empty()) return;
  const auto subject = loaded(path);
  harness::set_call_seconds(*subject, call_seconds);
  harness::put_under_test(subject);
}

bool subject_fits_case(const harness::Case& c, const std::string& file, const char* command) {
  if (!c.subject) return true;
  const harness::Subject* now = harness::subject_under_test();
  if (now == nullptr) {
    std::fprintf(stderr,
                 "crosscheck %s: %s: found with the subject %s, not crosscheck's library: give --subject PATH (or set "
                 "%s) to ask it\n",
                 command, file.c_str(), identity_text(*c.subject).c_str(), kSubjectVariable);
    return false;
  }
  if (now->identity().sha256 != c.subject->sha256) {
    std::fprintf(stderr, "crosscheck %s: %s: found with %s; asking %s\n", command, file.c_str(),
                 identity_text(*c.subject).c_str(), identity_text(now->identity()).c_str());
  }
  return true;
}

std::vector<harness::QueryKind> answered_kinds(const std::vector<harness::QueryKind>& kinds, const char* command) {
  const harness::Subject* subject = harness::subject_under_test();
  if (subject == nullptr) return kinds;
  std::vector<harness::QueryKind> out;
  std::string skipped;
  for (harness::QueryKind kind : kinds) {
    if (subject->answers(kind)) {
      out.push_back(kind);
    } else {
      skipped += (skipped.empty() ? "" : ", ") + std::string(name(kind));
    }
  }
  std::printf("crosscheck %s: subject %s%s%s\n", command, subject->path().c_str(),
              skipped.empty() ? "" : "; skipped, as it does not answer them: ", skipped.c_str());
  return out;
}

}  // namespace cc::tool
