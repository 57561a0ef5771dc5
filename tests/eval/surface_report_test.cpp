#include "pmap/eval/surface_report.h"

#include <gtest/gtest.h>

namespace pmap::eval {
namespace {
using nlohmann::json;

SurfaceEvaluation twoOfThree() {
  SurfaceEvaluation e;
  e.surfaces = 4;
  e.map_surfaces_unmatched = 1;
  e.gt_surfaces = 3;
  e.matched_surfaces = 2;
  e.matched_by_kind["wall"] = {2, 2};
  e.matched_by_kind["door"] = {1, 0};
  e.unmatched.push_back({7, "door", 450});
  for (int id : {1, 2}) {
    SurfaceScore s;
    s.gt_id = id;
    s.kind = "wall";
    s.hits = 1000;
    s.map_id = 10 + id;
    s.map_surfaces_matching = id;
    s.points = 900;
    s.normal_error_deg = id;
    s.offset_error_m = 0.01 * id;
    s.corner_error_m = 0.1 * id;
    s.matching_spread_m = 0.05 * (id - 1);
    e.normal_error_deg.add(s.normal_error_deg);
    e.offset_error_m.add(s.offset_error_m);
    e.corner_error_m.add(s.corner_error_m);
    e.per_surface.push_back(s);
  }
  e.labels.recall = 0.9;
  e.labels.precision = 0.8;
  e.labels.f1 = 2 * 0.9 * 0.8 / 1.7;
  e.labels.clutter_points = 50;
  e.labels.clutter_rejected = 40;
  e.labels.clutter_rejected_fraction = 0.8;
  return e;
}

TEST(SurfaceReport, KeysAtTheTopLevel) {
  json doc = {{"pose_ate_m", 0.01}};
  addSurfaceKeys(twoOfThree(), SurfaceEvalOptions{}, doc);
  EXPECT_EQ(doc["pose_ate_m"], 0.01);
  EXPECT_EQ(doc["surfaces"], 4);
  EXPECT_EQ(doc["gt_surfaces"], 3);
  EXPECT_EQ(doc["matched_surfaces"], 2);
  EXPECT_EQ(doc["map_surfaces_unmatched"], 1);
  EXPECT_EQ(doc["matched_by_kind"]["door"], json({{"gt", 1}, {"matched", 0}}));
  EXPECT_EQ(doc["unmatched"][0], json({{"id", 7}, {"kind", "door"}, {"hits", 450}}));
  EXPECT_NEAR(doc["normal_error_deg"]["mean"].get<double>(), 1.5, 1e-12);
  EXPECT_NEAR(doc["corner_error_m"]["max"].get<double>(), 0.2, 1e-12);
  EXPECT_NEAR(doc["offset_error_m"]["mean"].get<double>(), 0.015, 1e-12);
  ASSERT_EQ(doc["per_surface"].size(), 2u);
  const json& p = doc["per_surface"][1];
  EXPECT_EQ(p["gt_id"], 2);
  EXPECT_EQ(p["map_id"], 12);
  EXPECT_EQ(p["map_surfaces_matching"], 2);
  EXPECT_EQ(p["points"], 900);
  EXPECT_EQ(p["kind"], "wall");
  EXPECT_NEAR(p["corner_error_m"].get<double>(), 0.2, 1e-12);
  EXPECT_NEAR(p["matching_spread_m"].get<double>(), 0.05, 1e-12);
  EXPECT_EQ(doc["label_recall"], 0.9);
  EXPECT_EQ(doc["label_precision"], 0.8);
  EXPECT_EQ(doc["clutter_points"], 50);
  EXPECT_EQ(doc["clutter_rejected_fraction"], 0.8);
  EXPECT_EQ(doc["surface_options"]["min_hits"], 200);
}

TEST(SurfaceReport, UndefinedValuesAreNull) {
  json doc;
  addSurfaceKeys(SurfaceEvaluation{}, SurfaceEvalOptions{}, doc);
  EXPECT_TRUE(doc["corner_error_m"]["mean"].is_null());
  EXPECT_TRUE(doc["corner_error_m"]["max"].is_null());
  EXPECT_TRUE(doc["label_recall"].is_null());
  EXPECT_TRUE(doc["label_f1"].is_null());
  EXPECT_TRUE(doc["clutter_rejected_fraction"].is_null());
  EXPECT_TRUE(doc["per_surface"].is_array());
  EXPECT_TRUE(doc["unmatched"].is_array());
  EXPECT_TRUE(doc["matched_by_kind"].is_object());
  EXPECT_NE(surfaceReportText(doc).find("corner -/- m"), std::string::npos);
}

TEST(SurfaceReport, TextNamesTheHeadlineNumbers) {
  json doc;
  EXPECT_EQ(surfaceReportText(doc), "");
  addSurfaceKeys(twoOfThree(), SurfaceEvalOptions{}, doc);
  const std::string text = surfaceReportText(doc);
  EXPECT_NE(text.find("surfaces matched 2 / 3 (map surfaces 4)"), std::string::npos) << text;
  EXPECT_NE(text.find("corner 0.1500/0.2000 m"), std::string::npos) << text;
  EXPECT_NE(text.find("recall 0.9000"), std::string::npos) << text;
  EXPECT_NE(text.find("clutter rejected 0.8000 of 50 points"), std::string::npos) << text;
}

}  // namespace
}  // namespace pmap::eval
