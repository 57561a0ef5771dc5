// Small, strict text helpers shared by the loaders (config, poses, PLY, CLI).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace pmap {

/// Removes leading and trailing spaces, tabs, CR and LF.
std::string trim(std::string_view s);

/// Lower-case ASCII copy.
std::string toLower(std::string_view s);

/// Splits on any character of `separators`, dropping empty fields.
std::vector<std::string> splitFields(std::string_view s, std::string_view separators = " \t");

/// Strict parsers: the whole (trimmed) string must be the number, finite,
/// in range for the type. "1.5m", "abc", "", "nan", "inf" and overflow fail.
std::optional<double> parseDouble(std::string_view s);
std::optional<std::int64_t> parseInt(std::string_view s);
/// true/false, yes/no, on/off, 1/0 (case-insensitive).
std::optional<bool> parseBool(std::string_view s);

/// Levenshtein edit distance (case-insensitive).
std::size_t editDistance(std::string_view a, std::string_view b);

/// The candidate closest to `word` by edit distance if it is close enough to
/// be a plausible typo (distance <= max(2, |word|/3)); empty otherwise.
std::string nearestWord(std::string_view word, const std::vector<std::string>& candidates);

/// One line from an exception text: MRPT's multi-line exceptions
/// ("==== MRPT exception ====\nMessage: ...\nLocation: ...") give their
/// Message; others their first non-empty line. At most 240 characters.
std::string oneLineError(std::string_view what);

/// Lines joined with '\n' (several errors in one exception, one a line:
/// the apps print each as its own "<app>: error: ..." line).
std::string joinLines(const std::vector<std::string>& lines);

/// The non-empty lines of `text`.
std::vector<std::string> splitLines(std::string_view text);

/// `text` made safe inside an HTML element's content or attribute (& < > " ').
std::string escapeHtml(std::string_view text);

}  // namespace pmap
