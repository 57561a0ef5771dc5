#include "pmap/texture/map_texturer.h"

#include <gtest/gtest.h>

#include <map>
#include <opencv2/imgproc.hpp>

#include "synthetic_views.h"

namespace pmap::texture {
namespace {

constexpr double kWallLength = 4.0, kWallHeight = 2.5, kWallY = 1.5;

// The test pattern plus fine detail (periods of 2 to 2.5 cm, 4 to 5 texels).
cv::Vec3f detailedPattern(double s_m, double t_m) {
  const float fine =
      static_cast<float>(30 * std::sin(2 * M_PI * s_m / 0.02) * std::sin(2 * M_PI * t_m / 0.025));
  return test::pattern(s_m, t_m) + cv::Vec3f(fine, fine, fine);
}

// A 4 m wall painted with the test pattern, seen by a camera sliding along
// it at 1 m height, 1.5 m away.
struct Corridor {
  std::vector<test::PaintedQuad> world;
  std::vector<CameraFrame> frames;
  std::map<std::string, cv::Mat> images;
  std::vector<float> gains;  // exposure of each frame

  explicit Corridor(std::vector<float> exposure = {}, bool pillar = false,
                    std::vector<double> blur_sigma_px = {}, bool detailed = false) {
    test::PaintedQuad wall{test::wallQuad(3, 0, kWallLength, kWallY, kWallHeight),
                           [detailed](double s, double t) {
                             return detailed ? detailedPattern(s * kWallLength, t * kWallHeight)
                                             : test::pattern(s * kWallLength, t * kWallHeight);
                           }};
    world.push_back(wall);
    if (pillar) {  // red, 0.7 m in front of the wall
      world.push_back({test::wallQuad(9, 1.9, 2.1, 0.8, kWallHeight),
                       [](double, double) { return cv::Vec3f(0, 0, 255); }});
    }
    for (int i = 0; i < 19; ++i) {
      const std::string label = "f" + std::to_string(i);
      frames.push_back(
          test::lookAt({0.2 + 0.2 * i, 0, 1.0}, {0, 1, 0}, {0, 0, 1}, label, 320, 240));
      const float g =
          exposure.empty() ? 1.f : exposure[static_cast<std::size_t>(i) % exposure.size()];
      gains.push_back(g);
      images[label] = test::render(frames.back(), world, g);
      const double blur = blur_sigma_px.empty()
                              ? 0.0
                              : blur_sigma_px[static_cast<std::size_t>(i) % blur_sigma_px.size()];
      if (blur > 0) {
        cv::GaussianBlur(images[label], images[label], cv::Size(0, 0), blur);
      }
    }
  }
  ImageLoader loader() const {
    return [this](const CameraFrame& f) { return images.at(f.label); };
  }
  products::MapModel model() const {
    products::MapModel m;
    for (const auto& q : world) {
      m.quads.push_back(q.quad);
    }
    return m;
  }
};

// PSNR of the wall's texture against the pattern over the well-seen middle,
// after a least-squares gain (exposure is relative).
double wallPsnr(const products::MapModel& m, bool detailed = false) {
  for (const auto& q : m.quads) {
    if (q.surface_id != 3)
      continue;
    const cv::Mat& tex = q.texture;
    cv::Mat expected(tex.size(), CV_8UC3);
    for (int r = 0; r < tex.rows; ++r) {
      for (int c = 0; c < tex.cols; ++c) {
        const double s = (c + 0.5) / tex.cols, t = (tex.rows - r - 0.5) / tex.rows;
        expected.at<cv::Vec3b>(r, c) =
            cv::Vec3b(detailed ? detailedPattern(s * kWallLength, t * kWallHeight)
                               : test::pattern(s * kWallLength, t * kWallHeight));
      }
    }
    // x in [0.5, 3.5] m, z in [0.55, 1.45] m: seen by several frames.
    const cv::Rect mid(100, 210, 600, 180);
    cv::Mat a, b;
    tex(mid).convertTo(a, CV_64F);
    expected(mid).convertTo(b, CV_64F);
    const double gain = a.dot(b) / a.dot(a);
    cv::Mat scaled;
    cv::Mat(a * gain).convertTo(scaled, CV_8U);
    return test::psnr(scaled, expected(mid));
  }
  return 0;
}

TEST(MapTexturer, TextureReproducesThePaintedWall) {
  const Corridor c;
  products::MapModel m = c.model();
  const TextureResult r = textureMap(m, c.frames, c.loader(), TextureOptions{});
  ASSERT_EQ(m.quads.size(), 1u);
  EXPECT_EQ(r.textured_tiles, 1u);
  EXPECT_EQ(r.frames_used, 19u);
  EXPECT_GT(r.coverage, 0.44);  // z from 0.44 to 1.56 m of the 2.5 m wall
  EXPECT_EQ(m.quads[0].texture.cols, 800);
  EXPECT_EQ(m.quads[0].texture.rows, 500);
  EXPECT_GT(wallPsnr(m), 30.0);
}

TEST(MapTexturer, BestViewModeAlsoReproducesIt) {
  const Corridor c;
  products::MapModel m = c.model();
  TextureOptions o;
  o.blend = "best";
  textureMap(m, c.frames, c.loader(), o);
  EXPECT_GT(wallPsnr(m), 30.0);
}

TEST(MapTexturer, ExposureCompensationUndoesGainChanges) {
  const Corridor c({0.8f, 1.2f});
  products::MapModel with = c.model(), without = c.model();
  const TextureResult r = textureMap(with, c.frames, c.loader(), TextureOptions{});
  TextureOptions off;
  off.exposure_compensation = false;
  textureMap(without, c.frames, c.loader(), off);
  // The compensating gains invert the exposures: g_even / g_odd = 1.2 / 0.8.
  for (std::size_t i = 2; i + 1 < r.gains.size(); i += 2) {
    EXPECT_NEAR(r.gains[i] / r.gains[i + 1], 1.5, 0.05) << i;
  }
  EXPECT_GT(wallPsnr(with), wallPsnr(without) + 3.0);
  EXPECT_GT(wallPsnr(with), 30.0);
}

TEST(MapTexturer, BlurredFramesAreRecognisedAndWeighLess) {
  const Corridor c({}, false, {0.0, 0.0, 2.5}, true);  // every third frame defocused
  products::MapModel weighed = c.model(), plain = c.model();
  const TextureResult r = textureMap(weighed, c.frames, c.loader(), TextureOptions{});
  TextureOptions off;
  off.sharpness_power = 0;
  textureMap(plain, c.frames, c.loader(), off);
  double sharp = 0, blurred = 0;
  int n_sharp = 0, n_blurred = 0;
  for (std::size_t i = 0; i < r.detail_slope.size(); ++i) {
    ASSERT_GE(r.detail_slope[i], 0.0) << i;  // the pattern has detail everywhere
    (i % 3 == 2 ? blurred : sharp) += r.detail_slope[i];
    ++(i % 3 == 2 ? n_blurred : n_sharp);
  }
  std::printf("mean slope sharp %.3f blurred %.3f; PSNR weighed %.2f plain %.2f\n", sharp / n_sharp,
              blurred / n_blurred, wallPsnr(weighed, true), wallPsnr(plain, true));
  EXPECT_LT(blurred / n_blurred, 0.5 * sharp / n_sharp);
  EXPECT_GT(wallPsnr(weighed, true), wallPsnr(plain, true) + 1.0);
}

TEST(MapTexturer, OccluderDoesNotPaintTheWallBehindIt) {
  const Corridor c({}, /*pillar=*/true);
  products::MapModel m = c.model();
  textureMap(m, c.frames, c.loader(), TextureOptions{});
  const cv::Mat& tex = m.quads[0].texture;  // the wall (surface 3)
  ASSERT_EQ(m.quads[0].surface_id, 3);
  // Behind the pillar (x = 2.0): the wall's own colours, not red.
  const int col = tex.cols / 2, row = tex.rows / 2;
  const cv::Vec3b got = tex.at<cv::Vec3b>(row, col);
  const cv::Vec3f want = test::pattern(2.0 + 0.5 / 200, (tex.rows - row - 0.5) / 200.0);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(got[k], want[k], 20) << k;
  }
  EXPECT_GT(wallPsnr(m), 28.0);
}

TEST(MapTexturer, ThreadsDoNotChangeTheTextures) {
  const Corridor c({}, true);
  products::MapModel a = c.model(), b = c.model();
  TextureOptions one, four;
  four.threads = 4;
  textureMap(a, c.frames, c.loader(), one);
  textureMap(b, c.frames, c.loader(), four);
  ASSERT_EQ(a.quads.size(), b.quads.size());
  for (std::size_t i = 0; i < a.quads.size(); ++i) {
    EXPECT_EQ(cv::norm(a.quads[i].texture, b.quads[i].texture, cv::NORM_INF), 0.0);
  }
}

TEST(MapTexturer, FineTriangleVerticesTakeTheColourUnderThem) {
  const Corridor c;
  products::MapModel m = c.model();
  m.fine.vertices = {
      {1.0, kWallY - 0.01, 0.8}, {1.05, kWallY - 0.01, 0.8}, {1.0, kWallY - 0.01, 0.85}};
  m.fine.triangles = {{0, 1, 2}};
  const TextureResult r = textureMap(m, c.frames, c.loader(), TextureOptions{});
  EXPECT_EQ(r.fine_vertices_seen, 3u);
  ASSERT_EQ(m.fine.colors.size(), 3u);
  const cv::Vec3f want = test::pattern(1.0, 0.8);  // BGR
  EXPECT_NEAR(m.fine.colors[0].x() * 255, want[2], 12);
  EXPECT_NEAR(m.fine.colors[0].z() * 255, want[0], 12);
}

TEST(MapTexturer, NoFramesLeavesTheMapUntextured) {
  const Corridor c;
  products::MapModel m = c.model();
  const TextureResult r = textureMap(m, {}, c.loader(), TextureOptions{});
  EXPECT_EQ(r.textured_tiles, 0u);
  EXPECT_EQ(r.coverage, 0.0);
  EXPECT_TRUE(m.quads[0].texture.empty());
}

}  // namespace
}  // namespace pmap::texture
