#include "pmap/sim/world_loader.h"

#include <gtest/gtest.h>

#include "pmap/common/error.h"
#include "sim_test_support.h"

namespace pmap::sim {
namespace {

std::string errorOf(const std::string& json) {
  try {
    parseWorldText(json, "w.json");
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

/// A valid world with `inner` spliced into its first corridor.
std::string corridorWith(const std::string& inner) {
  return R"({"name": "t", "corridors": [{"centreline": [[0, 0], [10, 0]])" + inner +
         R"(}], "path": {"waypoints": [[1, 0], [9, 0]]}})";
}

TEST(WorldLoader, LoadsTheBundledWorlds) {
  for (const char* name : {"default", "second", "office", "long"}) {
    const WorldSpec w =
        loadWorldFile(std::string(PMAP_SOURCE_DIR) + "/config/worlds/" + name + ".json");
    EXPECT_EQ(w.name, name);
    EXPECT_FALSE(w.corridors.empty());
    EXPECT_GE(w.path.waypoints.size(), 2u);
  }
}

TEST(WorldLoader, DefaultsAreThePapersRobot) {
  const WorldSpec w = parseWorldText(corridorWith(""), "w.json");
  EXPECT_EQ(w.sensors.cycle_hz, 5.0);
  EXPECT_EQ(w.sensors.laser_v.label, "LASER_V");
  EXPECT_EQ(w.sensors.laser_v.beams, 181);
  EXPECT_EQ(w.sensors.laser_v.ypr_deg[1], -90.0);
  EXPECT_EQ(w.sensors.laser_v.position_m[2], 0.3);
  EXPECT_EQ(w.sensors.laser_h.position_m[0], 0.2);
  EXPECT_EQ(w.sensors.laser_h.max_range_m, 30.0);
  EXPECT_EQ(w.noise.range_sigma_m, 0.02);
  EXPECT_EQ(w.path.speed_m_s, 0.4);
  EXPECT_EQ(w.sensors.cameras.mounts.size(), 2u);
  EXPECT_EQ(w.corridors[0].width_m, 2.2);
}

TEST(WorldLoader, UnknownKeyNamesPathAndSuggests) {
  const std::string e = errorOf(corridorWith(R"(, "widht_m": 2.0)"));
  EXPECT_NE(e.find("w.json"), std::string::npos) << e;
  EXPECT_NE(e.find("corridors[0].widht_m"), std::string::npos) << e;
  EXPECT_NE(e.find("did you mean \"width_m\""), std::string::npos) << e;
  const std::string top = errorOf(R"({"name": "t", "pathh": {}})");
  EXPECT_NE(top.find("did you mean \"path\""), std::string::npos) << top;
  const std::string door = errorOf(
      corridorWith(R"(, "doors": [{"leg": 0, "side": "left", "centre_m": 3, "recces_m": 0.1}])"));
  EXPECT_NE(door.find("corridors[0].doors[0].recces_m"), std::string::npos) << door;
  EXPECT_NE(door.find("recess_m"), std::string::npos) << door;
}

TEST(WorldLoader, WrongTypesAreErrors) {
  const std::string e = errorOf(corridorWith(R"(, "width_m": "wide")"));
  EXPECT_NE(e.find("corridors[0].width_m: expected a number, got a string"), std::string::npos)
      << e;
  EXPECT_NE(errorOf(corridorWith(R"(, "closed_start": 1)")).find("expected true or false"),
            std::string::npos);
  const std::string leg =
      errorOf(corridorWith(R"(, "doors": [{"leg": 0.5, "side": "left", "centre_m": 3}])"));
  EXPECT_NE(leg.find("doors[0].leg: expected an integer"), std::string::npos) << leg;
  EXPECT_NE(
      errorOf(R"({"name": "t", "path": {"waypoints": [[1, 0], [2]]}})").find("path.waypoints[1]"),
      std::string::npos);
}

TEST(WorldLoader, OutOfRangeAndMissingValuesAreErrors) {
  EXPECT_NE(errorOf(corridorWith(R"(, "width_m": -1)")).find("out of range"), std::string::npos);
  const std::string leg =
      errorOf(corridorWith(R"(, "doors": [{"leg": 3, "side": "left", "centre_m": 3}])"));
  EXPECT_NE(leg.find("doors[0].leg: 3 is out of range [0, 0]"), std::string::npos) << leg;
  const std::string side =
      errorOf(corridorWith(R"(, "doors": [{"leg": 0, "side": "lfet", "centre_m": 3}])"));
  EXPECT_NE(side.find("did you mean \"left\""), std::string::npos) << side;
  const std::string missing =
      errorOf(corridorWith(R"(, "doors": [{"leg": 0, "side": "left", "centre": 3}])"));
  EXPECT_NE(missing.find("centre_m: missing required key (found \"centre\""), std::string::npos)
      << missing;
  EXPECT_NE(errorOf(R"({"name": "t"})").find("path: missing required key"), std::string::npos);
  EXPECT_NE(errorOf(R"({"name": "t", "path": {"waypoints": [[1, 0], [2, 0]]},
                        "noise": {"range_sigma_m": 5}})")
                .find("noise.range_sigma_m"),
            std::string::npos);
}

/// A valid world with `cameras` as its sensors.cameras block.
std::string camerasWith(const std::string& cameras) {
  return R"({"name": "t", "path": {"waypoints": [[1, 0], [2, 0]]}, "sensors": {"cameras": )" +
         cameras + "}}";
}

TEST(WorldLoader, CameraImagingDefaultsAndOverrides) {
  const WorldSpec d = parseWorldText(camerasWith("{}"), "w.json");
  EXPECT_EQ(d.sensors.cameras.exposure.gain[0], 0.8);
  EXPECT_EQ(d.sensors.cameras.blur.blurred_fraction, 0.3);
  EXPECT_EQ(d.sensors.cameras.lens.vignetting, 0.25);
  EXPECT_FALSE(d.sensors.cameras.lens.hasDistortion());
  const WorldSpec w = parseWorldText(camerasWith(R"({
      "lens": {"vignetting": 0.1, "distortion": [-0.2, 0.05, 0.0, 0.001, 0.0]},
      "blur": {"psf_sigma_px": [0.1, 0.2], "blurred_fraction": 0.5, "defocus_sigma_px": [2, 3],
               "motion_share": 0.25, "motion_length_px": [4, 4]},
      "exposure": {"gain": [0.9, 1.1], "offset_dn": [-2, 2], "gamma": [1, 1.2]},
      "noise": {"read_sigma_dn": 3, "full_well_e": 9000}})"),
                                     "w.json");
  const CameraOptions& c = w.sensors.cameras;
  EXPECT_EQ(c.lens.vignetting, 0.1);
  EXPECT_EQ(c.lens.distortion[3], 0.001);
  EXPECT_EQ(c.blur.psf_sigma_px[1], 0.2);
  EXPECT_EQ(c.blur.motion_length_px[0], 4.0);
  EXPECT_EQ(c.blur.motion_share, 0.25);
  EXPECT_EQ(c.exposure.offset_dn[0], -2.0);
  EXPECT_EQ(c.exposure.gamma[1], 1.2);
  EXPECT_EQ(c.noise.read_sigma_dn, 3.0);
  EXPECT_EQ(c.noise.full_well_e, 9000.0);
}

TEST(WorldLoader, BadCameraImagingValuesNameTheKey) {
  const std::string order = errorOf(camerasWith(R"({"exposure": {"gain": [1.2, 0.8]}})"));
  EXPECT_NE(order.find("w.json: sensors.cameras.exposure.gain: [1.2, 0.8]: the lower bound"),
            std::string::npos)
      << order;
  const std::string range = errorOf(camerasWith(R"({"exposure": {"gain": [0, 1]}})"));
  EXPECT_NE(range.find("sensors.cameras.exposure.gain: 0 is out of range (0, 10]"),
            std::string::npos)
      << range;
  const std::string shape = errorOf(camerasWith(R"({"blur": {"defocus_sigma_px": 2}})"));
  EXPECT_NE(shape.find("sensors.cameras.blur.defocus_sigma_px: expected an array of 2 numbers"),
            std::string::npos)
      << shape;
  const std::string fraction = errorOf(camerasWith(R"({"blur": {"blurred_fraction": 1.3}})"));
  EXPECT_NE(fraction.find("sensors.cameras.blur.blurred_fraction"), std::string::npos) << fraction;
  const std::string noise = errorOf(camerasWith(R"({"noise": {"full_well_e": "big"}})"));
  EXPECT_NE(noise.find("sensors.cameras.noise.full_well_e: expected a number"), std::string::npos)
      << noise;
  const std::string typo = errorOf(camerasWith(R"({"noise": {"read_sigma": 2}})"));
  EXPECT_NE(typo.find("unknown key \"sensors.cameras.noise.read_sigma\""), std::string::npos)
      << typo;
  EXPECT_NE(typo.find("did you mean \"read_sigma_dn\""), std::string::npos) << typo;
  const std::string tangential =
      errorOf(camerasWith(R"({"lens": {"distortion": [0, 0, 0.3, 0, 0]}})"));
  EXPECT_NE(tangential.find("sensors.cameras.lens.distortion: the tangential"), std::string::npos)
      << tangential;
  const std::string fold = errorOf(camerasWith(R"({"lens": {"distortion": [-0.6, 0, 0, 0, 0]}})"));
  EXPECT_NE(fold.find("lens.distortion: the radial distortion folds over"), std::string::npos)
      << fold;
  const std::string moved = errorOf(R"({"name": "t", "path": {"waypoints": [[1, 0], [2, 0]]},
                                        "noise": {"image_sigma": 2}})");
  EXPECT_NE(moved.find("noise.image_sigma: moved"), std::string::npos) << moved;
  EXPECT_NE(moved.find("sensors.cameras.noise"), std::string::npos) << moved;
}

TEST(WorldLoader, SyntaxErrorsAndDuplicateKeys) {
  EXPECT_NE(errorOf("{\"name\": ").find("w.json: invalid JSON"), std::string::npos);
  EXPECT_NE(errorOf(R"({"name": "a", "name": "b"})").find("duplicate key \"name\""),
            std::string::npos);
  EXPECT_NE(errorOf("[1, 2]").find("expected an object"), std::string::npos);
}

TEST(WorldLoader, MissingFileIsAConfigError) {
  EXPECT_THROW(loadWorldFile("/nonexistent/world.json"), ConfigError);
}

TEST(WorldLoader, FreeRectanglesMustBeRectangles) {
  const std::string base = R"({"name": "t", "path": {"waypoints": [[1, 0], [2, 0]]},
    "rectangles": [{"kind": "panel", "corners": )";
  const WorldSpec ok = parseWorldText(base + "[[0,0,0],[1,0,0],[1,0,1],[0,0,1]]}]}", "w.json");
  ASSERT_EQ(ok.rectangles.size(), 1u);
  EXPECT_EQ(ok.rectangles[0].kind, "panel");
  EXPECT_NE(errorOf(base + "[[0,0,0],[1,0,0],[1.5,0,1],[0,0,1]]}]}").find("complete a rectangle"),
            std::string::npos);
  EXPECT_NE(errorOf(base + "[[0,0,0],[1,0,0],[1.5,0,1],[0.5,0,1]]}]}").find("perpendicular"),
            std::string::npos);
}

}  // namespace
}  // namespace pmap::sim
