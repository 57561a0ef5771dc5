// Expands a WorldSpec into the rectangles of a World (doc/ground-truth.md lists
// what each corridor, door, doorway and poster becomes). Geometric mistakes
// (a door outside its wall, overlapping openings, turns other than +-90
// degrees, legs shorter than the corridor is wide) are ConfigErrors naming the
// file and the JSON path of the offending element.
#pragma once

#include "pmap/sim/world.h"
#include "pmap/sim/world_spec.h"

namespace pmap::sim {

World buildWorld(const WorldSpec& spec);

}  // namespace pmap::sim
