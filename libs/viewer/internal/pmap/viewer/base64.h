// Base64 (RFC 4648, standard alphabet, '=' padding), as the browser's atob()
// decodes it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace pmap::viewer {

/// Base64 text of `size` bytes at `data` (no line breaks).
std::string encodeBase64(const std::uint8_t* data, std::size_t size);

}  // namespace pmap::viewer
