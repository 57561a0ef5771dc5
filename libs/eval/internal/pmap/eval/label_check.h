// Independent geometry check: every mapped point whose beam the simulator
// labelled with the object its true ray hit should lie on that object, within
// the range noise. Uses the ground truth's own geometry, not the mapper's.
#pragma once

#include "pmap/eval/ground_truth.h"
#include "pmap/eval/map_files.h"
#include "pmap/eval/pose_metrics.h"

namespace pmap::eval {

struct LabelCheck {
  std::size_t points = 0;         ///< mapped points with a ground-truth label entry
  std::size_t labelled = 0;       ///< ... whose true ray hit a fixed object
  std::size_t unlabelled = 0;     ///< ... whose true ray hit nothing (should be ~0)
  std::size_t on_people = 0;      ///< ... whose true ray hit a person walking through
  std::size_t within_3sigma = 0;  ///< labelled points within 3 sigma of their object
  double fraction_within_3sigma = 0;
  double median_m = 0;
  double p99_m = 0;
  double max_m = 0;
};

/// Points are moved into the ground-truth frame with `to_gt` first.
LabelCheck checkLabels(const GroundTruth& gt, const MapPoints& points, const Rigid2D& to_gt);

}  // namespace pmap::eval
