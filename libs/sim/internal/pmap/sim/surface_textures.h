// Procedural textures of the simulated building, one material per surface or
// clutter kind: subtle paint noise on walls, wood grain on doors, tiles on the
// ceiling, a checked floor, ribbed plastic bins, concrete pillars. Colours are
// BGR (OpenCV, MRPT CImage) in [0, 255]; texture coordinates in metres.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string>

namespace pmap::sim {

enum class Material {
  kWallPaint,
  kRoomPaint,
  kWood,
  kFrame,
  kCeilingTiles,
  kFloor,
  kPlastic,
  kConcrete,
};

Material materialForSurfaceKind(const std::string& kind);
Material materialForClutterKind(const std::string& kind);

/// Colour of `material` at (u, v) metres; `variant` (e.g. the object id) varies
/// the pattern and tint slightly between objects of the same material.
Eigen::Vector3f materialColour(Material material, double u_m, double v_m, std::uint32_t variant);

/// Smooth value noise in [0, 1) (bilinear, smoothstep), deterministic.
float valueNoise(double x, double y, std::uint32_t seed);

}  // namespace pmap::sim
