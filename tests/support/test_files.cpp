#include "test_files.h"

#include <unistd.h>

#include <fstream>
#include <iterator>

namespace pmap::testing {
namespace fs = std::filesystem;

fs::path processTestDir(const std::string& group, const std::string& name) {
  const fs::path dir = fs::path(PMAP_TEST_TMP_DIR) / group / name / std::to_string(::getpid());
  fs::remove_all(dir);
  fs::create_directories(dir);
  return fs::canonical(dir);
}

void writeText(const fs::path& path, const std::string& text) {
  if (path.has_parent_path()) {
    fs::create_directories(path.parent_path());
  }
  std::ofstream(path, std::ios::binary) << text;
}

std::string readText(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

std::map<std::string, std::string> snapshot(const fs::path& dir) {
  std::map<std::string, std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    out[e.path().lexically_relative(dir).generic_string()] =
        e.is_directory() ? "<dir>" : readText(e.path());
  }
  return out;
}

}  // namespace pmap::testing
