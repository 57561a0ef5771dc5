#include "pmap/products/output_layout.h"

#include <cmath>
#include <cstdio>
#include <regex>

namespace pmap::products {
namespace {

using Kind = LayoutEntry::Kind;
using Owner = LayoutEntry::Owner;

std::vector<LayoutEntry> makeEntries() {
  using L = OutputLayout;
  const std::string report = std::string(L::kReportDir) + "/";
  return {
      {L::kPosesTxt, Kind::kFile, Owner::kRun, "the trajectory used (s, m, rad)"},
      {L::kPosesTum, Kind::kFile, Owner::kRun, "the same trajectory in TUM format"},
      {L::kScansCsv, Kind::kFile, Owner::kRun, "one row per placed structure scan"},
      {L::kPointsPly, Kind::kFile, Owner::kRun, "the structure points (binary PLY)"},
      {L::kRawWrl, Kind::kFile, Owner::kRun, "the raw polygon map (VRML97)"},
      {L::kRawGlb, Kind::kFile, Owner::kRun, "the raw map as glTF binary, geometry only"},
      {L::kMapWrl, Kind::kFile, Owner::kRun, "the planar map (VRML97)"},
      {L::kTexturesDir, Kind::kDirectory, Owner::kRun, "the texture images of map.wrl"},
      {"textures/surface_<n>_<n>.png", Kind::kPattern, Owner::kRun, "a texture tile"},
      {"textures/surface_<n>.png", Kind::kPattern, Owner::kRun, "a texture (one tile)"},
      {L::kMapGlb, Kind::kFile, Owner::kRun, "the planar map as glTF binary"},
      {L::kMapGeometryGlb, Kind::kFile, Owner::kRun, "map.glb without textures"},
      {L::kTexturesCsv, Kind::kFile, Owner::kRun, "one row per texture image"},
      {L::kFramesCsv, Kind::kFile, Owner::kRun, "one row per camera image"},
      {L::kMapScene, Kind::kFile, Owner::kRun, "the map as an MRPT scene"},
      {L::kViewerHtml, Kind::kFile, Owner::kRun, "the map in a browser"},
      {L::kReportDir, Kind::kDirectory, Owner::kRun, "pictures and report.html"},
      {report + L::kReportHtml, Kind::kFile, Owner::kRun, "the report page"},
      {report + L::kReportPerspective, Kind::kFile, Owner::kRun, "the map in perspective"},
      {report + L::kReportTop, Kind::kFile, Owner::kRun, "the map from above"},
      {report + L::kReportIterations, Kind::kFile, Owner::kRun, "offline EM chart"},
      {report + L::kReportPerScan, Kind::kFile, Owner::kRun, "online EM chart"},
      {L::kSurfacesCsv, Kind::kFile, Owner::kRun, "one row per map surface"},
      {L::kSummary, Kind::kFile, Owner::kRun, "counts and timings"},
      {L::kOnlineCsv, Kind::kFile, Owner::kRun, "online mode: one row per structure scan"},
      {L::kSnapshotsDir, Kind::kDirectory, Owner::kRun, "online maps every N scans"},
      {"snapshots/map_<n>.wrl", Kind::kPattern, Owner::kRun, "the map after N scans"},
      {L::kEffectiveIni, Kind::kFile, Owner::kRun, "the configuration in force"},
      {L::kManifest, Kind::kFile, Owner::kRun, "the files of the run, sizes and SHA-256"},
      {L::kPosesGraph, Kind::kFile, Owner::kRun, "the pose graph (loop closure; MRPT format)"},
      {L::kGridPng, Kind::kFile, Owner::kRun, "the pose laser's occupancy grid as a picture"},
      {L::kGridMap, Kind::kFile, Owner::kRun, "the pose laser's occupancy grid (MRPT)"},
      {L::kSimpleMap, Kind::kFile, Owner::kRun, "the pose laser's scans and poses (MRPT)"},
      {L::kEvalJson, Kind::kFile, Owner::kEvaluation, "map-eval's evaluation"},
      {"octomap_<x>cm.bt", Kind::kPattern, Owner::kEvaluation, "map-eval's OctoMap baselines"},
  };
}

std::string regexFor(const std::string& pattern) {
  std::string out;
  for (std::size_t i = 0; i < pattern.size(); ++i) {
    if (pattern.compare(i, 3, "<n>") == 0) {
      out += "-?[0-9]+";
      i += 2;
    } else if (pattern.compare(i, 3, "<x>") == 0) {
      out += "[0-9]+(\\.[0-9]+)?";
      i += 2;
    } else if (std::string("\\^$.|?*+()[]{}").find(pattern[i]) != std::string::npos) {
      out += std::string("\\") + pattern[i];
    } else {
      out += pattern[i];
    }
  }
  return out;
}

struct Matcher {
  const LayoutEntry* entry;
  std::regex pattern;
};

const std::vector<Matcher>& matchers() {
  static const std::vector<Matcher> all = [] {
    std::vector<Matcher> m;
    for (const LayoutEntry& e : OutputLayout::entries()) {
      m.push_back({&e, std::regex(regexFor(e.name))});
    }
    return m;
  }();
  return all;
}

/// "<name>" without a ".tmp-<pid>" / ".old-<pid>" suffix.
std::string withoutTemporarySuffix(const std::string& name) {
  static const std::regex kSuffix("(.+)\\.(tmp|old)-[0-9]+");
  std::smatch m;
  return std::regex_match(name, m, kSuffix) ? m[1].str() : name;
}

std::string normalised(const std::string& relative) {
  std::string r = relative;
  while (r.rfind("./", 0) == 0) {
    r.erase(0, 2);
  }
  while (!r.empty() && r.back() == '/') {
    r.pop_back();
  }
  return r;
}

}  // namespace

std::string OutputLayout::textureFile(std::int32_t surface_id) {
  return std::string(kTexturesDir) + "/surface_" + std::to_string(surface_id) + ".png";
}

std::string OutputLayout::textureFile(std::int32_t surface_id, std::int32_t tile) {
  return std::string(kTexturesDir) + "/surface_" + std::to_string(surface_id) + "_" +
         std::to_string(tile) + ".png";
}

std::string OutputLayout::snapshotFile(std::size_t scans) {
  char name[48];
  std::snprintf(name, sizeof name, "/map_%06zu.wrl", scans);
  return kSnapshotsDir + std::string(name);
}

std::string OutputLayout::octomapFile(double resolution_m) {
  char cm[32];
  std::snprintf(cm, sizeof cm, "%g", std::round(resolution_m * 1e4) / 100);  // 0.1 mm steps
  return std::string("octomap_") + cm + "cm.bt";
}

const std::vector<LayoutEntry>& OutputLayout::entries() {
  static const std::vector<LayoutEntry> all = makeEntries();
  return all;
}

const LayoutEntry* OutputLayout::find(const std::string& relative) {
  const std::string r = normalised(relative);
  for (const std::string& name : {r, withoutTemporarySuffix(r)}) {
    for (const Matcher& m : matchers()) {
      if (std::regex_match(name, m.pattern)) {
        return m.entry;
      }
    }
  }
  return nullptr;
}

bool OutputLayout::names(const std::string& relative) {
  return find(relative) != nullptr;
}

bool OutputLayout::manifestExempt(const std::string& relative) {
  const LayoutEntry* e = find(relative);
  return e != nullptr && (e->owner == Owner::kEvaluation || e->name == kManifest);
}

}  // namespace pmap::products
