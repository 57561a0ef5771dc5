#include "pmap/mapper/mapper_config.h"

#include <algorithm>

#include "pmap/common/error.h"
#include "pmap/common/text.h"
#include "pmap/config/section_reader.h"
#include "pmap/config/strict_mrpt_config.h"

namespace pmap::mapper {
namespace {

const std::vector<std::string>& projectSections() {
  static const std::vector<std::string> s = {"Sensors",  "Poses",   "Output",    "PlanarEM",
                                             "OnlineEM", "Texture", "Refinement"};
  return s;
}

bool ownedByMrpt(const std::string& section) {
  for (const auto& m : mrptSections()) {
    if (m.back() == '*' ? section.rfind(m.substr(0, m.size() - 1), 0) == 0 : section == m) {
      return true;
    }
  }
  return false;
}

void rejectUnknownSections(const config::IniDocument& doc, std::vector<std::string>& errors) {
  std::vector<std::string> known = projectSections();
  known.push_back("ICP");
  known.push_back("MappingApplication");
  for (const auto& s : doc.sectionNames()) {
    const bool project =
        std::find(projectSections().begin(), projectSections().end(), s) != projectSections().end();
    if (!project && !ownedByMrpt(s)) {
      const std::string near = nearestWord(s, known);
      errors.push_back(doc.origin() + ": unknown section [" + s + "]" +
                       (near.empty() ? "" : " (did you mean [" + near + "]?)"));
    }
  }
}

// Runs `load`, adding the lines of a ConfigError it throws to `errors`.
template <class F>
void collect(std::vector<std::string>& errors, F&& load) {
  try {
    load();
  } catch (const ConfigError& e) {
    for (std::string& line : splitLines(e.what())) {
      errors.push_back(std::move(line));
    }
  }
}

template <class T>
void loadSection(MapperConfig& cfg, const std::string& section, T& opts,
                 std::vector<std::string>& errors) {
  collect(errors, [&] {
    config::loadOptions(cfg.doc, section, opts, cfg.effective.get(), config::Presence::kOptional);
  });
}

}  // namespace

const std::vector<std::string>& mrptSections() {
  static const std::vector<std::string> s = {"ICP", "MappingApplication*"};
  return s;
}

void PosesSection::load(config::SectionReader& r) {
  r.read("max_speed_mps", motion.max_speed_mps);
  r.read("max_turn_rate_dps", motion.max_turn_rate_dps);
  r.read("max_step_m", motion.max_step_m);
  r.read("max_step_deg", motion.max_step_deg);
  r.read("max_coordinate_m", motion.max_coordinate_m);
  r.read("reset_after", motion.reset_after);
  poses::LoopClosureOptions& l = loops;
  r.read("loop_closure", l.enabled);
  r.read("keyframe_distance_m", l.keyframe_distance_m);
  r.read("keyframe_angle_deg", l.keyframe_angle_deg);
  r.read("loop_min_path_m", l.min_loop_path_m);
  r.read("loop_search_radius_m", l.search_radius_m);
  r.read("loop_search_growth", l.search_growth);
  r.read("loop_max_search_radius_m", l.max_search_radius_m);
  r.read("loop_search_angle_deg", l.search_angle_deg);
  r.read("loop_search_angle_growth_deg_per_m", l.search_angle_growth_deg_per_m);
  r.read("loop_max_search_angle_deg", l.max_search_angle_deg);
  r.read("loop_candidates_per_keyframe", l.candidates_per_keyframe);
  r.read("loop_submap_path_m", l.submap_path_m);
  r.read("loop_query_path_m", l.query_path_m);
  r.read("loop_min_score", l.min_score);
  r.read("loop_max_ambiguity", l.max_ambiguity);
  r.read("loop_ambiguity_distance_m", l.ambiguity_distance_m);
  r.read("loop_accept_axis_ambiguity", l.accept_axis_ambiguity);
  r.read("loop_max_free_space_conflict", l.max_free_space_conflict);
  r.read("loop_free_space_margin_m", l.free_space_margin_m);
  r.read("loop_min_same_side_ratio", l.min_same_side_ratio);
  r.read("loop_max_chi2", l.max_chi2);
  r.read("loop_sigma_m", l.loop_sigma_m);
  r.read("loop_sigma_deg", l.loop_sigma_deg);
  r.read("loop_refinement", l.refine_loops);
  r.read("loop_min_axis_ratio", l.min_axis_ratio);
  r.read("odometry_sigma_fraction", l.odometry_sigma_fraction);
  r.read("odometry_sigma_deg", l.odometry_sigma_deg);
  r.read("loop_loss_scale", l.loop_loss_scale);
  r.read("loop_search_latency_keyframes", l.search_latency_keyframes);
  r.read("keyframe_refinement", l.refine_keyframes);
  r.read("keyframe_refine_map_path_m", l.refine_map_path_m);
  r.read("keyframe_refine_scans", l.refine_scans);
  r.read("keyframe_refine_sigma_m", l.refine.sigma_m);
  r.read("keyframe_refine_max_distance_m", l.refine.max_distance_m);
  r.read("keyframe_refine_information_scale", l.refine.information_scale);
  r.read("keyframe_refine_one_sided_normals", l.refine.one_sided_normals);
  r.read("odometry_prior", l.odometry.enabled);
  r.read("odometry_noise_fraction", l.odometry.noise_fraction);
  r.read("odometry_noise_min_m", l.odometry.noise_min_m);
  r.read("odometry_noise_deg_per_m", l.odometry.noise_deg_per_m);
  r.read("odometry_noise_min_deg", l.odometry.noise_min_deg);
  r.read("odometry_noise_turn_fraction", l.odometry.noise_turn_fraction);
  r.read("odometry_calibration_scale_sigma", l.odometry.scale_sigma);
  r.read("odometry_calibration_turn_sigma", l.odometry.turn_sigma);
  r.read("odometry_calibration_drift_sigma_deg_per_m", l.odometry.drift_sigma_deg_per_m);
  r.read("odometry_calibration_path_m", l.odometry.calibration_path_m);
  r.read("odometry_calibration_huber_chi", l.odometry.huber_chi);
  r.read("path_constraints", l.path.count);
  r.read("path_constraint_spacing_m", l.path.spacing_m);
  r.read("path_constraint_submap_m", l.path.submap_half_path_m);
  r.read("path_constraint_max_chi2", l.path.max_chi2);
  r.read("path_constraint_min_along_ratio", l.path.min_along_ratio);
  r.read("path_constraint_max_gap_m", l.path.max_gap_m);
  r.read("front_map_radius_m", l.front_map_radius_m);
  r.read("front_map_spacing_m", l.front_map_spacing_m);
  refine::PlanePoseOptions& p = planes;
  r.read("plane_refinement", p.enabled);
  r.read("plane_refine_knot_spacing_m", p.knot_spacing_m);
  r.read("plane_refine_sigma_m", p.sigma_m);
  r.read("plane_refine_motion_sigma_m_per_m", p.motion_sigma_m_per_m);
  r.read("plane_refine_motion_sigma_deg_per_m", p.motion_sigma_deg_per_m);
  r.read("plane_refine_max_normal_z", p.max_normal_z);
  r.read("plane_refine_absolute_sigma_m", p.absolute_sigma_m);
  r.read("plane_refine_absolute_sigma_deg", p.absolute_sigma_deg);
  r.read("plane_refine_points_per_scan_surface", p.points_per_scan_surface);
  r.read("plane_refine_huber_sigmas", p.huber_sigmas);
  r.read("plane_refine_rounds", p.rounds);
  r.read("plane_refine_max_iterations", p.max_iterations);
}

void OutputOptions::load(config::SectionReader& reader) {
  reader.read("raw_map", raw_map);
  reader.read("raw_max_edge_m", raw_mesh.max_edge_m);
  reader.read("scene_points", scene_points);
  reader.read("laser_maps", laser_maps.enabled);
  reader.read("grid_resolution_m", laser_maps.resolution_m);
  reader.read("grid_max_range_m", laser_maps.max_range_m);
}

bool OutputOptions::validate(std::string* why) const {
  return raw_mesh.validate(why) && laser_maps.validate(why);
}

void PlanarEmSection::load(config::SectionReader& r) {
  r.readNumberOrAuto("sigma_m", em.sigma_m, em.sigma_auto);
  r.read("auto_sigma_points", em.auto_sigma_points);
  r.read("z_max_m", em.z_max_m);
  r.read("kappa", em.kappa);
  r.read("selection_interval", em.selection_interval);
  r.read("max_new_per_round", em.max_new_per_round);
  r.read("seed_outlier_probability", em.seed_outlier_probability);
  r.read("min_support", em.min_support);
  r.read("min_curvature_radius_m", em.min_curvature_radius_m);
  r.read("min_curvature_depth_m", em.min_curvature_depth_m);
  r.read("fuse_angle_deg", em.fuse_angle_deg);
  r.read("fuse_offset_m", em.fuse_offset_m);
  r.read("fuse_gap_m", em.fuse_gap_m);
  r.read("split_cell_m", em.split_cell_m);
  r.read("split_min_offset_m", em.split_min_offset_m);
  r.read("empty_area_cost", em.empty_area_cost);
  r.read("max_iterations", em.max_iterations);
  r.read("coarse_points", em.coarse_points);
  r.read("fine_iterations", em.fine_iterations);
  r.read("block_points", em.block_points);
  r.read("block_coarse_points", em.block_coarse_points);
  r.read("block_margin_m", em.block_margin_m);
  r.read("convergence_tolerance", em.convergence_tolerance);
  r.read("convergence_patience", em.convergence_patience);
  r.read("convergence_absolute_nats", em.convergence_absolute_nats);
  r.read("min_rows", em.min_rows);
  r.read("min_gain", em.min_gain);
  r.read("responsibility_tolerance", em.responsibility_tolerance);
  r.read("fine_max_edge_m", em.fine_max_edge_m);
  r.read("fine_cell_m", em.fine_cell_m);
  auto seed = static_cast<std::int64_t>(em.seed);
  r.read("seed", seed);
  if (seed < 0) {
    r.fail("seed", "must be >= 0");
  }
  em.seed = static_cast<std::uint64_t>(seed);
  r.read("threads", em.threads);
  r.read("cloud_neighbour_radius_m", cloud_neighbour_radius_m);
}

void OnlineEmSection::load(config::SectionReader& r) {
  r.read("revisit_budget", online.revisit_budget);
  r.read("freeze_after", online.freeze_after);
  r.read("boundary_margin_nats", online.boundary_margin_nats);
  r.read("sample_cap", online.sample_cap);
  r.read("seed_window_scans", online.seed_window_scans);
  r.read("selection_per_scan", online.selection_per_scan);
  r.read("selection_sample_cap", online.selection_sample_cap);
  r.read("removal_after_scans", online.removal_after_scans);
  r.read("seed_every_scans", online.seed_every_scans);
  r.read("select_every_scans", online.select_every_scans);
}

void TextureSection::load(config::SectionReader& r) {
  texture::TextureOptions& t = texture;
  r.read("enabled", t.enabled);
  r.read("pixels_per_m", t.pixels_per_m);
  r.read("max_side_px", t.max_side_px);
  r.read("max_total_mpx", t.max_total_mpx);
  r.read("memory_budget_mb", t.memory_budget_mb);
  r.read("blend", t.blend);
  r.read("interpolation", t.interpolation);
  r.read("max_view_angle_deg", t.max_view_angle_deg);
  r.read("max_distance_m", t.max_distance_m);
  r.read("angle_power", t.angle_power);
  r.read("feather_px", t.feather_px);
  r.read("sharpness_power", t.sharpness_power);
  r.read("exposure_compensation", t.exposure_compensation);
  r.read("occlusion_margin_m", t.occlusion_margin_m);

  r.read("threads", t.threads);
}

void RefinementSection::load(config::SectionReader& r) {
  refine::RefineOptions& o = refine;
  r.read("enabled", o.enabled);
  r.read("fuse", o.fuse);
  r.read("fuse_sigmas", o.fuse_sigmas);
  r.read("seam_distance_m", o.seam_distance_m);
  r.read("seam_min_length_m", o.seam_min_length_m);
  r.read("seam_min_angle_deg", o.seam_min_angle_deg);
  r.read("seam_max_edge_angle_deg", o.seam_max_edge_angle_deg);
  r.read("seam_sigma_m", o.seam_sigma_m);
  r.read("seam_give_up_m", o.seam_give_up_m);
  r.read("extent_sigma_m", o.extent_sigma_m);
  r.read("free_rotation", o.free_rotation);
  r.read("rotation_sigma_deg", o.rotation_sigma_deg);
  r.read("robust_loss_sigmas", o.robust_loss_sigmas);
  r.read("max_points_per_surface", o.max_points_per_surface);
  r.read("max_iterations", o.max_iterations);
  r.read("manhattan", o.manhattan);
  r.read("manhattan_tolerance_deg", o.manhattan_tolerance_deg);
  r.read("manhattan_sigma_deg", o.manhattan_sigma_deg);
  r.read("max_normal_change_deg", o.max_normal_change_deg);
  r.read("openings", o.openings);
  r.read("opening_max_angle_deg", o.opening_max_angle_deg);
}

bool PlanarEmSection::validate(std::string* why) const {
  if (!(cloud_neighbour_radius_m > 0.0)) {
    *why = "cloud_neighbour_radius_m must be > 0";
    return false;
  }
  return em.validate(why);
}

std::unique_ptr<poses::IcpPoseTracker> makeIcpTracker(const MapperConfig& config,
                                                      std::vector<std::string>* app_keys) {
  config::StrictMrptConfig mrpt_config(config.doc, mrptSections(), config.effective.get());
  std::vector<std::string> errors;
  collect(errors, [&] { mrpt_config.requireSection("ICP"); });
  collect(errors, [&] { mrpt_config.requireSection("MappingApplication"); });
  std::unique_ptr<poses::IcpPoseTracker> tracker;
  collect(errors, [&] {
    try {
      tracker = std::make_unique<poses::IcpPoseTracker>(mrpt_config);
    } catch (const Error&) {
      throw;
    } catch (const std::exception& e) {
      mrpt_config.throwLoaderError(e);
    }
  });
  collect(errors, [&] {
    const std::vector<std::string> keys = mrpt_config.checkAllRead();
    if (app_keys != nullptr) {
      *app_keys = keys;
    }
  });
  if (!errors.empty()) {
    throw ConfigError(joinLines(errors));
  }
  return tracker;
}

MapperConfig loadMapperConfig(const std::filesystem::path& path) {
  MapperConfig cfg{config::IniDocument::load(path),
                   std::make_shared<config::EffectiveConfig>(),
                   {},
                   {},
                   {},
                   {},
                   {},
                   {},
                   {},
                   {},
                   {},
                   {}};
  std::vector<std::string> errors;
  rejectUnknownSections(cfg.doc, errors);
  loadSection(cfg, "Sensors", cfg.sensors, errors);
  PosesSection poses;
  loadSection(cfg, "Poses", poses, errors);
  cfg.motion = poses.motion;
  cfg.loops = poses.loops;
  cfg.plane_poses = poses.planes;
  loadSection(cfg, "Output", cfg.output, errors);
  loadSection(cfg, "PlanarEM", cfg.planar_em, errors);
  OnlineEmSection online;
  loadSection(cfg, "OnlineEM", online, errors);
  cfg.online_em = online.online;
  TextureSection texture;
  loadSection(cfg, "Texture", texture, errors);
  cfg.texture = texture.texture;
  RefinementSection refinement;
  loadSection(cfg, "Refinement", refinement, errors);
  cfg.refine = refinement.refine;
  std::vector<std::string> app_keys;
  collect(errors, [&] { makeIcpTracker(cfg, &app_keys); });  // MRPT's sections, checked once
  if (!errors.empty()) {
    throw ConfigError(joinLines(errors));
  }
  if (!app_keys.empty()) {
    std::string list;
    for (const std::string& k : app_keys) {
      list += (list.empty() ? "" : ", ") + k;
    }
    cfg.warnings.push_back(cfg.doc.origin() + ": ignored " + std::to_string(app_keys.size()) +
                           " key(s) that only MRPT's own applications read: " + list);
  }
  return cfg;
}

}  // namespace pmap::mapper
