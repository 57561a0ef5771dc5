#include "pmap/sim/laser_sim.h"

#include <algorithm>
#include <cmath>

namespace pmap::sim {

double beamAngle(const LaserOptions& laser, int beam) {
  const double aperture = degToRad(laser.aperture_deg);
  return -0.5 * aperture + beam * aperture / (laser.beams - 1);
}

Pose6D laserMountPose(const LaserOptions& laser) {
  return pose6DFromDegrees({laser.position_m[0], laser.position_m[1], laser.position_m[2],
                            laser.ypr_deg[0], laser.ypr_deg[1], laser.ypr_deg[2]});
}

RigidTransform laserToWorld(const Pose2D& robot, const LaserOptions& laser) {
  return compose(toTransform(robot), toTransform(laserMountPose(laser)));
}

Eigen::Vector3d beamDirectionInWorld(const Pose2D& robot, const LaserOptions& laser, int beam) {
  const double a = beamAngle(laser, beam);
  const Eigen::Vector3d in_sensor(std::cos(a), std::sin(a), 0.0);
  const Eigen::Vector3d d = laserToWorld(robot, laser).rotation * in_sensor;
  return d;
}

namespace {

// The range noise's standard deviation for a hit at range t, met at
// incidence cosine c (0: unknown).
double rangeSigma(const NoiseOptions& noise, double t, double c) {
  const LaserErrorOptions& l = noise.laser;
  double sigma = noise.range_sigma_m + l.sigma_per_m * t;
  if (c > 0.0 && l.incidence_factor > 0.0) {
    sigma *= 1.0 + l.incidence_factor * (1.0 / std::max(c, 0.1) - 1.0);
  }
  return sigma;
}

// Whether beam i's neighbour lies across a depth edge, and its true range:
// it hits another object (or nothing; in voxel worlds, whose hits have no
// ids, any neighbour) more than jump_m nearer or further. Along one surface
// met at a grazing angle neighbouring ranges also jump, but there the spot
// stays on that surface: the incidence noise's business.
std::optional<double> acrossEdge(const SimulatedScan& scan, std::size_t i, double jump_m) {
  const std::vector<double>& t = scan.true_ranges_m;
  const std::vector<int>& id = scan.hit_ids;
  for (const std::size_t j : {i - 1, i + 1}) {
    if (j < t.size() && std::abs(t[j] - t[i]) > jump_m && (id[j] != id[i] || id[i] < 0)) {
      return t[j];
    }
  }
  return std::nullopt;
}

// One beam against a World: the static objects in `candidates`, glass (a
// beam goes through unless it meets the pane within glass_return_deg of its
// normal) and the people where they are at the scan's time.
std::optional<BeamHit> castBeam(const RayCaster& caster, const std::vector<int>& candidates,
                                const PeopleAt& people, const NoiseOptions& noise,
                                const Eigen::Vector3d& origin, const Eigen::Vector3d& dir,
                                double max_range_m) {
  constexpr int kMaxPanes = 8;  // a beam through more panes than this returns from the last
  const double cos_return = std::cos(noise.laser.glass_return_deg * M_PI / 180.0);
  double t_min = 1e-9;
  bool through_glass = false;
  for (int pane = 0;; ++pane) {
    const std::optional<SceneHit> hit = caster.cast(origin, dir, max_range_m, &candidates, t_min);
    const double t_max = hit ? hit->t : max_range_m;
    if (const auto person = people.cast(origin, dir, t_min, t_max)) {
      return BeamHit{person->hit.t, person->id, person->hit.normal, through_glass};
    }
    if (!hit) {
      return std::nullopt;
    }
    const bool specular = std::abs(dir.dot(hit->normal)) >= cos_return;
    if (!caster.isGlass(*hit) || specular || pane == kMaxPanes) {
      return BeamHit{hit->t, hit->id, hit->normal, through_glass};
    }
    through_glass = true;
    t_min = hit->t + 1e-6;
  }
}

}  // namespace

SimulatedScan simulateScan(const BeamCaster& cast, const Pose2D& robot, const LaserOptions& laser,
                           const NoiseOptions& noise, Rng& rng) {
  const LaserErrorOptions& l = noise.laser;
  const RigidTransform sensor = laserToWorld(robot, laser);
  const Eigen::Vector3d origin = sensor.translation;
  const std::size_t n = static_cast<std::size_t>(laser.beams);
  SimulatedScan scan;
  scan.ranges_m.resize(n);
  scan.valid.resize(n);
  scan.hit_ids.resize(n);
  scan.true_ranges_m.resize(n);
  std::vector<char> has_hit(n, 0);
  std::vector<char> through_glass(n, 0);
  std::vector<double> cosines(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const double a = beamAngle(laser, static_cast<int>(i));
    const Eigen::Vector3d dir = sensor.rotation * Eigen::Vector3d(std::cos(a), std::sin(a), 0.0);
    const std::optional<BeamHit> hit = cast(origin, dir, laser.max_range_m);
    scan.hit_ids[i] = hit ? hit->id : -1;
    scan.true_ranges_m[i] = hit ? hit->t_m : laser.max_range_m;
    has_hit[i] = hit ? 1 : 0;
    through_glass[i] = hit && hit->through_glass ? 1 : 0;
    cosines[i] = hit ? std::abs(dir.dot(hit->normal)) : 0.0;
  }
  // Spurious and mixed returns are marked after the loop: the depth edges
  // are found on the true hits.
  std::vector<char> on_no_object(n, 0);
  const double grazing_cos = std::cos(l.grazing_dropout_deg * M_PI / 180.0);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = scan.true_ranges_m[i];
    const bool hit = has_hit[i] != 0;
    const double c = cosines[i];
    const double z = rng.normal();  // drawn hit or not: the stream stays the same
    double noisy = hit ? t + rangeSigma(noise, t, c) * z : laser.max_range_m;
    bool ok = hit && !(c > 0.0 && l.grazing_dropout_deg < 90.0 && c < grazing_cos);
    if (l.dropout_probability > 0.0 && rng.uniform() < l.dropout_probability) {
      ok = false;
    }
    if (l.spurious_probability > 0.0 && rng.uniform() < l.spurious_probability) {
      noisy = rng.uniform(0.1, std::min(t, laser.max_range_m));
      ok = true;
      on_no_object[i] = 1;
    } else if (ok && l.mixed_pixel_probability > 0.0) {
      const std::optional<double> other = acrossEdge(scan, i, l.mixed_pixel_jump_m);
      if (other && rng.uniform() < l.mixed_pixel_probability) {
        noisy = t + rng.uniform() * (*other - t);
        on_no_object[i] = 1;
      }
    }
    // Drawn only for beams through glass: worlds without glass keep their streams.
    if (through_glass[i] && l.glass_dropout_probability > 0.0 &&
        rng.uniform() < l.glass_dropout_probability) {
      ok = false;
    }
    ok = ok && noisy > 0.0 && noisy <= laser.max_range_m;
    scan.valid[i] = ok ? 1 : 0;
    scan.ranges_m[i] = static_cast<float>(ok ? noisy : laser.max_range_m);
  }
  for (std::size_t i = 0; i < n; ++i) {
    scan.hit_ids[i] = on_no_object[i] ? -1 : scan.hit_ids[i];
  }
  return scan;
}

SimulatedScan simulateScan(const RayCaster& caster, const Pose2D& robot, const LaserOptions& laser,
                           const NoiseOptions& noise, Rng& rng, double t_s) {
  const RigidTransform sensor = laserToWorld(robot, laser);
  // Every beam lies in the sensor's x-y plane: only objects meeting it matter.
  const std::vector<int> candidates =
      caster.selectNearPlane(sensor.translation, sensor.rotation.col(2), laser.max_range_m);
  const PeopleAt people(caster.world().people, t_s);
  const BeamCaster cast = [&](const Eigen::Vector3d& origin, const Eigen::Vector3d& dir,
                              double max_range_m) {
    return castBeam(caster, candidates, people, noise, origin, dir, max_range_m);
  };
  return simulateScan(cast, robot, laser, noise, rng);
}

}  // namespace pmap::sim
