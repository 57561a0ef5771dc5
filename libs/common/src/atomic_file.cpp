#include "pmap/common/atomic_file.h"

#include <unistd.h>

#include <system_error>

#include "pmap/common/error.h"

namespace pmap {
namespace fs = std::filesystem;

void writeFileAtomically(const fs::path& path, const std::function<void(std::ostream&)>& writer,
                         bool binary) {
  const fs::path tmp = path.string() + ".tmp-" + std::to_string(::getpid());
  {
    std::ofstream out(tmp, binary ? std::ios::binary | std::ios::trunc : std::ios::trunc);
    if (!out) {
      throw OutputError(path.string() + ": cannot open for writing");
    }
    try {
      writer(out);
    } catch (...) {
      out.close();
      std::error_code ec;
      fs::remove(tmp, ec);
      throw;
    }
    out.flush();
    if (!out) {
      out.close();
      std::error_code ec;
      fs::remove(tmp, ec);
      throw OutputError(path.string() + ": write failed (disk full or I/O error)");
    }
  }
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) {
    std::error_code ignored;
    fs::remove(tmp, ignored);
    throw OutputError(path.string() + ": cannot rename temporary file into place: " + ec.message());
  }
}

void writeTextFileAtomically(const fs::path& path, const std::string& text) {
  writeFileAtomically(path, [&](std::ostream& out) { out << text; });
}

void ensureWritableDirectory(const fs::path& dir) {
  std::error_code ec;
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec)) {
    throw OutputError(dir.string() + ": output path exists and is not a directory");
  }
  fs::create_directories(dir, ec);
  if (ec) {
    throw OutputError(dir.string() + ": cannot create output directory: " + ec.message());
  }
  if (::access(dir.c_str(), W_OK | X_OK) != 0) {
    throw OutputError(dir.string() + ": output directory is not writable");
  }
}

}  // namespace pmap
