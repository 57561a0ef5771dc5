// peer-bench: issue 16's peer benchmark. Runs PCL's and CGAL's plane
// detectors on one cloud with the benchmark's one parameter rule (sigma = the
// median root smallest eigenvalue of 100-neighbour covariances over 2,000
// points, floor 2 mm; inlier distance 2.5 sigma; minimum support max(200,
// 0.5 % of the points)), scores them and planar-mapper's result on the same
// cloud against the simulator's ground-truth planes (RSPD matching,
// pmap/eval/plane_detection.h) and writes the figures as JSON.
// Not part of the product: built with -DPMAP_PEER_BENCH=ON by
// scripts/peer-benchmark.sh. Exit codes: 0 ok, 1 usage, 2 input error.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "peer_methods.h"
#include "pmap/common/error.h"
#include "pmap/common/ply.h"
#include "pmap/em/noise_estimate.h"
#include "pmap/eval/ground_truth.h"
#include "pmap/eval/map_files.h"
#include "pmap/eval/plane_detection.h"
#include "pmap/eval/point_labels.h"

namespace {

using pmap::peers::Planes;

const char* const kUsage =
    "usage: peer-bench --cloud CLOUD.ply [--gt WORLD.gt.json] [--ours DIR] [--only NAME] "
    "--json OUT.json\n"
    "  --cloud  a PLY with x y z (with --gt: a planar-mapper points.ply of a run on the world's\n"
    "           true poses, whose scan and beam columns give each point's ground-truth plane)\n"
    "  --gt     the simulator's ground truth: planes are scored (precision, recall, F1)\n"
    "  --ours   a planar-mapper --cloud CLOUD.ply output folder (points.ply, summary.json)\n"
    "  --only   run one library method (pcl-sac, pcl-rg, cgal-ransac, cgal-rg) or none\n";

struct Args {
  std::string cloud, gt, ours, only, json;
};

Args parseArgs(int argc, char** argv) {
  Args a;
  const std::map<std::string, std::string*> keys = {{"--cloud", &a.cloud},
                                                    {"--gt", &a.gt},
                                                    {"--ours", &a.ours},
                                                    {"--only", &a.only},
                                                    {"--json", &a.json}};
  for (int i = 1; i < argc; ++i) {
    const std::string k = argv[i];
    if (k == "--help" || k == "-h") {
      std::cout << kUsage;
      std::exit(0);
    }
    const auto it = keys.find(k);
    if (it == keys.end() || i + 1 >= argc) {
      throw pmap::ConfigError(it == keys.end() ? "unknown option '" + k + "'"
                                               : k + " needs a value");
    }
    *it->second = argv[++i];
  }
  if (a.cloud.empty() || a.json.empty()) {
    throw pmap::ConfigError("--cloud and --json are required");
  }
  const std::vector<std::string> only = {"", "pcl-sac", "pcl-rg", "cgal-ransac", "cgal-rg", "none"};
  if (std::find(only.begin(), only.end(), a.only) == only.end()) {
    throw pmap::ConfigError("--only '" + a.only + "' is not a method (" + kUsage + ")");
  }
  return a;
}

struct Cloud {
  std::vector<Eigen::Vector3d> points;
  std::vector<int> plane;          ///< ground-truth plane per point (empty: no ground truth)
  std::vector<std::string> kinds;  ///< per ground-truth plane
  std::map<int, std::vector<int>> members;  ///< ground-truth plane -> its points
};

Cloud readCloud(const Args& a) {
  Cloud c;
  if (a.gt.empty()) {
    const pmap::PlyVertices v = pmap::readPlyVertices(a.cloud);
    const int x = v.find("x"), y = v.find("y"), z = v.find("z");
    if (x < 0 || y < 0 || z < 0) {
      throw pmap::InputError(a.cloud + ": PLY vertices lack x, y or z");
    }
    for (std::size_t i = 0; i < v.size(); ++i) {
      c.points.emplace_back(v.columns[x][i], v.columns[y][i], v.columns[z][i]);
    }
    return c;
  }
  const pmap::eval::MapPoints m = pmap::eval::readMapPoints(a.cloud);
  const pmap::eval::GroundTruth gt = pmap::eval::readGroundTruth(a.gt);
  c.points = m.xyz;
  pmap::eval::GtPlanes planes =
      pmap::eval::groundTruthPlanes(gt, m.xyz, pmap::eval::pointLabels(gt, m));
  c.plane = std::move(planes.plane_of_point);
  c.kinds = std::move(planes.kinds);
  for (std::size_t i = 0; i < c.plane.size(); ++i) {
    c.members[c.plane[i]].push_back(static_cast<int>(i));
  }
  return c;
}

/// planar-mapper's surfaces on the cloud: points.ply's beam is the index of
/// the input vertex (--cloud), surface its most likely surface.
Planes oursPlanes(const std::string& dir, std::size_t n) {
  const pmap::eval::MapPoints m = pmap::eval::readMapPoints(dir + "/points.ply");
  std::map<int, std::vector<int>> by_surface;
  for (std::size_t i = 0; i < m.beam.size(); ++i) {
    if (m.beam[i] < 0 || static_cast<std::size_t>(m.beam[i]) >= n) {
      throw pmap::InputError(dir + "/points.ply: beam " + std::to_string(m.beam[i]) +
                             " is not a vertex of the cloud (not a --cloud run on it?)");
    }
    if (m.surface[i] >= 0) {
      by_surface[m.surface[i]].push_back(m.beam[i]);
    }
  }
  Planes planes;
  for (auto& [id, idx] : by_surface) {
    planes.push_back(std::move(idx));
  }
  return planes;
}

nlohmann::json scoreJson(const Cloud& c, const Planes& planes, std::size_t min_support) {
  nlohmann::json j;
  j["planes"] = planes.size();
  if (c.plane.empty()) {
    return j;
  }
  pmap::eval::PlaneScoreOptions o;
  o.min_gt_points = min_support;
  const pmap::eval::PlaneScore s = pmap::eval::scorePlanes(c.points, c.plane, planes, o);
  j["precision"] = s.precision;
  j["recall"] = s.recall;
  j["f1"] = s.f1;
  j["detected_matched"] = s.detected_matched;
  j["gt_planes"] = s.gt_planes;
  j["gt_matched"] = s.gt_matched;
  j["gt_split"] = s.gt_split;
  // Each missed plane: its points and the normal of their fit, to see what is missed.
  j["missed"] = nlohmann::json::array();
  for (const int plane : s.missed) {
    const Eigen::Vector3d n = pmap::eval::fittedNormal(c.points, c.members.at(plane));
    j["missed"].push_back({{"plane", plane},
                           {"kind", c.kinds[static_cast<std::size_t>(plane)]},
                           {"points", c.members.at(plane).size()},
                           {"normal", {n.x(), n.y(), n.z()}}});
  }
  return j;
}

int run(const Args& a) {
  const Cloud c = readCloud(a);
  const std::size_t n = c.points.size();
  if (n < 200) {
    throw pmap::InputError(a.cloud + ": " + std::to_string(n) + " points, fewer than 200");
  }
  const pmap::em::NoiseEstimate sigma = pmap::em::estimateRangeSigma(c.points);
  pmap::peers::PeerParams p;
  p.inlier_m = 2.5 * sigma.sigma_m;
  p.min_support = std::max<std::size_t>(200, static_cast<std::size_t>(0.005 * n));
  nlohmann::json out = {{"cloud", a.cloud},
                        {"points", n},
                        {"sigma_m", sigma.sigma_m},
                        {"inlier_m", p.inlier_m},
                        {"min_support", p.min_support}};
  const std::vector<std::pair<std::string, std::function<Planes()>>> methods = {
      {"pcl-sac", [&] { return pmap::peers::pclSacSegmentation(c.points, p); }},
      {"pcl-rg", [&] { return pmap::peers::pclRegionGrowing(c.points, p); }},
      {"cgal-ransac", [&] { return pmap::peers::cgalEfficientRansac(c.points, p); }},
      {"cgal-rg", [&] { return pmap::peers::cgalRegionGrowing(c.points, p); }}};
  for (const auto& [name, detect] : methods) {
    if (!a.only.empty() && a.only != name) {
      continue;
    }
    std::cerr << "peer-bench: " << name << " on " << n << " points ...\n";
    const auto t0 = std::chrono::steady_clock::now();
    const Planes planes = detect();
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    nlohmann::json j = scoreJson(c, planes, p.min_support);
    j["seconds"] = s;
    out["methods"][name] = j;
  }
  if (!a.ours.empty()) {
    nlohmann::json j = scoreJson(c, oursPlanes(a.ours, n), p.min_support);
    std::ifstream f(a.ours + "/summary.json");
    const nlohmann::json summary = nlohmann::json::parse(f, nullptr, false);
    if (summary.is_discarded() || !summary.contains("timing_s")) {
      throw pmap::InputError(a.ours + "/summary.json: missing or not planar-mapper's");
    }
    j["seconds"] = summary["timing_s"]["em"];
    j["sigma_m"] = summary.value("sigma_estimate", nlohmann::json::object()).value("sigma_m", 0.0);
    out["methods"]["ours"] = j;
  }
  std::ofstream f(a.json);
  f << out.dump(1) << "\n";
  if (!f) {
    throw pmap::OutputError(a.json + ": cannot write");
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(parseArgs(argc, argv));
  } catch (const pmap::Error& e) {
    std::cerr << "peer-bench: error: " << e.what() << "\n";
    return e.exitCode();
  } catch (const std::exception& e) {
    std::cerr << "peer-bench: error: " << e.what() << "\n";
    return 3;
  }
}
