// Textures the map from its camera frames (doc/textures.md): rectangles are
// cut into tiles, every frame that sees a tile adds its view (weighted by
// angle, distance, border distance and blur, occlusions removed by a
// depth buffer of the map, exposure matched across frames), unseen texels
// are filled by push-pull; fine triangles get per-vertex colours the same way.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "pmap/products/map_model.h"
#include "pmap/texture/camera_frame.h"
#include "pmap/texture/texture_options.h"

namespace pmap::texture {

/// Returns a frame's image as BGR 8-bit; throws InputError when it cannot.
using ImageLoader = std::function<cv::Mat(const CameraFrame&)>;

struct TextureResult {
  std::size_t frames = 0;       ///< camera frames given
  std::size_t frames_used = 0;  ///< frames that coloured at least one texel or vertex
  std::size_t image_reads = 0;  ///< images decoded (3 times per used frame, more with groups)
  std::size_t tiles = 0;
  std::size_t textured_tiles = 0;  ///< tiles seen by at least one frame
  std::size_t groups = 0;          ///< passes over the images (memory budget)
  long long texels = 0;
  double coverage = 0.0;      ///< fraction of texels seen by some frame
  double pixels_per_m = 0.0;  ///< effective resolution (lower than asked over budget)
  std::size_t fine_vertices = 0;
  std::size_t fine_vertices_seen = 0;
  std::vector<float> gains;  ///< per frame exposure gain (1: none or unused)
  /// Per frame: the high-pass slope of its samples on the reference texture
  /// (detail_transfer.h; below 1: blurred), -1 when unknown or not measured.
  std::vector<double> detail_slope;
  std::vector<std::uint8_t> frame_used;  ///< per frame: coloured something

  std::string message;
};

/// Replaces `model.quads` by textured tiles (same geometry) and colours
/// `model.fine`. Deterministic for any options.threads.
TextureResult textureMap(products::MapModel& model, const std::vector<CameraFrame>& frames,
                         const ImageLoader& load, const TextureOptions& options);

}  // namespace pmap::texture
