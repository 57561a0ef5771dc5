#include "pmap/products/texture_png.h"

#include <unistd.h>

#include <gtest/gtest.h>

#include <fstream>
#include <opencv2/imgcodecs.hpp>

#include "map_model_fixture.h"
#include "pmap/common/error.h"

namespace pmap::products {
namespace {
namespace fs = std::filesystem;

bool sameImage(const cv::Mat& a, const cv::Mat& b) {
  return a.size() == b.size() && a.type() == b.type() && cv::norm(a, b, cv::NORM_INF) == 0;
}

TEST(TexturePng, RelativePathNamesTheSurface) {
  EXPECT_EQ(textureRelativePath(0), "textures/surface_0.png");
  EXPECT_EQ(textureRelativePath(42), "textures/surface_42.png");
  EXPECT_EQ(textureRelativePath(42, 0), "textures/surface_42_0.png");
  EXPECT_EQ(textureRelativePath(5, 11), "textures/surface_5_11.png");
}

TEST(TexturePng, EncodesLosslessly) {
  const cv::Mat image = test::gradientTexture(17, 5, 4);  // odd, non-square
  const std::vector<std::uint8_t> png = encodePng(image);
  ASSERT_GT(png.size(), 8u);
  EXPECT_EQ(std::string(png.begin() + 1, png.begin() + 4), "PNG");
  EXPECT_TRUE(sameImage(cv::imdecode(png, cv::IMREAD_UNCHANGED), image));
}

TEST(TexturePng, EmptyImageIsAnOutputError) {
  EXPECT_THROW(encodePng(cv::Mat()), OutputError);
}

TEST(TexturePng, WritesAtomically) {
  const fs::path dir = test::freshDir("texture_png_writes");
  const cv::Mat image = test::gradientTexture(8, 12, 1);
  writePngAtomically(dir / "a.png", image);
  writePngAtomically(dir / "a.png", image);  // replaces
  EXPECT_TRUE(sameImage(cv::imread((dir / "a.png").string(), cv::IMREAD_UNCHANGED), image));
  EXPECT_EQ(test::filesBelow(dir), std::vector<std::string>{"a.png"});
}

TEST(TexturePng, FailedWriteKeepsThePreviousFile) {
  const fs::path dir = test::freshDir("texture_png_fails");
  const cv::Mat old_image = test::gradientTexture(8, 12, 1);
  writePngAtomically(dir / "a.png", old_image);
  // A directory in the way of the temporary file makes the write fail.
  fs::create_directory(dir / ("a.png.tmp-" + std::to_string(::getpid())));
  EXPECT_THROW(writePngAtomically(dir / "a.png", test::gradientTexture(3, 3, 2)), OutputError);
  EXPECT_TRUE(sameImage(cv::imread((dir / "a.png").string(), cv::IMREAD_UNCHANGED), old_image));
  EXPECT_THROW(writePngAtomically(dir / "missing" / "b.png", old_image), OutputError);
}

}  // namespace
}  // namespace pmap::products
