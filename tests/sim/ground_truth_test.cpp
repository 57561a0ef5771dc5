#include "pmap/sim/ground_truth.h"

#include <gtest/gtest.h>

#include <sstream>

#include "pmap/sim/world_builder.h"
#include "pmap/sim/world_loader.h"
#include "sim_test_support.h"

namespace pmap::sim {
namespace {

World tinyWorld() {
  return buildWorld(parseWorldText(test::tinyWorldJson(), "tiny.json"));
}

GroundTruthRecorder recorder() {
  GroundTruthRecorder gt;
  gt.addPose(100.0, Pose2D{1.0, 0.1, 0.0});
  gt.addPose(100.0, Pose2D{1.0, 0.1, 0.0});  // duplicate timestamp kept once
  gt.addPose(100.1, Pose2D{1.04, 0.1, 0.01});
  gt.addStructureScan(100.1, "LASER_V", {3, 4, -1});
  ImageRecord image;
  image.file = "CAMERA_LEFT_000000.jpg";
  image.label = "CAMERA_LEFT";
  image.timestamp_s = 100.05;
  image.effects.exposure.gain = 1.1;
  image.effects.blur_sigma_px = 1.7;
  image.effects.blurred = true;
  image.quality.sharpness = 0.2;
  gt.addImage(image);
  return gt;
}

TEST(GroundTruth, JsonHasTheDocumentedSchema) {
  const World w = tinyWorld();
  GroundTruthMeta meta;
  meta.world_name = "tiny";
  meta.seed = 7;
  meta.sigma_m = 0.02;
  meta.images_dir_name = "run_Images";
  const OrderedJson doc = recorder().toJson(w, meta);
  for (const char* key :
       {"format", "world", "seed", "sigma_m", "frame", "start_time", "sensors", "pose_fields",
        "poses", "surfaces", "posters", "clutter", "structure_scans", "images"}) {
    EXPECT_TRUE(doc.contains(key)) << key;
  }
  EXPECT_EQ(doc["format"], "pmap-gt/1");
  EXPECT_EQ(doc["poses"].size(), 2u);
  EXPECT_EQ(doc["poses"][1].size(), 7u);
  EXPECT_EQ(doc["pose_fields"][0], "t");
  const auto& s = doc["surfaces"][0];
  for (const char* key : {"id", "kind", "corners", "normal", "holes", "parent"}) {
    EXPECT_TRUE(s.contains(key)) << key;
  }
  EXPECT_EQ(s["corners"].size(), 4u);
  EXPECT_EQ(doc["posters"][0]["image"],
            "run_Images/poster_" + std::to_string(w.posters[0].id) + ".png");
  EXPECT_EQ(doc["structure_scans"][0]["hits"][2], -1);
  EXPECT_EQ(doc["structure_scans"][0]["index"], 0);
  EXPECT_EQ(doc["sensors"]["structure_laser"]["label"], "LASER_V");
  EXPECT_EQ(doc["sensors"]["pose_laser"]["label"], "LASER_H");
  EXPECT_EQ(doc["sensors"]["cameras"].size(), 2u);
  EXPECT_EQ(doc["clutter"][0]["shape"], "cylinder");
  const auto& image = doc["images"][0];
  for (const char* key : {"file", "image", "timestamp", "label", "index", "gain", "offset_dn",
                          "gamma", "blur_sigma_px", "motion_blur_px", "blurred", "sharpness",
                          "laplacian_var", "saturated_fraction"}) {
    EXPECT_TRUE(image.contains(key)) << key;
  }
  EXPECT_EQ(image["file"], "CAMERA_LEFT_000000.jpg");
  EXPECT_EQ(image["image"], "run_Images/CAMERA_LEFT_000000.jpg");
  EXPECT_EQ(image["gain"], 1.1);
  EXPECT_EQ(image["blur_sigma_px"], 1.7);
  const auto& cam = doc["sensors"]["cameras"][0];
  EXPECT_EQ(cam["distortion"].size(), 5u);
  EXPECT_EQ(cam["vignetting"], 0.25);
  const auto& imaging = doc["config"]["cameras"];
  EXPECT_EQ(imaging["exposure"]["gain"][1], 1.2);
  EXPECT_EQ(imaging["blur"]["blurred_fraction"], 0.3);
  EXPECT_TRUE(imaging["noise"].contains("full_well_e"));
  EXPECT_FALSE(doc["config"]["noise"].contains("image_sigma"));
}

TEST(GroundTruth, BoxClutterHasItsSizeAndYaw) {
  const World w =
      buildWorld(loadWorldFile(std::string(PMAP_SOURCE_DIR) + "/config/worlds/second.json"));
  const OrderedJson clutter = clutterJson(w);
  bool found = false;
  for (const auto& c : clutter) {
    if (c["shape"] == "box") {
      found = true;
      EXPECT_EQ(c["kind"], "pillar");
      ASSERT_EQ(c["size_m"].size(), 3u);
      EXPECT_NEAR(c["size_m"][2].get<double>(), 2.8, 1e-12);
      EXPECT_TRUE(c.contains("yaw"));
    }
  }
  EXPECT_TRUE(found);
}

TEST(GroundTruth, FormattedTextParsesBackToTheSameDocument) {
  const World w = tinyWorld();
  const OrderedJson doc = recorder().toJson(w, GroundTruthMeta{});
  const std::string text = formatGroundTruth(doc);
  EXPECT_EQ(OrderedJson::parse(text), doc);
  EXPECT_NE(text.find("\n    {\"id\":0,"), std::string::npos);  // one surface per line
}

TEST(GroundTruth, PosesTextIsTheMappersFormat) {
  const std::string text = recorder().posesText();
  std::istringstream in(text);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line[0], '#');
  std::getline(in, line);
  EXPECT_EQ(line, "100.000000 1.000000 0.100000 0.000000 0.000000000 0.000000000 0.000000000");
  int n = 1;
  while (std::getline(in, line)) {
    ++n;
  }
  EXPECT_EQ(n, 2);
}

}  // namespace
}  // namespace pmap::sim
