// Minimal, strict PLY (Stanford polygon format) reading and writing of the
// "vertex" element: ascii, binary_little_endian and binary_big_endian, scalar
// properties of any PLY type. Other elements (faces, ...) are skipped.
// Malformed headers, counts larger than the file can hold and short files are
// InputErrors naming the file (and line or byte offset); nothing allocates
// more than the file's size implies.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace pmap {

/// Vertex properties as columns of doubles.
struct PlyVertices {
  std::vector<std::string> names;            ///< property names, in file order
  std::vector<std::vector<double>> columns;  ///< one column per property
  std::size_t size() const { return columns.empty() ? 0 : columns[0].size(); }
  /// Index of property `name`, or -1.
  int find(const std::string& name) const;
};

/// Reads the vertex element of a PLY file. Throws InputError.
PlyVertices readPlyVertices(const std::filesystem::path& path);

/// One vertex property for writing: its PLY type and values.
struct PlyColumn {
  std::string name;
  std::string type;  ///< "float", "double", "int", "uchar", ...
  const std::vector<double>* values = nullptr;
};

/// Writes a binary little-endian PLY with one vertex element (atomically,
/// throws OutputError). All columns must have the same length.
void writePlyVertices(const std::filesystem::path& path, const std::vector<PlyColumn>& columns,
                      const std::vector<std::string>& comments = {});

}  // namespace pmap
