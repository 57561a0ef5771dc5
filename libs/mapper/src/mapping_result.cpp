#include "pmap/mapper/mapping_result.h"

namespace pmap::mapper {

const char* toString(MapMode mode) {
  switch (mode) {
    case MapMode::kOnline:
      return "online";
    case MapMode::kOffline:
      return "offline";
    case MapMode::kRaw:
      return "raw";
  }
  return "?";
}

const char* toString(RunKind kind) {
  switch (kind) {
    case RunKind::kOnline:
      return "online";
    case RunKind::kOffline:
      return "offline";
    case RunKind::kRaw:
      return "raw";
    case RunKind::kPosesOnly:
      return "poses-only";
  }
  return "?";
}

const char* toString(PoseSource source) {
  switch (source) {
    case PoseSource::kIcp:
      return "icp";
    case PoseSource::kFile:
      return "file";
    case PoseSource::kIdentity:
      return "identity";
    case PoseSource::kCloud:
      return "cloud";
  }
  return "?";
}

std::optional<MapMode> parseMapMode(const std::string& text) {
  for (const MapMode m : {MapMode::kOnline, MapMode::kOffline, MapMode::kRaw}) {
    if (text == toString(m)) {
      return m;
    }
  }
  return std::nullopt;
}

}  // namespace pmap::mapper
