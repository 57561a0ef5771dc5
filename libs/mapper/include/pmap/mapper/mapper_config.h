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
#include "pmap/refine/refine_options.h"
#include "pmap/texture/texture_options.h"

namespace pmap::config {
class SectionReader;
}

namespace pmap::mapper {

/// [Output]
struct OutputOptions {
  bool raw_map = true;              ///< write raw.wrl, the paper's raw polygon map
  points::RawMeshOptions raw_mesh;  ///< raw_max_edge_m
  bool scene_points = false;        ///< map.3Dscene also holds the raw points
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
  OutputOptions output;
  PlanarEmSection planar_em;
  em::OnlineEmOptions online_em;
  texture::TextureOptions texture;
  refine::RefineOptions refine;
};

/// Loads and validates the project's sections; rejects sections nobody owns.
/// MRPT's sections are checked when the pose stage reads them.
MapperConfig loadMapperConfig(const std::filesystem::path& path);

/// MRPT-owned section names (an entry ending in '*' is a prefix).
const std::vector<std::string>& mrptSections();

}  // namespace pmap::mapper
