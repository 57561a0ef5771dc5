#include "pmap/viewer/viewer_html.h"

#include <cstring>
#include <map>

#include "pmap/common/atomic_file.h"
#include "pmap/common/error.h"
#include "pmap/common/text.h"
#include "pmap/viewer/base64.h"
#include "pmap/viewer/html_template.h"
#include "pmap/viewer/point_subsample.h"
#include "viewer_assets.h"

namespace pmap::viewer {
namespace {

/// A GLB starts with the magic "glTF" and version 2 (little-endian uint32).
void checkGlb(const std::vector<std::uint8_t>& glb) {
  if (glb.empty()) {
    return;
  }
  const std::uint8_t header[8] = {'g', 'l', 'T', 'F', 2, 0, 0, 0};
  if (glb.size() < 20 || std::memcmp(glb.data(), header, sizeof(header)) != 0) {
    throw ProcessingError("viewer: the model is not a binary glTF 2.0 (GLB), " +
                          std::to_string(glb.size()) + " bytes");
  }
}

std::string pageTitle(const nlohmann::json& info) {
  const auto title = info.find("title");
  if (title != info.end() && title->is_string()) {
    return title->get<std::string>();
  }
  return "planar map";
}

/// The JSON read by tools/viewer/embedded_data.js.
std::string metaJson(const nlohmann::json& info, std::size_t points_total,
                     std::size_t points_shown) {
  const nlohmann::json meta = {{"info", info},
                               {"points", {{"total", points_total}, {"shown", points_shown}}}};
  return escapeJsonForScript(meta.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace));
}

}  // namespace

std::string renderViewerHtml(const std::vector<std::uint8_t>& glb_bytes,
                             const std::vector<Eigen::Vector3f>& raw_points,
                             const nlohmann::json& info) {
  checkGlb(glb_bytes);
  if (!info.is_object() && !info.is_null()) {
    throw ProcessingError("viewer: info must be a JSON object, got " +
                          std::string(info.type_name()));
  }
  const nlohmann::json info_object = info.is_null() ? nlohmann::json::object() : info;
  const std::vector<Eigen::Vector3f> shown = subsamplePoints(raw_points, kMaxViewerPoints);
  const std::vector<std::uint8_t> packed = packFloat32(shown);
  const std::map<std::string, std::string> values = {
      {"TITLE", escapeHtml(pageTitle(info_object))},
      {"META_JSON", metaJson(info_object, raw_points.size(), shown.size())},
      {"GLB_BASE64", encodeBase64(glb_bytes.data(), glb_bytes.size())},
      {"POINTS_BASE64", encodeBase64(packed.data(), packed.size())},
      {"VIEWER_JS", std::string(assets::viewerScript())},
  };
  return fillTemplate(assets::pageTemplate(), values);
}

void writeViewerHtml(const std::filesystem::path& html, const std::vector<std::uint8_t>& glb_bytes,
                     const std::vector<Eigen::Vector3f>& raw_points, const nlohmann::json& info) {
  const std::string page = renderViewerHtml(glb_bytes, raw_points, info);
  writeFileAtomically(
      html, [&page](std::ostream& out) { out.write(page.data(), std::streamsize(page.size())); },
      true);
}

}  // namespace pmap::viewer
