// The mutant catalogue: a good catalogue reads field by field; a bad one is refused with a
// message naming the file and the place; a stale mutant (its original text absent, or there
// more than once) is told apart from one that applies; applying a mutant replaces its text once.
#include "tool/mutant_catalogue.h"

#include <gtest/gtest.h>

#include <string>

#include "collide/simd.h"
#include "temp_folder.h"

namespace cc::tool {
namespace {

struct Folder : test::TempFolder {
  Folder() : TempFolder("crosscheck_mutant_catalogue_test") {}
};

// A catalogue file whose "mutants" array holds `mutants` (JSON text).
std::string catalogue_text(const std::string& mutants) {
  return "{\n  \"format\": \"crosscheck-mutants\",\n  \"version\": 1,\n  \"mutants\": [" + mutants + "]\n}\n";
}

const std::string kFlip =
    R"json({"id": "box.flip", "query": "aabb_aabb", "file": "src/box.cpp", "original": "a <= b",
        "replacement": "a < b", "description": "`<` for `<=`"})json";
const std::string kSwap =
    R"json({"id": "box.swap", "query": "aabb_aabb", "file": "src/box.cpp", "original": "f(a, b)",
        "replacement": "f(b, a)", "description": "arguments swapped", "equivalent": "f is symmetric"})json";

// The message of the CatalogueError that reading `text` as a catalogue throws ("" if none).
std::string error_reading(const std::string& text) {
  const Folder folder;
  const auto path = folder.write("mutants.json", text);
  try {
    read_catalogue(path);
  } catch (const CatalogueError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind(path.string() + ": ", 0), 0u) << "does not name the file first: " << message;
    return message;
  }
  ADD_FAILURE() << "no error for:\n" << text;
  return "";
}

TEST(MutantCatalogue, ReadsEveryFieldInOrder) {
  const Folder folder;
  const auto mutants = read_catalogue(folder.write("mutants.json", catalogue_text(kFlip + ",\n" + kSwap)));
  ASSERT_EQ(mutants.size(), 2u);
  const Mutant& flip = mutants[0];
  EXPECT_EQ(flip.id, "box.flip");
  EXPECT_EQ(flip.query, "aabb_aabb");
  EXPECT_EQ(flip.file, "src/box.cpp");
  EXPECT_EQ(flip.original, "a <= b");
  EXPECT_EQ(flip.replacement, "a < b");
  EXPECT_EQ(flip.description, "`<` for `<=`");
  EXPECT_EQ(flip.equivalent, "");  // optional: absent means counted
  EXPECT_EQ(mutants[1].id, "box.swap");
  EXPECT_EQ(mutants[1].equivalent, "f is symmetric");
}

TEST(MutantCatalogue, AKernelNamesTheSimdCodeAMutantBelongsTo) {
  const Folder folder;
  const auto mutants = read_catalogue(folder.write(
      "mutants.json", catalogue_text(R"json({"id": "batch.avx2", "query": "ray_aabb", "file": "src/b.cpp",
                                        "original": "x", "replacement": "y", "description": "d",
                                        "kernel": "avx2"})json")));
  ASSERT_EQ(mutants.size(), 1u);
  EXPECT_EQ(mutants[0].kernel, "avx2");
  EXPECT_NE(error_reading(catalogue_text(R"json({"id": "a", "query": "q", "file": "f", "original": "x",
                                            "replacement": "y", "description": "d", "kernel": "neon"})json"))
                .find(": /mutants/0/kernel: \"neon\" is not a kernel"),
            std::string::npos);
}

TEST(MutantCatalogue, AMutantOfAKernelTheProcessorLacksIsNotExecutableHere) {
  Mutant m;
  EXPECT_EQ(not_executable_here(m), std::nullopt);  // no kernel: runs everywhere
  for (simd::Kernel k : simd::kAllKernels) {
    m.kernel = std::string(simd::to_string(k));
    const auto why = not_executable_here(m);
    EXPECT_EQ(why.has_value(), !simd::supported(k)) << m.kernel;
    if (why) {
      EXPECT_NE(why->find("this processor lacks"), std::string::npos) << *why;
    }
  }
}

TEST(MutantCatalogue, AnEmptyReplacementDeletesTheText) {
  const Folder folder;
  const auto mutants = read_catalogue(folder.write(
      "mutants.json", catalogue_text(R"json({"id": "x.gone", "query": "q", "file": "src/x.cpp", "original": "check();",
                                        "replacement": "", "description": "a check dropped"})json")));
  ASSERT_EQ(mutants.size(), 1u);
  EXPECT_EQ(mutated(mutants[0], "a(); check(); b();"), "a();  b();");
}

TEST(MutantCatalogue, ASyntaxErrorNamesTheLineAndColumn) {
  // The comma after the version is missing: the parser stops at the end of the unexpected
  // string "mutants" (line 4, columns 3 to 11).
  const std::string message =
      error_reading("{\n  \"format\": \"crosscheck-mutants\",\n  \"version\": 1\n  \"mutants\": []\n}\n");
  EXPECT_NE(message.find(": line 4, column 11: syntax error"), std::string::npos) << message;
}

TEST(MutantCatalogue, ABadFieldIsNamedByItsJsonPointer) {
  const std::string without_original = R"json({"id": "b", "query": "q", "file": "src/x.cpp", "replacement": "y",
                                           "description": "d"})json";
  EXPECT_NE(error_reading(catalogue_text(kFlip + "," + without_original))
                .find(": /mutants/1: missing field \"original\""),
            std::string::npos);
  EXPECT_NE(error_reading(catalogue_text(R"json({"id": 7, "query": "q", "file": "f", "original": "a",
                                            "replacement": "b", "description": "d"})json"))
                .find(": /mutants/0/id: not a string"),
            std::string::npos);
  EXPECT_NE(error_reading(catalogue_text(R"json({"id": "a", "query": "q", "file": "f", "original": "same",
                                            "replacement": "same", "description": "d"})json"))
                .find(": /mutants/0/replacement: the same as the original text"),
            std::string::npos);
  EXPECT_NE(error_reading(catalogue_text(R"json({"id": "a", "query": "q", "file": "f", "original": "x",
                                            "replacement": "y", "description": "d", "severity": "high"})json"))
                .find(": /mutants/0/severity: unknown field"),
            std::string::npos);
  EXPECT_NE(error_reading(catalogue_text(kFlip + "," + kFlip)).find(": /mutants/1/id: \"box.flip\" is used twice"),
            std::string::npos);
}

