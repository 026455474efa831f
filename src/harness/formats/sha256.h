// SHA-256 (FIPS 180-4) of a file's bytes: how a case names the subject that answered it.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace cc::harness {

/// The SHA-256 digest of the bytes, as 64 lowercase hex digits.
std::string sha256_hex(std::string_view bytes);

/// The same of a file's contents; throws std::runtime_error naming the file when it cannot be
/// read.
std::string sha256_of_file(const std::filesystem::path& path);

}  // namespace cc::harness
