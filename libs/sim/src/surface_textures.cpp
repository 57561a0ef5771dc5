#include "pmap/sim/surface_textures.h"

#include <cmath>

namespace pmap::sim {
namespace {

float hash01(std::int64_t x, std::int64_t y, std::uint32_t seed) {
  std::uint32_t h = static_cast<std::uint32_t>(x) * 374761393u +
                    static_cast<std::uint32_t>(y) * 668265263u + seed * 2246822519u;
  h = (h ^ (h >> 13)) * 1274126177u;
  h ^= h >> 16;
  return static_cast<float>(h & 0xFFFFFFu) / 16777216.0f;
}

double frac(double x) {
  return x - std::floor(x);
}

Eigen::Vector3f paint(const Eigen::Vector3f& base, double u, double v, std::uint32_t seed) {
  const float coarse = valueNoise(u * 1.5, v * 1.5, seed) - 0.5f;
  const float fine = valueNoise(u * 35.0, v * 35.0, seed + 1) - 0.5f;
  return base * (1.0f + 0.05f * coarse + 0.04f * fine);
}

Eigen::Vector3f wood(double u, double v, std::uint32_t seed) {
  const Eigen::Vector3f base(45.0f, 85.0f, 140.0f);
  const double warp = 3.0 * valueNoise(u * 4.0, v * 0.4, seed);
  const double grain = 0.5 + 0.5 * std::sin(2.0 * M_PI * (u * 18.0 + warp));
  const float fine = valueNoise(u * 60.0, v * 4.0, seed + 7) - 0.5f;
  const float tint = 0.9f + 0.2f * hash01(seed, 3, 11);
  return base * tint * static_cast<float>(0.8 + 0.25 * grain + 0.08 * fine);
}

Eigen::Vector3f ceilingTiles(double u, double v, std::uint32_t seed) {
  constexpr double kTile_m = 0.6;
  constexpr double kGrout = 0.03;
  const double fu = frac(u / kTile_m);
  const double fv = frac(v / kTile_m);
  if (fu < kGrout || fv < kGrout) {
    return Eigen::Vector3f(140.0f, 140.0f, 145.0f);
  }
  const auto tile_seed =
      seed + static_cast<std::uint32_t>(std::floor(u / kTile_m) * 31 + std::floor(v / kTile_m));
  const float fissures = valueNoise(u * 40.0, v * 40.0, tile_seed) - 0.5f;
  return Eigen::Vector3f(228.0f, 230.0f, 232.0f) * (1.0f + 0.08f * fissures);
}

Eigen::Vector3f floorChecks(double u, double v, std::uint32_t seed) {
  constexpr double kSquare_m = 0.3;
  const auto parity = (static_cast<std::int64_t>(std::floor(u / kSquare_m)) +
                       static_cast<std::int64_t>(std::floor(v / kSquare_m))) &
                      1;
  const Eigen::Vector3f base =
      parity ? Eigen::Vector3f(95.0f, 105.0f, 115.0f) : Eigen::Vector3f(150.0f, 160.0f, 170.0f);
  const float speckle = valueNoise(u * 50.0, v * 50.0, seed) - 0.5f;
  return base * (1.0f + 0.1f * speckle);
}

}  // namespace

float valueNoise(double x, double y, std::uint32_t seed) {
  const double fx = std::floor(x);
  const double fy = std::floor(y);
  const auto ix = static_cast<std::int64_t>(fx);
  const auto iy = static_cast<std::int64_t>(fy);
  const float tx = static_cast<float>(x - fx);
  const float ty = static_cast<float>(y - fy);
  const float sx = tx * tx * (3.0f - 2.0f * tx);
  const float sy = ty * ty * (3.0f - 2.0f * ty);
  const float a = hash01(ix, iy, seed);
  const float b = hash01(ix + 1, iy, seed);
  const float c = hash01(ix, iy + 1, seed);
  const float d = hash01(ix + 1, iy + 1, seed);
  return (a + (b - a) * sx) + ((c + (d - c) * sx) - (a + (b - a) * sx)) * sy;
}

Material materialForSurfaceKind(const std::string& kind) {
  if (kind == "door" || kind == "cabinet") {
    return Material::kWood;
  }
  if (kind == "jamb" || kind == "panel") {
    return Material::kFrame;
  }
  if (kind == "ceiling" || kind == "room_ceiling") {
    return Material::kCeilingTiles;
  }
  if (kind == "floor" || kind == "room_floor") {
    return Material::kFloor;
  }
  if (kind == "room_wall") {
    return Material::kRoomPaint;
  }
  return Material::kWallPaint;
}

Material materialForClutterKind(const std::string& kind) {
  return kind == "bin" ? Material::kPlastic : Material::kConcrete;
}

Eigen::Vector3f materialColour(Material m, double u, double v, std::uint32_t variant) {
  switch (m) {
    case Material::kWallPaint:
      return paint(Eigen::Vector3f(196.0f, 214.0f, 226.0f), u, v, variant);
    case Material::kRoomPaint:
      return paint(Eigen::Vector3f(226.0f, 206.0f, 188.0f), u, v, variant);
    case Material::kWood:
      return wood(u, v, variant);
    case Material::kFrame:
      return paint(Eigen::Vector3f(238.0f, 238.0f, 236.0f), u, v, variant);
    case Material::kCeilingTiles:
      return ceilingTiles(u, v, variant);
    case Material::kFloor:
      return floorChecks(u, v, variant);
    case Material::kPlastic: {
      const double ribs = 0.88 + 0.12 * std::sin(2.0 * M_PI * u / 0.05);
      return Eigen::Vector3f(50.0f, 120.0f, 45.0f) * static_cast<float>(ribs);
    }
    case Material::kConcrete:
      return paint(Eigen::Vector3f(160.0f, 162.0f, 165.0f), 3.0 * u, 3.0 * v, variant);
  }
  return Eigen::Vector3f(255.0f, 0.0f, 255.0f);
}

}  // namespace pmap::sim
