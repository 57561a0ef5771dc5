#include "pmap/mapper/output_guard.h"

#include <unistd.h>

#include <algorithm>
#include <system_error>

#include "pmap/common/error.h"
#include "pmap/common/staged_directory.h"
#include "pmap/products/output_layout.h"

namespace pmap::mapper {
namespace fs = std::filesystem;
using products::OutputLayout;

namespace {

fs::path resolved(const fs::path& p) {
  std::error_code ec;
  fs::path r = fs::weakly_canonical(fs::absolute(p, ec), ec);
  return ec ? fs::absolute(p).lexically_normal() : r;
}

// True when planar-mapper may write, replace or remove `input` as one of its
// outputs in `out`, or as the lock file beside it.
bool isAnOutputPath(const fs::path& out, const fs::path& input) {
  if (input == StagedDirectory::siblingPath(out, "lock", 0)) {
    return true;
  }
  const fs::path rel = input.lexically_relative(out);
  if (rel.empty() || *rel.begin() == "..") {
    return false;  // not inside the output directory
  }
  return OutputLayout::names(rel.begin()->string()) || OutputLayout::names(rel.generic_string());
}

void collectForeign(const fs::path& root, const fs::path& rel, std::vector<std::string>& found) {
  std::error_code ec;
  for (const fs::directory_entry& e : fs::directory_iterator(root / rel, ec)) {
    const fs::path entry = rel / e.path().filename();
    if (!OutputLayout::names(entry.generic_string())) {
      found.push_back(entry.generic_string());
    } else if (e.is_directory(ec) && !e.is_symlink(ec)) {
      collectForeign(root, entry, found);
    }
  }
}

}  // namespace

void checkOutputsSpareInputs(const MapperArgs& args) {
  const fs::path out = resolved(args.out);
  for (const fs::path& input : {args.rawlog, args.cloud, args.poses, args.config}) {
    std::error_code ec;
    if (input.empty() || !fs::exists(input, ec)) {
      continue;  // a missing input is reported by its reader
    }
    const fs::path in = resolved(input);
    if (in == out) {
      throw OutputError(args.out.string() + ": the output directory is the input file " +
                        input.string() + "; choose another --out");
    }
    if (isAnOutputPath(out, in)) {
      throw OutputError(args.out.string() +
                        ": writing the outputs would overwrite the input file " + input.string() +
                        "; choose another --out");
    }
  }
}

std::vector<std::string> foreignEntries(const fs::path& out) {
  std::vector<std::string> found;
  collectForeign(out, {}, found);
  std::sort(found.begin(), found.end());
  return found;
}

void checkOutputFolder(const fs::path& out, const std::string& shown) {
  std::error_code ec;
  const fs::file_status status = fs::status(out, ec);
  if (!fs::exists(status)) {
    return;
  }
  if (!fs::is_directory(status)) {
    throw OutputError(shown + ": output path exists and is not a directory");
  }
  if (isMountPoint(out)) {
    throw OutputError(shown +
                      ": is a mount point; a run replaces its output folder as a whole, which "
                      "needs a folder it can rename: use a folder inside it (e.g. --out " +
                      (fs::path(shown) / "run").string() + ")");
  }
  if (::access(out.c_str(), W_OK | X_OK) != 0) {
    throw OutputError(shown + ": output directory is not writable");
  }
  if (fs::exists(out / OutputLayout::kManifest, ec)) {
    return;  // an output folder: what the layout does not name stays in place
  }
  const std::vector<std::string> foreign = foreignEntries(out);
  if (!foreign.empty()) {
    const std::string more =
        foreign.size() > 1 ? " (and " + std::to_string(foreign.size() - 1) + " more)" : "";
    throw OutputError(shown + ": holds " + foreign.front() + more +
                      ", which planar-mapper does not write, and no " + OutputLayout::kManifest +
                      ": not the output folder of a run; nothing was deleted or moved: choose an "
                      "empty or new --out");
  }
}

}  // namespace pmap::mapper
