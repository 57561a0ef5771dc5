#include "pmap/common/ply.h"

#include <cstring>
#include <fstream>
#include <map>
#include <sstream>

#include "pmap/common/atomic_file.h"
#include "pmap/common/error.h"
#include "pmap/common/text.h"

namespace pmap {
namespace fs = std::filesystem;
namespace {

enum class Format { kAscii, kBinaryLE, kBinaryBE };

struct Property {
  std::string name;
  std::string type;        // scalar type, or the item type of a list
  std::string count_type;  // non-empty for lists
};

struct Element {
  std::string name;
  std::uint64_t count = 0;
  std::vector<Property> properties;
};

struct Header {
  Format format = Format::kAscii;
  std::vector<Element> elements;
  std::uint64_t data_offset = 0;
};

int typeSize(const std::string& t) {
  static const std::map<std::string, int> sizes = {
      {"char", 1},  {"uchar", 1},   {"int8", 1},   {"uint8", 1},  {"short", 2}, {"ushort", 2},
      {"int16", 2}, {"uint16", 2},  {"int", 4},    {"uint", 4},   {"int32", 4}, {"uint32", 4},
      {"float", 4}, {"float32", 4}, {"double", 8}, {"float64", 8}};
  const auto it = sizes.find(t);
  return it == sizes.end() ? 0 : it->second;
}

[[noreturn]] void bad(const fs::path& path, const std::string& what) {
  throw InputError(path.string() + ": " + what);
}

Header parseHeader(std::istream& in, const fs::path& path) {
  Header h;
  std::string line;
  int lineno = 0;
  bool has_format = false;
  auto fail = [&](const std::string& what) {
    bad(path, "line " + std::to_string(lineno) + ": " + what);
  };
  while (std::getline(in, line)) {
    ++lineno;
    if (lineno > 1000 || line.size() > 4096) {
      fail("PLY header too long");
    }
    const auto f = splitFields(trim(line));
    if (lineno == 1) {
      if (f.size() != 1 || f[0] != "ply") {
        bad(path, "not a PLY file (missing 'ply' magic)");
      }
      continue;
    }
    if (f.empty() || f[0] == "comment" || f[0] == "obj_info") {
      continue;
    }
    if (f[0] == "format" && f.size() == 3) {
      has_format = true;
      h.format = f[1] == "ascii"                  ? Format::kAscii
                 : f[1] == "binary_little_endian" ? Format::kBinaryLE
                 : f[1] == "binary_big_endian"    ? Format::kBinaryBE
                                               : (fail("unknown format '" + f[1] + "'"), Format{});
    } else if (f[0] == "element" && f.size() == 3) {
      const auto n = parseInt(f[2]);
      if (!n || *n < 0) {
        fail("bad element count '" + f[2] + "'");
      }
      h.elements.push_back({f[1], static_cast<std::uint64_t>(*n), {}});
    } else if (f[0] == "property" && !h.elements.empty()) {
      Property p;
      if (f.size() == 3 && typeSize(f[1]) > 0) {
        p = {f[2], f[1], ""};
      } else if (f.size() == 5 && f[1] == "list" && typeSize(f[2]) > 0 && typeSize(f[3]) > 0) {
        p = {f[4], f[3], f[2]};
      } else {
        fail("bad property line '" + trim(line) + "'");
      }
      h.elements.back().properties.push_back(p);
    } else if (f[0] == "end_header") {
      if (!has_format) {
        fail("missing format line");
      }
      h.data_offset = static_cast<std::uint64_t>(in.tellg());
      return h;
    } else {
      fail("unexpected header line '" + trim(line) + "'");
    }
  }
  bad(path, "PLY header without end_header");
}

double decode(const unsigned char* b, const std::string& t, bool swap) {
  unsigned char tmp[8];
  const int n = typeSize(t);
  for (int i = 0; i < n; ++i) {
    tmp[i] = swap ? b[n - 1 - i] : b[i];
  }
  auto as = [&](auto v) {
    std::memcpy(&v, tmp, sizeof v);
    return static_cast<double>(v);
  };
  if (t == "char" || t == "int8")
    return as(std::int8_t{});
  if (t == "uchar" || t == "uint8")
    return as(std::uint8_t{});
  if (t == "short" || t == "int16")
    return as(std::int16_t{});
  if (t == "ushort" || t == "uint16")
    return as(std::uint16_t{});
  if (t == "int" || t == "int32")
    return as(std::int32_t{});
  if (t == "uint" || t == "uint32")
    return as(std::uint32_t{});
  if (t == "float" || t == "float32")
    return as(float{});
  return as(double{});
}

class DataReader {
 public:
  DataReader(std::istream& in, const Header& h, const fs::path& path)
      : in_(in), format_(h.format), path_(path) {}

