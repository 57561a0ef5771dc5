// Every bad-input case of ROBUSTNESS.md that planar-mapper meets as a whole
// program: one row per case, run in-process (as the CLI tests), with its
// exit code and a fragment of its one-line message. doc/robustness.md lists
// these rows by name next to the unit tests of the other cases.
#include <gtest/gtest.h>

#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>

#include "app_runner.h"
#include "bad_input_cases.h"
#include "corruption.h"
#include "pmap/mapper/planar_mapper_app.h"
#include "rawlog_fixtures.h"

namespace pmap::mapper {
namespace {
namespace fs = std::filesystem;

// The error lines planar-mapper printed ("planar-mapper: error: ...").
std::vector<std::string> errorLines(const std::string& stderr_text) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start < stderr_text.size()) {
    const std::size_t end = stderr_text.find('\n', start);
    const std::string line = stderr_text.substr(start, end - start);
    if (line.find("error:") != std::string::npos) {
      lines.push_back(line);
    }
    start = end == std::string::npos ? stderr_text.size() : end + 1;
  }
  return lines;
}

class BadInput : public ::testing::TestWithParam<testing::BadInputCase> {};

TEST_P(BadInput, ExitCodeAndOneLineMessage) {
  const testing::BadInputCase& c = GetParam();
  const fs::path dir = testing::freshTestDir("bad_input/" + c.name);
  const std::vector<std::string> args = c.setup(dir);
  const bool had_points = fs::exists(dir / "out" / "points.ply");  // an input there
  auto run = [&args] { return testing::runMain(&planarMapperMain, "planar-mapper", args); };

  ::testing::internal::CaptureStderr();
  const int code = c.unprivileged ? testing::runUnprivileged(run) : run();
  const std::string err = ::testing::internal::GetCapturedStderr();

  EXPECT_EQ(code, c.exit_code) << err;
  EXPECT_NE(err.find(c.message), std::string::npos) << "expected '" << c.message << "' in:\n"
                                                    << err;
  const std::vector<std::string> errors = errorLines(err);
  if (c.exit_code == 0) {
    EXPECT_TRUE(errors.empty()) << err;
  } else {
    // One line per problem: a configuration file's problems are all reported
    // in one run (issue 13, item 7), every other error is one line.
    ASSERT_GE(errors.size(), 1u) << err;
    if (c.exit_code != 1) {
      EXPECT_EQ(errors.size(), 1u) << err;
    }
    for (const std::string& line : errors) {
      EXPECT_EQ(line.rfind("planar-mapper: error: ", 0), 0u) << line;
    }
  }
  if (c.exit_code != 0 && !had_points) {  // no partial map
    EXPECT_FALSE(fs::exists(dir / "out" / "points.ply"));
  }
  if (c.check) {
    c.check(dir);
  }
}

INSTANTIATE_TEST_SUITE_P(Cases, BadInput, ::testing::ValuesIn(testing::badInputCases()),
                         [](const ::testing::TestParamInfo<testing::BadInputCase>& info) {
                           return info.param.name;
                         });

}  // namespace
}  // namespace pmap::mapper
