#include "pmap/sim/image_sensor.h"

#include <gtest/gtest.h>

namespace pmap::sim {
namespace {

const cv::Mat kNoFalloff;

/// Mean and variance of one channel of `img`.
std::pair<double, double> stats(const cv::Mat& img, int channel) {
  std::vector<cv::Mat> ch;
  cv::split(img, ch);
  cv::Scalar mean, stddev;
  cv::meanStdDev(ch[static_cast<std::size_t>(channel)], mean, stddev);
  return {mean[0], stddev[0] * stddev[0]};
}

cv::Mat flat(double value) {
  return cv::Mat(200, 200, CV_32FC3, cv::Scalar::all(value));
}

TEST(ImageSensor, ShotAndReadNoiseStatistics) {
  CameraNoiseOptions n;
  n.read_sigma_dn = 2.0;
  n.full_well_e = 2000.0;
  for (const double signal : {20.0, 100.0, 200.0}) {
    const SensorReadout r = readSensor(flat(signal), kNoFalloff, n, FrameExposure{}, 3);
    const double expected_var = 4.0 + signal * 255.0 / 2000.0;
    for (int ch = 0; ch < 3; ++ch) {
      const auto [mean, var] = stats(r.image, ch);
      EXPECT_NEAR(mean, signal, 0.1) << signal;                                    // mean unchanged
      EXPECT_NEAR(var, expected_var + 1.0 / 12.0, 0.06 * expected_var) << signal;  // + rounding
    }
  }
  // The variance grows with the signal.
  const double dark = stats(readSensor(flat(20.0), kNoFalloff, n, {}, 4).image, 1).second;
  const double bright = stats(readSensor(flat(200.0), kNoFalloff, n, {}, 4).image, 1).second;
  EXPECT_GT(bright, 2.5 * dark);
}

TEST(ImageSensor, ChannelsAndPixelsAreIndependent) {
  const SensorReadout r = readSensor(flat(120.0), kNoFalloff, CameraNoiseOptions{}, {}, 8);
  std::vector<cv::Mat> ch;
  cv::split(r.image, ch);
  cv::Mat b, g;
  ch[0].convertTo(b, CV_64F);
  ch[1].convertTo(g, CV_64F);
  b -= cv::mean(b)[0];
  g -= cv::mean(g)[0];
  const double corr = b.dot(g) / std::sqrt(b.dot(b) * g.dot(g));
  EXPECT_LT(std::abs(corr), 0.03);
  const double lag = b.colRange(0, 199).dot(b.colRange(1, 200)) / b.dot(b);
  EXPECT_LT(std::abs(lag), 0.03);
}

TEST(ImageSensor, DeterministicForASeed) {
  const cv::Mat in = flat(90.0);
  const CameraNoiseOptions n;
  const SensorReadout a = readSensor(in, kNoFalloff, n, {}, 17);
  const SensorReadout b = readSensor(in, kNoFalloff, n, {}, 17);
  const SensorReadout c = readSensor(in, kNoFalloff, n, {}, 18);
  EXPECT_EQ(cv::norm(a.image, b.image, cv::NORM_INF), 0.0);
  EXPECT_GT(cv::norm(a.image, c.image, cv::NORM_INF), 0.0);
}

TEST(ImageSensor, GainOffsetAndClipping) {
  CameraNoiseOptions quiet;
  quiet.read_sigma_dn = 0.0;
  quiet.full_well_e = 1.0e7;
  const SensorReadout r =
      readSensor(flat(100.0), kNoFalloff, quiet, FrameExposure{1.2, 3.0, 1.0}, 1);
  EXPECT_NEAR(stats(r.image, 0).first, 123.0, 0.5);
  EXPECT_EQ(r.saturated_fraction, 0.0);
  const SensorReadout hot =
      readSensor(flat(240.0), kNoFalloff, quiet, FrameExposure{1.2, 0.0, 1.0}, 1);
  EXPECT_EQ(stats(hot.image, 2).first, 255.0);  // clipped like a real sensor
  EXPECT_EQ(hot.saturated_fraction, 1.0);
  const SensorReadout cold =
      readSensor(flat(2.0), kNoFalloff, quiet, FrameExposure{1.0, -10.0, 1.0}, 1);
  EXPECT_EQ(stats(cold.image, 0).first, 0.0);
  // Noise near white is clipped too: nothing wraps around.
  const SensorReadout noisy = readSensor(flat(254.0), kNoFalloff, CameraNoiseOptions{}, {}, 1);
  double lo, hi;
  cv::minMaxLoc(noisy.image.reshape(1), &lo, &hi);
  EXPECT_GT(lo, 200.0);
  EXPECT_GT(noisy.saturated_fraction, 0.3);
}

TEST(ImageSensor, FalloffAndToneCurve) {
  CameraNoiseOptions quiet;
  quiet.read_sigma_dn = 0.0;
  quiet.full_well_e = 1.0e7;
  cv::Mat falloff(200, 200, CV_32FC1, cv::Scalar(0.5));
  EXPECT_NEAR(stats(readSensor(flat(100.0), falloff, quiet, {}, 1).image, 1).first, 50.0, 0.5);
  // gamma 2: 255 * (64 / 255)^(1/2) = 127.7
  const SensorReadout g =
      readSensor(flat(64.0), kNoFalloff, quiet, FrameExposure{1.0, 0.0, 2.0}, 1);
  EXPECT_NEAR(stats(g.image, 0).first, 128.0, 0.6);
}

}  // namespace
}  // namespace pmap::sim
