// map.wrl read back by Coin3D (Open Inventor with VRML97 nodes): a real VRML
// parser, not our own reading. Texture images are loaded through simage
// (Debian: libsimage-dev), which Coin opens at run time.
#include <Inventor/SbImage.h>
#include <Inventor/SoDB.h>
#include <Inventor/SoInput.h>
#include <Inventor/VRMLnodes/SoVRMLAppearance.h>
#include <Inventor/VRMLnodes/SoVRMLColor.h>
#include <Inventor/VRMLnodes/SoVRMLCoordinate.h>
#include <Inventor/VRMLnodes/SoVRMLImageTexture.h>
#include <Inventor/VRMLnodes/SoVRMLIndexedFaceSet.h>
#include <Inventor/VRMLnodes/SoVRMLShape.h>
#include <Inventor/VRMLnodes/SoVRMLTextureCoordinate.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/errors/SoReadError.h>
#include <Inventor/lists/SoPathList.h>
#include <Inventor/nodes/SoSeparator.h>
#include <gtest/gtest.h>

#include "coin_reader.h"
#include "map_model_fixture.h"
#include "pmap/products/map_vrml.h"

namespace pmap::products {
namespace {
namespace fs = std::filesystem;

/// Releases Coin's global state at exit (else LeakSanitizer reports it).
class CoinEnvironment : public ::testing::Environment {
 public:
  void TearDown() override { SoDB::finish(); }
};
const auto* const coin_environment = ::testing::AddGlobalTestEnvironment(new CoinEnvironment);

using pmap::test::as;
using pmap::test::coinReadErrors;
using pmap::test::faceSetsOf;
using pmap::test::imageTexturesOf;
using pmap::test::readScene;
using pmap::test::shapesOf;

class VrmlCoin : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = test::freshDir("vrml_coin");
    writeMapVrml(dir_ / "map.wrl", model_, "Coin read-back");
    root_ = readScene(dir_ / "map.wrl");
    ASSERT_NE(root_, nullptr) << "Coin could not read " << (dir_ / "map.wrl");
    EXPECT_TRUE(coinReadErrors().empty()) << coinReadErrors().front();
  }
  void TearDown() override {
    if (root_ != nullptr) {
      root_->unref();
    }
  }
  MapModel model_ = test::texturedRoomModel();
  fs::path dir_;
  SoSeparator* root_ = nullptr;
};

TEST_F(VrmlCoin, OneShapePerQuadPlusTheFineTriangles) {
  const auto faces = faceSetsOf(shapesOf(root_));
  ASSERT_EQ(faces.size(), model_.quads.size() + 1);
  for (const SoVRMLIndexedFaceSet* f : faces) {
    ASSERT_NE(f, nullptr);
  }
  for (std::size_t i = 0; i < model_.quads.size(); ++i) {
    EXPECT_EQ(faces[i]->coordIndex.getNum(), 8);
    EXPECT_FALSE(faces[i]->solid.getValue());
    const auto* coord = as<SoVRMLCoordinate>(faces[i]->coord.getValue());
    ASSERT_NE(coord, nullptr);
    ASSERT_EQ(coord->point.getNum(), 4);
    const SbVec3f c2 = coord->point[2];
    EXPECT_NEAR(c2[0], model_.quads[i].corners[2].x(), 1e-4);
    EXPECT_NEAR(c2[2], model_.quads[i].corners[2].z(), 1e-4);
    const auto* st = as<SoVRMLTextureCoordinate>(faces[i]->texCoord.getValue());
    ASSERT_NE(st, nullptr);
    ASSERT_EQ(st->point.getNum(), 4);
    EXPECT_EQ(st->point[3], SbVec2f(0, 1));
  }
  const SoVRMLIndexedFaceSet* fine = faces.back();
  EXPECT_EQ(fine->coordIndex.getNum(), 4 * static_cast<int>(model_.fine.triangles.size()));
  EXPECT_TRUE(fine->colorPerVertex.getValue());
  const auto* colors = as<SoVRMLColor>(fine->color.getValue());
  ASSERT_NE(colors, nullptr);
  EXPECT_EQ(colors->color.getNum(), static_cast<int>(model_.fine.colors.size()));
}

// Coin resolves each url while reading (an unresolved one is a read error,
// see below) and decodes the PNG with its own image loader (simage). The
// texture node itself only loads its image for a GL context, so the image is
// read with SbImage from the url beside map.wrl. Coin's images start at the
// bottom row (t = 0 in VRML97), which is the PNG's last row.
TEST_F(VrmlCoin, TextureUrlsResolveToTheTextureImages) {
  const auto textures = imageTexturesOf(shapesOf(root_));
  ASSERT_EQ(textures.size(), test::texturedQuadCount(model_));
  const SbString wrl_dir(dir_.c_str());
  const SbString* dirs[] = {&wrl_dir};
  for (std::size_t i = 0; i < textures.size(); ++i) {
    const TexturedQuad& q = model_.quads[i];
    ASSERT_EQ(textures[i]->url.getNum(), 1);
    const std::string url = textures[i]->url[0].getString();
    EXPECT_EQ(url, "textures/surface_" + std::to_string(q.surface_id) + "_" +
                       std::to_string(q.tile) + ".png");
    SbImage image;
    ASSERT_TRUE(image.readFile(url.c_str(), dirs, 1))
        << "Coin could not load " << url
        << " (is libsimage-dev installed? scripts/install-deps.sh)";
    SbVec3s size;
    int channels = 0;
    const unsigned char* pixels = image.getValue(size, channels);
    ASSERT_NE(pixels, nullptr);
    EXPECT_EQ(size[0], q.texture.cols);
    EXPECT_EQ(size[1], q.texture.rows);
    ASSERT_EQ(channels, 3);
    const cv::Vec3b bgr = q.texture.at<cv::Vec3b>(q.texture.rows - 1, 0);
    EXPECT_EQ(pixels[0], bgr[2]);
    EXPECT_EQ(pixels[1], bgr[1]);
    EXPECT_EQ(pixels[2], bgr[0]);
  }
}

TEST_F(VrmlCoin, AMissingTextureFileIsAReadError) {
  fs::remove(dir_ / "textures" / "surface_7_0.png");
  SoSeparator* root = readScene(dir_ / "map.wrl");
  ASSERT_NE(root, nullptr);
  root->unref();
  ASSERT_EQ(coinReadErrors().size(), 1u);
  EXPECT_NE(coinReadErrors()[0].find("surface_7_0.png"), std::string::npos) << coinReadErrors()[0];
}

}  // namespace
}  // namespace pmap::products
