// Private helpers of the world builder: the frame of each corridor leg, the
// wall pieces openings and posters attach to, and a small assembler that hands
// out surface ids.
#pragma once

#include <Eigen/Core>
#include <map>
#include <string>
#include <vector>

#include "pmap/sim/world.h"

namespace pmap::sim::detail {

/// A leg of a corridor: s along the leg from its start waypoint, y to the left
/// of the direction of travel, z up.
struct LegFrame {
  Eigen::Vector2d start = Eigen::Vector2d::Zero();
  Eigen::Vector2d dir = Eigen::Vector2d::UnitX();
  Eigen::Vector2d left = Eigen::Vector2d::UnitY();
  double length_m = 0.0;
  double slope_tan = 0.0;  ///< tan(ceiling_slope_deg), positive raises the left side
  int turn_in = 0;         ///< +1 left turn, -1 right turn, 0 none (first leg)
  int turn_out = 0;        ///< same, at the end (0 for the last leg)

  Eigen::Vector3d point(double s, double y, double z) const;
};

/// A wall rectangle of one side of a leg, covering s in [s_lo, s_hi].
struct WallPiece {
  int surface_index = -1;
  double s_lo = 0.0;
  double s_hi = 0.0;
  double height_m = 0.0;
};

/// Collects surfaces; a surface's id is its index.
class SceneAssembler {
 public:
  explicit SceneAssembler(World& world) : world_(world) {}
  int addSurface(const std::string& kind, const Rectangle3& rect, int parent_id = -1);
  Surface& surface(int index) { return world_.surfaces[static_cast<std::size_t>(index)]; }
  World& world() { return world_; }
  /// Openings and posters already placed on a surface, in its (u, v) frame.
  std::vector<HoleRange>& occupied(int surface_index) { return occupied_[surface_index]; }

 private:
  World& world_;
  std::map<int, std::vector<HoleRange>> occupied_;
};

struct CorridorLayout {
  std::string file;
  std::string where;
  double width_m = 0.0;
  double height_m = 0.0;
  std::vector<LegFrame> legs;
  std::map<std::pair<int, int>, std::vector<WallPiece>> pieces;  ///< (leg, side) -> pieces

  /// Ceiling height of leg `leg` at lateral offset y.
  double ceilingAt(int leg, double y) const;
  /// Height of the wall of `side` along the leg proper (outside corner squares).
  double wallHeight(int leg, Side side) const;
};

/// Corridor shell: walls, end walls, floors, ceilings, bulkheads.
CorridorLayout buildCorridorShell(const CorridorSpec& spec, const std::string& file,
                                  SceneAssembler& scene);

/// Openings and posters on the walls of a built corridor.
void addDoor(const CorridorLayout& layout, const DoorSpec& door, SceneAssembler& scene);
void addDoorway(const CorridorLayout& layout, const DoorwaySpec& doorway, SceneAssembler& scene);
void addPoster(const CorridorLayout& layout, const PosterSpec& poster, SceneAssembler& scene);

}  // namespace pmap::sim::detail
