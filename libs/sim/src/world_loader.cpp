#include "pmap/sim/world_loader.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "options_loader.h"
#include "pmap/common/error.h"
#include "strict_json.h"

namespace pmap::sim {
namespace {

using detail::closed;
using detail::JsonReader;
using detail::positive;

constexpr double kMaxCoordinate_m = 1.0e5;
constexpr double kMaxSize_m = 1000.0;

Side readSide(JsonReader& r) {
  return r.choice("side", "", {"left", "right"}, true) == "left" ? Side::kLeft : Side::kRight;
}

int readLeg(JsonReader& r, std::size_t leg_count) {
  return r.integer("leg", 0, 0, static_cast<int>(leg_count) - 1);
}

DoorSpec readDoor(JsonReader r, std::size_t legs) {
  DoorSpec d;
  d.where = r.path();
  d.leg = readLeg(r, legs);
  d.side = readSide(r);
  d.centre_m = r.requiredNumber("centre_m", closed(0.0, kMaxCoordinate_m));
  d.width_m = r.number("width_m", d.width_m, positive(kMaxSize_m));
  d.height_m = r.number("height_m", d.height_m, positive(kMaxSize_m));
  d.recess_m = r.number("recess_m", d.recess_m, positive(10.0));
  r.finish();
  return d;
}

DoorwaySpec readDoorway(JsonReader r, std::size_t legs) {
  DoorwaySpec d;
  d.where = r.path();
  d.leg = readLeg(r, legs);
  d.side = readSide(r);
  d.centre_m = r.requiredNumber("centre_m", closed(0.0, kMaxCoordinate_m));
  d.width_m = r.number("width_m", d.width_m, positive(kMaxSize_m));
  d.height_m = r.number("height_m", d.height_m, positive(kMaxSize_m));
  d.wall_thickness_m = r.number("wall_thickness_m", d.wall_thickness_m, positive(10.0));
  JsonReader room = r.object("room");
  d.room.width_m = room.requiredNumber("width_m", positive(kMaxSize_m));
  d.room.depth_m = room.requiredNumber("depth_m", positive(kMaxSize_m));
  d.room.height_m = room.requiredNumber("height_m", positive(kMaxSize_m));
  d.room.offset_m = room.number("offset_m", 0.0, closed(-kMaxSize_m, kMaxSize_m));
  room.finish();
  r.finish();
  return d;
}

PosterSpec readPoster(JsonReader r, std::size_t legs) {
  PosterSpec p;
  p.where = r.path();
  p.leg = readLeg(r, legs);
  p.side = readSide(r);
  p.centre_m = r.requiredNumber("centre_m", closed(0.0, kMaxCoordinate_m));
  p.bottom_m = r.number("bottom_m", p.bottom_m, closed(0.0, kMaxSize_m));
  p.width_m = r.number("width_m", p.width_m, positive(100.0));
  p.height_m = r.number("height_m", p.height_m, positive(100.0));
  p.pixels_per_m = r.number("pixels_per_m", p.pixels_per_m, closed(20.0, 2000.0));
  r.finish();
  if (p.width_m * p.pixels_per_m > 8192.0 || p.height_m * p.pixels_per_m > 8192.0) {
    r.fail("pixels_per_m", "the poster image would exceed 8192 pixels");
  }
  return p;
}

CorridorSpec readCorridor(JsonReader r) {
  CorridorSpec c;
  c.where = r.path();
  c.name = r.string("name", "");
  c.centreline = r.points2("centreline", 2);
  c.width_m = r.number("width_m", c.width_m, positive(100.0));
  c.height_m = r.number("height_m", c.height_m, positive(100.0));
  c.closed_start = r.boolean("closed_start", c.closed_start);
  c.closed_end = r.boolean("closed_end", c.closed_end);
  const std::size_t legs = c.centreline.size() - 1;
  c.legs.assign(legs, LegSpec{});
  if (r.has("legs")) {
    std::vector<JsonReader> leg_readers = r.objects("legs");
    if (leg_readers.size() != legs) {
      r.fail("legs", "expected one entry per leg (" + std::to_string(legs) + ")");
    }
    for (std::size_t i = 0; i < legs; ++i) {
      c.legs[i].ceiling_slope_deg =
          leg_readers[i].number("ceiling_slope_deg", 0.0, closed(-45.0, 45.0));
      leg_readers[i].finish();
    }
  }
  for (JsonReader d : r.objects("doors")) {
    c.doors.push_back(readDoor(d, legs));
  }
  for (JsonReader d : r.objects("doorways")) {
    c.doorways.push_back(readDoorway(d, legs));
  }
  for (JsonReader p : r.objects("posters")) {
    c.posters.push_back(readPoster(p, legs));
  }
  r.finish();
  return c;
}

ClutterSpec readClutter(JsonReader r) {
  ClutterSpec c;
  c.where = r.path();
  c.kind = r.choice("kind", "", clutterKinds(), true);
  const std::string shape = r.choice("shape", "cylinder", {"cylinder", "box"});
  c.shape = shape == "box" ? ClutterShape::kBox : ClutterShape::kCylinder;
  c.centre = r.point2("centre");
  if (c.shape == ClutterShape::kCylinder) {
    c.radius_m = r.requiredNumber("radius_m", positive(100.0));
  } else {
    c.size_m = r.point2("size_m");
    if (!(c.size_m.minCoeff() > 0.0)) {
      r.fail("size_m", "sizes must be > 0");
    }
    c.yaw_deg = r.number("yaw_deg", 0.0, closed(-360.0, 360.0));
  }
  c.z_min_m = r.number("z_min_m", 0.0, closed(-100.0, 100.0));
  c.z_max_m = r.requiredNumber("z_max_m", closed(-100.0, 100.0));
  if (!(c.z_max_m > c.z_min_m)) {
    r.fail("z_max_m", "must be greater than z_min_m");
  }
  r.finish();
  return c;
}

FreeRectangleSpec readRectangle(JsonReader r) {
  FreeRectangleSpec s;
  s.where = r.path();
  s.kind = r.choice("kind", "wall", freeRectangleKinds());
  const std::vector<Eigen::Vector3d> c = r.points3("corners", 4);
  r.finish();
  const Eigen::Vector3d u = c[1] - c[0];
  const Eigen::Vector3d v = c[3] - c[0];
  const double scale = std::max(u.norm(), v.norm());
  if (u.norm() < 1e-3 || v.norm() < 1e-3) {
    r.fail("corners", "edges must be at least 1 mm long");
  }
  if (std::abs(u.normalized().dot(v.normalized())) > 1e-6) {
    r.fail("corners", "edges c0-c1 and c0-c3 are not perpendicular");
  }
  if ((c[2] - (c[1] + v)).norm() > 1e-6 * std::max(1.0, scale)) {
    r.fail("corners", "corner 2 does not complete a rectangle (expected c1 + c3 - c0)");
  }
  for (int i = 0; i < 4; ++i) {
    s.corners[static_cast<std::size_t>(i)] = c[static_cast<std::size_t>(i)];
  }
  return s;
}

PersonSpec readPerson(JsonReader r) {
  PersonSpec p;
  p.where = r.path();
  p.waypoints = r.points2("waypoints", 2);
  p.speed_m_s = r.number("speed_m_s", p.speed_m_s, positive(10.0));
  p.radius_m = r.number("radius_m", p.radius_m, positive(2.0));
  p.height_m = r.number("height_m", p.height_m, positive(3.0));
  p.start_s = r.number("start_s", p.start_s, closed(0.0, 1.0e6));
  p.corner_radius_m = r.number("corner_radius_m", p.corner_radius_m, closed(0.0, 100.0));
  r.finish();
  return p;
}

/// The "octomap" block of a voxel world; a relative file is taken from the
/// world file's directory.
OctomapSpec readOctomap(JsonReader r, const std::string& world_file) {
  OctomapSpec o;
  o.where = r.path();
  o.file_as_written = r.string("file", "");
  if (o.file_as_written.empty()) {
    r.failMissing("file");
  }
  std::filesystem::path file(o.file_as_written);
  if (file.is_relative()) {
    file = std::filesystem::path(world_file).parent_path() / file;
  }
  o.file = file.lexically_normal();
  constexpr int kMaxLimit = 1000000000;
  o.max_tree_nodes = static_cast<std::uint64_t>(
      r.integer("max_tree_nodes", static_cast<int>(o.max_tree_nodes), 1, kMaxLimit));
  o.max_occupied_voxels = static_cast<std::uint64_t>(
      r.integer("max_occupied_voxels", static_cast<int>(o.max_occupied_voxels), 1, kMaxLimit));
  r.finish();
  return o;
}

/// A voxel world has no textures to render: a "cameras" block other than
/// {"enabled": false} is refused, and the cameras are off.
void disableCamerasOfVoxelWorld(const nlohmann::json& root, const std::string& file,
                                SensorOptions& sensors) {
  const auto s = root.find("sensors");
  if (s != root.end() && s->is_object() && s->contains("cameras")) {
    const nlohmann::json& c = s->at("cameras");
    const bool off =
        c.is_object() && c.size() == 1 && c.contains("enabled") && c["enabled"] == false;
    if (!off) {
      throw ConfigError(file +
                        ": sensors.cameras: cameras are not supported in octomap worlds (voxels "
                        "have no texture to render): remove the block or set \"enabled\": false");
    }
  }
  sensors.cameras.enabled = false;
}

}  // namespace

WorldSpec parseWorldText(const std::string& text, const std::string& file_name) {
  const nlohmann::json root = detail::parseStrictJson(text, file_name);
  JsonReader r(root, file_name, "");
  for (const char* key : {"name", "description", "corridors", "clutter", "rectangles", "people",
                          "octomap", "path", "sensors", "noise"}) {
    r.has(key);  // register every top-level key first: typos are reported as such
  }
  r.finish();
  WorldSpec w;
  w.source_file = file_name;
  w.name = r.string("name", "");
  if (w.name.empty()) {
    r.failMissing("name");
  }
  w.description = r.string("description", "");
  if (r.has("octomap")) {
    for (const char* geometry : {"corridors", "clutter", "rectangles"}) {
      if (r.has(geometry)) {
        r.fail(geometry,
               "an octomap world takes its geometry from the tree: remove corridors, clutter "
               "and rectangles (or the octomap block)");
      }
    }
    w.octomap = readOctomap(r.object("octomap"), file_name);
  }
  for (JsonReader c : r.objects("corridors")) {
    w.corridors.push_back(readCorridor(c));
  }
  for (JsonReader c : r.objects("clutter")) {
    w.clutter.push_back(readClutter(c));
  }
  for (JsonReader c : r.objects("rectangles")) {
    w.rectangles.push_back(readRectangle(c));
  }
  for (JsonReader p : r.objects("people")) {
    w.people.push_back(readPerson(p));
  }
  if (!r.has("path")) {
    r.failMissing("path");
  }
  w.path = detail::readPath(r.object("path"));
  w.sensors = detail::readSensors(r.object("sensors"));
  w.noise = detail::readNoise(r.object("noise"));
  r.finish();
  if (w.octomap) {
    disableCamerasOfVoxelWorld(root, file_name, w.sensors);
  }
  return w;
}

WorldSpec loadWorldFile(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    throw ConfigError(path.string() + ": world file not found (or not a regular file)");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw ConfigError(path.string() + ": cannot open world file");
  }
  std::ostringstream text;
  text << in.rdbuf();
  if (!in.good() && !in.eof()) {
    throw ConfigError(path.string() + ": cannot read world file");
  }
  return parseWorldText(text.str(), path.string());
}

}  // namespace pmap::sim
