#include "pmap/products/gltf_builder.h"

#include <algorithm>
#include <cassert>
#include <cstring>
#include <limits>
#include <stdexcept>

#include "pmap/products/glb_container.h"

namespace pmap::products {
namespace {

const char* accessorType(int components) {
  switch (components) {
    case 1:
      return "SCALAR";
    case 2:
      return "VEC2";
    case 3:
      return "VEC3";
    case 4:
      return "VEC4";
    default:
      throw std::invalid_argument("glTF accessor: 1 to 4 components");
  }
}

}  // namespace

GltfBuilder::GltfBuilder(const std::string& generator) {
  json_["asset"] = {{"version", "2.0"}, {"generator", generator}};
}

int GltfBuilder::addBufferView(const void* data, std::size_t bytes, Target target,
                               int byte_stride) {
  assert(bytes > 0);
  assert(byte_stride == 0 || (byte_stride % 4 == 0 && byte_stride >= 4 && byte_stride <= 252));
  bin_.resize((bin_.size() + 3) / 4 * 4, 0);
  const View view{bin_.size(), bytes};
  bin_.resize(bin_.size() + bytes);
  std::memcpy(bin_.data() + view.offset, data, bytes);
  views_.push_back(view);
  nlohmann::json v = {{"buffer", 0}, {"byteOffset", view.offset}, {"byteLength", bytes}};
  if (target != kNoTarget) {
    v["target"] = static_cast<int>(target);
  }
  if (byte_stride > 0) {
    v["byteStride"] = byte_stride;
  }
  return add("bufferViews", std::move(v));
}

int GltfBuilder::addFloatAccessor(int view, std::size_t byte_offset, std::size_t count,
                                  int components, bool bounds) {
  const View& v = views_.at(static_cast<std::size_t>(view));
  const std::size_t floats = count * static_cast<std::size_t>(components);
  assert(byte_offset % sizeof(float) == 0 && count > 0);
  assert(byte_offset + floats * sizeof(float) <= v.length);
  nlohmann::json a = {{"bufferView", view},
                      {"byteOffset", byte_offset},
                      {"componentType", kFloat},
                      {"count", count},
                      {"type", accessorType(components)}};
  if (bounds) {
    std::vector<float> lo(static_cast<std::size_t>(components), std::numeric_limits<float>::max());
    std::vector<float> hi(lo.size(), std::numeric_limits<float>::lowest());
    for (std::size_t i = 0; i < floats; ++i) {
      float x = 0;
      std::memcpy(&x, bin_.data() + v.offset + byte_offset + i * sizeof(float), sizeof x);
      const std::size_t c = i % lo.size();
      lo[c] = std::min(lo[c], x);
      hi[c] = std::max(hi[c], x);
    }
    a["min"] = lo;
    a["max"] = hi;
  }
  return add("accessors", std::move(a));
}

int GltfBuilder::addIndexAccessor(int view, std::size_t byte_offset, std::size_t count) {
  assert(byte_offset % sizeof(std::uint32_t) == 0 && count > 0);
  assert(byte_offset + count * sizeof(std::uint32_t) <=
         views_.at(static_cast<std::size_t>(view)).length);
  return add("accessors", {{"bufferView", view},
                           {"byteOffset", byte_offset},
                           {"componentType", kUnsignedInt},
                           {"count", count},
                           {"type", "SCALAR"}});
}

int GltfBuilder::add(const std::string& array, nlohmann::json object) {
  nlohmann::json& list = json_[array];
  list.push_back(std::move(object));
  return static_cast<int>(list.size()) - 1;
}

std::vector<std::uint8_t> GltfBuilder::glb() const {
  nlohmann::json doc = json_;
  if (!bin_.empty()) {
    doc["buffers"] = nlohmann::json::array({{{"byteLength", bin_.size()}}});
  }
  return packGlb(doc.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace), bin_);
}

}  // namespace pmap::products
