// Reading an input file whole (a case file, a mesh), with the limits every reader keeps: a
// device, a FIFO or a socket is refused (/dev/zero never ends), and so is a file over the
// reader's size limit, before anything is read.
#pragma once

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>

namespace cc::harness {

/// A case file is at most 64 MiB; a mesh file (OBJ) at most 512 MiB.
inline constexpr std::uintmax_t kMaxCaseFileBytes = std::uintmax_t{64} << 20;
inline constexpr std::uintmax_t kMaxMeshFileBytes = std::uintmax_t{512} << 20;

/// Why a file cannot be read (what() names no file: the reader adds it).
class InputFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The bytes of the regular file at `path`, at most `limit` of them; `noun` names what it should
/// be ("case file"). Throws InputFileError: "a folder, not a <noun>", "not a regular file (a device, a FIFO or a socket)", "N bytes, over the
/// limit of M MiB", "cannot read the file: <reason>".
std::string read_input_file(const std::filesystem::path& path, std::uintmax_t limit, const std::string& noun = "file");

}  // namespace cc::harness
