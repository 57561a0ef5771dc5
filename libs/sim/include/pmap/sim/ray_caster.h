// Closest-hit ray casting against a World (surfaces and clutter; posters are
// part of their wall). Candidate selection by bounding spheres keeps the cost
// low: a planar scan only needs the objects whose sphere meets its plane.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "pmap/sim/world.h"

namespace pmap::sim {

enum class ObjectType { kSurface, kClutter };

struct SceneHit {
  double t = 0.0;  ///< ray parameter (the distance for a unit direction)
  int id = -1;     ///< surface or clutter id
  ObjectType type = ObjectType::kSurface;
  int index = -1;  ///< index into World::surfaces or World::clutter
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  Eigen::Vector2d local = Eigen::Vector2d::Zero();  ///< texture coordinates, metres
};

class RayCaster {
 public:
  /// Keeps a reference: `world` must outlive the caster.
  explicit RayCaster(const World& world);

  /// Objects whose bounding sphere comes within `range_m` of `point`.
  std::vector<int> selectNearPoint(const Eigen::Vector3d& point, double range_m) const;
  /// Objects whose bounding sphere meets the plane through `point` with unit
  /// normal `normal`, within `range_m` of `point`.
  std::vector<int> selectNearPlane(const Eigen::Vector3d& point, const Eigen::Vector3d& normal,
                                   double range_m) const;

  /// Closest hit with t in (t_min, t_max]; only `candidates` (from select*) if given.
  std::optional<SceneHit> cast(const Eigen::Vector3d& origin, const Eigen::Vector3d& dir,
                               double t_max, const std::vector<int>* candidates = nullptr,
                               double t_min = 1e-9) const;

  /// Whether the hit is on a pane of glass (a surface of kind "glass").
  bool isGlass(const SceneHit& hit) const {
    return hit.type == ObjectType::kSurface && glass_[static_cast<std::size_t>(hit.index)] != 0;
  }

  std::size_t objectCount() const { return spheres_.size(); }
  const World& world() const { return world_; }

 private:
  struct Sphere {
    Eigen::Vector3d centre;
    double radius;
  };
  std::optional<SceneHit> castOne(int object, const Eigen::Vector3d& origin,
                                  const Eigen::Vector3d& dir, double t_min, double t_max) const;

  const World& world_;
  std::vector<Sphere> spheres_;  ///< surfaces first, then clutter
  std::vector<char> glass_;      ///< per surface
};

}  // namespace pmap::sim
