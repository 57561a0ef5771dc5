// A glTF 2.0 document under construction: its JSON and its one binary buffer
// (the GLB's BIN chunk), with the spec's alignment rules (glTF 2.0, 3.6.2.4
// "Data Alignment"): every bufferView starts at a multiple of 4 bytes and an
// accessor's offset is a multiple of its component size.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace pmap::products {

class GltfBuilder {
 public:
  /// accessor.componentType values.
  enum ComponentType : int { kUnsignedInt = 5125, kFloat = 5126 };
  /// bufferView.target values (0: none, e.g. images).
  enum Target : int { kNoTarget = 0, kArrayBuffer = 34962, kElementArrayBuffer = 34963 };

  /// asset.version "2.0" and asset.generator = `generator`.
  explicit GltfBuilder(const std::string& generator);

  /// Appends `bytes` bytes as a new bufferView (4-byte aligned, zero
  /// padding before it); returns its index. `bytes` must be > 0.
  /// `byte_stride` (0: none) is required for vertex data shared by several
  /// accessors: the element size, a multiple of 4 in [4, 252].
  int addBufferView(const void* data, std::size_t bytes, Target target, int byte_stride = 0);
  template <class T>
  int addBufferView(const std::vector<T>& values, Target target, int byte_stride = 0) {
    return addBufferView(values.data(), values.size() * sizeof(T), target, byte_stride);
  }

  /// A FLOAT accessor of `count` elements of `components` floats (SCALAR,
  /// VEC2, VEC3 or VEC4) starting `byte_offset` bytes into `view`; with
  /// `bounds`, min/max are computed from the stored values (required for
  /// POSITION). Returns its index.
  int addFloatAccessor(int view, std::size_t byte_offset, std::size_t count, int components,
                       bool bounds);
  /// An UNSIGNED_INT SCALAR accessor (indices). Returns its index.
  int addIndexAccessor(int view, std::size_t byte_offset, std::size_t count);

  /// Appends `object` to the top-level array `array` ("meshes", "nodes",
  /// ...); returns its index.
  int add(const std::string& array, nlohmann::json object);
  nlohmann::json& json() { return json_; }

  /// The document as GLB bytes (buffers[0] set when the buffer is not empty).
  std::vector<std::uint8_t> glb() const;

 private:
  struct View {
    std::size_t offset = 0;
    std::size_t length = 0;
  };
  nlohmann::json json_;
  std::vector<std::uint8_t> bin_;
  std::vector<View> views_;
};

}  // namespace pmap::products
