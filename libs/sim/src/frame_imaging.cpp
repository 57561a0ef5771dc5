#include "pmap/sim/frame_imaging.h"

#include <algorithm>
#include <cmath>

#include "pmap/sim/camera_optics.h"
#include "pmap/sim/rng.h"

namespace pmap::sim {
namespace {

/// A value drawn uniformly from `range`, rounded to 1e-6 so that gt.json
/// records exactly the value used. Draws even if lo == hi: stable streams.
double draw(Rng& rng, const Interval& range) {
  const double x = range[0] + (range[1] - range[0]) * rng.uniform();
  return std::clamp(std::round(x * 1.0e6) / 1.0e6, range[0], range[1]);
}

PinholeIntrinsics outputIntrinsics(const CameraOptions& o) {
  PinholeIntrinsics k = PinholeIntrinsics::fromFov(o.width_px, o.height_px, degToRad(o.hfov_deg));
  k.distortion = o.lens.distortion;
  return k;
}

}  // namespace

FrameEffects drawFrameEffects(const CameraOptions& options, std::uint64_t seed) {
  Rng rng(seed);
  const CameraBlurOptions& b = options.blur;
  FrameEffects fx;
  fx.exposure.gain = draw(rng, options.exposure.gain);
  fx.exposure.offset_dn = draw(rng, options.exposure.offset_dn);
  fx.exposure.gamma = draw(rng, options.exposure.gamma);
  const double psf = draw(rng, b.psf_sigma_px);
  const double event = rng.uniform();
  const double kind = rng.uniform();
  const double defocus = draw(rng, b.defocus_sigma_px);
  const double streak = draw(rng, b.motion_length_px);
  fx.blurred = event < b.blurred_fraction;
  const bool motion = fx.blurred && kind < b.motion_share;
  fx.blur_sigma_px =
      fx.blurred && !motion ? std::round(std::hypot(psf, defocus) * 1.0e6) / 1.0e6 : psf;
  fx.motion_blur_px = motion ? streak : 0.0;
  return fx;
}

ImagingPipeline::ImagingPipeline(const CameraOptions& options)
    : noise_(options.noise), intrinsics_(outputIntrinsics(options)), warp_(intrinsics_) {
  if (options.lens.vignetting > 0.0) {
    falloff_ = vignettingMap(intrinsics_, options.lens.vignetting);
  }
}

DevelopedFrame ImagingPipeline::develop(const cv::Mat& render, const FrameEffects& effects,
                                        std::uint64_t noise_seed) const {
  const cv::Mat optical = warp_.apply(render);
  const cv::Mat blurred = blurImage(optical, effects.blur_sigma_px, effects.motion_blur_px);
  SensorReadout readout = readSensor(blurred, falloff_, noise_, effects.exposure, noise_seed);
  DevelopedFrame out;
  const double sharp_var = laplacianVariance(optical);
  out.quality.sharpness = sharp_var > 0.0 ? laplacianVariance(blurred) / sharp_var : 1.0;
  out.quality.laplacian_var = laplacianVariance(readout.image);
  out.quality.saturated_fraction = readout.saturated_fraction;
  out.image = readout.image;
  return out;
}

}  // namespace pmap::sim
