// crosscheck kind-files [KIND]... [--source DIR] [--check]: for each query kind, the files of the
// source tree that name it (its name as a word, or its input type), sorted by where they are:
// its units (*/kinds/<kind>.h, .cpp in each layer), the registry, the manual (the README and
// docs/*.md), its corpora
// folder, the units of kinds that build on it (they include its unit's header), the places not
// counted (tests, which mirror the units; bench, whose rows are named after the library's
// primitives; the library, src/collide, which has no query kinds: a file or an include path
// named after a library function, collide/<name>.h, is not the kind, nor is a folder of FCL's,
// fcl/<name>/), and anything else. Then what the checklist for adding a kind
// (docs/query-kinds.md) asks that is missing. With --check, exit 1 when a kind is named anywhere
// else or its checklist is not complete.
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string_view>

#include "harness/model/query_kind.h"
#include "tool/commands.h"

namespace cc::tool {
namespace {

namespace fs = std::filesystem;

struct KindFilesArgs {
  std::vector<std::string> kinds;
  std::string source = ".";
  bool check = false;
};

// The kind's input type's name: its name in CamelCase, then Input.
std::string input_type_of(std::string_view kind) {
  std::string out;
  bool upper = true;
  for (char c : kind) {
    if (c == '_') {
      upper = true;
      continue;
    }
    out += upper ? static_cast<char>(std::toupper(static_cast<unsigned char>(c))) : c;
    upper = false;
  }
  return out + "Input";
}

bool word_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// Whether `text` at `at` is a path into the library's headers or FCL's (collide/<word>...,
// fcl/<word>/...): a file or folder of theirs, named after what they do, not a query kind.
bool in_other_code_path(const std::string& text, std::size_t at) {
  for (const std::string_view folder : {"collide/", "fcl/"}) {
    if (at >= folder.size() && text.compare(at - folder.size(), folder.size(), folder) == 0) return true;
  }
  return false;
}

// Whether `text` has `word` delimited by characters that are not letters, digits or '_', other
// than in a path into the library or FCL.
bool names(const std::string& text, const std::string& word) {
  for (std::size_t at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) {
    const bool starts = at == 0 || !word_char(text[at - 1]);
    const bool ends = at + word.size() == text.size() || !word_char(text[at + word.size()]);
    if (starts && ends && !in_other_code_path(text, at)) return true;
  }
  return false;
}

// The text files of the tree, as paths relative to it: everything but version control, build
// folders and the case files (a kind's cases are its corpora folder).
std::vector<std::string> source_files(const fs::path& root) {
  std::vector<std::string> out;
  for (auto it = fs::recursive_directory_iterator(root); it != fs::recursive_directory_iterator(); ++it) {
    const std::string rel = fs::relative(it->path(), root).generic_string();
    if (it->is_directory() && (rel == ".git" || rel == "build" || rel == "corpora")) {
      it.disable_recursion_pending();
      continue;
    }
    if (it->is_regular_file()) out.push_back(rel);
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  std::string text = s.str();
  if (text.find('\0') != std::string::npos) return {};  // not text
  return text;
}

// The kind whose unit a file belongs to (*/kinds/<kind>.h or .cpp, model/inputs/<kind>.h), if any.
std::string unit_of(const std::string& rel) {
  const fs::path p(rel);
  const fs::path folder = p.parent_path().filename();
  if (folder != "kinds" && folder != "inputs") return {};
  const std::string stem = p.stem().string();
  return harness::query_kind_named(stem) ? stem : std::string();
}

// Whether `text`, a peer's oracle/<peer>/no_parties.cpp, declares that it has no parties for
// `kind` (a CC_NO_PARTIES line): that line is the kind's unit there.
bool declares_no_parties(const std::string& rel, const std::string& text, const std::string& kind) {
  if (fs::path(rel).filename() != "no_parties.cpp") return false;
  for (std::size_t line = text.find("\nCC_NO_PARTIES("); line != std::string::npos;
       line = text.find("\nCC_NO_PARTIES(", line + 1)) {
    const std::size_t comma = text.find(", ", line);
    if (comma != std::string::npos && text.compare(comma + 2, kind.size() + 1, kind + ",") == 0) return true;
  }
  return false;
}

std::string not_counted_because(const std::string& rel) {
  if (rel.starts_with("tests/")) return "tests";
  if (rel.starts_with("bench/")) return "bench";
  if (rel.starts_with("src/collide/")) return "the library";
  return {};
}

// Whether `file` under `root` holds `text`.
bool holds(const fs::path& root, const std::string& file, const std::string& text) {
  return read_text(root / file).find(text) != std::string::npos;
}

bool has_file_in(const fs::path& folder, const std::string& extension) {
  std::error_code ec;
  for (auto it = fs::directory_iterator(folder, ec); !ec && it != fs::directory_iterator(); ++it) {
    if (it->is_regular_file() && (extension.empty() || it->path().extension() == extension)) return true;
  }
  return false;
}

// What the checklist for adding a kind (docs/query-kinds.md, "Adding a query kind") asks that
// the tree lacks: its units in every layer (the harness, the exact reference, each peer's
// oracle/<peer>/kinds/, or the peer's line saying it has none), hand-written cases and fuzz seeds in its corpora folder, its rows in the
// manual (query-kinds.md, bands.md, peers.md), and its case in the distinct-inputs switch. The
// registry line is what makes it a kind.
std::vector<std::string> checklist_gaps(const fs::path& root, const std::string& kind) {
  std::vector<std::string> gaps;
  std::vector<std::string> units = {"src/harness/model/inputs/" + kind + ".h", "src/harness/kinds/" + kind + ".h",
                                    "src/harness/kinds/" + kind + ".cpp", "oracle/exact/kinds/" + kind + ".cpp"};
  std::error_code ec;
  std::set<std::string> peers;
  for (auto it = fs::directory_iterator(root / "oracle", ec); !ec && it != fs::directory_iterator(); ++it) {
    const std::string peer = it->path().filename().string();
    if (peer != "exact" && fs::is_directory(it->path() / "kinds")) peers.insert(peer);
  }
  for (const std::string& peer : peers) {
    const std::string none = "oracle/" + peer + "/no_parties.cpp";
    if (!declares_no_parties(none, read_text(root / none), kind)) units.push_back("oracle/" + peer + "/kinds/" + kind + ".cpp");
  }
  for (const std::string& unit : units) {
    if (!fs::is_regular_file(root / unit)) gaps.push_back("its unit " + unit + " (or, for a peer, a line in its no_parties.cpp)");
  }
  if (!has_file_in(root / "corpora" / kind, ".json")) gaps.push_back("hand-written cases in corpora/" + kind + "/");
  if (!has_file_in(root / "corpora" / kind / "seed", "")) gaps.push_back("fuzz seeds in corpora/" + kind + "/seed/");
  for (const std::string page : {"docs/query-kinds.md", "docs/bands.md", "docs/peers.md"}) {
    if (!holds(root, page, "`" + kind + "`")) gaps.push_back("its row in " + page);
  }
  if (!holds(root, "tests/harness/formats/distinct_inputs.h", "case QueryKind::" + kind + ":")) {
    gaps.push_back("its case in the switch of tests/harness/formats/distinct_inputs.h");
  }
  return gaps;
}

int run(const KindFilesArgs& args) {
  std::vector<std::string> kinds;
  for (const std::string& k : args.kinds) {
    if (!harness::query_kind_named(k)) {
      std::fprintf(stderr, "crosscheck kind-files: unknown query \"%s\"\n", k.c_str());
      return kExitBadInput;
    }
    kinds.push_back(k);
  }
  if (kinds.empty()) {
    for (harness::QueryKind kind : harness::kAllQueryKinds) kinds.emplace_back(harness::name(kind));
  }
  const fs::path root(args.source);
  if (!fs::is_directory(root)) {
    std::fprintf(stderr, "crosscheck kind-files: --source %s is not a folder\n", args.source.c_str());
    return kExitBadInput;
  }
  std::vector<std::pair<std::string, std::string>> texts;
  for (const std::string& rel : source_files(root)) texts.emplace_back(rel, read_text(root / rel));

  bool clean = true;
  for (const std::string& kind : kinds) {
    const std::string type = input_type_of(kind);
    std::map<std::string, std::vector<std::string>> where;  // category -> files
    int elsewhere = 0;
    for (const auto& [rel, text] : texts) {
      if (!names(text, kind) && !names(text, type)) continue;
      const std::string unit = unit_of(rel);
      std::string category;
      if (unit == kind || declares_no_parties(rel, text, kind)) {
        category = "its units";
      } else if (rel == "src/harness/model/registry.h" || rel == "src/harness/kinds/pieces.cpp") {
        category = "the registry";
      } else if (rel == "README.md" || (rel.starts_with("docs/") && rel.ends_with(".md"))) {
        category = "the manual";
      } else if (!unit.empty() && text.find("kinds/" + kind + ".h\"") != std::string::npos) {
        category = "units that build on it";
      } else if (const std::string why = not_counted_because(rel); !why.empty()) {
        category = "not counted: " + why;
      } else {
        category = "elsewhere";
        ++elsewhere;
      }
      where[category].push_back(rel);
    }
    if (fs::is_directory(root / "corpora" / kind)) where["its corpora folder"].push_back("corpora/" + kind + "/");
    const auto count = [&where](const char* category) {
      const auto it = where.find(category);
      return it == where.end() ? std::size_t{0} : it->second.size();
    };
    const std::size_t places = count("the registry") + count("the manual") + count("its corpora folder") +
                               count("units that build on it") + static_cast<std::size_t>(elsewhere);
    std::printf("%s (or %s): named outside its units in %zu place%s%s\n", kind.c_str(), type.c_str(), places,
                places == 1 ? "" : "s", elsewhere > 0 ? (", " + std::to_string(elsewhere) + " of them elsewhere").c_str() : "");
    for (const char* category : {"its units", "the registry", "the manual", "its corpora folder",
                                 "units that build on it", "elsewhere"}) {
      const auto it = where.find(category);
      if (it == where.end()) continue;
      std::printf("  %s:", category);
      for (const std::string& f : it->second) std::printf(" %s", f.c_str());
      std::printf("\n");
    }
    for (const auto& [category, files] : where) {
      if (category.starts_with("not counted")) std::printf("  (%s: %zu files)\n", category.c_str(), files.size());
    }
    const std::vector<std::string> gaps = checklist_gaps(root, kind);
    if (gaps.empty()) {
      std::printf("  the checklist: complete\n");
    } else {
      for (const std::string& gap : gaps) std::printf("  the checklist lacks %s\n", gap.c_str());
    }
    clean &= elsewhere == 0 && gaps.empty();
  }
  return args.check && !clean ? kExitFound : 0;
}

}  // namespace

void add_kind_files_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<KindFilesArgs>();
  auto* cmd = app.add_subcommand("kind-files", "List, per query kind, the files of the source tree that name it");
  cmd->add_option("kinds", args->kinds, "Query kinds (default: all)");
  cmd->add_option("--source", args->source, "The source tree")->capture_default_str();
  cmd->add_flag("--check", args->check,
                "Exit 1 if a kind is named outside its units, the registry, the manual (README, docs/) and its corpora "
                "folder, or if the checklist for adding a kind (docs/query-kinds.md) is not complete");
  cmd->callback([args, &exit_code] { exit_code = run(*args); });
}

}  // namespace cc::tool
