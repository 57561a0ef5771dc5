#include "pmap/mapper/online_stage.h"

#include <chrono>
#include <thread>

#include "pmap/common/atomic_file.h"
#include "pmap/common/interrupt.h"
#include "pmap/products/map_model.h"
#include "pmap/products/map_vrml.h"
#include "pmap/products/output_layout.h"

namespace pmap::mapper {

OnlineStage::OnlineStage(const em::PlanarEmOptions& em, const em::OnlineEmOptions& online,
                         std::filesystem::path out_dir, int snapshot_every)
    : options_(em),
      online_options_(online),
      out_dir_(std::move(out_dir)),
      snapshot_every_(snapshot_every) {
  if (!em.sigma_auto) {
    em_.emplace(em, online);
  }
}

void OnlineStage::addScan(const points::PointMap& map, std::size_t record) {
  throwIfInterrupted();  // once per scan: SIGINT / SIGTERM stop the run here
  if (em_) {
    feed(map, record);
    return;
  }
  waiting_.push_back(record);
  if (map.size() >= static_cast<std::size_t>(options_.auto_sigma_points)) {
    start(map);
  }
}

void OnlineStage::finish(const points::PointMap& map) {
  if (!em_) {
    start(map);
  }
}

// sigma_m = auto: estimated from the measurements placed so far (when there
// are too few for it, or the estimate is not a valid sigma_m, the configured
// sigma_m stays), then the EM takes the waiting scans.
void OnlineStage::start(const points::PointMap& map) {
  const auto t0 = std::chrono::steady_clock::now();
  em::PlanarEmOptions o = options_;
  sigma_estimate_ = em::estimateSigmaInto(o, map.xyz());
  seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  em_.emplace(o, online_options_);
  for (const std::size_t record : waiting_) {
    feed(map, record);
  }
  waiting_.clear();
}

void OnlineStage::feed(const points::PointMap& map, std::size_t record) {
  const points::ScanRecord& s = map.scans()[record];
  const std::vector<em::GridKey> keys = keyer_.keysOf(map, s);
  const std::vector<Eigen::Vector3d> pts(
      map.xyz().begin() + static_cast<std::ptrdiff_t>(s.first_point),
      map.xyz().begin() + static_cast<std::ptrdiff_t>(s.first_point + s.num_points));
  const auto t0 = std::chrono::steady_clock::now();
  OnlineRecord r;
  r.update = em_->addScan(pts, keys);
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  seconds_ += secs;
  r.scan = s.index;
  r.em_ms = 1000.0 * secs;
  r.surfaces = em_->surfaceCount();
  r.points = em_->points();
  history_.push_back(r);
  if (snapshot_every_ > 0 && history_.size() % static_cast<std::size_t>(snapshot_every_) == 0) {
    writeSnapshot(map);
  }
}

void OnlineStage::moveScans(const points::PointMap& map, const std::vector<std::size_t>& moved) {
  if (!em_) {
    return;  // the waiting scans go to the EM from where they are when it starts
  }
  OnlineRepair repair;
  std::vector<std::int32_t> indices;
  std::vector<Eigen::Vector3d> positions;
  for (const std::size_t record : moved) {
    const points::ScanRecord& s = map.scans()[record];
    for (std::size_t i = s.first_point; i < s.first_point + s.num_points && i < em_->points();
         ++i) {
      indices.push_back(static_cast<std::int32_t>(i));  // the EM's order is the map's (addScan)
      positions.push_back(map.xyz()[i]);
    }
    ++repair.scans;
  }
  if (indices.empty()) {
    return;
  }
  const auto t0 = std::chrono::steady_clock::now();
  repair.update = em_->movePoints(indices, positions);
  repair.ms = 1000.0 * std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  seconds_ += repair.ms / 1000.0;
  repair.points = indices.size();
  repairs_.push_back(repair);
}

void OnlineStage::writeSnapshot(const points::PointMap& map) const {
  const std::filesystem::path file =
      out_dir_ / products::OutputLayout::snapshotFile(history_.size());
  ensureWritableDirectory(file.parent_path());
  const em::PlanarMap m = em_->map();
  std::vector<Eigen::Vector3d> pts(map.xyz().begin(),
                                   map.xyz().begin() + static_cast<std::ptrdiff_t>(em_->points()));
  products::writeMapVrml(
      file, products::buildMapModel(m, pts, {}),
      "planar-mapper online map after " + std::to_string(history_.size()) + " structure scans");
}

void Pacer::waitFor(double t) {
  if (rate_ <= 0.0) {
    return;
  }
  if (!started_) {
    started_ = true;
    t0_ = t;
    wall0_ = std::chrono::steady_clock::now();
    return;
  }
  const auto due = wall0_ + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                std::chrono::duration<double>((t - t0_) / rate_));
  std::this_thread::sleep_until(due);
}

}  // namespace pmap::mapper
