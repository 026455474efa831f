// Doubles as text that round-trips exactly: the shortest decimal that reads back as the same
// double, with NaN, infinities and -0 spelled out ("nan", "-nan", "inf", "-inf", "-0").
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace cc::harness {

/// The shortest round-trip decimal of x ("0.1", "-0", "5e-324", "nan", "inf", "-inf"); a NaN
/// with its sign bit set is "-nan" (its payload is not kept: reading gives the quiet one).
std::string format_double(double x);

/// The double a text denotes, if the whole text is a decimal number (rounded to nearest) or one
/// of "nan", "-nan", "+nan", "inf", "-inf", "+inf". Nothing for anything else.
std::optional<double> parse_double(std::string_view text);

}  // namespace cc::harness
