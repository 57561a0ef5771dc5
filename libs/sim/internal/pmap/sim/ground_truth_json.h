// JSON descriptions of the world and sensors for PREFIX.gt.json (format
// "pmap-gt/1", doc/ground-truth.md), plus the compact layout the file is
// written in (one record per line, so that it stays readable and diffable).
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "pmap/sim/camera_model.h"
#include "pmap/sim/frame_imaging.h"
#include "pmap/sim/voxel_world.h"
#include "pmap/sim/world.h"

namespace pmap::sim {

using OrderedJson = nlohmann::ordered_json;

/// Every surface: id, kind, corners, normal, holes, parent.
OrderedJson surfacesJson(const World& world);
/// Every poster: id, wall_id, corners, image (relative to the gt.json's
/// directory: "<images_dir_name>/poster_<id>.png"), pixels_per_m, size.
OrderedJson postersJson(const World& world, const std::string& images_dir_name);
/// Every clutter object: id, kind, shape and its parameters.
OrderedJson clutterJson(const World& world);
/// The people walking through (kind "person"): each one's cylinder and walk,
/// so that its position at any time can be computed again (people.h).
OrderedJson peopleJson(const World& world);

/// A voxel world's tree: the file read (as resolved and as written, size,
/// FNV-1a hash), its type, resolution, nodes, occupied leaves and voxels, the
/// box of the occupied voxels, and how unknown space was treated.
OrderedJson octomapJson(const VoxelWorld& voxels);

/// The effective odometry drift, for the sensors block.
struct OdometryTruth {
  double scale_error = 0.0;
  double heading_drift_rad_per_m = 0.0;
};

/// Structure laser, pose laser, odometry and cameras (intrinsics and pose).
OrderedJson sensorsJson(const World& world, const PinholeIntrinsics& intrinsics,
                        bool cameras_enabled, const OdometryTruth& odometry);

/// The effective path, noise and camera imaging options of the run (the world
/// file's values after defaults and command-line overrides).
OrderedJson configJson(const World& world);

/// One camera image: file (in the images directory), image (relative to the
/// gt.json's directory), timestamp, label, index, its exposure, blur and
/// measured sharpness.
OrderedJson imageJson(const ImageRecord& record, const std::string& images_dir_name);

/// Writes `doc` with the top-level keys one per line and, for arrays of
/// records, one record per line.
std::string formatGroundTruth(const OrderedJson& doc);

}  // namespace pmap::sim
