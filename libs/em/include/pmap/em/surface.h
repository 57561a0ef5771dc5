#pragma once

#include <cstdint>

#include "pmap/em/rectangle.h"

namespace pmap::em {

/// A surface of the map: its rectangle and bookkeeping.
struct Surface {
  Rectangle rect;
  std::int32_t id = -1;      ///< stable id (output files), unique within a run
  std::int32_t support = 0;  ///< points whose most likely cause it is
  /// Trimmed once already: not trimmed again (boundary points the outlier
  /// band lets it win back would otherwise regrow and re-trim it forever).
  bool trimmed = false;
};

}  // namespace pmap::em
