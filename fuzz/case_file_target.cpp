// The fuzz target of the case-file reader (harness/formats/case_file.h): any bytes are either
// refused with a CaseFileError naming the place, or read into a case that the writer writes
// back and the reader reads again to the same text. Anything else (another exception, a crash,
// a text that changes on the round trip) is a finding.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "harness/formats/case_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  // No folder to find mesh files in: a case naming one is refused, without reading the disk.
  const std::filesystem::path no_folder = "/nonexistent/crosscheck-fuzz";
  cc::harness::Case c;
  try {
    c = cc::harness::read_case_text(text, "fuzz input", no_folder);
  } catch (const cc::harness::CaseFileError&) {
    return 0;
  }
  const std::string written = cc::harness::case_to_json(c).dump(2);
  const std::string again = cc::harness::case_to_json(cc::harness::read_case_text(written, "written", no_folder)).dump(2);
  if (again != written) {
    std::fprintf(stderr, "a case read, written and read again changed:\n%s\n---\n%s\n", written.c_str(), again.c_str());
    std::abort();
  }
  return 0;
}
