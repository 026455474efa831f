// Query inputs as JSON, for case files and for printing findings. Every double is a string in
// the format of number_text.h, so it reads back exactly.
#pragma once

#include <nlohmann/json.hpp>

#include <filesystem>
#include <stdexcept>
#include <string>

#include "harness/model/input.h"

namespace cc::harness {

using Json = nlohmann::ordered_json;

/// A problem in a JSON document, at a place given as a JSON pointer ("/inputs/origin/1").
class FormatError : public std::runtime_error {
 public:
  FormatError(std::string pointer, const std::string& message)
      : std::runtime_error(message), pointer_(std::move(pointer)) {}
  const std::string& pointer() const { return pointer_; }

 private:
  std::string pointer_;
};

/// The inputs of a query as a JSON object; its layout depends on the kind (see README).
Json input_to_json(const Input& input);

/// The inputs of a query of the given kind read from `json` (found at `pointer` in its document,
/// for error messages). Mesh files are looked for from `case_dir` (see find_mesh_file). Throws
/// FormatError naming the place of a missing field, a value of the wrong type, a number that
/// does not parse, or a mesh file that is missing or broken (with the file's own line).
Input input_from_json(QueryKind kind, const Json& json, const std::string& pointer,
                      const std::filesystem::path& case_dir = {});

/// A mesh as a case file gives it: {"file": ...}, {"procedural": ...} or {"triangles": [...]}.
Json mesh_to_json(const MeshRef& mesh);

/// A double as JSON (a string) and back; the reader also accepts plain JSON numbers.
Json number_to_json(double x);
double number_from_json(const Json& json, const std::string& pointer);

}  // namespace cc::harness
