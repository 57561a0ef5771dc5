#include "pmap/sim/voxel_world.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace pmap::sim {
namespace {

constexpr std::int64_t kKeyOffset = 32768;        // OctoMap's key of voxel index 0
constexpr std::uint64_t kMaxVoxels = 1000000000;  // far above any world file limit
constexpr std::uint64_t kFullBrick = ~std::uint64_t{0};

bool inRange(std::int64_t i) {
  return i >= VoxelWorld::kMinIndex && i <= VoxelWorld::kMaxIndex;
}

void checkBlock(const VoxelWorld::Block& b) {
  if (b.side < 1 || b.side > 65536 || (b.side & (b.side - 1)) != 0) {
    throw std::invalid_argument("VoxelWorld: a block's side must be a power of two in [1, 65536]");
  }
  for (int a = 0; a < 3; ++a) {
    const std::int64_t lo = b.corner[a];
    if (!inRange(lo) || !inRange(lo + b.side - 1) || (lo + kKeyOffset) % b.side != 0) {
      throw std::invalid_argument(
          "VoxelWorld: a block lies outside the key range or is not aligned to its size");
    }
  }
}

}  // namespace

VoxelWorld::VoxelWorld(double resolution_m, const std::vector<Block>& blocks, OctreeFileInfo info)
    : resolution_m_(resolution_m), info_(std::move(info)) {
  if (!(resolution_m > 0.0) || !std::isfinite(resolution_m)) {
    throw std::invalid_argument("VoxelWorld: the resolution must be a positive number");
  }
  for (const Block& b : blocks) {
    checkBlock(b);
    occupied_voxels_ += static_cast<std::uint64_t>(b.side) * b.side * b.side;
    if (occupied_voxels_ > kMaxVoxels) {
      throw std::invalid_argument("VoxelWorld: more than 1e9 occupied voxels");
    }
  }
  std::vector<std::pair<std::uint64_t, std::uint64_t>> entries;  // brick key, mask
  min_index_ = Eigen::Vector3i::Constant(kMaxIndex);
  max_index_ = Eigen::Vector3i::Constant(kMinIndex);
  for (const Block& b : blocks) {
    min_index_ = min_index_.cwiseMin(b.corner);
    max_index_ = max_index_.cwiseMax(b.corner + Eigen::Vector3i::Constant(b.side - 1));
    const int step = b.side >= 4 ? 4 : 1;  // whole bricks, or single voxels
    for (int x = 0; x < b.side; x += step) {
      for (int y = 0; y < b.side; y += step) {
        for (int z = 0; z < b.side; z += step) {
          const Eigen::Vector3i v = b.corner + Eigen::Vector3i(x, y, z);
          entries.emplace_back(brickKey(v),
                               step == 4 ? kFullBrick : std::uint64_t{1} << brickBit(v));
        }
      }
    }
  }
  std::sort(entries.begin(), entries.end());
  for (const auto& [key, mask] : entries) {
    if (!brick_keys_.empty() && brick_keys_.back() == key) {
      brick_masks_.back() |= mask;
    } else {
      brick_keys_.push_back(key);
      brick_masks_.push_back(mask);
    }
  }
  if (blocks.empty()) {
    min_index_ = max_index_ = Eigen::Vector3i::Zero();
  }
}

Eigen::Vector3i VoxelWorld::voxelOf(const Eigen::Vector3d& p) const {
  return (p / resolution_m_).array().floor().cast<int>().matrix();
}

bool VoxelWorld::inKeyRange(const Eigen::Vector3d& p) const {
  const Eigen::Vector3d s = p / resolution_m_;
  return (s.array() >= kMinIndex).all() && (s.array() < kMaxIndex + 1.0).all();
}

Eigen::Vector3d VoxelWorld::voxelCentre(const Eigen::Vector3i& v) const {
  return (v.cast<double>().array() + 0.5).matrix() * resolution_m_;
}

bool VoxelWorld::occupied(const Eigen::Vector3i& v) const {
  if (!inRange(v.x()) || !inRange(v.y()) || !inRange(v.z())) {
    return false;
  }
  return ((brickMask(brickKey(v)) >> brickBit(v)) & 1u) != 0;
}

std::uint64_t VoxelWorld::brickKey(const Eigen::Vector3i& v) {
  const auto k = [](int i) { return static_cast<std::uint64_t>(i + kKeyOffset) >> 2; };
  return (k(v.x()) << 28) | (k(v.y()) << 14) | k(v.z());
}

int VoxelWorld::brickBit(const Eigen::Vector3i& v) {
  const auto b = [](int i) { return static_cast<int>((i + kKeyOffset) & 3); };
  return b(v.x()) | (b(v.y()) << 2) | (b(v.z()) << 4);
}

std::uint64_t VoxelWorld::brickMask(std::uint64_t brick_key) const {
  const auto it = std::lower_bound(brick_keys_.begin(), brick_keys_.end(), brick_key);
  if (it == brick_keys_.end() || *it != brick_key) {
    return 0;
  }
  return brick_masks_[static_cast<std::size_t>(it - brick_keys_.begin())];
}

}  // namespace pmap::sim
