#include "pmap/sim/frame_imaging.h"

#include <gtest/gtest.h>

#include "pmap/sim/camera_optics.h"
#include "pmap/sim/poster_art.h"
#include "pmap/sim/rng.h"

namespace pmap::sim {
namespace {

TEST(FrameImaging, EffectsStayInTheirRangesAndBlurAShare) {
  const CameraOptions opts;
  int blurred = 0, motion = 0;
  const int n = 2000;
  double gain_lo = 10.0, gain_hi = 0.0;
  for (int i = 0; i < n; ++i) {
    const FrameEffects fx = drawFrameEffects(opts, deriveSeed(1, "test", i));
    gain_lo = std::min(gain_lo, fx.exposure.gain);
    gain_hi = std::max(gain_hi, fx.exposure.gain);
    EXPECT_GE(fx.exposure.gain, 0.8);
    EXPECT_LE(fx.exposure.gain, 1.2);
    EXPECT_EQ(fx.exposure.offset_dn, 0.0);
    EXPECT_EQ(fx.exposure.gamma, 1.0);
    blurred += fx.blurred ? 1 : 0;
    motion += fx.motion_blur_px > 0.0 ? 1 : 0;
    if (!fx.blurred) {
      EXPECT_GE(fx.blur_sigma_px, opts.blur.psf_sigma_px[0]);
      EXPECT_LE(fx.blur_sigma_px, opts.blur.psf_sigma_px[1]);
      EXPECT_EQ(fx.motion_blur_px, 0.0);
    } else if (fx.motion_blur_px > 0.0) {
      EXPECT_GE(fx.motion_blur_px, 3.0);
      EXPECT_LE(fx.motion_blur_px, 8.0);
    } else {
      EXPECT_GE(fx.blur_sigma_px, 1.0);
      EXPECT_LE(fx.blur_sigma_px, std::hypot(0.5, 2.5));
    }
  }
  EXPECT_NEAR(static_cast<double>(blurred) / n, 0.3, 0.04);
  EXPECT_NEAR(static_cast<double>(motion) / blurred, 0.5, 0.08);
  EXPECT_LT(gain_lo, 0.82);  // the whole range is used
  EXPECT_GT(gain_hi, 1.18);
}

TEST(FrameImaging, EffectsAreDeterministicAndFixedIntervalsAreFixed) {
  CameraOptions opts;
  const FrameEffects a = drawFrameEffects(opts, 42);
  const FrameEffects b = drawFrameEffects(opts, 42);
  EXPECT_EQ(a.exposure.gain, b.exposure.gain);
  EXPECT_EQ(a.blur_sigma_px, b.blur_sigma_px);
  EXPECT_EQ(a.motion_blur_px, b.motion_blur_px);
  opts.exposure.gain = {1.0, 1.0};
  opts.blur.blurred_fraction = 0.0;
  opts.blur.psf_sigma_px = {0.0, 0.0};
  const FrameEffects c = drawFrameEffects(opts, 42);
  EXPECT_EQ(c.exposure.gain, 1.0);
  EXPECT_EQ(c.blur_sigma_px, 0.0);
  EXPECT_FALSE(c.blurred);
}

TEST(FrameImaging, DevelopMeasuresSharpness) {
  CameraOptions opts;
  opts.width_px = 200;
  opts.height_px = 140;
  const ImagingPipeline pipeline(opts);
  EXPECT_EQ(pipeline.renderIntrinsics().width_px, 200);
  cv::Mat render;
  generatePosterImage(200, 140, 5).convertTo(render, CV_32FC3);
  FrameEffects sharp;
  sharp.blur_sigma_px = 0.3;
  FrameEffects blurred = sharp;
  blurred.blur_sigma_px = 2.0;
  blurred.blurred = true;
  const DevelopedFrame a = pipeline.develop(render, sharp, 7);
  const DevelopedFrame b = pipeline.develop(render, blurred, 7);
  ASSERT_EQ(a.image.type(), CV_8UC3);
  EXPECT_EQ(a.image.size(), cv::Size(200, 140));
  EXPECT_GT(a.quality.sharpness, 0.6);
  EXPECT_LE(a.quality.sharpness, 1.0);
  EXPECT_LT(b.quality.sharpness, 0.15);
  // Measured on the noisy 8-bit output too, the blurred frame is much less sharp.
  EXPECT_GT(a.quality.laplacian_var, 3.0 * b.quality.laplacian_var);
  EXPECT_NEAR(a.quality.laplacian_var, laplacianVariance(a.image), 1e-9);
  // Same seed and effects: the same bytes.
  EXPECT_EQ(cv::norm(a.image, pipeline.develop(render, sharp, 7).image, cv::NORM_INF), 0.0);
}

TEST(FrameImaging, DistortionChangesTheRenderCanvasOnly) {
  CameraOptions opts;
  opts.lens.distortion = {-0.2, 0.05, 0.0, 0.0, 0.0};
  const ImagingPipeline pipeline(opts);
  EXPECT_EQ(pipeline.intrinsics().width_px, 640);
  EXPECT_EQ(pipeline.intrinsics().distortion[0], -0.2);
  EXPECT_GT(pipeline.renderIntrinsics().width_px, 640);
  EXPECT_EQ(pipeline.renderIntrinsics().distortion[0], 0.0);
  EXPECT_EQ(pipeline.renderIntrinsics().fx, pipeline.intrinsics().fx);
  const cv::Mat render(pipeline.renderIntrinsics().height_px, pipeline.renderIntrinsics().width_px,
                       CV_32FC3, cv::Scalar::all(100));
  const DevelopedFrame f = pipeline.develop(render, FrameEffects{}, 1);
  EXPECT_EQ(f.image.size(), cv::Size(640, 480));
}

}  // namespace
}  // namespace pmap::sim
