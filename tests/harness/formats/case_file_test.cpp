#include "harness/formats/case_file.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <cstring>
#include <fstream>

#include "harness/formats/distinct_inputs.h"

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

// An answer with parameters, pairs and frames whose values all differ, and pairs (i, j) with
// i != j, so that a swap shows.
Answer distinct_answer(test::DistinctValues& values) {
  Answer a;
  a.hit = values.below(2) == 0;
  for (std::uint64_t i = values.below(4); i > 0; --i) a.params.push_back(values.next());
  const auto pairs = [&] {
    std::vector<FacePair> out;
    for (std::uint64_t i = values.below(4); i > 0; --i) {
      const auto first = static_cast<std::uint32_t>(values.below(1000));
      out.emplace_back(first, first + 1 + static_cast<std::uint32_t>(values.below(1000)));
    }
    return out;
  };
  a.pairs = pairs();
  for (std::uint64_t f = values.below(4); f > 0; --f) a.frames.push_back(pairs());
  return a;
}

std::vector<std::uint64_t> bits_of(const std::vector<double>& xs) {
  std::vector<std::uint64_t> out;
  for (double x : xs) {
    std::uint64_t b = 0;
    std::memcpy(&b, &x, sizeof b);
    out.push_back(b);
  }
  return out;
}

void expect_same(const Answer& a, const Answer& b, const std::string& what) {
  EXPECT_EQ(a.hit, b.hit) << what;
  EXPECT_EQ(bits_of(a.params), bits_of(b.params)) << what;
  EXPECT_EQ(a.pairs, b.pairs) << what;
  EXPECT_EQ(a.frames, b.frames) << what;
}

// Every field of a case whose values all differ comes back from the file's text in its place:
// the inputs of every kind (every double bit for bit, the shape and the options), every party's
// answer, the exact verdict, the class, the margin, the provenance and the note.
TEST(CaseFile, EveryFieldOfEveryKindRoundTripsThroughTheText) {
  const std::string names[] = {"library.test_ray_aabbs", "libccd.GJK", "fcl.OBBd::overlap"};
  for (QueryKind kind : kAllQueryKinds) {
    for (std::uint64_t seed = 0; seed < 25; ++seed) {
      test::DistinctValues values(seed * 31 + static_cast<std::uint64_t>(kind));
      Case c;
      c.input = test::distinct_input(kind, values, test::Reach::case_file);
      c.library = distinct_answer(values);
      c.exact.answer = distinct_answer(values);
      c.exact.contract = static_cast<Contract>(values.below(3));
      c.exact.decided = values.below(2) == 0;
      c.exact.margin = values.next();
      c.exact.note = values.below(2) ? "" : "note " + std::to_string(values.below(100));
      for (const std::string& party : names) {
        Opinion o{party, static_cast<Opinion::Status>(values.below(3)), {}, ""};
        if (o.status == Opinion::Status::answered) o.answer = distinct_answer(values);
        if (values.below(2)) o.detail = "detail " + std::to_string(values.below(100));
        c.opinions.push_back(o);
      }
      c.cls = kAllClasses[values.below(std::size(kAllClasses))];
      c.provenance = {values.below(2) ? "campaign" : "fuzz", values.below(1u << 20), values.below(1u << 20),
                      "detail " + std::to_string(values.below(100))};
      c.note = "note " + std::to_string(values.below(100));
      const std::string what = std::string(name(kind)) + " seed " + std::to_string(seed);

      const Case back = case_from_json(Json::parse(case_to_json(c).dump(2)));
      Input in = c.input, in_back = back.input;
      EXPECT_EQ(test::value_bits(in_back), test::value_bits(in)) << what << ": " << input_to_json(c.input).dump();
      EXPECT_TRUE(in_back == in) << what << ": the shape or an option changed";
      expect_same(back.library, c.library, what + " library");
      if (c.exact.decided) expect_same(back.exact.answer, c.exact.answer, what + " exact");  // else none is stored
      EXPECT_EQ(back.exact.contract, c.exact.contract) << what;
      EXPECT_EQ(back.exact.decided, c.exact.decided) << what;
      EXPECT_EQ(bits_of({back.exact.margin}), bits_of({c.exact.margin})) << what;
      EXPECT_EQ(back.exact.note, c.exact.note) << what;
      ASSERT_EQ(back.opinions.size(), c.opinions.size()) << what;
      for (std::size_t i = 0; i < c.opinions.size(); ++i) {
        EXPECT_EQ(back.opinions[i].party, c.opinions[i].party) << what;
        EXPECT_EQ(back.opinions[i].status, c.opinions[i].status) << what;
        EXPECT_EQ(back.opinions[i].detail, c.opinions[i].detail) << what;
        expect_same(back.opinions[i].answer, c.opinions[i].answer, what + " " + c.opinions[i].party);
      }
      EXPECT_EQ(back.cls, c.cls) << what;
      EXPECT_EQ(back.provenance.source, c.provenance.source) << what;
      EXPECT_EQ(back.provenance.seed, c.provenance.seed) << what;
      EXPECT_EQ(back.provenance.case_index, c.provenance.case_index) << what;
      EXPECT_EQ(back.provenance.detail, c.provenance.detail) << what;
      EXPECT_EQ(back.note, c.note) << what;
    }
  }
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

// Only answers some party gave: a library that crashed has "failed" instead of an answer, an
// exact verdict nobody computed has no "hit", and a case stored unshrunk says why; all read back.
TEST(CaseFile, MarksWhatNobodyComputed) {
  Case c = sample();
  c.library_failure = "killed by signal 11 (Segmentation fault) in the library";
  c.exact = {};
  c.exact.decided = false;
  c.exact.margin = NAN;
  c.exact.note = "not computed: the library crashed";
  c.opinions.clear();
  c.not_shrunk = "interrupted";
  const Json j = case_to_json(c);
  EXPECT_FALSE(j["answers"]["library"].contains("hit")) << j.dump();
  EXPECT_EQ(j["answers"]["library"]["failed"], c.library_failure);
  EXPECT_FALSE(j["answers"]["exact"].contains("hit")) << j.dump();
  EXPECT_EQ(j["answers"]["exact"]["decided"], false);
  EXPECT_EQ(j["provenance"]["not_shrunk"], "interrupted");
  const Case back = case_from_json(Json::parse(j.dump()));
  EXPECT_EQ(back.library_failure, c.library_failure);
  EXPECT_FALSE(back.exact.decided);
  EXPECT_EQ(back.exact.note, c.exact.note);
  EXPECT_EQ(back.not_shrunk, "interrupted");
  EXPECT_EQ(case_to_json(back).dump(), j.dump());
}

// Version 1 wrote "hit": false, "decided": true for an unspecified verdict nobody gave: read as
// no verdict. Its other fields read as before.
TEST(CaseFile, ReadsVersionOne) {
  Json j = case_to_json(sample());
  j["version"] = 1;
  const Case v1 = case_from_json(j);
  EXPECT_TRUE(v1.exact.decided);
  EXPECT_TRUE(v1.exact.answer.hit);
  j["answers"]["exact"]["contract"] = "unspecified";
  j["answers"]["exact"]["hit"] = false;
  j["answers"]["exact"]["decided"] = true;
  EXPECT_FALSE(case_from_json(j).exact.decided);
  j["answers"]["library"] = {{"failed", "x"}};  // version 2's mark is no answer in version 1
  EXPECT_THROW(case_from_json(j), FormatError);
}

// Another case under the same name (a hash collision) keeps its file; the new one takes the
// next free name. The same case again writes nothing. No temporary file is left.
TEST(CaseFile, TakesTheNextFreeNameForAnotherCase) {
  const auto dir = std::filesystem::temp_directory_path() / ("crosscheck_case_names_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  const auto path = dir / "x" / "0000000000000001.json";
  Case other = sample();
  std::get<RayAabbInput>(other.input).ray.tmax = 5;
  EXPECT_EQ(write_new_case_file(path, sample()), path);
  EXPECT_EQ(write_new_case_file(path, other), dir / "x" / "0000000000000001-2.json");
  EXPECT_EQ(write_new_case_file(path, other), std::nullopt);
  EXPECT_EQ(write_new_case_file(path, sample()), std::nullopt);
  EXPECT_EQ(read_case_file(path).note, sample().note);
  std::size_t entries = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir / "x")) ++entries;
  EXPECT_EQ(entries, 2u);
  EXPECT_THROW(write_new_case_file("/proc/crosscheck/x.json", sample()), CaseFileError);
  std::filesystem::remove_all(dir);
}

