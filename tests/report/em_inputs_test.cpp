#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "pmap/common/error.h"
#include "pmap/report/em_charts.h"

namespace pmap::report {
namespace {
namespace fs = std::filesystem;

fs::path writeFile(const std::string& name, const std::string& text) {
  const fs::path dir = fs::path(PMAP_TEST_TMP_DIR) / "report_em_inputs";
  fs::create_directories(dir);
  std::ofstream(dir / name) << text;
  return dir / name;
}

TEST(EmInputs, HistoryFromSummary) {
  const auto summary = nlohmann::json::parse(R"({"history": [
      {"iteration": 1, "surfaces": 12, "explained_fraction": 0.5, "log_posterior": -10.5},
      {"iteration": 2, "surfaces": 10, "explained_fraction": 0.75}]})");
  const auto rows = historyFromSummary(summary);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[1].iteration, 2);
  EXPECT_DOUBLE_EQ(rows[0].surfaces, 12.0);
  EXPECT_DOUBLE_EQ(rows[1].explained_fraction, 0.75);
  EXPECT_DOUBLE_EQ(rows[0].log_posterior, -10.5);
}

TEST(EmInputs, AbsentHistoryIsEmptyAndBadHistoryNamesTheEntry) {
  EXPECT_TRUE(historyFromSummary(nlohmann::json::object()).empty());
  EXPECT_TRUE(historyFromSummary(nlohmann::json::parse(R"({"history": []})")).empty());
  const auto bad = nlohmann::json::parse(R"({"history": [{"iteration": 1, "surfaces": "x"}]})");
  try {
    historyFromSummary(bad);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("history[0]"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("surfaces"), std::string::npos);
  }
  EXPECT_THROW(historyFromSummary(nlohmann::json::parse(R"({"history": 3})")), InputError);
}

TEST(EmInputs, ReadsOnlineCsvByColumnName) {
  const fs::path csv = writeFile(
      "online.csv",
      "scan,em_ms,surfaces,points,new_points,revisited,reassigned,active,added,removed,fused,"
      "split\n3,1.25,4,100,100,0,0,4,4,0,0,0\n5,2.5,6,200,100,0,0,6,2,0,0,0\n");
  const auto rows = readOnlineCsv(csv);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].scan, 3);
  EXPECT_DOUBLE_EQ(rows[1].em_ms, 2.5);
  EXPECT_EQ(rows[1].surfaces, 6);
}

TEST(EmInputs, OnlineCsvErrorsNameFileAndLine) {
  EXPECT_THROW(readOnlineCsv(writeFile("no_column.csv", "scan,surfaces\n1,2\n")), InputError);
  try {
    readOnlineCsv(writeFile("bad_row.csv", "scan,em_ms,surfaces\n1,2,3\n2,abc,3\n"));
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bad_row.csv: line 3"), std::string::npos);
  }
  EXPECT_THROW(readOnlineCsv(writeFile("empty.csv", "")), InputError);
  EXPECT_THROW(readOnlineCsv("/nonexistent/online.csv"), InputError);
}

}  // namespace
}  // namespace pmap::report
