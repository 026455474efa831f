// One case evaluated with the opinions asked in a child process, so that a party that crashes
// or is cut short neither ends nor damages the caller (judging/evaluate.h does the rest).
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "harness/judging/evaluate.h"

namespace cc::harness {

/// evaluate(), the opinions asked first in a child process (crosscheck's own library too, to
/// prove it returns), which passes them back (as case files store them, exactly); the library
/// (a subject in its own process) and the exact reference are asked here. A party that crashes, or is cut short by a jump out of its code (see
/// SecondOpinion::abandoned_calls), thus neither ends nor damages the caller. Nothing when the
/// child did not answer (it crashed, ran past timeout_seconds when that is not 0, or was
/// stopped when `stop` said so: finish_child), and then how it ended into `how` when given
/// (ChildEnd::what()).
std::optional<Evaluation> evaluate_in_child(const Input& input, const ExactReference& exact, const SecondOpinion& second,
                                            double timeout_seconds = 0, std::string* how = nullptr,
                                            const std::function<bool()>& stop = {});

}  // namespace cc::harness
