// Helpers shared by the simulator tests: a tiny world, temporary directories
// and reading rawlogs back with MRPT alone.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <string>
#include <vector>

#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt/serialization/CSerializable.h>

namespace pmap::sim::test {

inline std::filesystem::path freshDir(const std::string& name) {
  // Per process: CTest runs the test cases of one binary in parallel.
  const std::filesystem::path dir =
      std::filesystem::path(PMAP_TEST_TMP_DIR) / "sim" / name / std::to_string(::getpid());
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

inline std::string readBytes(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

inline std::filesystem::path writeText(const std::filesystem::path& p, const std::string& text) {
  std::ofstream(p, std::ios::binary) << text;
  return p;
}

/// A file as snapshot() records it: its size and a hash of its bytes
/// (readable when a test prints a difference).
inline std::string fileEntry(const std::string& bytes) {
  return std::to_string(bytes.size()) + " bytes, hash " +
         std::to_string(std::hash<std::string>{}(bytes));
}

/// Every file and directory under `dir`: relative path -> "<dir>" or
/// fileEntry(its bytes). Equal snapshots are identical trees.
inline std::map<std::string, std::string> snapshot(const std::filesystem::path& dir) {
  std::map<std::string, std::string> out;
  for (const auto& e : std::filesystem::recursive_directory_iterator(dir)) {
    out[std::filesystem::relative(e.path(), dir).string()] =
        e.is_directory() ? "<dir>" : fileEntry(readBytes(e.path()));
  }
  return out;
}

/// Every object of a rawlog, read one by one until EOF (as RawLogViewer does).
inline std::vector<mrpt::serialization::CSerializable::Ptr> readRawlog(
    const std::filesystem::path& path) {
  std::vector<mrpt::serialization::CSerializable::Ptr> out;
  mrpt::io::CFileGZInputStream in(path.string());
  auto archive = mrpt::serialization::archiveFrom(in);
  try {
    while (true) {
      out.push_back(archive.ReadObject());
    }
  } catch (const mrpt::serialization::CExceptionEOF&) {
  }
  return out;
}

/// A 10 m straight corridor (2 m wide, 2.5 m high) with a door, a doorway to
/// a room, a poster and a bin; small camera images keep the tests quick.
inline std::string tinyWorldJson(const std::string& extra_sensors = "") {
  return R"({
  "name": "tiny",
  "corridors": [{
    "centreline": [[0, 0], [10, 0]],
    "width_m": 2.0,
    "height_m": 2.5,
    "doors": [{"leg": 0, "side": "left", "centre_m": 3.0, "width_m": 0.9, "height_m": 2.0}],
    "doorways": [{"leg": 0, "side": "right", "centre_m": 6.0, "width_m": 1.0, "height_m": 2.0,
                  "room": {"width_m": 3.0, "depth_m": 2.0, "height_m": 2.4}}],
    "posters": [{"leg": 0, "side": "left", "centre_m": 6.0, "bottom_m": 0.8, "width_m": 1.0,
                 "height_m": 0.7, "pixels_per_m": 100}]
  }],
  "clutter": [{"kind": "bin", "centre": [8.0, -0.7], "radius_m": 0.2, "z_max_m": 1.0}],
  "path": {"waypoints": [[1.0, 0.1], [9.0, 0.1]]},
  "sensors": {"cameras": {"width_px": 64, "height_px": 48})" +
         extra_sensors + R"(}
})";
}

}  // namespace pmap::sim::test
