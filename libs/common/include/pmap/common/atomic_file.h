// Files are written under a temporary name in the target directory and renamed
// into place only once complete, so a failed run never replaces a good file.
#pragma once

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

namespace pmap {

/// Writes `path` atomically: `writer` fills a stream opened on
/// "<path>.tmp-<pid>"; on success the temporary file is renamed to `path`.
/// Throws OutputError (naming the file) if the file cannot be opened, the
/// stream fails, or the rename fails; the temporary file is removed then.
void writeFileAtomically(const std::filesystem::path& path,
                         const std::function<void(std::ostream&)>& writer, bool binary = false);

/// Convenience: atomically writes a string.
void writeTextFileAtomically(const std::filesystem::path& path, const std::string& text);

/// Creates `dir` (and parents) if needed and checks that it is a writable
/// directory; throws OutputError otherwise.
void ensureWritableDirectory(const std::filesystem::path& dir);

}  // namespace pmap
