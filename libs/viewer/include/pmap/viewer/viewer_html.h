// viewer.html: the planar map in a browser (doc/viewer.md). One self-contained
// page: three.js and the viewer code (bundled at build time), the model as a
// base64 GLB and the raw points as a base64 Float32Array are all inlined, so
// the page works opened from disk with no network.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace pmap::viewer {

/// At most this many raw points are embedded (deterministic stride).
inline constexpr std::size_t kMaxViewerPoints = 300000;

/// The page as a string. `glb_bytes`: a binary glTF (y up, as glTF
/// prescribes; empty: no model). `raw_points`: world points (metres, z up);
/// non-finite ones are dropped and the rest subsampled to kMaxViewerPoints.
/// `info`: an object; its string "title" names the page and heads the HUD,
/// its other scalar entries (e.g. "surfaces", "triangles") are listed in the
/// HUD. Throws ProcessingError if `glb_bytes` is not empty and is not a GLB,
/// or `info` is not an object (or null).
std::string renderViewerHtml(const std::vector<std::uint8_t>& glb_bytes,
                             const std::vector<Eigen::Vector3f>& raw_points,
                             const nlohmann::json& info);

/// Writes renderViewerHtml(...) to `html` atomically (pmap::writeFileAtomically):
/// throws OutputError naming the file if it cannot be written.
void writeViewerHtml(const std::filesystem::path& html, const std::vector<std::uint8_t>& glb_bytes,
                     const std::vector<Eigen::Vector3f>& raw_points, const nlohmann::json& info);

}  // namespace pmap::viewer
