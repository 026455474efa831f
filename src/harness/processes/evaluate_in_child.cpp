#include "harness/processes/evaluate_in_child.h"

#include <system_error>

#include "harness/formats/case_file.h"
#include "harness/formats/write_all.h"
#include "harness/model/library.h"
#include "harness/model/subject.h"
#include "harness/processes/child.h"

namespace cc::harness {

std::optional<Evaluation> evaluate_in_child(const Input& input, const ExactReference& exact, const SecondOpinion& second,
                                            double timeout_seconds, std::string* how, const std::function<bool()>& stop) {
  // The child asks every party but the exact reference; the library again here, which is safe:
  // crosscheck's own library returned there on this input, and a subject is asked in a process
  // of its own (processes/subject_process.h), not this one's nor the child's.
  const auto fail = [how](std::string what) {
    if (how != nullptr) *how = std::move(what);
    return std::nullopt;
  };
  ChildEnd child;
  try {
    child = run_in_child(
        [&](int out) {
          Evaluation e;
          if (subject_under_test() == nullptr) ask_library_into(e, input);
          e.opinions = library_alternatives(input);
          for (Opinion& o : second.opinions(input)) e.opinions.push_back(std::move(o));
          return write_all(out, opinions_to_json(e.opinions).dump()) ? 0 : 1;
        },
        timeout_seconds, stop);
  } catch (const std::system_error& error) {
    return fail(std::string("could not be started: ") + error.what());
  }
  if (!child.succeeded()) return fail(child.what());
  const std::string& text = child.output;
  Evaluation e;
  try {
    e.opinions = opinions_from_json(Json::parse(text), "");
    restore_bands(e.opinions, second, kind_of(input));
  } catch (const std::exception&) {
    return fail("passed back answers that do not read");
  }
  ask_library_into(e, input);
  e.exact = exact.judge(input);
  judge_into(e, input);
  return e;
}

}  // namespace cc::harness
