#include "harness/case_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace cc::harness {
namespace {

const std::filesystem::path kBad = std::filesystem::path(CROSSCHECK_TEST_DATA) / "bad_cases";

Case sample() {
  Case c;
  c.input = RayAabbInput{{{-1, 0.5, -0.0}, {1, 0, 5e-324}, 0, INFINITY}, {{0, 0, 0}, {1, 1, 1}}};
  c.library = {true, {1, 2}, {}, {}};
  c.exact.answer = {true, {1, 2}, {}, {}};
  c.exact.margin = 0.5;
  c.opinions = {{"libccd.GJK", Opinion::Status::not_applicable, {}, "a ray of infinite length"},
                {"libccd.MPR", Opinion::Status::answered, {true, {}, {}, {}}, ""}};
  c.cls = CaseClass::agree;
  c.provenance = {"campaign", 7, 1234, "seed 7"};
  c.note = "a ray through the middle";
  return c;
}

TEST(CaseFile, RoundTripsEveryField) {
  const Case c = sample();
  const Json j = case_to_json(c);
  const Case back = case_from_json(j);
  EXPECT_EQ(case_to_json(back).dump(), j.dump());
  EXPECT_EQ(j["version"], kCaseFormatVersion);
  EXPECT_EQ(j["inputs"]["origin"][2], "-0");
  EXPECT_EQ(j["inputs"]["tmax"], "inf");
  EXPECT_EQ(back.provenance.case_index, 1234u);
  EXPECT_EQ(back.opinions[0].status, Opinion::Status::not_applicable);
}

TEST(CaseFile, IsNamedByAHashOfItsInputs) {
  const Case c = sample();
  const std::string a = case_file_name(c.input);
  EXPECT_EQ(a.size(), 21u);  // 16 hex digits + ".json"
  Case other = c;
  other.note = "another note";
  EXPECT_EQ(case_file_name(other.input), a);
  std::get<RayAabbInput>(other.input).ray.tmax = 5;
  EXPECT_NE(case_file_name(other.input), a);
}

TEST(CaseFile, IsNeverOverwritten) {
  const auto dir = std::filesystem::temp_directory_path() / "crosscheck_case_file_test";
  std::filesystem::remove_all(dir);
  const auto path = dir / "x" / case_file_name(sample().input);
  EXPECT_TRUE(write_new_case_file(path, sample()));
  Case changed = sample();
  changed.note = "changed";
  EXPECT_FALSE(write_new_case_file(path, changed));
  EXPECT_EQ(read_case_file(path).note, "a ray through the middle");
  EXPECT_EQ(case_files_under({dir}).size(), 1u);
  std::filesystem::remove_all(dir);
}

void expect_error(const std::string& file, const std::string& place, const std::string& fragment) {
  try {
    read_case_file(kBad / file);
    ADD_FAILURE() << "no error for " << file;
  } catch (const CaseFileError& e) {
    EXPECT_NE(e.file().find(file), std::string::npos);
    EXPECT_EQ(e.place(), place) << e.what();
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(CaseFile, BadInputNamesTheFileAndThePlace) {
  expect_error("syntax_error.json", "line 3, column 9", "syntax error");  // where the parser stopped
  expect_error("unknown_query.json", "/query", "unknown query kind \"cone_cone\"");
  expect_error("missing_field.json", "/inputs", "missing field \"b\"");
  expect_error("bad_number.json", "/inputs/b/center/1", "\"1.5.2\" is not a number");
  expect_error("newer_version.json", "/version", "format version 99 is not supported");
  expect_error("no_such_file.json", "", "cannot read the file");
}

}  // namespace
}  // namespace cc::harness
