#include "harness/formats/printable.h"

#include <cstdio>

namespace cc::harness {
namespace {

// The length of the well-formed UTF-8 sequence of more than one byte at `at`, or 0 (RFC 3629:
// no overlong forms, no surrogates, nothing past U+10FFFF), nor the C1 controls U+0080-U+009F,
// which terminals take as commands as they take an escape, nor the bidirectional controls.
std::size_t utf8_length(std::string_view text, std::size_t at) {
  const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
  const unsigned char first = byte(at);
  std::size_t n = 0;
  unsigned char lo = 0x80, hi = 0xbf;  // the range of the second byte
  if (first >= 0xc2 && first <= 0xdf) {
    n = 2;
    if (first == 0xc2) lo = 0xa0;
  } else if (first >= 0xe0 && first <= 0xef) {
    n = 3;
    if (first == 0xe0) lo = 0xa0;
    if (first == 0xed) hi = 0x9f;
  } else if (first >= 0xf0 && first <= 0xf4) {
    n = 4;
    if (first == 0xf0) lo = 0x90;
    if (first == 0xf4) hi = 0x8f;
  } else {
    return 0;
  }
  if (at + n > text.size() || byte(at + 1) < lo || byte(at + 1) > hi) return 0;
  for (std::size_t i = 2; i < n; ++i) {
    if (byte(at + i) < 0x80 || byte(at + i) > 0xbf) return 0;
  }
  // The bidirectional embeddings, overrides and isolates (U+202A-U+202E, U+2066-U+2069) reorder
  // what a terminal shows after them: escaped too.
  if (first == 0xe2 && ((byte(at + 1) == 0x80 && byte(at + 2) >= 0xaa && byte(at + 2) <= 0xae) ||
                        (byte(at + 1) == 0x81 && byte(at + 2) >= 0xa6 && byte(at + 2) <= 0xa9))) {
    return 0;
  }
  return n;
}

}  // namespace

std::string printable(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    const auto byte = static_cast<unsigned char>(text[i]);
    if (byte >= 0x20 && byte < 0x7f) {
      out += text[i++];
      continue;
    }
    if (const std::size_t n = byte >= 0x80 ? utf8_length(text, i) : 0; n > 0) {
      out.append(text.substr(i, n));
      i += n;
      continue;
    }
    char escaped[8];
    std::snprintf(escaped, sizeof escaped, "\\x%02x", byte);
    out += escaped;
    ++i;
  }
  return out;
}

}  // namespace cc::harness
