// Issue 14: a library's include/ holds only what other libraries or the apps
// use; headers used inside the library alone live in its internal/ folder
// (libs/README.md). Reads the source tree: every public header must be
// included from outside its library, or by another public header of it.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

/// A project header as its include path names it: library and file name.
using HeaderKey = std::pair<std::string, std::string>;

std::vector<HeaderKey> projectIncludes(const fs::path& file) {
  static const std::regex kInclude(R"(#\s*include\s+"pmap/([a-z_]+)/([^"]+)\")");
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  const std::string s = text.str();
  std::vector<HeaderKey> out;
  for (std::sregex_iterator it(s.begin(), s.end(), kInclude), end; it != end; ++it) {
    out.emplace_back((*it)[1].str(), (*it)[2].str());
  }
  return out;
}

bool isSource(const fs::path& p) {
  const std::string ext = p.extension().string();
  return ext == ".h" || ext == ".cpp";
}

/// Every header in libs/<lib>/<folder>/pmap/<lib>/, with its path.
std::map<HeaderKey, fs::path> headersIn(const fs::path& libs, const std::string& folder) {
  std::map<HeaderKey, fs::path> out;
  for (const auto& lib : fs::directory_iterator(libs)) {
    const fs::path dir = lib.path() / folder / "pmap" / lib.path().filename();
    if (!fs::is_directory(dir)) {
      continue;
    }
    for (const auto& f : fs::recursive_directory_iterator(dir)) {
      if (f.is_regular_file()) {
        out[{lib.path().filename().string(), fs::relative(f.path(), dir).string()}] = f.path();
      }
    }
  }
  return out;
}

/// The public headers some other library or app includes, closed over the
/// public headers' own includes.
std::set<HeaderKey> usedFromOutside(const fs::path& root,
                                    const std::map<HeaderKey, fs::path>& public_headers) {
  std::set<HeaderKey> used;
  for (const char* top : {"libs", "apps"}) {
    for (const auto& f : fs::recursive_directory_iterator(root / top)) {
      if (!f.is_regular_file() || !isSource(f.path())) {
        continue;
      }
      const fs::path rel = fs::relative(f.path(), root);
      const std::string owner = top == std::string("libs") ? std::next(rel.begin())->string() : "";
      for (const HeaderKey& key : projectIncludes(f.path())) {
        if (key.first != owner && public_headers.count(key) != 0) {
          used.insert(key);
        }
      }
    }
  }
  for (std::vector<HeaderKey> todo(used.begin(), used.end()); !todo.empty();) {
    const HeaderKey key = todo.back();
    todo.pop_back();
    for (const HeaderKey& inc : projectIncludes(public_headers.at(key))) {
      if (public_headers.count(inc) != 0 && used.insert(inc).second) {
        todo.push_back(inc);
      }
    }
  }
  return used;
}

}  // namespace

TEST(HeaderLayout, Item14_EveryPublicHeaderIsUsedOutsideItsLibrary) {
  const fs::path root = PMAP_SOURCE_DIR;
  const auto public_headers = headersIn(root / "libs", "include");
  ASSERT_GT(public_headers.size(), 50u);
  const std::set<HeaderKey> used = usedFromOutside(root, public_headers);
  for (const auto& [key, path] : public_headers) {
    EXPECT_TRUE(used.count(key) != 0) << fs::relative(path, root).string()
                                      << " is used inside its library alone: move it to libs/"
                                      << key.first << "/internal/pmap/" << key.first << "/";
  }
}

TEST(HeaderLayout, Item14_NoInternalHeaderIsAlsoPublic) {
  const fs::path root = PMAP_SOURCE_DIR;
  const auto public_headers = headersIn(root / "libs", "include");
  const auto internal_headers = headersIn(root / "libs", "internal");
  ASSERT_GT(internal_headers.size(), 10u);
  for (const auto& [key, path] : internal_headers) {
    EXPECT_EQ(public_headers.count(key), 0u) << key.first << "/" << key.second;
  }
}
