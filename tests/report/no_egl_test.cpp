// Without a usable EGL vendor the report still gets written, with a warning
// instead of the map pictures. Its own executable: libglvnd reads the vendor
// list once per process, at the first EGL call.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "pmap/report/report.h"
#include "report_test_model.h"

namespace pmap::report {
namespace {
namespace fs = std::filesystem;

TEST(NoEgl, ReportHasAWarningInsteadOfMapPictures) {
  ::setenv("__EGL_VENDOR_LIBRARY_FILENAMES", "/nonexistent/egl_vendor.json", 1);
  const fs::path dir = fs::path(PMAP_TEST_TMP_DIR) / "report_no_egl";
  fs::remove_all(dir);
  const auto model = test::corridor();
  const nlohmann::json summary = {{"surfaces", 4}};
  const ReportResult r = writeReport(dir, {model, summary, {}});
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_NE(r.warnings[0].find("offscreen rendering unavailable"), std::string::npos);
  EXPECT_EQ(r.warnings[0].find('\n'), std::string::npos);
  EXPECT_FALSE(fs::exists(r.dir / "map_perspective.png"));
  EXPECT_FALSE(fs::exists(r.dir / "map_top.png"));
  std::ifstream in(r.dir / "report.html");
  std::stringstream html;
  html << in.rdbuf();
  EXPECT_NE(html.str().find("warning: map pictures not rendered"), std::string::npos);
}

}  // namespace
}  // namespace pmap::report
