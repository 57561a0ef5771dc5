#include "pmap/sim/simulator.h"

#include <gtest/gtest.h>

#include <mrpt/img/CImage.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationImage.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose3D.h>
#include <csignal>
#include <map>
#include <nlohmann/json.hpp>
#include <set>

#include "pmap/common/error.h"
#include "pmap/common/interrupt.h"
#include "sim_test_support.h"

namespace pmap::sim {
namespace {

namespace fs = std::filesystem;

struct Scan {
  std::string label;
  double t;
  std::vector<float> ranges;
  std::vector<bool> valid;
  bool operator==(const Scan& o) const {
    return label == o.label && t == o.t && ranges == o.ranges && valid == o.valid;
  }
};

void collect(const mrpt::obs::CObservation::Ptr& obs, std::vector<Scan>& scans) {
  if (const auto s = std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(obs)) {
    Scan out{s->sensorLabel, mrpt::Clock::toDouble(s->timestamp), {}, {}};
    for (std::size_t i = 0; i < s->getScanSize(); ++i) {
      out.ranges.push_back(s->getScanRange(i));
      out.valid.push_back(s->getScanRangeValidity(i));
    }
    scans.push_back(out);
  }
}

std::vector<Scan> scansOf(const fs::path& rawlog) {
  std::vector<Scan> scans;
  for (const auto& obj : test::readRawlog(rawlog)) {
    if (const auto sf = std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(obj)) {
      for (const auto& o : *sf) {
        collect(o, scans);
      }
    } else if (const auto o = std::dynamic_pointer_cast<mrpt::obs::CObservation>(obj)) {
      collect(o, scans);
    }
  }
  return scans;
}

SimulationSummary simulate(const fs::path& dir, RawlogFormat format, std::uint64_t seed = 5,
                           double duration = 3.0, bool cameras = true,
                           std::optional<double> sigma = std::nullopt) {
  SimulatorOptions o;
  o.sigma_m = sigma;
  o.world_file = test::writeText(dir / "tiny.json", test::tinyWorldJson());
  o.seed = seed;
  o.format = format;
  o.duration_s = duration;
  o.cameras = cameras;
  o.out_prefix = (dir / "run").string();
  o.progress = false;
  return Simulator(o).run();
}

TEST(Simulator, BothFormatsContainTheSameScans) {
  const auto a = test::freshDir("sim_obs");
  const auto b = test::freshDir("sim_sf");
  const SimulationSummary sa = simulate(a, RawlogFormat::kObservations);
  simulate(b, RawlogFormat::kSensoryFrames);
  const std::vector<Scan> obs = scansOf(a / "run.rawlog");
  const std::vector<Scan> sf = scansOf(b / "run.rawlog");
  ASSERT_EQ(obs.size(), 2 * sa.cycles);
  ASSERT_EQ(obs.size(), sf.size());
  for (std::size_t i = 0; i < obs.size(); ++i) {
    EXPECT_TRUE(obs[i] == sf[i]) << "scan " << i;
  }
}

TEST(Simulator, OdometryObservationsAndActionsAgree) {
  const auto a = test::freshDir("sim_odo_obs");
  const auto b = test::freshDir("sim_odo_sf");
  simulate(a, RawlogFormat::kObservations, 5, 3.0, false);
  simulate(b, RawlogFormat::kSensoryFrames, 5, 3.0, false);
  std::vector<mrpt::poses::CPose2D> absolute;
  for (const auto& obj : test::readRawlog(a / "run.rawlog")) {
    if (const auto o = std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(obj)) {
      absolute.push_back(o->odometry);
    }
  }
  mrpt::poses::CPose2D integrated;
  std::size_t k = 0;
  for (const auto& obj : test::readRawlog(b / "run.rawlog")) {
    if (const auto acts = std::dynamic_pointer_cast<mrpt::obs::CActionCollection>(obj)) {
      integrated = integrated + acts->getBestMovementEstimation()->rawOdometryIncrementReading;
      ASSERT_LT(k, absolute.size());
      EXPECT_NEAR(integrated.x(), absolute[k].x(), 1e-9);
      EXPECT_NEAR(integrated.y(), absolute[k].y(), 1e-9);
      EXPECT_NEAR(integrated.phi(), absolute[k].phi(), 1e-9);
      ++k;
    }
  }
  EXPECT_EQ(k, absolute.size());
}

TEST(Simulator, SameSeedGivesIdenticalBytes) {
  const auto a = test::freshDir("sim_det_a");
  const auto b = test::freshDir("sim_det_b");
  const auto c = test::freshDir("sim_det_c");
  simulate(a, RawlogFormat::kObservations, 9);
  simulate(b, RawlogFormat::kObservations, 9);
  simulate(c, RawlogFormat::kObservations, 10);
  for (const char* f :
       {"run.rawlog", "run.gt.json", "run.poses.txt", "run_Images/CAMERA_LEFT_000002.jpg",
        "run_Images/CAMERA_RIGHT_000005.jpg"}) {
    EXPECT_EQ(test::readBytes(a / f), test::readBytes(b / f)) << f;
  }
  EXPECT_NE(test::readBytes(a / "run.rawlog"), test::readBytes(c / "run.rawlog"));
  EXPECT_NE(test::readBytes(a / "run_Images/CAMERA_LEFT_000002.jpg"),
            test::readBytes(c / "run_Images/CAMERA_LEFT_000002.jpg"));
}

TEST(Simulator, GroundTruthMatchesTheRawlog) {
  const auto dir = test::freshDir("sim_gt");
  const SimulationSummary s = simulate(dir, RawlogFormat::kObservations);
  std::ifstream in(dir / "run.gt.json");
  const nlohmann::json gt = nlohmann::json::parse(in);
  EXPECT_EQ(gt["format"], "pmap-gt/1");
  EXPECT_EQ(gt["world"], "tiny");
  EXPECT_EQ(gt["seed"], 5);
  std::vector<Scan> v;
  for (const Scan& scan : scansOf(dir / "run.rawlog")) {
    if (scan.label == "LASER_V") {
      v.push_back(scan);
    }
  }
  const auto& entries = gt["structure_scans"];
  ASSERT_EQ(entries.size(), v.size());
  ASSERT_EQ(entries.size(), s.structure_scans);
  for (std::size_t i = 0; i < v.size(); ++i) {
    EXPECT_EQ(entries[i]["index"], i);
    EXPECT_EQ(entries[i]["timestamp"].get<double>(), v[i].t);
    EXPECT_EQ(entries[i]["hits"].size(), v[i].ranges.size());
    for (std::size_t b = 0; b < v[i].ranges.size(); ++b) {
      if (v[i].valid[b]) {
        EXPECT_GE(entries[i]["hits"][b].get<int>(), 0);  // a valid range has a true hit
      }
    }
  }
  // A true pose at every laser timestamp, sorted by time.
  std::set<double> pose_times;
  double last = 0.0;
  for (const auto& p : gt["poses"]) {
    ASSERT_EQ(p.size(), 7u);
    EXPECT_GT(p[0].get<double>(), last);
    last = p[0].get<double>();
    pose_times.insert(last);
  }
  for (const Scan& scan : scansOf(dir / "run.rawlog")) {
    EXPECT_TRUE(pose_times.count(scan.t)) << scan.label << " at " << scan.t;
  }
  EXPECT_EQ(gt["posters"].size(), 1u);
  EXPECT_TRUE(fs::exists(dir / gt["posters"][0]["image"].get<std::string>()));
}

Eigen::Vector3d jsonPoint(const nlohmann::json& j) {
  return Eigen::Vector3d(j[0].get<double>(), j[1].get<double>(), j[2].get<double>());
}

/// End to end with MRPT's own geometry: every valid noise-free LASER_V return,
/// projected by MRPT (robot pose from gt.json (+) sensorPose (+) beam point),
/// lies on the ground-truth surface (or clutter object) its beam reports.
TEST(Simulator, StructurePointsLieOnTheirGroundTruthSurfaces) {
  const auto dir = test::freshDir("sim_points");
  simulate(dir, RawlogFormat::kObservations, 5, 6.0, false, 0.0);
  std::ifstream in(dir / "run.gt.json");
  const nlohmann::json gt = nlohmann::json::parse(in);
  std::map<double, mrpt::poses::CPose3D> poses;
  for (const auto& p : gt["poses"]) {
    poses[p[0].get<double>()] = mrpt::poses::CPose3D(p[1], p[2], p[3], p[4], p[5], p[6]);
  }
  std::map<int, nlohmann::json> objects;
  for (const char* key : {"surfaces", "clutter"}) {
    for (const auto& o : gt[key]) {
      objects[o["id"].get<int>()] = o;
    }
  }
  std::size_t scan_index = 0;
  std::size_t checked = 0;
  for (const auto& obj : test::readRawlog(dir / "run.rawlog")) {
    const auto s = std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(obj);
    if (!s || s->sensorLabel != "LASER_V") {
      continue;
    }
    const auto& hits = gt["structure_scans"][scan_index++]["hits"];
    const mrpt::poses::CPose3D sensor =
        poses.at(mrpt::Clock::toDouble(s->timestamp)) + s->sensorPose;
    for (std::size_t i = 0; i < s->getScanSize(); ++i) {
      if (!s->getScanRangeValidity(i)) {
        continue;
      }
      const double r = s->getScanRange(i);
      const double a = s->getScanAngle(i);
      double x, y, z;
      sensor.composePoint(r * std::cos(a), r * std::sin(a), 0.0, x, y, z);
      const nlohmann::json& o = objects.at(hits[i].get<int>());
      if (o.contains("normal")) {
        const Eigen::Vector3d n = jsonPoint(o["normal"]);
        EXPECT_NEAR(n.dot(Eigen::Vector3d(x, y, z) - jsonPoint(o["corners"][0])), 0.0, 1e-4)
            << "scan " << scan_index - 1 << " beam " << i << " surface " << o["id"];
      } else {
        EXPECT_NEAR(std::hypot(x - o["centre"][0].get<double>(), y - o["centre"][1].get<double>()),
                    o["radius_m"].get<double>(), 1e-4);
      }
      ++checked;
    }
  }
  EXPECT_GT(checked, 20u * 150u);
}

TEST(Simulator, ImagesAreExternalFilesMrptCanLoad) {
  const auto dir = test::freshDir("sim_images");
  const SimulationSummary s = simulate(dir, RawlogFormat::kObservations);
  EXPECT_EQ(s.images, 2u * 6u);  // 2 Hz for 3 s: images at 0, 0.6, 1.0, 1.6, 2.0, 2.6 s
  mrpt::img::CImage::setImagesPathBase((dir / "run_Images").string());
  std::size_t checked = 0;
  for (const auto& obj : test::readRawlog(dir / "run.rawlog")) {
    if (const auto img = std::dynamic_pointer_cast<mrpt::obs::CObservationImage>(obj)) {
      EXPECT_TRUE(img->image.isExternallyStored());
      EXPECT_EQ(img->image.getWidth(), 64u);  // loads the JPEG
      ++checked;
    }
  }
  EXPECT_EQ(checked, s.images);
  mrpt::img::CImage::setImagesPathBase(".");
}

/// gt.json lists every image of the rawlog, in file order, with its
/// exposure, blur and sharpness; the gains lie in the configured range.
TEST(Simulator, GroundTruthRecordsEveryImage) {
  const auto dir = test::freshDir("sim_gt_images");
  const SimulationSummary s = simulate(dir, RawlogFormat::kObservations, 5, 6.0);
  std::ifstream in(dir / "run.gt.json");
  const nlohmann::json gt = nlohmann::json::parse(in);
  std::vector<std::pair<std::string, double>> logged;
  for (const auto& obj : test::readRawlog(dir / "run.rawlog")) {
    if (const auto img = std::dynamic_pointer_cast<mrpt::obs::CObservationImage>(obj)) {
      logged.emplace_back(img->image.getExternalStorageFile(),
                          mrpt::Clock::toDouble(img->timestamp));
    }
  }
  const auto& images = gt["images"];
  ASSERT_EQ(images.size(), s.images);
  ASSERT_EQ(images.size(), logged.size());
  const auto& range = gt["config"]["cameras"]["exposure"]["gain"];
  std::set<double> gains;
  for (std::size_t i = 0; i < images.size(); ++i) {
    const auto& im = images[i];
    EXPECT_EQ(im["file"], logged[i].first);
    EXPECT_EQ(im["timestamp"].get<double>(), logged[i].second);
    EXPECT_EQ(im["image"], "run_Images/" + logged[i].first);
    EXPECT_TRUE(fs::exists(dir / im["image"].get<std::string>()));
    EXPECT_EQ(im["file"].get<std::string>().rfind(im["label"].get<std::string>(), 0), 0u);
    EXPECT_GE(im["gain"].get<double>(), range[0].get<double>());
    EXPECT_LE(im["gain"].get<double>(), range[1].get<double>());
    EXPECT_GT(im["sharpness"].get<double>(), 0.0);
    EXPECT_LE(im["sharpness"].get<double>(), 1.0 + 1e-9);
    EXPECT_GT(im["laplacian_var"].get<double>(), 0.0);
    gains.insert(im["gain"].get<double>());
  }
  EXPECT_EQ(gains.size(), images.size());  // drawn per frame
}

TEST(Simulator, NoCamerasAndDurationCut) {
  const auto dir = test::freshDir("sim_nocam");
  const SimulationSummary s = simulate(dir, RawlogFormat::kObservations, 5, 1.0, false);
  EXPECT_EQ(s.images, 0u);
  EXPECT_EQ(s.cycles, 5u);  // t = 0 .. 0.8 s (the V scan of cycle k is at t_k + 0.1)
  EXPECT_EQ(test::readRawlog(dir / "run.rawlog").size(), 3u * 5u);
  EXPECT_TRUE(fs::exists(dir / "run_Images"));  // the poster image is still written
}

// A rename fails in the middle of the commit (the backup name of poses.txt is
// taken by a non-empty directory: EISDIR after the images and gt.json were
// moved aside): the earlier set stays whole and no temporary remains.
TEST(Simulator, Item12_FailedRenameKeepsOldSet) {
  const auto dir = test::freshDir("sim_failed_rename");
  simulate(dir, RawlogFormat::kObservations, 5, 1.0);
  const fs::path blocker = dir / ("run.poses.txt.old-" + std::to_string(::getpid()));
  fs::create_directories(blocker / "keep");
  const auto before = test::snapshot(dir);
  ASSERT_GT(before.size(), 6u);  // 3 files, the images and the blocker
  try {
    simulate(dir, RawlogFormat::kSensoryFrames, 6, 2.0);
    FAIL() << "no OutputError";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("run.poses.txt: cannot move the previous output aside"),
              std::string::npos)
        << e.what();
  }
  EXPECT_EQ(test::snapshot(dir), before);
}

TEST(Simulator, Item12_ADirectoryAtTheRawlogIsRefusedBeforeAnyWork) {
  const auto dir = test::freshDir("sim_rawlog_dir");
  fs::create_directories(dir / "run.rawlog" / "keep");
  test::writeText(dir / "tiny.json", test::tinyWorldJson());
  const auto before = test::snapshot(dir);
  EXPECT_THROW(simulate(dir, RawlogFormat::kObservations), OutputError);
  EXPECT_EQ(test::snapshot(dir), before);
}

TEST(Simulator, Item12_InterruptKeepsOldSetAndRemovesTheTemporaries) {
  const auto dir = test::freshDir("sim_interrupt");
  simulate(dir, RawlogFormat::kObservations, 5, 1.0);
  const auto before = test::snapshot(dir);
  ::signal(SIGTERM, SIG_DFL);  // in case the test runner's parent ignored it
  InterruptGuard guard;
  ::raise(SIGTERM);  // recorded; run() stops at its first check, after staging
  try {
    simulate(dir, RawlogFormat::kObservations, 6, 2.0);
    FAIL() << "no Interrupted";
  } catch (const Interrupted& e) {
    EXPECT_EQ(e.exitCode(), 128 + SIGTERM);
  }
  EXPECT_EQ(test::snapshot(dir), before);
}

}  // namespace
}  // namespace pmap::sim
