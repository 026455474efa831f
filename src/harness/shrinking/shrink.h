// Minimising a case at the level of values: every number moves toward
// 0, then small integers, then halves, then fewer mantissa bits, and k-DOP point sets lose
// points, as long as the case keeps its signature (kind, class, and who disagrees how).
#pragma once

#include <filesystem>
#include <functional>

#include "harness/judging/evaluate.h"

namespace cc::harness {

using Evaluator = std::function<Evaluation(const Input&)>;

struct ShrinkResult {
  Input input;
  Evaluation evaluation;
  int attempts = 0;  // evaluations tried
  int accepted = 0;  // simplifications kept
  bool out_of_time = false;  // stopped by max_seconds with simplifications left to try
};

/// Shrinks `input` (whose evaluation is `start`) with at most `max_attempts` evaluations and
/// within about `max_seconds`. Besides values, a box's frame (and a mesh's pose) moves toward
/// the identity and the signed permutations as a whole (one entry alone would leave it
/// non-orthonormal), and a mesh query loses faces first (shrink_faces.h). Mesh files named by
/// the input are looked for from `case_dir` (see find_mesh_file).
ShrinkResult shrink(const Input& input, const Evaluation& start, const Evaluator& evaluate, int max_attempts = 4000,
                    double max_seconds = 60, const std::filesystem::path& case_dir = {});

/// How simple a double is, for ordering: 0, then integers by size, then halves by size, then
/// values by the number of mantissa bits they need; non-finite values last.
double complexity(double x);

/// The number of values in the inputs that are not small integers or halves (|x| <= 1024,
/// 2x integral): the measure of how far shrinking got.
int complex_values(const Input& input);

}  // namespace cc::harness
