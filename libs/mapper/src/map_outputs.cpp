#include "pmap/mapper/map_outputs.h"

#include <algorithm>
#include <cstdio>

#include "pmap/common/atomic_file.h"
#include "pmap/common/interrupt.h"
#include "pmap/products/map_gltf.h"
#include "pmap/products/map_vrml.h"
#include "pmap/products/output_layout.h"
#include "pmap/products/texture_index.h"
#include "pmap/report/report.h"
#include "pmap/scene/map_scene.h"
#include "pmap/scene/scene_file.h"
#include "pmap/viewer/viewer_html.h"

namespace pmap::mapper {
namespace {

using products::OutputLayout;

// {min, p50, max} of the values; null when there are none.
nlohmann::json range(std::vector<double> v) {
  if (v.empty()) {
    return nullptr;
  }
  std::sort(v.begin(), v.end());
  return {{"min", v.front()}, {"p50", v[v.size() / 2]}, {"max", v.back()}};
}

// frames.csv: what each camera frame did for the textures.
void writeFramesCsv(const std::filesystem::path& csv, const MapProducts& p) {
  const texture::TextureResult& t = *p.texture;
  writeFileAtomically(csv, [&](std::ostream& out) {
    out << "label,timestamp,used,gain,detail_slope\n";
    char buf[160];
    for (std::size_t i = 0; i < p.frames.size(); ++i) {
      std::snprintf(buf, sizeof buf, "%s,%.6f,%d,%.4f,%.4f\n", p.frames[i].label.c_str(),
                    p.frames[i].timestamp, t.frame_used[i] != 0 ? 1 : 0, t.gains[i],
                    t.detail_slope[i]);
      out << buf;
    }
  });
}

}  // namespace

void writeMapFiles(const std::filesystem::path& dir, const std::string& folder_name,
                   const MapProducts& p, const MappingResult& r, const OutputOptions& options) {
  using L = OutputLayout;
  const products::MapModel& m = p.model;
  const std::size_t surfaces = r.planar->map.surfaces.size();
  const std::size_t fine = m.fine.triangles.size();
  products::writeMapVrml(dir / L::kMapWrl, m,
                         "planar-mapper map: " + std::to_string(surfaces) + " rectangles (" +
                             std::to_string(m.quads.size()) + " textured quads), " +
                             std::to_string(fine) + " fine triangles");
  const bool textured = p.texture.has_value();
  if (textured) {
    products::writeTexturesCsv(dir / L::kTexturesCsv, m);
    writeFramesCsv(dir / L::kFramesCsv, p);
    // The geometry alone, for size comparisons (map-eval's planar_map).
    products::writeMapGeometryGlb(dir / L::kMapGeometryGlb, m);
  }
  const std::vector<std::uint8_t> glb = products::encodeMapGlb(m, textured);
  writeFileAtomically(dir / L::kMapGlb, [&glb](std::ostream& os) {
    os.write(reinterpret_cast<const char*>(glb.data()), static_cast<std::streamsize>(glb.size()));
  });
  throwIfInterrupted();
  std::vector<Eigen::Vector3f> points;
  const points::PointMap& map = r.points.map;
  points.reserve(map.size());
  for (const Eigen::Vector3d& x : map.xyz()) {
    points.push_back(x.cast<float>());
  }
  const nlohmann::json info = {{"title", "planar-mapper: " + folder_name},
                               {"surfaces", surfaces},
                               {"fine triangles", fine},
                               {"points", map.size()},
                               {"textured", textured}};
  viewer::writeViewerHtml(dir / L::kViewerHtml, glb, points, info);
  throwIfInterrupted();
  scene::SceneOptions scene_options;
  scene_options.points = options.scene_points ? &map.xyz() : nullptr;
  scene::writeMapScene(dir / L::kMapScene, *scene::buildMapScene(m, scene_options));
  throwIfInterrupted();
}

std::vector<std::string> writeReportFiles(const std::filesystem::path& out, const MapProducts& p,
                                          const MappingResult& r, const nlohmann::json& summary) {
  std::vector<report::OnlineScanRow> rows;
  for (const OnlineRecord& rec : r.planar->online) {
    rows.push_back({rec.scan, rec.em_ms, rec.surfaces});
  }
  return report::writeReport(out, report::ReportInputs{p.model, summary, std::move(rows)}).warnings;
}

nlohmann::json textureSummary(const MapperConfig& config, const MapProducts& p) {
  using nlohmann::json;
  if (!p.texture) {
    return {{"textured", false}, {"reason", p.untextured_reason}};
  }
  const texture::TextureResult& t = *p.texture;
  std::vector<double> gains, slopes;
  std::size_t unknown_slopes = 0;
  for (std::size_t i = 0; i < t.gains.size(); ++i) {
    if (t.frame_used[i] != 0) {
      gains.push_back(t.gains[i]);
      if (t.detail_slope[i] >= 0) {
        slopes.push_back(t.detail_slope[i]);
      } else {
        ++unknown_slopes;
      }
    }
  }
  return {{"textured", true},
          {"blend", config.texture.blend},
          {"frames", t.frames + p.frames_without_pose},
          {"frames_without_pose", p.frames_without_pose},
          {"frames_used", t.frames_used},
          {"image_reads", t.image_reads},
          {"tiles", t.tiles},
          {"textured_tiles", t.textured_tiles},
          {"texels", t.texels},
          {"coverage", t.coverage},
          {"pixels_per_m", t.pixels_per_m},
          {"fine_vertices", t.fine_vertices},
          {"fine_vertices_seen", t.fine_vertices_seen},
          {"exposure_gains", range(gains)},
          {"detail_slope", range(slopes)},
          {"detail_slope_unknown", unknown_slopes},
          {"message", t.message}};
}

}  // namespace pmap::mapper
