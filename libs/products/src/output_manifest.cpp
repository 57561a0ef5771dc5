#include "pmap/products/output_manifest.h"

#include <algorithm>
#include <ctime>
#include <fstream>
#include <set>

#include "pmap/common/atomic_file.h"
#include "pmap/common/error.h"
#include "pmap/common/sha256.h"
#include "pmap/products/output_layout.h"

namespace pmap::products {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

bool isHexDigest(const std::string& s) {
  return s.size() == 64 && std::all_of(s.begin(), s.end(), [](char c) {
           return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f');
         });
}

/// A relative path that stays inside the folder ("a/b.png"; no "..", no
/// leading '/', no empty or "." parts).
bool staysInside(const std::string& path) {
  if (path.empty() || path.front() == '/' || path.find('\\') != std::string::npos) {
    return false;
  }
  std::size_t start = 0;
  while (start <= path.size()) {
    const std::size_t end = std::min(path.find('/', start), path.size());
    const std::string part = path.substr(start, end - start);
    if (part.empty() || part == "." || part == "..") {
      return false;
    }
    start = end + 1;
  }
  return true;
}

ManifestFile fileEntry(const json& e, std::size_t index, const fs::path& file) {
  const auto fail = [&](const std::string& what) {
    throw InputError(file.string() + ": files[" + std::to_string(index) + "]: " + what);
  };
  if (!e.is_object() || !e.contains("path") || !e["path"].is_string()) {
    fail("needs a string 'path'");
  }
  ManifestFile f;
  f.path = e["path"].get<std::string>();
  if (!staysInside(f.path)) {
    fail("path '" + f.path + "' is not a relative path inside the folder");
  }
  if (!e.contains("bytes") || !e["bytes"].is_number_unsigned()) {
    fail(f.path + ": 'bytes' is missing or not a non-negative integer");
  }
  f.bytes = e["bytes"].get<std::uint64_t>();
  if (!e.contains("sha256") || !e["sha256"].is_string() ||
      !isHexDigest(e["sha256"].get<std::string>())) {
    fail(f.path + ": 'sha256' is missing or not 64 lowercase hex digits");
  }
  f.sha256 = e["sha256"].get<std::string>();
  return f;
}

std::string stringOr(const json& doc, const char* key) {
  const auto it = doc.find(key);
  return it != doc.end() && it->is_string() ? it->get<std::string>() : std::string();
}

}  // namespace

const ManifestFile* OutputManifest::find(const std::string& path) const {
  const auto it =
      std::lower_bound(files.begin(), files.end(), path,
                       [](const ManifestFile& f, const std::string& p) { return f.path < p; });
  return it != files.end() && it->path == path ? &*it : nullptr;
}

nlohmann::ordered_json OutputManifest::toJson() const {
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const ManifestFile& f : files) {
    list.push_back({{"path", f.path}, {"bytes", f.bytes}, {"sha256", f.sha256}});
  }
  return {{"format", kFormat},
          {"version", kVersion},
          {"program", program},
          {"command", command},
          {"config_sha256", config_sha256},
          {"written_utc", written_utc},
          {"files", list}};
}

std::vector<ManifestFile> listFiles(const fs::path& dir) {
  std::vector<ManifestFile> files;
  std::error_code ec;
  for (fs::recursive_directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    if (!it->is_regular_file(ec) || it->is_symlink(ec)) {
      continue;
    }
    const std::string rel = it->path().lexically_relative(dir).generic_string();
    if (rel == OutputLayout::kManifest) {
      continue;
    }
    try {
      files.push_back(
          {rel, static_cast<std::uint64_t>(fs::file_size(it->path())), fileSha256(it->path())});
    } catch (const std::exception& e) {
      throw OutputError(std::string("manifest: ") + e.what());
    }
  }
  if (ec) {
    throw OutputError(dir.string() + ": cannot list the outputs for the manifest: " + ec.message());
  }
  std::sort(files.begin(), files.end(),
            [](const ManifestFile& a, const ManifestFile& b) { return a.path < b.path; });
  return files;
}

void writeManifest(const fs::path& dir, OutputManifest manifest) {
  manifest.files = listFiles(dir);
  writeTextFileAtomically(dir / OutputLayout::kManifest, manifest.toJson().dump(2) + "\n");
}

OutputManifest readManifest(const fs::path& file) {
  std::ifstream in(file);
  if (!in) {
    throw InputError(file.string() + ": cannot open");
  }
  json doc;
  try {
    doc = json::parse(in);
  } catch (const json::exception& e) {
    throw InputError(file.string() + ": not valid JSON: " + e.what());
  }
  if (!doc.is_object() || stringOr(doc, "format") != OutputManifest::kFormat) {
    throw InputError(file.string() + ": not a planar-mapper manifest (\"format\" is not \"" +
                     OutputManifest::kFormat + "\")");
  }
  if (!doc.contains("version") || !doc["version"].is_number_integer() ||
      doc["version"].get<int>() != OutputManifest::kVersion) {
    throw InputError(file.string() + ": manifest version " + doc.value("version", json()).dump() +
                     " is not " + std::to_string(OutputManifest::kVersion) +
                     " (written by another planar-mapper version?)");
  }
  if (!doc.contains("files") || !doc["files"].is_array()) {
    throw InputError(file.string() + ": 'files' is missing or not an array");
  }
  OutputManifest m;
  m.program = stringOr(doc, "program");
  m.config_sha256 = stringOr(doc, "config_sha256");
  m.written_utc = stringOr(doc, "written_utc");
  for (const json& arg : doc.value("command", json::array())) {
    m.command.push_back(arg.is_string() ? arg.get<std::string>() : arg.dump());
  }
  std::set<std::string> seen;
  for (std::size_t i = 0; i < doc["files"].size(); ++i) {
    ManifestFile f = fileEntry(doc["files"][i], i, file);
    if (!seen.insert(f.path).second) {
      throw InputError(file.string() + ": files[" + std::to_string(i) + "]: " + f.path +
                       " is listed twice");
    }
    m.files.push_back(std::move(f));
  }
  std::sort(m.files.begin(), m.files.end(),
            [](const ManifestFile& a, const ManifestFile& b) { return a.path < b.path; });
  return m;
}

std::string utcNow() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  ::gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

}  // namespace pmap::products
