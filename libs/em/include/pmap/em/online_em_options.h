// Options of the online EM ([OnlineEM] in the ini): the bounds that make the
// work per scan constant however large the map grows (paper section V).
#pragma once

#include <string>

namespace pmap::em {

struct OnlineEmOptions {
  // Work bounds per scan (the decisions' thresholds are PlanarEmOptions,
  // shared with the offline EM). Units, range, and why this value.

  /// Past measurements re-examined per scan (those on the boundary of two
  /// surfaces or unexplained), >= 0: about two structure scans (181 beams)
  /// of revisits, which keeps the queue short on the simulated worlds.
  int revisit_budget = 300;
  /// Visits after which a measurement's assignment is frozen, [1, 255]: a
  /// boundary point that has not settled after 6 looks never will, and
  /// revisiting it again would only spend the budget.
  int freeze_after = 6;
  /// A measurement is on a boundary when its second most likely cause scores
  /// within this many nats of its most likely one, > 0: 3 nats is a
  /// likelihood ratio of 20, below which an assignment may still flip.
  double boundary_margin_nats = 3.0;
  /// Points of a surface used to refit its rectangle per update, besides its
  /// hull and its newest points (a seeded random subsample), >= 16: enough
  /// to keep the extent of a wall seen by thousands of points.
  int sample_cap = 400;
  /// Scans whose unexplained measurements may seed and grow a new surface,
  /// >= 2: 12 scans (about 1 m of driving) hold min_rows scans of a new wall
  /// with room for its seed to grow.
  int seed_window_scans = 12;
  /// Surfaces examined for fusion and splits per selection turn (round
  /// robin), >= 0: one keeps the turn's cost at one surface's tests.
  int selection_per_scan = 1;
  /// Seeding runs every this many scans, selection turns on the scans in
  /// between (so their costs do not add up in one scan), >= 1.
  int seed_every_scans = 2;
  int select_every_scans = 2;
  /// Points a split / fusion test looks at, at most (a seeded subsample),
  /// >= 100: enough for the grid tests on a wall's cells, bounded for a
  /// corridor-long ceiling.
  int selection_sample_cap = 1500;
  /// Scans after which a surface without min_support points is removed,
  /// >= 1: a new surface still growing with the robot (about 2 m at 8 cm
  /// per scan) is given time to reach its support.
  int removal_after_scans = 25;
  // Seeding work per turn (fixed, not read from the ini).
  /// Seeding turns a measurement may stay unexplained and still seed, in
  /// [1, 255]: past them it is clutter or a patch too small, and is not
  /// tried again (bounds the work of a cluttered window).
  int seed_tries = 4;
  /// Regions grown per seeding turn, >= 1, and surfaces kept per turn, >= 1:
  /// a scan rarely meets more than two new surfaces, and the window gives
  /// the rest the next turns.
  int seed_regions_per_turn = 6;
  int seeds_per_turn = 2;

  bool validate(std::string* why) const;
};

}  // namespace pmap::em