TEST(MutantCatalogue, AFileOutsideTheSourceTreeIsRefused) {
  for (const char* file : {"/etc/passwd", "../outside.cpp", "src/../../outside.cpp"}) {
    const std::string mutant = std::string(R"json({"id": "a", "query": "q", "file": ")json") + file +
                               R"json(", "original": "x", "replacement": "y", "description": "d"})json";
    EXPECT_NE(error_reading(catalogue_text(mutant)).find(": /mutants/0/file: must be a path inside the source tree"),
              std::string::npos)
        << file;
  }
}

TEST(MutantCatalogue, TheEnvelopeIsChecked) {
  EXPECT_NE(error_reading("[]").find(": /: not a JSON object"), std::string::npos);
  EXPECT_NE(error_reading(R"json({"format": "crosscheck-case", "version": 1, "mutants": []})json").find(": /format:"),
            std::string::npos);
  EXPECT_NE(error_reading(R"json({"format": "crosscheck-mutants", "version": 2, "mutants": []})json").find(": /version:"),
            std::string::npos);
  EXPECT_NE(error_reading(R"json({"format": "crosscheck-mutants", "version": 1, "mutants": {}})json").find(": /mutants:"),
            std::string::npos);
}

TEST(MutantCatalogue, AMissingFileIsNamed) {
  const Folder folder;
  const auto path = folder.path() / "no_such_catalogue.json";
  try {
    read_catalogue(path);
    ADD_FAILURE() << "no error for a missing file";
  } catch (const CatalogueError& e) {
    EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
  }
}

Mutant flip() {
  Mutant m;
  m.id = "box.flip";
  m.file = "src/box.cpp";
  m.original = "a <= b";
  m.replacement = "a < b";
  return m;
}

TEST(MutantCatalogue, AMutantAppliesWhenItsOriginalOccursExactlyOnce) {
  EXPECT_EQ(staleness(flip(), "if (a <= b) return;"), std::nullopt);
}

TEST(MutantCatalogue, AMutantWhoseOriginalIsAbsentIsStale) {
  const auto why = staleness(flip(), "if (a < b) return;");
  ASSERT_TRUE(why.has_value());
  EXPECT_NE(why->find("not found in src/box.cpp"), std::string::npos) << *why;
  EXPECT_TRUE(staleness(flip(), "").has_value());
}

TEST(MutantCatalogue, AMutantWhoseOriginalOccursTwiceIsStale) {
  const auto why = staleness(flip(), "if (a <= b) x(); if (a <= b) y();");
  ASSERT_TRUE(why.has_value());
  EXPECT_NE(why->find("occurs 2 times in src/box.cpp"), std::string::npos) << *why;
  // Overlapping occurrences count too: "aa" occurs twice in "aaa".
  Mutant overlapping = flip();
  overlapping.original = "aa";
  EXPECT_NE(staleness(overlapping, "aaa").value_or("").find("occurs 2 times"), std::string::npos);
}

TEST(MutantCatalogue, ApplyingAMutantReplacesItsTextAndNothingElse) {
  const std::string text = "// a <= b? \nif (a <= b) return;\n";
  Mutant m = flip();
  m.original = "(a <= b)";
  m.replacement = "(a < b)";
  ASSERT_EQ(staleness(m, text), std::nullopt);
  EXPECT_EQ(mutated(m, text), "// a <= b? \nif (a < b) return;\n");
  // The mutated text no longer holds the original: applied twice, the mutant is stale.
  EXPECT_TRUE(staleness(m, mutated(m, text)).has_value());
}

TEST(MutantCatalogue, TextRoundTripsThroughAFile) {
  const Folder folder;
  using namespace std::string_literals;
  const std::string text = "line one\r\nline two\0with a NUL\n"s;
  write_text(folder.path() / "f.cpp", text);
  EXPECT_EQ(read_text(folder.path() / "f.cpp"), text);
  EXPECT_THROW(read_text(folder.path() / "none.cpp"), std::runtime_error);
  EXPECT_THROW(write_text(folder.path() / "no_such_folder" / "f.cpp", text), std::runtime_error);
}

}  // namespace
}  // namespace cc::tool
