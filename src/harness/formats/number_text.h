// Doubles as text that round-trips exactly: the shortest decimal that reads back as the same
// double, with NaN, infinities and -0 spelled out ("nan", "inf", "-inf", "-0").
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace cc::harness {

/// The shortest round-trip decimal of x ("0.1", "-0", "5e-324", "nan", "inf", "-inf").
std::string format_double(double x);

/// The double a text denotes, if the whole text is a decimal number (rounded to nearest) or one
/// of "nan", "inf", "-inf", "+inf". Nothing for anything else.
std::optional<double> parse_double(std::string_view text);

}  // namespace cc::harness
