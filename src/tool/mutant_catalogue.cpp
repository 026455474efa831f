#include "tool/mutant_catalogue.h"

#include "collide/simd.h"

#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

namespace cc::tool {
namespace {

using Json = nlohmann::json;

std::string line_and_column(const std::string& text, std::size_t byte) {
  std::size_t line = 1, column = 1;
  for (std::size_t i = 0; i < byte && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line, column = 1;
    } else {
      ++column;
    }
  }
  return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

// A required string field of `object` (at `pointer`); `optional` fields may be absent.
std::string field(const Json& object, const std::string& pointer, const char* name, const std::string& file,
                  bool optional = false) {
  const auto it = object.find(name);
  if (it == object.end()) {
    if (optional) return {};
    throw CatalogueError(file + ": " + pointer + ": missing field \"" + name + "\"");
  }
  if (!it->is_string()) throw CatalogueError(file + ": " + pointer + "/" + name + ": not a string");
  if (it->get_ref<const std::string&>().empty() && !optional) {
    throw CatalogueError(file + ": " + pointer + "/" + name + ": empty");
  }
  return it->get<std::string>();
}

}  // namespace

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path.string() + ": cannot read the file");
  std::stringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) throw std::runtime_error(path.string() + ": cannot read the file");
  return buffer.str();
}

void write_text(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
  out.close();
  if (!out) throw std::runtime_error(path.string() + ": cannot write the file");
}

std::vector<Mutant> read_catalogue(const std::filesystem::path& path) {
  const std::string file = path.string();
  std::string text;
  try {
    text = read_text(path);
  } catch (const std::runtime_error& e) {
    throw CatalogueError(e.what());
  }
  Json json;
  try {
    json = Json::parse(text);
  } catch (const Json::parse_error& e) {
    std::string message = e.what();
    const auto at = message.find("syntax error");
    if (at != std::string::npos) message = message.substr(at);
    throw CatalogueError(file + ": " + line_and_column(text, e.byte == 0 ? 0 : e.byte - 1) + ": " + message);
  }
  if (!json.is_object()) throw CatalogueError(file + ": /: not a JSON object");
  if (json.value("format", "") != "crosscheck-mutants") {
    throw CatalogueError(file + ": /format: must be \"crosscheck-mutants\"");
  }
  if (!json.contains("version") || !json["version"].is_number_integer() || json["version"].get<int>() != 1) {
    throw CatalogueError(file + ": /version: must be 1 (this crosscheck reads version 1)");
  }
  if (!json.contains("mutants") || !json["mutants"].is_array()) {
    throw CatalogueError(file + ": /mutants: missing, or not an array");
  }
  std::vector<Mutant> out;
  std::set<std::string> ids;
  for (std::size_t i = 0; i < json["mutants"].size(); ++i) {
    const Json& m = json["mutants"][i];
    const std::string pointer = "/mutants/" + std::to_string(i);
    if (!m.is_object()) throw CatalogueError(file + ": " + pointer + ": not a JSON object");
    Mutant mutant;
    mutant.id = field(m, pointer, "id", file);
    mutant.query = field(m, pointer, "query", file);
    mutant.file = field(m, pointer, "file", file);
    mutant.original = field(m, pointer, "original", file);
    if (!m.contains("replacement") || !m["replacement"].is_string()) {
      throw CatalogueError(file + ": " + pointer + "/replacement: missing, or not a string");
    }
    mutant.replacement = m["replacement"].get<std::string>();
    mutant.description = field(m, pointer, "description", file);
    mutant.equivalent = field(m, pointer, "equivalent", file, true);
    mutant.kernel = field(m, pointer, "kernel", file, true);
    if (!mutant.kernel.empty() && !simd::kernel_named(mutant.kernel)) {
      throw CatalogueError(file + ": " + pointer + "/kernel: \"" + mutant.kernel + "\" is not a kernel (scalar, avx2, avx512)");
    }
    if (mutant.original == mutant.replacement) {
      throw CatalogueError(file + ": " + pointer + "/replacement: the same as the original text");
    }
    if (std::filesystem::path(mutant.file).is_absolute() || mutant.file.find("..") != std::string::npos) {
      throw CatalogueError(file + ": " + pointer + "/file: must be a path inside the source tree");
    }
    for (const auto& [key, value] : m.items()) {
      static const std::set<std::string> known = {"id", "query", "file", "original", "replacement", "description",
                                                  "equivalent", "kernel"};
      if (!known.count(key)) throw CatalogueError(file + ": " + pointer + "/" + key + ": unknown field");
    }
    if (!ids.insert(mutant.id).second) {
      throw CatalogueError(file + ": " + pointer + "/id: \"" + mutant.id + "\" is used twice");
    }
    out.push_back(std::move(mutant));
  }
  return out;
}

std::optional<std::string> staleness(const Mutant& m, const std::string& text) {
  std::size_t count = 0;
  for (std::size_t at = text.find(m.original); at != std::string::npos; at = text.find(m.original, at + 1)) ++count;
  if (count == 1) return std::nullopt;
  if (count == 0) return "the original text is not found in " + m.file;
  return "the original text occurs " + std::to_string(count) + " times in " + m.file + " (must be once)";
}

std::optional<std::string> not_executable_here(const Mutant& m) {
  if (m.kernel.empty()) return std::nullopt;
  const simd::Kernel k = *simd::kernel_named(m.kernel);
  if (const auto why = simd::unsupported_reason(k)) {
    return "its code is the " + m.kernel + " kernel, and " + *why + ": not run, left out of the score";
  }
  return std::nullopt;
}

std::string mutated(const Mutant& m, const std::string& text) {
  std::string out = text;
  const std::size_t at = out.find(m.original);
  out.replace(at, m.original.size(), m.replacement);
  return out;
}

}  // namespace cc::tool
