#include "pmap/eval/glb_mesh.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

#include "pmap/common/error.h"
#include "pmap/eval/map_files.h"

namespace pmap::eval {
namespace {
using nlohmann::json;

constexpr std::uint32_t kMagic = 0x46546C67;      // "glTF"
constexpr std::uint32_t kChunkJson = 0x4E4F534A;  // "JSON"
constexpr std::uint32_t kChunkBin = 0x004E4942;   // "BIN\0"
constexpr int kTriangles = 4;

std::uint32_t u32(const std::vector<std::uint8_t>& b, std::size_t at) {
  std::uint32_t v = 0;
  for (int k = 3; k >= 0; --k)
    v = v << 8 | b[at + static_cast<std::size_t>(k)];
  return v;
}

class GlbFile {
 public:
  explicit GlbFile(const std::filesystem::path& path) : where_(path.string() + ": ") {
    requireRegularFile(path);
    std::ifstream in(path, std::ios::binary);
    if (!in)
      fail("cannot open");
    bytes_.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    if (bytes_.size() < 20 || u32(bytes_, 0) != kMagic || u32(bytes_, 4) != 2) {
      fail("not a glTF 2.0 binary file");
    }
    const std::size_t json_len = u32(bytes_, 12);
    if (u32(bytes_, 16) != kChunkJson || 20 + json_len > bytes_.size())
      fail("bad JSON chunk");
    try {
      doc_ = json::parse(bytes_.begin() + 20, bytes_.begin() + 20 + json_len);
    } catch (const json::exception& e) {
      fail(std::string("JSON chunk: ") + e.what());
    }
    const std::size_t bin_at = 20 + json_len;
    if (bin_at + 8 <= bytes_.size()) {
      if (u32(bytes_, bin_at + 4) != kChunkBin)
        fail("second chunk is not BIN");
      bin_start_ = bin_at + 8;
      bin_len_ = u32(bytes_, bin_at);
      if (bin_start_ + bin_len_ > bytes_.size())
        fail("BIN chunk runs past the end");
    }
  }

  [[noreturn]] void fail(const std::string& what) const { throw InputError(where_ + what); }

  /// Element k of an accessor as `components` doubles.
  struct View {
    const std::uint8_t* data = nullptr;
    std::size_t count = 0, stride = 0;
    int type = 0;
  };
  View accessor(int index, std::size_t components, std::size_t component_bytes) const {
    const json& a = doc_.at("accessors").at(index);
    const json& v = doc_.at("bufferViews").at(a.at("bufferView").get<int>());
    View out;
    out.type = a.at("componentType").get<int>();
    out.count = a.at("count").get<std::size_t>();
    const std::size_t element = components * component_bytes;
    out.stride = v.value("byteStride", element);
    const std::size_t start =
        v.value("byteOffset", std::size_t{0}) + a.value("byteOffset", std::size_t{0});
    const std::size_t end = out.count == 0 ? start : start + (out.count - 1) * out.stride + element;
    if (end > v.at("byteLength").get<std::size_t>() + v.value("byteOffset", std::size_t{0}) ||
        end > bin_len_) {
      fail("accessor " + std::to_string(index) + " runs past its buffer");
    }
    out.data = bytes_.data() + bin_start_ + start;
    return out;
  }

  std::vector<Eigen::Vector3d> positions(int index) const {
    const View v = accessor(index, 3, 4);
    if (v.type != 5126)
      fail("POSITION is not FLOAT");
    std::vector<Eigen::Vector3d> out(v.count);
    for (std::size_t k = 0; k < v.count; ++k) {
      float f[3];
      std::memcpy(f, v.data + k * v.stride, sizeof f);
      if (!std::isfinite(f[0]) || !std::isfinite(f[1]) || !std::isfinite(f[2])) {
        fail("accessor " + std::to_string(index) + ": POSITION " + std::to_string(k) +
             " is not finite");
      }
      out[k] = Eigen::Vector3d(f[0], f[1], f[2]);
    }
    return out;
  }

  std::vector<std::uint32_t> indices(int index) const {
    const int type = doc_.at("accessors").at(index).at("componentType").get<int>();
    const std::size_t bytes = type == 5125 ? 4 : type == 5123 ? 2 : type == 5121 ? 1 : 0;
    if (bytes == 0)
      fail("unsupported index type " + std::to_string(type));
    const View v = accessor(index, 1, bytes);
    std::vector<std::uint32_t> out(v.count);
    for (std::size_t k = 0; k < v.count; ++k) {
      std::uint32_t x = 0;
      std::memcpy(&x, v.data + k * v.stride, bytes);  // little-endian host
      out[k] = x;
    }
    return out;
  }

  const json& doc() const { return doc_; }

 private:
  std::string where_;
  std::vector<std::uint8_t> bytes_;
  json doc_;
  std::size_t bin_start_ = 0, bin_len_ = 0;
};

void appendPrimitive(const GlbFile& f, const json& prim, std::vector<Triangle3>& out) {
  if (prim.value("mode", kTriangles) != kTriangles)
    return;
  const std::vector<Eigen::Vector3d> pos = f.positions(prim.at("attributes").at("POSITION"));
  std::vector<std::uint32_t> idx;
  if (prim.contains("indices")) {
    idx = f.indices(prim.at("indices").get<int>());
  } else {
    for (std::uint32_t k = 0; k < pos.size(); ++k)
      idx.push_back(k);
  }
  if (idx.size() % 3 != 0)
    f.fail("index count is not a multiple of 3");
  for (std::size_t k = 0; k < idx.size(); k += 3) {
    if (idx[k] >= pos.size() || idx[k + 1] >= pos.size() || idx[k + 2] >= pos.size()) {
      f.fail("index out of range");
    }
    out.push_back({pos[idx[k]], pos[idx[k + 1]], pos[idx[k + 2]]});
  }
}

}  // namespace

std::vector<Triangle3> readGlbTriangles(const std::filesystem::path& glb) {
  const GlbFile f(glb);
  std::vector<Triangle3> out;
  try {
    for (const json& mesh : f.doc().value("meshes", json::array())) {
      for (const json& prim : mesh.at("primitives")) {
        appendPrimitive(f, prim, out);
      }
    }
  } catch (const json::exception& e) {
    f.fail(std::string("unexpected glTF structure: ") + e.what());
  }
  return out;
}

}  // namespace pmap::eval
