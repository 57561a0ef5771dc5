// Texture quality on the simulator's posters (doc/evaluation.md): the map's
// texture resampled over each poster against the poster image itself.
//
// The poster image is box-filtered to the texture's resolution (a texture of
// p px/m cannot hold finer detail), and the texture is sampled bilinearly at
// the same cells, shifted by up to max_shift_px texels along the wall and
// kept at the best shift (sub-pixel registration of the two images). The
// simulator shades what its cameras see (light falls off with distance and
// angle, exposure varies), so a texture records radiance, not the poster's
// albedo: before the error is taken, the texture is mapped to the poster's
// values by a per-channel least-squares gain and offset. PSNR over all cells
// and channels: 10 log10(255^2 / MSE).
#pragma once

#include <array>
#include <filesystem>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "pmap/eval/ground_truth.h"
#include "pmap/eval/pose_metrics.h"

namespace pmap::eval {

/// One texture image of the map (a row of textures.csv, doc/outputs.md).
struct MapTexture {
  std::string file;
  int surface_id = -1;
  int tile = 0;
  std::array<Eigen::Vector3d, 4> corners;  ///< map frame
  cv::Mat image;                           ///< BGR 8-bit
};

/// Reads textures.csv and its images. Throws InputError naming file, line
/// and column, or the image that cannot be read or has the wrong size.
std::vector<MapTexture> readMapTextures(const std::filesystem::path& csv);

struct TextureQualityOptions {
  double max_shift_px = 2.0;   ///< registration search, texels either way
  double shift_step_px = 0.5;  ///< search step (texels)
};

struct PosterScore {
  int poster_id = -1;
  int surface_id = -1;  ///< texture the poster's centre falls on (-1: none)
  double psnr_db = 0;   ///< at the best shift
  double psnr_unshifted_db = 0;
  Eigen::Vector2d shift_px = Eigen::Vector2d::Zero();  ///< best shift (texels, along u, v)
  double pixels_per_m = 0;                             ///< texture resolution the comparison ran at
  std::size_t cells = 0;                               ///< compared cells
  double covered = 0;  ///< fraction of the poster's cells on some texture
};

/// Scores every poster of `gt`. `map_to_gt` aligns the map's frame (poses
/// evaluation); posters whose cells are not covered by any texture get
/// surface_id -1 and no PSNR.
std::vector<PosterScore> scorePosters(const GroundTruth& gt,
                                      const std::vector<MapTexture>& textures,
                                      const Rigid2D& map_to_gt,
                                      const TextureQualityOptions& options = {});

}  // namespace pmap::eval
