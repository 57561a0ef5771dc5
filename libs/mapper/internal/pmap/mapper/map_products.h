// From the mapping result to what the exporters write: the map model
// (rectangles and fine triangles) and its camera textures.
#pragma once

#include <optional>
#include <string>

#include "pmap/mapper/mapper_args.h"
#include "pmap/mapper/mapper_config.h"
#include "pmap/mapper/pipeline.h"
#include "pmap/products/map_model.h"
#include "pmap/texture/map_texturer.h"

namespace pmap::mapper {

struct MapProducts {
  products::MapModel model;
  std::vector<texture::CameraFrame> frames;       ///< placed camera frames (the textures' input)
  std::optional<texture::TextureResult> texture;  ///< empty: untextured
  std::string untextured_reason;                  ///< why, when untextured
  std::size_t frames_without_pose = 0;            ///< images outside the trajectory (not used)
  double seconds = 0;
};

/// Builds the model of `result`'s planar map (which must exist) and textures
/// it unless [Texture] enabled = false, --no-textures or no images. Throws
/// InputError when an image cannot be read.
MapProducts buildMapProducts(const MapperConfig& config, const MapperArgs& args,
                             const MappingResult& result);

}  // namespace pmap::mapper
