#include "pmap/sim/ground_truth_json.h"

#include <cmath>
#include <sstream>

#include "pmap/sim/laser_sim.h"

namespace pmap::sim {
namespace {

OrderedJson point(const Eigen::Vector3d& p) {
  return OrderedJson::array({p.x(), p.y(), p.z()});
}

OrderedJson cornerList(const std::array<Eigen::Vector3d, 4>& c) {
  OrderedJson out = OrderedJson::array();
  for (const Eigen::Vector3d& p : c) {
    out.push_back(point(p));
  }
  return out;
}

OrderedJson poseJson(const Pose6D& p) {
  return OrderedJson::array({p.x, p.y, p.z, p.yaw, p.pitch, p.roll});
}

OrderedJson laserJson(const LaserOptions& laser) {
  OrderedJson j;
  j["label"] = laser.label;
  j["pose_on_robot"] = poseJson(laserMountPose(laser));
  j["beams"] = laser.beams;
  j["aperture_rad"] = degToRad(laser.aperture_deg);
  j["right_to_left"] = true;
  j["max_range_m"] = laser.max_range_m;
  j["time_offset_s"] = laser.time_offset_s;
  return j;
}

/// `v` rounded to a multiple of 1 / `per_unit` (measurements, to keep
/// gt.json short; dividing by an exact integer prints the short decimal).
double rounded(double v, double per_unit) {
  return std::round(v * per_unit) / per_unit;
}

OrderedJson cameraImagingJson(const CameraOptions& c) {
  OrderedJson j;
  j["lens"] = {{"vignetting", c.lens.vignetting}, {"distortion", c.lens.distortion}};
  j["blur"] = {{"psf_sigma_px", c.blur.psf_sigma_px},
               {"blurred_fraction", c.blur.blurred_fraction},
               {"defocus_sigma_px", c.blur.defocus_sigma_px},
               {"motion_share", c.blur.motion_share},
               {"motion_length_px", c.blur.motion_length_px}};
  j["exposure"] = {
      {"gain", c.exposure.gain}, {"offset_dn", c.exposure.offset_dn}, {"gamma", c.exposure.gamma}};
  j["noise"] = {{"read_sigma_dn", c.noise.read_sigma_dn}, {"full_well_e", c.noise.full_well_e}};
  return j;
}

}  // namespace

OrderedJson surfacesJson(const World& world) {
  OrderedJson out = OrderedJson::array();
  for (const Surface& s : world.surfaces) {
    OrderedJson j;
    j["id"] = s.id;
    j["kind"] = s.kind;
    j["corners"] = cornerList(s.rect.corners());
    j["normal"] = point(s.rect.normal());
    OrderedJson holes = OrderedJson::array();
    for (const HoleRange& h : s.rect.holes) {
      holes.push_back(cornerList(s.rect.holeCorners(h)));
    }
    j["holes"] = holes;
    j["parent"] = s.parent_id >= 0 ? OrderedJson(s.parent_id) : OrderedJson(nullptr);
    out.push_back(j);
  }
  return out;
}

OrderedJson postersJson(const World& world, const std::string& images_dir_name) {
  OrderedJson out = OrderedJson::array();
  for (const Poster& p : world.posters) {
    OrderedJson j;
    j["id"] = p.id;
    j["wall_id"] = p.wall_id;
    j["corners"] = cornerList(p.rect.corners());
    j["image"] = images_dir_name + "/poster_" + std::to_string(p.id) + ".png";
    j["pixels_per_m"] = p.pixels_per_m;
    j["width_px"] = p.width_px;
    j["height_px"] = p.height_px;
    out.push_back(j);
  }
  return out;
}

OrderedJson clutterJson(const World& world) {
  OrderedJson out = OrderedJson::array();
  for (const Clutter& c : world.clutter) {
    OrderedJson j;
    j["id"] = c.id;
    j["kind"] = c.kind;
    if (c.shape == ClutterShape::kCylinder) {
      j["shape"] = "cylinder";
      j["centre"] = {c.cylinder.centre.x(), c.cylinder.centre.y()};
      j["radius_m"] = c.cylinder.radius_m;
      j["z_min_m"] = c.cylinder.z_min_m;
      j["z_max_m"] = c.cylinder.z_max_m;
    } else {
      j["shape"] = "box";
      j["centre"] = {c.box.centre.x(), c.box.centre.y()};
      j["size_m"] = {2.0 * c.box.half_size_m.x(), 2.0 * c.box.half_size_m.y(),
                     c.box.z_max_m - c.box.z_min_m};
      j["yaw"] = c.box.yaw_rad;  // radians, like every angle in the file
      j["z_min_m"] = c.box.z_min_m;
      j["z_max_m"] = c.box.z_max_m;
    }
    out.push_back(j);
  }
  return out;
}

OrderedJson peopleJson(const World& world) {
  OrderedJson out = OrderedJson::array();
  for (const WalkingPerson& p : world.people) {
    const PersonSpec& s = p.spec();
    OrderedJson waypoints = OrderedJson::array();
    for (const Eigen::Vector2d& w : s.waypoints) {
      waypoints.push_back({w.x(), w.y()});
    }
    OrderedJson j;
    j["id"] = p.id;
    j["kind"] = "person";
    j["shape"] = "cylinder";
    j["radius_m"] = s.radius_m;
    j["z_min_m"] = 0.0;
    j["z_max_m"] = s.height_m;
    j["waypoints"] = waypoints;
    j["speed_m_s"] = s.speed_m_s;
    j["corner_radius_m"] = p.walk().cornerRadius_m();
    j["start_s"] = s.start_s;
    j["walk"] =
        "stands at the first waypoint until start_s, then walks to the last and back, "
        "again and again";
    out.push_back(j);
  }
  return out;
}

OrderedJson octomapJson(const VoxelWorld& voxels) {
  const OctreeFileInfo& info = voxels.info();
  const double res = voxels.resolution_m();
  const Eigen::Vector3d lo = voxels.minIndex().cast<double>() * res;
  const Eigen::Vector3d hi = (voxels.maxIndex().cast<double>().array() + 1.0).matrix() * res;
  OrderedJson j;
  j["file"] = info.file;
  j["file_as_written"] = info.file_as_written;
  j["bytes"] = info.bytes;
  j["fnv1a_64"] = info.fnv1a_64;
  j["tree_type"] = info.tree_type;
  j["resolution_m"] = res;
  j["tree_nodes"] = info.tree_nodes;
  j["occupied_leaves"] = info.occupied_leaves;
  j["occupied_voxels"] = voxels.occupiedVoxels();
  j["occupied_box_m"] = OrderedJson::array({point(lo), point(hi)});
  j["unknown_space"] = "free";
  j["ground_truth"] = "the tree's occupied voxels: map-eval --gt-octomap <file>";
  return j;
}

OrderedJson sensorsJson(const World& world, const PinholeIntrinsics& k, bool cameras_enabled,
                        const OdometryTruth& odometry) {
  const SensorOptions& s = world.sensors;
  OrderedJson j;
  j["cycle_hz"] = s.cycle_hz;
  j["pose_fields"] = {"x", "y", "z", "yaw", "pitch", "roll"};
  j["structure_laser"] = laserJson(s.laser_v);
  j["pose_laser"] = laserJson(s.laser_h);
  j["odometry"] = {{"label", s.odometry_label},
                   {"scale_error", odometry.scale_error},
                   {"heading_drift_rad_per_m", odometry.heading_drift_rad_per_m},
                   {"start_pose", {0.0, 0.0, 0.0}}};
  OrderedJson cams = OrderedJson::array();
  for (const CameraMount& m : s.cameras.mounts) {
    OrderedJson c;
    c["label"] = m.label;
    c["enabled"] = cameras_enabled;
    c["look"] = m.look;
    c["pose_on_robot"] = poseJson(cameraMountPose(m));
    c["frame"] = "optical: +z forward, +x right, +y down";
    c["width_px"] = k.width_px;
    c["height_px"] = k.height_px;
    c["fx"] = k.fx;
    c["fy"] = k.fy;
    c["cx"] = k.cx;
    c["cy"] = k.cy;
    c["distortion"] = k.distortion;  // k1 k2 p1 p2 k3
    c["vignetting"] = s.cameras.lens.vignetting;
    c["rate_hz"] = s.cameras.rate_hz;
    c["time_offset_s"] = s.cameras.time_offset_s;
    cams.push_back(c);
  }
  j["cameras"] = cams;
  return j;
}

OrderedJson configJson(const World& world) {
  const PathSpec& p = world.path;
  OrderedJson waypoints = OrderedJson::array();
  for (const Eigen::Vector2d& w : p.waypoints) {
    waypoints.push_back({w.x(), w.y()});
  }
  const NoiseOptions& n = world.noise;
  OrderedJson j;
  j["path"] = {{"waypoints", waypoints},
               {"speed_m_s", p.speed_m_s},
               {"corner_radius_m", p.corner_radius_m},
               {"max_yaw_rate_deg_s", p.max_yaw_rate_deg_s},
               {"robot_radius_m", p.robot_radius_m}};
  j["noise"] = {{"range_sigma_m", n.range_sigma_m},
                {"odometry_scale_error", n.odometry_scale_error},
                {"odometry_heading_drift_deg_per_m", n.odometry_heading_drift_deg_per_m},
                {"odometry_random_signs", n.odometry_random_signs},
                {"odometry_sigma_xy_m", n.odometry_sigma_xy_m},
                {"odometry_sigma_yaw_deg", n.odometry_sigma_yaw_deg}};
  j["cameras"] = cameraImagingJson(world.sensors.cameras);
  return j;
}

OrderedJson imageJson(const ImageRecord& r, const std::string& images_dir_name) {
  OrderedJson j;
  j["file"] = r.file;
  j["image"] = images_dir_name + "/" + r.file;
  j["timestamp"] = r.timestamp_s;
  j["label"] = r.label;
  j["index"] = r.index;
  j["gain"] = r.effects.exposure.gain;
  j["offset_dn"] = r.effects.exposure.offset_dn;
  j["gamma"] = r.effects.exposure.gamma;
  j["blur_sigma_px"] = r.effects.blur_sigma_px;
  j["motion_blur_px"] = r.effects.motion_blur_px;
  j["blurred"] = r.effects.blurred;
  j["sharpness"] = rounded(r.quality.sharpness, 1.0e4);
  j["laplacian_var"] = rounded(r.quality.laplacian_var, 100.0);
  j["saturated_fraction"] = rounded(r.quality.saturated_fraction, 1.0e6);
  return j;
}

std::string formatGroundTruth(const OrderedJson& doc) {
  std::ostringstream out;
  out << "{\n";
  std::size_t i = 0;
  for (auto it = doc.begin(); it != doc.end(); ++it, ++i) {
    out << "  " << OrderedJson(it.key()).dump() << ": ";
    const OrderedJson& v = it.value();
    if (v.is_array() && !v.empty() && (v.front().is_object() || v.front().is_array())) {
      out << "[\n";
      for (std::size_t k = 0; k < v.size(); ++k) {
        out << "    " << v[k].dump() << (k + 1 < v.size() ? ",\n" : "\n");
      }
      out << "  ]";
    } else if (v.is_object()) {
      std::string nested = v.dump(2);  // indent nested objects by two more spaces
      for (std::size_t pos = nested.find('\n'); pos != std::string::npos;
           pos = nested.find('\n', pos + 3)) {
        nested.insert(pos + 1, "  ");
      }
      out << nested;
    } else {
      out << v.dump();
    }
    out << (i + 1 < doc.size() ? ",\n" : "\n");
  }
  out << "}\n";
  return out.str();
}

}  // namespace pmap::sim
