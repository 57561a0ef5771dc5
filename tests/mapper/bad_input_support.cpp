#include "bad_input_support.h"

#include <cmath>
#include <fstream>
#include <sstream>

#include "pmap/common/ply.h"

namespace pmap::testing {
namespace fs = std::filesystem;

fs::path writeFixture(const fs::path& dir, FixtureOptions o, const std::string& name) {
  const fs::path p = dir / name;
  writeFixtureRawlog(p, o);
  return p;
}

std::vector<std::string> mapArgs(const fs::path& rawlog, const fs::path& dir,
                                 const std::vector<std::string>& extra) {
  std::vector<std::string> args = {"--rawlog", rawlog.string(), "--out", (dir / "out").string(),
                                   "-q"};
  args.insert(args.end(), extra.begin(), extra.end());
  return args;
}

nlohmann::json readSummary(const fs::path& dir) {
  std::ifstream in(dir / "out" / "summary.json");
  return nlohmann::json::parse(in);
}

fs::path editedConfig(const fs::path& dir, const std::string& from, const std::string& to) {
  const fs::path src = fs::path(PMAP_SOURCE_DIR) / "config";
  bool edited = from.empty();
  for (const char* name : {"default.ini", "icp.ini"}) {  // the copy of default.ini is my.ini
    std::ifstream in(src / name);
    std::stringstream text;
    text << in.rdbuf();
    std::string ini = text.str();
    const std::size_t at = edited ? std::string::npos : ini.find(from);
    if (at != std::string::npos) {
      ini.replace(at, from.size(), to);
      edited = true;
    }
    const fs::path copy = dir / (std::string(name) == "icp.ini" ? "icp.ini" : "my.ini");
    std::ofstream(copy, std::ios::binary) << ini;
  }
  EXPECT_TRUE(edited) << "config/*.ini has no '" << from << "'";
  return dir / "my.ini";
}

nlohmann::json expectValidMap(const fs::path& dir) {
  const fs::path out = dir / "out";
  for (const char* file : {"points.ply", "summary.json", "poses.txt", "effective.ini"}) {
    EXPECT_TRUE(fs::exists(out / file)) << file;
  }
  const PlyVertices v = readPlyVertices(out / "points.ply");
  std::size_t non_finite = 0;
  for (const auto& column : v.columns) {
    for (double x : column) {
      non_finite += std::isfinite(x) ? 0 : 1;
    }
  }
  EXPECT_EQ(non_finite, 0u) << "non-finite values in points.ply";
  const nlohmann::json s = readSummary(dir);
  EXPECT_EQ(s["points"].get<std::size_t>(), v.size());
  return s;
}

}  // namespace pmap::testing
