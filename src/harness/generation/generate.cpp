#include "harness/generation/generate.h"

#include "harness/generation/values.h"
#include "harness/model/kind_pieces.h"

namespace cc::harness {

Input generate(QueryKind kind, Choices& choices, const GenerateOptions& options) {
  // Huge magnitudes dwarf every other coordinate, and with them the library's band: one case in
  // seven gets them.
  const bool huge = choices.chance(15);
  ValueSource values(choices, ValueRange{8, true, huge, options.out_of_contract});
  return pieces_of(kind).generate(values, options);
}

bool builds_hierarchies(QueryKind kind) {
  return pieces_of(kind).builds_hierarchies;
}

}  // namespace cc::harness
