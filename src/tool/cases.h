// Cases in the tool: evaluating one with the real oracles, turning an evaluation into a case
// file's contents, reading case files with the exit status of bad input, and triage text.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "harness/formats/case_file.h"
#include "harness/formats/printable.h"
#include "harness/judging/evaluate.h"
#include "harness/model/explanation.h"

namespace cc::tool {

/// Seconds a party may take on one case in the tool's own commands before it counts as hung.
inline constexpr double kPartyTimeLimit = 20;

/// The three answers to an input, from the library, the exact reference and the peers
/// (FCL/libccd, Bullet, ODE, Chipmunk), as every command asks them: every party but the exact
/// reference first in a child (harness::evaluate_in_child, under kPartyTimeLimit), so that a
/// party that crashes or hangs neither ends nor damages the caller, and no call leaves anything
/// behind in it (each case is answered as a fresh process answers it). A subject under test is
/// asked in its own process (harness/processes/subject_process.h), a fresh one for each case.
/// When the child dies, crosscheck's library is asked alone in a child, and the case is rebuilt
/// as the campaign rebuilds it (harness::evaluation_after_death): in the library if it fails
/// there, else in the second opinions.
harness::Evaluation evaluate_surviving_crashes(const harness::Input& input);

/// The same, for a case already answered elsewhere (a campaign's worker), within `seconds` and
/// until `stop` says so: nothing when either cuts it short first. A party hangs only at
/// kPartyTimeLimit: a shorter budget that runs out is no answer of its.
std::optional<harness::Evaluation> evaluate_again_within(const harness::Input& input, double seconds,
                                                         const std::function<bool()>& stop);

/// A case holding an input and its evaluation.
harness::Case case_of(const harness::Input& input, const harness::Evaluation& e, harness::Provenance provenance,
                      std::string note);

/// Reads a case file; on bad input prints one line naming the file and the place to stderr and
/// returns nothing.
std::optional<harness::Case> read_case_or_report(const std::filesystem::path& path);

/// The triage of a case: the answers, the class, the margin (also in ULPs of the deciding
/// quantity) and the reasoning of the exact reference. `recorded` is the case as stored.
std::string triage_text(const std::string& title, const harness::Case& recorded, const harness::Evaluation& now,
                        const harness::Explanation& why);

/// An SVG drawing of a case under `title` (its file, query and class): three orthographic views,
/// in which a point, a sphere of radius zero and a segment seen end-on are drawn as markers, and
/// the deciding axis. Valid XML whatever the text.
std::string svg_of(const harness::Input& input, const harness::Explanation& why, std::string_view title);

/// Every case file name (hash.json) stored under `root`, for skipping known cases.
std::vector<std::string> stored_case_names(const std::filesystem::path& root);

}  // namespace cc::tool
