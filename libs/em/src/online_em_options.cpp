#include "pmap/em/online_em_options.h"

#include <cmath>

namespace pmap::em {

bool OnlineEmOptions::validate(std::string* why) const {
  auto fail = [why](const char* rule) {
    if (why != nullptr) {
      *why = rule;
    }
    return false;
  };
  if (revisit_budget < 0)
    return fail("revisit_budget must be >= 0");
  if (freeze_after < 1 || freeze_after > 255)
    return fail("freeze_after must be in [1, 255]");
  if (!(std::isfinite(boundary_margin_nats) && boundary_margin_nats > 0.0)) {
    return fail("boundary_margin_nats must be > 0");
  }
  if (sample_cap < 16)
    return fail("sample_cap must be >= 16");
  if (seed_window_scans < 2)
    return fail("seed_window_scans must be >= 2");
  if (selection_per_scan < 0)
    return fail("selection_per_scan must be >= 0");
  if (seed_every_scans < 1 || select_every_scans < 1) {
    return fail("seed_every_scans and select_every_scans must be >= 1");
  }
  if (selection_sample_cap < 100)
    return fail("selection_sample_cap must be >= 100");
  if (removal_after_scans < 1)
    return fail("removal_after_scans must be >= 1");
  if (seed_tries < 1 || seed_tries > 255 || seed_regions_per_turn < 1 || seeds_per_turn < 1) {
    return fail("seed_tries must be in [1, 255], seed_regions_per_turn and seeds_per_turn >= 1");
  }
  return true;
}

}  // namespace pmap::em
