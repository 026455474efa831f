#include "harness/judging/replay.h"

#include <algorithm>

#include "harness/formats/number_text.h"

namespace cc::harness {
namespace {

// An answer as the case file has it, shortened for a message.
std::string text_of(const Answer& a) {
  std::string t = answer_json(a).dump();
  return t.size() > 240 ? t.substr(0, 240) + "..." : t;
}

// What a party said: its status and, when it answered, its whole answer.
std::string text_of(const Opinion& o) {
  switch (o.status) {
    case Opinion::Status::answered: return text_of(o.answer);
    case Opinion::Status::not_applicable: return "n/a";
    case Opinion::Status::failed: return "failed";
    case Opinion::Status::timed_out: return "timed out";
  }
  return "?";
}
bool timed_out(const Opinion& o) { return o.status == Opinion::Status::timed_out; }
// A time-out on either side is no change: it depends on the machine, not on the party.
bool same(const Opinion& a, const Opinion& b) {
  if (timed_out(a) || timed_out(b)) return true;
  return a.status == b.status && (a.status != Opinion::Status::answered || answer_json(a.answer) == answer_json(b.answer));
}
// Whether the library or the exact reference timed out in the record or now: the parties asked
// after it in the process that was cut off went unasked (evaluation_after_death), the exact
// reference among them.
bool early_time_out(const Case& c, const Evaluation& now) {
  return is_time_out(c.library_failure) || is_time_out(now.library_failure) || is_time_out(c.exact.note) ||
         is_time_out(now.exact.note);
}
// Whether some party, a second opinion too, timed out in the record or now: then a party missing
// on one side (the library's other ways are not asked when the second opinions are cut off) and
// the class that changed with it are no change either.
bool any_time_out(const Case& c, const Evaluation& now) {
  const auto in = [](const std::vector<Opinion>& os) { return std::any_of(os.begin(), os.end(), timed_out); };
  return early_time_out(c, now) || in(c.opinions) || in(now.opinions);
}

std::string contract_text(const ExactVerdict& v) {
  std::string t = v.contract == Contract::in ? "in contract" : (v.contract == Contract::documented ? "documented" : "unspecified");
  return t + (v.decided ? "" : ", undecided");
}

}  // namespace

std::vector<std::string> replay_changes(const Case& c, const Evaluation& now) {
  std::vector<std::string> out;
  const auto library_text = [](const Answer& a, const std::string& failure) {
    return failure.empty() ? text_of(a) : "failed: " + failure;
  };
  const bool library_same = is_time_out(c.library_failure) || is_time_out(now.library_failure) ||
                            (answer_json(now.library) == answer_json(c.library) && now.library_failure == c.library_failure);
  // A library wrong as recorded (an impl_bug kept, with the same answer) has not changed.
  const bool known_bug = c.cls == CaseClass::impl_bug && now.verdict.cls == CaseClass::impl_bug && library_same;
  if (now.verdict.parties[0].standing == Standing::wrong && !known_bug) {
    out.push_back("the library is wrong: " + now.verdict.parties[0].why);
  }
  if (!library_same) {
    out.push_back("the library's answer changed: recorded " + library_text(c.library, c.library_failure) + ", now " +
                  library_text(now.library, now.library_failure));
  }
  // With a time-out, which parties answered depends on where time ran out.
  const bool time_out = any_time_out(c, now);
  if (!early_time_out(c, now)) {
    if (!(answer_json(now.exact.answer) == answer_json(c.exact.answer))) {
      out.push_back("the exact reference's answer changed: recorded " + text_of(c.exact.answer) + ", now " +
                    text_of(now.exact.answer));
    }
    if (contract_text(now.exact) != contract_text(c.exact)) {
      out.push_back("the exact reference changed: recorded " + contract_text(c.exact) + ", now " + contract_text(now.exact));
    }
    if (format_double(now.exact.margin) != format_double(c.exact.margin)) {
      out.push_back("the exact margin changed: recorded " + format_double(c.exact.margin) + ", now " +
                    format_double(now.exact.margin));
    }
  }
  for (const Opinion& before : c.opinions) {
    const auto after = std::find_if(now.opinions.begin(), now.opinions.end(),
                                    [&](const Opinion& o) { return o.party == before.party; });
    if (after == now.opinions.end()) {
      if (!time_out) out.push_back(before.party + " no longer answers: recorded " + text_of(before));
    } else if (!same(*after, before)) {
      out.push_back(before.party + " changed its behaviour: recorded " + text_of(before) + ", now " + text_of(*after));
    }
  }
  for (const Opinion& after : now.opinions) {
    if (!time_out &&
        std::none_of(c.opinions.begin(), c.opinions.end(), [&](const Opinion& o) { return o.party == after.party; })) {
      out.push_back(after.party + " is not in the record: now " + text_of(after));
    }
  }
  if (now.verdict.cls != c.cls && !time_out) {
    out.push_back("class changed: recorded " + std::string(to_string(c.cls)) + ", now " + std::string(to_string(now.verdict.cls)));
  }
  return out;
}

}  // namespace cc::harness
