#include "test_files.h"

#include <unistd.h>

#include <fstream>
#include <iterator>
#include <stdexcept>

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

fs::path editedDefaultIni(const fs::path& dir, const std::string& from, const std::string& to) {
  const fs::path config = fs::path(PMAP_SOURCE_DIR) / "config";
  std::string text = readText(config / "default.ini");
  const auto at = text.find(from);
  if (at == std::string::npos) {
    throw std::runtime_error("config/default.ini holds no '" + from + "'");
  }
  text.replace(at, from.size(), to);
  writeText(dir / "my.ini", text);
  fs::copy_file(config / "icp.ini", dir / "icp.ini", fs::copy_options::overwrite_existing);
  return dir / "my.ini";
}

}  // namespace pmap::testing
