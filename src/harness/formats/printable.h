// Text from a file, made safe to show: what a file says (a note, a token, a file's name) never
// reaches a terminal raw, nor is cut short by a NUL when it travels in an error's message.
#pragma once

#include <string>
#include <string_view>

namespace cc::harness {

/// The text with every control character (a NUL, an escape, a newline, DEL, the C1 controls
/// U+0080-U+009F, the bidirectional controls U+202A-U+202E and U+2066-U+2069) and every byte that is not part of well-formed UTF-8 written as \xNN, byte by
/// byte; other well-formed UTF-8 beyond ASCII is kept.
std::string printable(std::string_view text);

}  // namespace cc::harness
