#include "pmap/sim/world_builder.h"

#include <cmath>

#include "corridor_layout.h"
#include "pmap/common/error.h"

namespace pmap::sim {
namespace {

void addClutter(const WorldSpec& spec, World& world) {
  for (const ClutterSpec& c : spec.clutter) {
    Clutter out;
    out.kind = c.kind;
    out.shape = c.shape;
    if (c.shape == ClutterShape::kCylinder) {
      out.cylinder = VerticalCylinder{c.centre, c.radius_m, c.z_min_m, c.z_max_m};
    } else {
      out.box =
          VerticalBox{c.centre, 0.5 * c.size_m, c.yaw_deg * M_PI / 180.0, c.z_min_m, c.z_max_m};
    }
    world.clutter.push_back(out);
  }
}

void addFreeRectangles(const WorldSpec& spec, detail::SceneAssembler& scene) {
  for (const FreeRectangleSpec& r : spec.rectangles) {
    scene.addSurface(r.kind, Rectangle3::fromCorners(r.corners[0], r.corners[1], r.corners[3]));
  }
}

void addPeople(const WorldSpec& spec, World& world) {
  for (const PersonSpec& p : spec.people) {
    world.people.emplace_back(p, spec.source_file);
  }
}

/// Surfaces keep their index as id; clutter, posters and people continue the
/// numbering.
void assignIds(World& world) {
  int next = static_cast<int>(world.surfaces.size());
  for (Clutter& c : world.clutter) {
    c.id = next++;
  }
  for (Poster& p : world.posters) {
    p.id = next++;
    p.wall_id = world.surfaces[static_cast<std::size_t>(p.wall_index)].id;
  }
  for (WalkingPerson& p : world.people) {
    p.id = next++;
  }
}

}  // namespace

World buildWorld(const WorldSpec& spec) {
  World world;
  world.name = spec.name;
  world.source_file = spec.source_file;
  world.path = spec.path;
  world.sensors = spec.sensors;
  world.noise = spec.noise;
  world.octomap = spec.octomap;
  addPeople(spec, world);
  if (spec.octomap) {
    assignIds(world);  // only people: the static geometry is the tree's, read by the simulator
    return world;
  }
  detail::SceneAssembler scene(world);
  for (const CorridorSpec& corridor : spec.corridors) {
    const detail::CorridorLayout layout =
        detail::buildCorridorShell(corridor, spec.source_file, scene);
    for (const DoorSpec& d : corridor.doors) {
      detail::addDoor(layout, d, scene);
    }
    for (const DoorwaySpec& d : corridor.doorways) {
      detail::addDoorway(layout, d, scene);
    }
    for (const PosterSpec& p : corridor.posters) {
      detail::addPoster(layout, p, scene);
    }
  }
  addFreeRectangles(spec, scene);
  addClutter(spec, world);
  assignIds(world);
  if (world.surfaces.empty() && world.clutter.empty()) {
    throw ConfigError(spec.source_file + ": the world has no corridors, rectangles or clutter");
  }
  return world;
}

}  // namespace pmap::sim
