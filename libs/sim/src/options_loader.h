// Readers of the path, sensors and noise blocks of a world file (private).
#pragma once

#include "pmap/sim/world_spec.h"
#include "strict_json.h"

namespace pmap::sim::detail {

PathSpec readPath(JsonReader reader);
SensorOptions readSensors(JsonReader reader);
NoiseOptions readNoise(JsonReader reader);

}  // namespace pmap::sim::detail
