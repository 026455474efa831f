// The fuzz target of the OBJ reader (harness/formats/obj_file.h): any bytes are either refused
// with a MeshFileError, or read into a mesh whose promises hold: at least one face, every face
// naming a vertex that exists, every coordinate finite. Anything else (another exception, a
// crash, a broken promise) is a finding.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "harness/formats/obj_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  cc::Mesh mesh;
  try {
    mesh = cc::harness::read_obj_text(text, "fuzz.obj");
  } catch (const cc::harness::MeshFileError&) {
    return 0;
  }
  bool kept = !mesh.faces.empty();
  for (const auto& face : mesh.faces) {
    for (std::uint32_t v : face) kept = kept && v < mesh.vertices.size();
  }
  for (const cc::Vec3& p : mesh.vertices) kept = kept && std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
  if (!kept) {
    std::fprintf(stderr, "a mesh read from OBJ text breaks the reader's promises (%zu vertices, %zu faces)\n",
                 mesh.vertices.size(), mesh.faces.size());
    std::abort();
  }
  return 0;
}
