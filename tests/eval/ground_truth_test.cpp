#include "pmap/eval/ground_truth.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "pmap/common/error.h"

namespace pmap::eval {
namespace {

TEST(GroundTruthGeometry, DistanceToRectangleInsideEdgeAndCorner) {
  // 2 x 1 rectangle in the plane z = 0.
  const std::array<Eigen::Vector3d, 4> r = {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(2, 0, 0),
                                            Eigen::Vector3d(2, 1, 0), Eigen::Vector3d(0, 1, 0)};
  EXPECT_NEAR(distanceToRectangle(r, {1, 0.5, 0.3}), 0.3, 1e-12);         // above the inside
  EXPECT_NEAR(distanceToRectangle(r, {1, -0.4, 0.3}), 0.5, 1e-12);        // beyond an edge
  EXPECT_NEAR(distanceToRectangle(r, {3, 2, 0}), std::sqrt(2.0), 1e-12);  // past a corner
  EXPECT_NEAR(distanceToRectangle(r, {0.5, 0.5, -0.2}), 0.2, 1e-12);
}

TEST(GroundTruthGeometry, CylinderAndBoxDistances) {
  GroundTruth gt;
  gt.cylinders.push_back({5, "bin", {0, 0}, 0.25, 0.0, 1.0});
  EXPECT_NEAR(gt.distance(5, {1.0, 0, 0.5}), 0.75, 1e-12);  // beside
  EXPECT_NEAR(gt.distance(5, {0.1, 0, 1.5}), 0.5, 1e-12);   // above the lid
  EXPECT_NEAR(gt.distance(5, {0.2, 0, 0.5}), 0.05, 1e-12);  // inside, near the side
  EXPECT_NEAR(gt.distance(5, {1.25, 0, 2.0}), std::sqrt(2.0), 1e-12);
  GtBox b;
  b.id = 6;
  b.min = {-0.5, -0.5, 0};
  b.max = {0.5, 0.5, 2};
  b.centre = {10, 0};
  b.yaw = M_PI / 4;
  gt.boxes.push_back(b);
  EXPECT_NEAR(gt.distance(6, {10 + 1.0, 0, 1}), 1.0 - std::sqrt(0.5), 1e-9);
  EXPECT_TRUE(std::isnan(gt.distance(99, {0, 0, 0})));
  EXPECT_TRUE(gt.isClutter(5));
  EXPECT_FALSE(gt.isClutter(99));
}

/// A minimal gt.json with `field` (a JSON member) added to surfaces[0] /
/// the document; returns the message readGroundTruth throws ("" if none).
std::string groundTruthError(const std::string& name, const std::string& text) {
  const std::filesystem::path dir = std::filesystem::path(PMAP_TEST_TMP_DIR) / "ground_truth";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / name) << text;
  try {
    readGroundTruth(dir / name);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::string gtText(const std::string& surface_id, const std::string& hits,
                   const std::string& sigma = "0.01") {
  return "{\"world\": \"t\",\n \"sigma_m\": " + sigma +
         ",\n \"poses\": [[0, 0, 0, 0, 0, 0, 0]],\n \"surfaces\": [{\"id\": " + surface_id +
         ", \"kind\": \"wall\", \"corners\": [[0,0,0],[1,0,0],[1,0,1],[0,0,1]], "
         "\"normal\": [0,1,0]}],\n \"structure_scans\": [{\"index\": 0, \"hits\": " +
         hits + "}]}\n";
}

TEST(GroundTruthFile, Item12_ValidFileReads) {
  EXPECT_EQ(groundTruthError("good.gt.json", gtText("3", "[3, -1, 3]")), "");
}

TEST(GroundTruthFile, Item12_NonFiniteAndNonIntegerValuesAreInputErrorsNamingTheElement) {
  // The JSON parser refuses 1e999 (it would be inf); the message gives the line.
  EXPECT_NE(groundTruthError("inf.gt.json", gtText("3", "[3]", "1e999"))
                .find("inf.gt.json:2: not valid JSON: "),
            std::string::npos);
  EXPECT_NE(groundTruthError("nan.gt.json", gtText("3", "[3]", "NaN")).find("nan.gt.json:2: "),
            std::string::npos);
  EXPECT_NE(
      groundTruthError("id.gt.json", gtText("1.5", "[3]")).find("surfaces[].id is not an integer"),
      std::string::npos);
  EXPECT_NE(groundTruthError("hit.gt.json", gtText("3", "[3, 1e20]"))
                .find("structure_scans[index 0].hits[1] is not an integer in int range"),
            std::string::npos);
  EXPECT_NE(groundTruthError("big.gt.json", gtText("3", "[3, 99999999999999999999]"))
                .find("hits[1] is not an integer"),
            std::string::npos);
}

TEST(GroundTruthFile, Issue16_PeopleWalkingThroughAreReadAsPeople) {
  std::string text = gtText("3", "[3, 9, -1]");
  text.insert(text.rfind('}'), R"(, "people": [{"id": 9, "kind": "person", "radius_m": 0.25}])");
  const std::filesystem::path dir = std::filesystem::path(PMAP_TEST_TMP_DIR) / "ground_truth";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "people.gt.json") << text;
  const GroundTruth gt = readGroundTruth(dir / "people.gt.json");
  EXPECT_TRUE(gt.isPerson(9));
  EXPECT_FALSE(gt.isPerson(3));
  EXPECT_FALSE(gt.isClutter(9));  // no fixed shape: not among the cylinders and boxes
  std::string no_id = gtText("3", "[3]");
  no_id.insert(no_id.rfind('}'), R"(, "people": [{"kind": "person"}])");
  EXPECT_NE(groundTruthError("people_bad.gt.json", no_id).find("people[]"), std::string::npos);
}

TEST(GroundTruthFile, Item12_DirectoryIsAnInputErrorNamingThePath) {
  const std::filesystem::path dir = std::filesystem::path(PMAP_TEST_TMP_DIR) / "ground_truth_dir";
  std::filesystem::create_directories(dir);
  try {
    readGroundTruth(dir);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), dir.string() + ": is a directory, not a file");
  }
}

}  // namespace
}  // namespace pmap::eval
