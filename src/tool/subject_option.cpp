#include "tool/subject_option.h"

#include <cstdio>
#include <map>
#include <memory>
#include <stdexcept>

#include "harness/model/subject.h"

namespace cc::tool {
namespace {

// Each path loaded once per process (a shared library stays loaded anyway).
std::shared_ptr<const harness::Subject> loaded(const std::string& path) {
  static std::map<std::string, std::shared_ptr<const harness::Subject>> subjects;
  auto& subject = subjects[path];
  if (!subject) subject = harness::Subject::load(path);
  return subject;
}

}  // namespace

void add_subject_option(CLI::App* cmd, std::string& path) {
  cmd->add_option("--subject", path,
                  "A shared library to put under test instead of crosscheck's own (include/crosscheck/subject.h)")
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

void put_subject_under_test(const std::string& path) {
  if (!path.empty()) harness::put_under_test(loaded(path));
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
