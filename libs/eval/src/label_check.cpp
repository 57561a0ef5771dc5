#include "pmap/eval/label_check.h"

#include <algorithm>
#include <cmath>

namespace pmap::eval {

LabelCheck checkLabels(const GroundTruth& gt, const MapPoints& points, const Rigid2D& to_gt) {
  LabelCheck c;
  std::vector<double> d;
  d.reserve(points.xyz.size());
  const double limit = 3.0 * gt.sigma_m;
  for (size_t i = 0; i < points.xyz.size(); ++i) {
    const auto it = gt.hits.find(points.scan[i]);
    if (it == gt.hits.end() || points.beam[i] < 0 ||
        static_cast<size_t>(points.beam[i]) >= it->second.size()) {
      continue;
    }
    ++c.points;
    const int id = it->second[static_cast<size_t>(points.beam[i])];
    if (id < 0) {
      ++c.unlabelled;
      continue;
    }
    if (gt.isPerson(id)) {  // walking: no fixed place to measure against
      ++c.on_people;
      continue;
    }
    ++c.labelled;
    const double dist = gt.distance(id, to_gt.apply(points.xyz[i]));
    d.push_back(dist);
    c.within_3sigma += dist <= limit ? 1 : 0;
  }
  if (!d.empty()) {
    std::sort(d.begin(), d.end());
    c.fraction_within_3sigma = static_cast<double>(c.within_3sigma) / static_cast<double>(d.size());
    c.median_m = d[d.size() / 2];
    c.p99_m = d[std::min(d.size() - 1, static_cast<size_t>(0.99 * static_cast<double>(d.size())))];
    c.max_m = d.back();
  }
  return c;
}

}  // namespace pmap::eval
