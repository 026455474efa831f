// History records: each run a new file named by its start and run, never replacing one, written
// whole or not at all.
#include "tool/history.h"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <optional>
#include <stdexcept>
#include <string>

#include "temp_folder.h"

namespace cc::tool {
namespace {

namespace fs = std::filesystem;

std::string read_text(const fs::path& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

nlohmann::json record(int seed) {
  return {{"format", "crosscheck history"}, {"run", "campaign"}, {"started", iso_utc(1796241000)}, {"seed", seed}};
}

int files_in(const fs::path& folder) {
  int n = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(folder)) ++n;
  return n;
}

TEST(History, ARecordIsNamedByItsStartAndRun) {
  EXPECT_EQ(iso_utc(1796241000), "2026-12-02T19:50:00Z");
  test::TempFolder temp("history");
  const fs::path folder = temp.path() / "new" / "history";  // created, with its parent
  const fs::path path = add_to_history(folder, record(1));
  EXPECT_EQ(path, folder / "20261202T195000Z-campaign.json");
  EXPECT_EQ(nlohmann::json::parse(read_text(path)), record(1));
  EXPECT_EQ(files_in(folder), 1);  // no temporary file left beside it
}

TEST(History, AStartIsReadBackOnlyInTheFormItIsWritten) {
  EXPECT_EQ(from_iso_utc("2026-12-02T19:50:00Z"), std::optional<std::time_t>(1796241000));
  EXPECT_EQ(from_iso_utc(iso_utc(0)), std::optional<std::time_t>(0));
  EXPECT_EQ(from_iso_utc("2024-02-29T23:59:59Z"), std::optional<std::time_t>(1709251199));  // a leap day
  for (const char* text : {"2026-12-02 19:50:00Z", "2026-12-02T19:50:00", "2026-12-02T19:50:00Z ", "2026-02-30T00:00:00Z",
                           "2026-12-02T24:00:00Z", "2026-12-2T19:50:00Z", "", "tomorrow"}) {
    EXPECT_EQ(from_iso_utc(text), std::nullopt) << text;
  }
}

TEST(History, ANameTakenIsNeverReplaced) {
  test::TempFolder temp("history");
  const fs::path folder = temp.path();
  const fs::path first = add_to_history(folder, record(1));
  const std::string before = read_text(first);
  const fs::path second = add_to_history(folder, record(2));
  const fs::path third = add_to_history(folder, record(3));
  EXPECT_EQ(second, folder / "20261202T195000Z-campaign-2.json");
  EXPECT_EQ(third, folder / "20261202T195000Z-campaign-3.json");
  EXPECT_EQ(read_text(first), before);
  EXPECT_EQ(nlohmann::json::parse(read_text(second))["seed"], 2);
  EXPECT_EQ(files_in(folder), 3);
  // A folder already holding a name: passed over as well.
  fs::create_directory(folder / "20261202T195000Z-campaign-4.json");
  EXPECT_EQ(add_to_history(folder, record(5)), folder / "20261202T195000Z-campaign-5.json");
}

TEST(History, AFolderThatCannotHoldRecordsIsNamedInTheError) {
  test::TempFolder temp("history");
  const fs::path file = temp.path() / "a_file";
  std::ofstream(file) << "not a folder";
  try {
    add_to_history(file, record(1));
    FAIL() << "a file taken as the history folder";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
  }
  EXPECT_EQ(read_text(file), "not a folder");
}

TEST(History, ARunOrStartThatCannotNameAFileIsRefused) {
  test::TempFolder temp("history");
  nlohmann::json escapes = record(1);
  escapes["run"] = "../campaign";
  EXPECT_THROW(add_to_history(temp.path(), escapes), std::runtime_error);
  nlohmann::json slashed = record(1);
  slashed["started"] = "2026/12/02";
  EXPECT_THROW(add_to_history(temp.path(), slashed), std::runtime_error);
  EXPECT_EQ(files_in(temp.path()), 0);
}

}  // namespace
}  // namespace cc::tool
