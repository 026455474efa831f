// JSON text read with the limits every reader of the project's JSON keeps: nesting at most
// kMaxJsonDepth deep (a deeper document would exhaust the stack when it is freed), no key twice
// in one object (which of two would count is a guess), numbers within a double's range.
#pragma once

#include <cstddef>
#include <stdexcept>

#include "harness/formats/printable.h"
#include <string>

#include "harness/formats/input_json.h"

namespace cc::harness {

/// The deepest nesting a document may have; a case file's is 6.
inline constexpr std::size_t kMaxJsonDepth = 64;

/// A document refused: where ("line 3, column 14", or a JSON pointer such as "/inputs/box") and why.
class JsonTextError : public std::runtime_error {
 public:
  /// The message is made printable (harness/formats/printable.h): it may quote the text.
  JsonTextError(std::string place, const std::string& message)
      : std::runtime_error(printable(message)), place_(std::move(place)) {}
  const std::string& place() const { return place_; }

 private:
  std::string place_;
};

/// The JSON document in `text`. Throws JsonTextError for a syntax error (its line and column), a
/// number beyond the range of a double (its line and column), nesting deeper than kMaxJsonDepth
/// or a key given twice in one object (the pointer of the place).
Json parse_json_text(const std::string& text);

/// "line L, column C" of the byte at `offset` in `text`.
std::string line_and_column(const std::string& text, std::size_t offset);

}  // namespace cc::harness
