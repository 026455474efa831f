#include "harness/generation/generate.h"

#include "harness/generation/values.h"

namespace cc::harness {

Input generate(QueryKind kind, Choices& choices, const GenerateOptions& options) {
  // Huge magnitudes dwarf every other coordinate, and with them the library's band: one case in
  // seven gets them.
  const bool huge = choices.chance(15);
  ValueSource values(choices, ValueRange{8, true, huge, options.out_of_contract});
  return with_kind(kind, [&]<class In>() -> Input { return Query<In>::generate(values, options); });
}

bool builds_hierarchies(QueryKind kind) {
  return with_kind(kind, []<class In>() { return Query<In>::builds_hierarchies; });
}

}  // namespace cc::harness
