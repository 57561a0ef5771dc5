#include "pmap/sim/camera_imaging_options.h"

#include <gtest/gtest.h>

#include <cmath>

#include "pmap/sim/sensor_options.h"

namespace pmap::sim {
namespace {

TEST(CameraImagingOptions, DefaultsValidateAndAreModerate) {
  std::string why;
  const CameraOptions c;
  EXPECT_TRUE(c.validate(&why)) << why;
  EXPECT_TRUE(c.lens.validate(&why)) << why;
  EXPECT_TRUE(c.blur.validate(&why)) << why;
  EXPECT_TRUE(c.exposure.validate(&why)) << why;
  EXPECT_TRUE(c.noise.validate(&why)) << why;
  EXPECT_FALSE(c.lens.hasDistortion());  // off by default
  EXPECT_EQ(c.exposure.gain[0], 0.8);
  EXPECT_EQ(c.exposure.gain[1], 1.2);
  EXPECT_EQ(c.blur.blurred_fraction, 0.3);
  EXPECT_LE(c.blur.psf_sigma_px[1], 0.5);
  EXPECT_GT(c.noise.read_sigma_dn, 0.0);
}

TEST(CameraImagingOptions, ValidateNamesTheKey) {
  std::string why;
  CameraExposureOptions e;
  e.gain = {1.2, 0.8};
  EXPECT_FALSE(e.validate(&why));
  EXPECT_NE(why.find("exposure.gain: the lower bound exceeds"), std::string::npos) << why;
  e = CameraExposureOptions();
  e.gain = {0.0, 1.0};
  EXPECT_FALSE(e.validate(&why));
  EXPECT_NE(why.find("exposure.gain: values must be in (0, 10]"), std::string::npos) << why;
  e = CameraExposureOptions();
  e.gamma = {0.1, 1.0};
  EXPECT_FALSE(e.validate(&why));
  EXPECT_NE(why.find("exposure.gamma"), std::string::npos) << why;

  CameraBlurOptions b;
  b.blurred_fraction = 1.5;
  EXPECT_FALSE(b.validate(&why));
  EXPECT_NE(why.find("blur.blurred_fraction"), std::string::npos) << why;
  b = CameraBlurOptions();
  b.motion_length_px = {5.0, std::nan("")};
  EXPECT_FALSE(b.validate(&why));
  EXPECT_NE(why.find("blur.motion_length_px"), std::string::npos) << why;

  CameraNoiseOptions n;
  n.full_well_e = 10.0;
  EXPECT_FALSE(n.validate(&why));
  EXPECT_NE(why.find("noise.full_well_e"), std::string::npos) << why;
  n = CameraNoiseOptions();
  n.read_sigma_dn = -1.0;
  EXPECT_FALSE(n.validate(&why));
  EXPECT_NE(why.find("noise.read_sigma_dn"), std::string::npos) << why;

  CameraLensOptions l;
  l.vignetting = 1.0;
  EXPECT_FALSE(l.validate(&why));
  EXPECT_NE(why.find("lens.vignetting"), std::string::npos) << why;
  l = CameraLensOptions();
  l.distortion = {0.0, 0.0, 0.5, 0.0, 0.0};
  EXPECT_FALSE(l.validate(&why));
  EXPECT_NE(why.find("lens.distortion"), std::string::npos) << why;
}

TEST(CameraImagingOptions, CameraOptionsRejectFoldingDistortion) {
  std::string why;
  CameraOptions c;
  c.lens.distortion = {-0.2, 0.05, 0.0, 0.0, 0.0};  // moderate barrel: fine at 90 degrees
  EXPECT_TRUE(c.validate(&why)) << why;
  c.lens.distortion = {-0.5, 0.0, 0.0, 0.0, 0.0};  // folds over before the image corners
  EXPECT_FALSE(c.validate(&why));
  EXPECT_NE(why.find("lens.distortion"), std::string::npos) << why;
  SensorOptions s;
  s.cameras.blur.defocus_sigma_px = {3.0, 2.0};
  EXPECT_FALSE(s.validate(&why));
  EXPECT_NE(why.find("cameras: blur.defocus_sigma_px"), std::string::npos) << why;
}

}  // namespace
}  // namespace pmap::sim