// Writers racing for one name (processes, as two campaigns are): exactly one creates it, the
// others are told the case is there; nothing is replaced or left half written.
TEST(CaseFile, ConcurrentWritersCreateEachFileOnce) {
  const auto dir = std::filesystem::temp_directory_path() / ("crosscheck_case_race_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  const auto path = dir / case_file_name(sample().input);
  std::vector<pid_t> writers;
  for (int i = 0; i < 8; ++i) {
    const pid_t pid = ::fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) std::_Exit(write_new_case_file(path, sample()) ? 10 : 11);
    writers.push_back(pid);
  }
  int created = 0, found = 0;
  for (const pid_t pid : writers) {
    int status = 0;
    ::waitpid(pid, &status, 0);
    created += WEXITSTATUS(status) == 10;
    found += WEXITSTATUS(status) == 11;
  }
  EXPECT_EQ(created, 1);
  EXPECT_EQ(found, 7);
  EXPECT_EQ(case_files_under({dir}).size(), 1u);
  std::size_t entries = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) ++entries;
  EXPECT_EQ(entries, 1u) << "a temporary file was left";
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
  expect_error("unknown_field.json", "/verdict", "unknown field \"verdict\"");
  expect_error("unknown_input_field.json", "/inputs/a/radus", "unknown field \"radus\" of a sphere_sphere input");
  expect_error("unknown_answer_field.json", "/answers/oracles/0/hits", "unknown field \"hits\"");
  expect_error("wrong_format.json", "/format", "expected \"crosscheck-case\", not \"fcl-case\"");
}

TEST(CaseFile, AFolderIsNotACaseFile) {
  try {
    read_case_file(kBad);
    ADD_FAILURE() << "no error for a folder";
  } catch (const CaseFileError& e) {
    EXPECT_NE(std::string(e.what()).find("a folder, not a case file"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace cc::harness
