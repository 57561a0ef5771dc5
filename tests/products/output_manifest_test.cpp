#include "pmap/products/output_manifest.h"

#include <gtest/gtest.h>

#include <fstream>

#include "pmap/common/error.h"
#include "pmap/common/sha256.h"
#include "test_files.h"

namespace pmap::products {
namespace {
namespace fs = std::filesystem;
using testing::writeText;

fs::path tmpDir(const std::string& name) {
  return testing::processTestDir("output_manifest", name);
}
using nlohmann::json;

OutputManifest header() {
  OutputManifest m;
  m.program = "planar-mapper 0.1.0";
  m.command = {"planar-mapper", "--out", "o"};
  m.config_sha256 = sha256Hex("[Sensors]\n");
  m.written_utc = "2025-12-02T04:36:00Z";
  return m;
}

TEST(OutputManifest, Item14_ListsEveryFileWithSizeAndDigestAndReadsBack) {
  const fs::path dir = tmpDir("round_trip");
  writeText(dir / "poses.txt", "1 2 3\n");
  writeText(dir / "report/report.html", "<html>");
  writeText(dir / "textures/surface_1_0.png", std::string(70000, 'p'));
  writeText(dir / "manifest.json", "an older one");  // never lists itself
  fs::create_directories(dir / "snapshots");         // empty folders hold no files
  writeManifest(dir, header());
  const OutputManifest m = readManifest(dir / "manifest.json");
  ASSERT_EQ(m.files.size(), 3u);
  EXPECT_EQ(m.files[0].path, "poses.txt");
  EXPECT_EQ(m.files[1].path, "report/report.html");
  EXPECT_EQ(m.files[2].path, "textures/surface_1_0.png");
  EXPECT_EQ(m.files[2].bytes, 70000u);
  EXPECT_EQ(m.files[2].sha256, sha256Hex(std::string(70000, 'p')));
  EXPECT_EQ(m.files[0].sha256, sha256Hex("1 2 3\n"));
  EXPECT_EQ(m.command, header().command);
  EXPECT_EQ(m.config_sha256, header().config_sha256);
  EXPECT_EQ(m.program, "planar-mapper 0.1.0");
  ASSERT_NE(m.find("report/report.html"), nullptr);
  EXPECT_EQ(m.find("report.html"), nullptr);
  std::ifstream in(dir / "manifest.json");
  const json doc = json::parse(in);
  EXPECT_EQ(doc["format"], "planar-mapper-manifest");
  EXPECT_EQ(doc["version"], 1);
}

TEST(OutputManifest, Item14_MalformedManifestsAreInputErrorsNamingTheFile) {
  const fs::path dir = tmpDir("malformed");
  const std::string digest(64, 'a');
  const auto entry = [&](const json& path, const json& bytes, const json& sha) {
    return json{{"format", "planar-mapper-manifest"},
                {"version", 1},
                {"files", json::array({{{"path", path}, {"bytes", bytes}, {"sha256", sha}}})}}
        .dump();
  };
  const std::pair<std::string, std::string> cases[] = {
      {"{not json", "not valid JSON"},
      {R"({"format": "other", "version": 1, "files": []})", "not a planar-mapper manifest"},
      {R"({"format": "planar-mapper-manifest", "version": 2, "files": []})", "version 2"},
      {R"({"format": "planar-mapper-manifest", "version": 1})", "'files'"},
      {entry("../x.txt", 1, digest), "not a relative path inside the folder"},
      {entry("/etc/passwd", 1, digest), "not a relative path inside the folder"},
      {entry("a//b", 1, digest), "not a relative path inside the folder"},
      {entry("a.txt", -1, digest), "'bytes'"},
      {entry("a.txt", 1, "ABC"), "'sha256'"},
      {entry(7, 1, digest), "'path'"},
  };
  for (const auto& [text, fragment] : cases) {
    writeText(dir / "manifest.json", text);
    try {
      readManifest(dir / "manifest.json");
      ADD_FAILURE() << "accepted: " << text;
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("manifest.json"), std::string::npos) << what;
      EXPECT_NE(what.find(fragment), std::string::npos) << what;
    }
  }
  json twice = json::parse(entry("a.txt", 1, digest));
  twice["files"].push_back(twice["files"][0]);
  writeText(dir / "manifest.json", twice.dump());
  EXPECT_THROW(readManifest(dir / "manifest.json"), InputError);
}

TEST(OutputManifest, Item14_UtcTimeFormat) {
  const std::string t = utcNow();
  ASSERT_EQ(t.size(), 20u) << t;
  EXPECT_EQ(t[4], '-');
  EXPECT_EQ(t[10], 'T');
  EXPECT_EQ(t.back(), 'Z');
}

}  // namespace
}  // namespace pmap::products
