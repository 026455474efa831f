#include "tool/cases.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>

#include "harness/model/library.h"
#include "harness/model/subject.h"
#include "harness/processes/child.h"
#include "harness/processes/evaluate_in_child.h"
#include "harness/processes/subject_process.h"
#include "harness/formats/number_text.h"
#include "oracle/exact/exact_reference.h"
#include "oracle/peers/peer_opinions.h"
#include "tool/child_process.h"

namespace cc::tool {

using namespace harness;

namespace {

const exact::ExactRationalReference& exact_reference() {
  static const exact::ExactRationalReference reference;
  return reference;
}

const peers::PeerOpinions& peer_opinions() {
  static const peers::PeerOpinions opinions;
  return opinions;
}

}  // namespace

std::optional<Evaluation> evaluate_again_within(const Input& input, double seconds, const std::function<bool()>& stop) {
  const double limit = std::min(seconds, kPartyTimeLimit);
  const double deadline = monotonic_seconds() + limit;  // both children share it
  // Cut short by the budget or the stop, not by the party: no answer at all.
  const auto cut_short = [&](const std::string& how) { return (stop && stop()) || (is_time_out(how) && limit < kPartyTimeLimit); };
  ask_subject_afresh();  // a subject's server may have answered other cases before
  std::string how;
  if (auto e = evaluate_in_child(input, exact_reference(), peer_opinions(), limit, &how, stop)) return e;
  if (cut_short(how)) return std::nullopt;
  // The child died: crosscheck's library alone, in a child of its own, tells whose fault. (A
  // subject is asked in its own server, whose failures are its answer's: the child never asks it.)
  if (subject_under_test() == nullptr) {
    const double left = deadline - monotonic_seconds();
    if (left <= 0 && limit < kPartyTimeLimit) return std::nullopt;
    const ChildEnd library = run_in_child(
        [&](int) {
          try {
            (void)ask_library(input);
          } catch (const std::exception&) {  // an answer that is no answer is not a crash
          }
          (void)library_alternatives(input);  // its other ways too, as the campaign asks them in the library
          return 0;
        },
        limit < kPartyTimeLimit ? left : kPartyTimeLimit, stop);
    if (cut_short(library.what())) return std::nullopt;
    if (!library.succeeded()) {
      return evaluation_after_death(input, exact_reference(), peer_opinions(), DiedIn::library, library.what());
    }
  }
  return evaluation_after_death(input, exact_reference(), peer_opinions(), DiedIn::second_opinions, how);
}

Evaluation evaluate_surviving_crashes(const Input& input) { return *evaluate_again_within(input, kPartyTimeLimit, {}); }

Case case_of(const Input& input, const Evaluation& e, Provenance provenance, std::string note) {
  Case c;
  c.input = input;
  c.library = e.library;
  c.library_failure = e.library_failure;
  c.exact = e.exact;
  c.opinions = e.opinions;
  c.cls = e.verdict.cls;
  c.provenance = std::move(provenance);
  c.note = std::move(note);
  if (const Subject* subject = subject_under_test()) c.subject = subject->identity();
  return c;
}

std::optional<Case> read_case_or_report(const std::filesystem::path& path) {
  try {
    return read_case_file(path);
  } catch (const CaseFileError& e) {
    std::fprintf(stderr, "crosscheck: %s\n", printable(e.what()).c_str());
    return std::nullopt;
  }
}

namespace {

std::string answer_text(const Answer& a) {
  std::string s = a.hit ? "hit" : "miss";
  if (!a.params.empty()) {
    s += " t = [";
    for (std::size_t i = 0; i < a.params.size(); ++i) s += (i ? ", " : "") + format_double(a.params[i]);
    s += "]";
  }
  if (!a.pairs.empty()) s += ", " + std::to_string(a.pairs.size()) + (a.pairs.size() == 1 ? " pair" : " pairs");
  return s;
}

std::string table(const Explanation& e) {
  std::vector<std::size_t> width(e.columns.size(), 0);
  for (std::size_t c = 0; c < e.columns.size(); ++c) width[c] = e.columns[c].size();
  for (const auto& row : e.rows) {
    for (std::size_t c = 0; c < row.size() && c < width.size(); ++c) width[c] = std::max(width[c], row[c].size());
  }
  std::ostringstream out;
  const auto line = [&](const std::vector<std::string>& cells, const std::string& mark) {
    out << "  " << mark << ' ';
    for (std::size_t c = 0; c < cells.size() && c < width.size(); ++c) {
      out << cells[c] << std::string(width[c] - cells[c].size() + 2, ' ');
    }
    out << '\n';
  };
  line(e.columns, " ");
  for (std::size_t r = 0; r < e.rows.size(); ++r) {
    line(e.rows[r], static_cast<int>(r) == e.deciding_row ? ">" : " ");
  }
  return out.str();
}

}  // namespace

std::string triage_text(const std::string& title, const Case& recorded, const Evaluation& now, const Explanation& why) {
  std::ostringstream out;
  out << printable(title) << "\n";
  out << "  query      " << name(kind_of(recorded.input)) << "\n";
  out << "  class      " << to_string(now.verdict.cls);
  if (now.verdict.cls != recorded.cls) out << "   (recorded: " << to_string(recorded.cls) << ")";
  out << "\n";
  if (!recorded.note.empty()) out << "  note       " << printable(recorded.note) << "\n";
  out << "  inputs     " << input_to_json(recorded.input).dump() << "\n";
  out << "  library    " << answer_text(now.library);
  if (!now.verdict.parties.empty()) out << "   [" << to_string(now.verdict.parties[0].standing) << "]";
  out << "\n";
  out << "  exact      " << (now.exact.decided ? answer_text(now.exact.answer) : std::string("no verdict"));
  if (now.exact.contract != Contract::in) out << "   (out of contract: " << now.exact.note << ")";
  out << "\n";
  for (const Opinion& o : now.opinions) {
    // A verdict out of contract, or undecided, judges no party: the answer is shown without one.
    const auto p = std::find_if(now.verdict.parties.begin(), now.verdict.parties.end(),
                                [&](const PartyStanding& s) { return s.party == o.party; });
    out << "  " << o.party << "  ";
    if (o.status == Opinion::Status::answered) {
      out << answer_text(o.answer);
      if (p != now.verdict.parties.end()) out << "   [" << to_string(p->standing) << "]";
    } else {
      out << (o.status == Opinion::Status::failed      ? "failed: "
              : o.status == Opinion::Status::timed_out ? "timed out: "
                                                       : "n/a: ")
          << printable(o.detail);
    }
    out << "\n";
  }
  char margin[120];
  std::snprintf(margin, sizeof margin, "%.6g of the largest coordinate (%s); %.4g ULPs of the deciding quantity",
                now.exact.margin == 0 ? 0.0 : now.exact.margin,
                now.exact.margin > 0 ? "overlapping" : (now.exact.margin < 0 ? "apart" : "touching"),
                why.deciding_ulps == 0 ? 0.0 : why.deciding_ulps);
  out << "  margin     " << margin << "\n";
  if (!why.deciding.empty()) out << "  deciding   " << why.deciding << " = " << format_double(why.deciding_value) << "\n";
  for (const auto& [k, v] : why.facts) out << "  " << k << ": " << v << "\n";
  for (const PartyStanding& p : now.verdict.parties) {
    if (p.standing == Standing::wrong || p.standing == Standing::within_band) {
      out << "  why        " << printable(p.party) << ": " << printable(p.why) << "\n";
    }
  }
  if (!why.rows.empty()) out << "  " << why.title << " (> marks the deciding one):\n" << table(why);
  return out.str();
}

std::vector<std::string> stored_case_names(const std::filesystem::path& root) {
  std::vector<std::string> names;
  for (const auto& f : case_files_under({root})) names.push_back(f.filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace cc::tool
