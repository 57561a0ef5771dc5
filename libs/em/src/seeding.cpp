#include "pmap/em/seeding.h"

#include <algorithm>
#include <deque>

#include "pmap/em/selection_policy.h"
#include "pmap/em/surface_fit.h"

namespace pmap::em {
namespace {

struct Triple {
  std::int32_t a, b, c;
};

// A poorly explained point and two poorly explained neighbours that are not
// collinear with it (e.g. the next beam and the next scan).
std::vector<Triple> seedTriples(const std::vector<Eigen::Vector3d>& points,
                                const Neighbours& neighbours, const std::vector<char>& poor) {
  std::vector<Triple> out;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!poor[i]) {
      continue;
    }
    std::int32_t first = -1;
    for (const std::int32_t n : neighbours[i]) {
      if (n < 0 || !poor[static_cast<std::size_t>(n)]) {
        continue;
      }
      if (first < 0) {
        first = n;
        continue;
      }
      Rectangle probe;
      if (planeFromPoints(points[i], points[first], points[n], probe)) {
        out.push_back({static_cast<std::int32_t>(i), first, n});
        break;
      }
    }
  }
  return out;
}

// Breadth-first growth over the neighbour graph from the seed triple.
std::vector<std::int32_t> growRegion(const std::vector<Eigen::Vector3d>& points,
                                     const Neighbours& neighbours, const std::vector<char>& free,
                                     const Triple& seed, double max_distance, Rectangle& plane) {
  std::vector<char> in(points.size(), 0);
  std::vector<std::int32_t> region = {seed.a, seed.b, seed.c};
  std::deque<std::int32_t> queue(region.begin(), region.end());
  for (const std::int32_t s : region) {
    in[static_cast<std::size_t>(s)] = 1;
  }
  std::size_t next_refit = 16;
  while (!queue.empty()) {
    const std::int32_t p = queue.front();
    queue.pop_front();
    for (const std::int32_t q : neighbours[static_cast<std::size_t>(p)]) {
      if (q < 0 || in[static_cast<std::size_t>(q)] || !free[static_cast<std::size_t>(q)] ||
          std::abs(plane.planeDistance(points[static_cast<std::size_t>(q)])) > max_distance) {
        continue;
      }
      in[static_cast<std::size_t>(q)] = 1;
      region.push_back(q);
      queue.push_back(q);
    }
    if (region.size() >= next_refit) {
      // The plane alone (eqs. 24-27, unit weights): the rectangle is fitted
      // once the region is complete.
      PlaneMoments m;
      m.reference = points[static_cast<std::size_t>(region.front())];
      for (const std::int32_t i : region) {
        m.add(points[static_cast<std::size_t>(i)], 1.0);
      }
      Rectangle refit = plane;
      if (planeFromMoments(m, plane.normal, refit) == FitStatus::kOk) {
        plane = refit;
      }
      next_refit *= 2;
    }
  }
  std::sort(region.begin(), region.end());
  return region;
}

}  // namespace

SeedResult seedSurfaces(const std::vector<Eigen::Vector3d>& points, const Neighbours& neighbours,
                        const std::vector<double>& outlier, const MeasurementModel& model,
                        const PlanarEmOptions& options, const SurfaceCheck& accept,
                        std::mt19937_64& rng, std::size_t max_attempts) {
  std::vector<char> free(points.size(), 0);
  for (std::size_t i = 0; i < points.size(); ++i) {
    free[i] = outlier[i] > options.seed_outlier_probability ? 1 : 0;
  }
  std::vector<Triple> triples = seedTriples(points, neighbours, free);
  SeedResult result;
  result.candidates = triples.size();
  std::shuffle(triples.begin(), triples.end(), rng);
  if (max_attempts == 0) {
    max_attempts = static_cast<std::size_t>(options.rules.seed_attempts_per_surface) *
                   static_cast<std::size_t>(options.max_new_per_round);
  }
  const double grow_distance = growDistance(options);
  for (const Triple& t : triples) {
    if (result.surfaces.size() >= static_cast<std::size_t>(options.max_new_per_round) ||
        result.attempts >= max_attempts) {
      break;
    }
    if (!free[static_cast<std::size_t>(t.a)] || !free[static_cast<std::size_t>(t.b)] ||
        !free[static_cast<std::size_t>(t.c)]) {
      continue;  // taken by a surface grown earlier in this round
    }
    ++result.attempts;
    Rectangle rect;
    planeFromPoints(points[t.a], points[t.b], points[t.c], rect);
    rect.bounded = options.bounded;
    std::vector<std::int32_t> region = growRegion(points, neighbours, free, t, grow_distance, rect);
    if (!accept(region, rect)) {
      continue;
    }
    // Check again on what the surface will explain once EM takes over: every
    // connected free point within the outlier distance. A bin passes the
    // first test on a thin strip, then bends visibly on the wider band.
    Rectangle wide = rect;  // growRegion refits its plane: keep `rect` the seed's fit
    std::vector<std::int32_t> band =
        growRegion(points, neighbours, free, t, model.outlierDistance(), wide);
    if (!accept(band, wide)) {
      continue;
    }
    for (const std::int32_t i : region) {
      free[static_cast<std::size_t>(i)] = 0;
    }
    result.surfaces.push_back(rect);
    result.members.push_back(std::move(region));
  }
  return result;
}

}  // namespace pmap::em