  double next(const std::string& type) {
    if (format_ == Format::kAscii) {
      std::string tok;
      if (!(in_ >> tok)) {
        bad(path_, "file ends inside the vertex data");
      }
      const auto v = parseDouble(tok);
      if (!v && toLower(tok) != "nan") {
        bad(path_, "bad number '" + tok + "' in the data");
      }
      return v ? *v : std::numeric_limits<double>::quiet_NaN();
    }
    unsigned char buf[8];
    if (!in_.read(reinterpret_cast<char*>(buf), typeSize(type))) {
      bad(path_, "file ends inside the data (at byte " + std::to_string(offset()) + ")");
    }
    const bool little = format_ == Format::kBinaryLE;
    const bool host_little = [] {
      const std::uint16_t one = 1;
      unsigned char c;
      std::memcpy(&c, &one, 1);
      return c == 1;
    }();
    return decode(buf, type, little != host_little);
  }

 private:
  std::uint64_t offset() {
    in_.clear();
    return static_cast<std::uint64_t>(in_.tellg());
  }
  std::istream& in_;
  Format format_;
  const fs::path& path_;
};

void checkCount(const Element& e, Format format, std::uint64_t data_bytes, const fs::path& path) {
  // The fewest bytes a row can take: binary, the scalar sizes (a list at least
  // its count); ascii, a digit and a separator per scalar.
  std::uint64_t min_row = 0;
  for (const auto& p : e.properties) {
    const std::string& t = p.count_type.empty() ? p.type : p.count_type;
    min_row += format == Format::kAscii ? 2 : static_cast<std::uint64_t>(typeSize(t));
  }
  min_row = std::max<std::uint64_t>(min_row, 1);
  if (e.count > data_bytes / min_row + 1) {
    bad(path, "element '" + e.name + "' claims " + std::to_string(e.count) +
                  " rows, more than the file can hold");
  }
}

}  // namespace

int PlyVertices::find(const std::string& name) const {
  for (size_t i = 0; i < names.size(); ++i) {
    if (names[i] == name) {
      return static_cast<int>(i);
    }
  }
  return -1;
}

PlyVertices readPlyVertices(const fs::path& path) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) {
    bad(path, "PLY file not found or not a regular file");
  }
  const std::uint64_t file_size = fs::file_size(path, ec);
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    bad(path, "cannot open for reading");
  }
  const Header h = parseHeader(in, path);
  DataReader reader(in, h, path);
  PlyVertices out;
  bool found = false;
  for (const auto& e : h.elements) {
    checkCount(e, h.format, file_size - h.data_offset, path);
    const bool is_vertex = e.name == "vertex";
    if (is_vertex) {
      found = true;
      for (const auto& p : e.properties) {
        out.names.push_back(p.name);
        out.columns.emplace_back();
        out.columns.back().reserve(e.count);
      }
    }
    for (std::uint64_t row = 0; row < e.count; ++row) {
      for (size_t k = 0; k < e.properties.size(); ++k) {
        const auto& p = e.properties[k];
        if (!p.count_type.empty()) {
          const double n = reader.next(p.count_type);
          if (!(n >= 0 && n < 1e6)) {
            bad(path, "bad list length in element '" + e.name + "'");
          }
          for (int i = 0; i < static_cast<int>(n); ++i) {
            reader.next(p.type);
          }
          continue;
        }
        const double v = reader.next(p.type);
        if (is_vertex) {
          out.columns[k].push_back(v);
        }
      }
    }
    if (is_vertex) {
      break;
    }
  }
  if (!found) {
    bad(path, "no 'vertex' element");
  }
  return out;
}

void writePlyVertices(const fs::path& path, const std::vector<PlyColumn>& columns,
                      const std::vector<std::string>& comments) {
  const size_t n = columns.empty() ? 0 : columns[0].values->size();
  for (const auto& c : columns) {
    if (c.values->size() != n || typeSize(c.type) == 0) {
      throw OutputError(path.string() + ": inconsistent PLY column '" + c.name + "'");
    }
  }
  writeFileAtomically(
      path,
      [&](std::ostream& out) {
        out << "ply\nformat binary_little_endian 1.0\n";
        for (const auto& c : comments) {
          out << "comment " << c << "\n";
        }
        out << "element vertex " << n << "\n";
        for (const auto& c : columns) {
          out << "property " << c.type << " " << c.name << "\n";
        }
        out << "end_header\n";
        std::vector<char> row;
        for (size_t i = 0; i < n; ++i) {
          row.clear();
          for (const auto& c : columns) {
            const double v = (*c.values)[i];
            auto put = [&](auto x) {
              const char* b = reinterpret_cast<const char*>(&x);
              row.insert(row.end(), b, b + sizeof x);
            };
            const int size = typeSize(c.type);
            if (c.type == "float" || c.type == "float32")
              put(static_cast<float>(v));
            else if (c.type == "double" || c.type == "float64")
              put(v);
            else if (size == 4)
              put(static_cast<std::int32_t>(v));
            else if (size == 2)
              put(static_cast<std::int16_t>(v));
            else
              put(static_cast<std::int8_t>(v));
          }
          out.write(row.data(), static_cast<std::streamsize>(row.size()));
        }
      },
      true);
}

}  // namespace pmap
