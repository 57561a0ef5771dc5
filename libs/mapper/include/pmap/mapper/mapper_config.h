// The run's configuration: one ini in MRPT syntax with the project's sections
// ([Sensors], [Output]) and MRPT's own ([ICP], [MappingApplication] and its
// sub-sections, read by MRPT's loaders through config::StrictMrptConfig).
// Unknown sections, keys and bad values are ConfigErrors (doc/configuration.md).
#pragma once

#include <filesystem>
#include <memory>
#include <string>

#include "pmap/config/effective_config.h"
#include "pmap/config/ini_document.h"
#include "pmap/em/online_em_options.h"
#include "pmap/em/planar_em_options.h"
#include "pmap/input/sensor_roles.h"
#include "pmap/points/raw_mesh.h"
#include "pmap/poses/icp_pose_tracker.h"
#include "pmap/poses/laser_maps.h"
#include "pmap/poses/loop_closure.h"
#include "pmap/poses/motion_gate.h"
#include "pmap/refine/plane_pose_options.h"
#include "pmap/refine/refine_options.h"
#include "pmap/texture/texture_options.h"

namespace pmap::config {
class SectionReader;
}

namespace pmap::mapper {

/// [Poses]: the pose stage's own keys (MRPT's ICP keys stay in [ICP] and
/// [MappingApplication]).
struct PosesSection {
  poses::MotionLimits motion;       ///< implausible motion (libs/poses motion_gate.h)
  poses::LoopClosureOptions loops;  ///< the pose graph (libs/poses loop_closure.h)
  refine::PlanePoseOptions planes;  ///< planes correct poses (libs/refine plane_poses.h)
  void load(config::SectionReader& reader);
  bool validate(std::string* why) const {
    return motion.validate(why) && loops.validate(why) && planes.validate(why);
  }
};

/// [Output]
struct OutputOptions {
  bool raw_map = true;                ///< write raw.wrl, the paper's raw polygon map
  points::RawMeshOptions raw_mesh;    ///< raw_max_edge_m
  bool scene_points = false;          ///< map.3Dscene also holds the raw points
  poses::LaserMapOptions laser_maps;  ///< grid.png, grid.gridmap.gz, map.simplemap
  void load(config::SectionReader& reader);
  bool validate(std::string* why) const;
};

/// [PlanarEM]: the EM options (libs/em, which knows nothing of ini files)
/// plus how neighbours are found in unorganised clouds.
struct PlanarEmSection {
  em::PlanarEmOptions em;
  double cloud_neighbour_radius_m = 0.15;  ///< nearest-neighbour radius for clouds (m)
  void load(config::SectionReader& reader);
  bool validate(std::string* why) const;
};

/// [Texture]: camera textures (libs/texture, doc/textures.md).
struct TextureSection {
  texture::TextureOptions texture;
  void load(config::SectionReader& reader);
  bool validate(std::string* why) const { return texture.validate(why); }
};

/// [OnlineEM]: the online EM's bounds (libs/em, doc/em.md).
struct OnlineEmSection {
  em::OnlineEmOptions online;
  void load(config::SectionReader& reader);
  bool validate(std::string* why) const { return online.validate(why); }
};

/// [Refinement]: fusion and the Ceres boundary refinement (libs/refine,
/// doc/refinement.md).
struct RefinementSection {
  refine::RefineOptions refine;
  void load(config::SectionReader& reader);
  bool validate(std::string* why) const { return refine.validate(why); }
};

struct MapperConfig {
  config::IniDocument doc;
  std::shared_ptr<config::EffectiveConfig> effective;
  input::SensorsOptions sensors;
  poses::MotionLimits motion;
  poses::LoopClosureOptions loops;
  OutputOptions output;
  PlanarEmSection planar_em;
  em::OnlineEmOptions online_em;
  texture::TextureOptions texture;
  refine::RefineOptions refine;
  refine::PlanePoseOptions plane_poses;
  /// Accepted but worth saying (MRPT application keys that were ignored).
  std::vector<std::string> warnings;
};

/// Loads and validates the whole file: the project's sections (each may be
/// left out: its defaults apply) and MRPT's [ICP] / [MappingApplication*]
/// (read by MRPT's loaders, strictly). Rejects sections nobody owns. Throws
/// one ConfigError listing every problem of the file, a line each.
MapperConfig loadMapperConfig(const std::filesystem::path& path);

/// The ICP tracker configured from [ICP] / [MappingApplication*]; every key
/// there must be read by MRPT's loaders, or be one that only MRPT's
/// applications read (returned in `app_keys`). Throws ConfigError.
std::unique_ptr<poses::IcpPoseTracker> makeIcpTracker(const MapperConfig& config,
                                                      std::vector<std::string>* app_keys = nullptr);

/// MRPT-owned section names (an entry ending in '*' is a prefix).
const std::vector<std::string>& mrptSections();

}  // namespace pmap::mapper
