#include "harness/formats/number_text.h"

#include <charconv>
#include <cmath>
#include <limits>

namespace cc::harness {

std::string format_double(double x) {
  // A NaN's sign is kept (x86's arithmetic makes -nan, e.g. inf - inf, and a peer may tell
  // them apart); its payload is not.
  if (std::isnan(x)) return std::signbit(x) ? "-nan" : "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, x);  // shortest round trip
  return std::string(buffer, result.ptr);
}

std::optional<double> parse_double(std::string_view text) {
  if (text == "nan" || text == "+nan") return std::numeric_limits<double>::quiet_NaN();
  if (text == "-nan") return -std::numeric_limits<double>::quiet_NaN();
  if (text == "inf" || text == "+inf") return std::numeric_limits<double>::infinity();
  if (text == "-inf") return -std::numeric_limits<double>::infinity();
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  if (text.empty() || text.front() == '+') return std::nullopt;
  double x = 0;
  const auto result = std::from_chars(text.data(), text.data() + text.size(), x, std::chars_format::general);
  if (result.ec != std::errc() || result.ptr != text.data() + text.size()) return std::nullopt;
  // from_chars accepts "nan" and "inf" spellings of its own ("infinity", "nan(...)"): refuse them.
  if (!std::isfinite(x)) return std::nullopt;
  return x;
}

}  // namespace cc::harness
