// Options of the online EM ([OnlineEM] in the ini): the bounds that make the
// work per scan constant however large the map grows (paper section V).
#pragma once

#include <string>

namespace pmap::em {

struct OnlineEmOptions {
  /// Past measurements re-examined per scan (those on the boundary of two
  /// surfaces or unexplained), >= 0.
  int revisit_budget = 300;
  /// Visits after which a measurement's assignment is frozen, >= 1.
  int freeze_after = 6;
  /// A measurement is on a boundary when its second most likely cause scores
  /// within this many nats of its most likely one, > 0.
  double boundary_margin_nats = 3.0;
  /// Points of a surface used to refit its rectangle per update, besides its
  /// hull and its newest points (a seeded random subsample), >= 16.
  int sample_cap = 400;
  /// Scans whose unexplained measurements may seed and grow a new surface, >= 2.
  int seed_window_scans = 12;
  /// Surfaces examined for fusion and splits per selection turn (round
  /// robin), >= 0.
  int selection_per_scan = 1;
  /// Seeding runs every this many scans, selection turns on the scans in
  /// between (so their costs do not add up in one scan), >= 1.
  int seed_every_scans = 2;
  int select_every_scans = 2;
  /// Points a split / fusion test looks at, at most (a seeded subsample), >= 100.
  int selection_sample_cap = 1500;
  /// Scans after which a surface without min_support points is removed, >= 1.
  int removal_after_scans = 25;

  bool validate(std::string* why) const;
};

}  // namespace pmap::em
