// Axis ranges and tick positions for the report charts.
#pragma once

#include <string>
#include <vector>

namespace pmap::report {

struct AxisRange {
  double lo = 0;
  double hi = 1;
};

/// A range covering [lo, hi] widened to whole tick steps ("nice" steps of
/// 1, 2 or 5 times a power of ten, about `target_ticks` of them). A single
/// value becomes a range around it; a span below 0.1 % of the values is
/// widened to that, so that tickLabel tells the ticks apart.
AxisRange niceRange(double lo, double hi, int target_ticks = 5);

/// [lo, hi] widened by `margin` of its span on both sides (no snapping to
/// ticks); a single value becomes a range around it.
AxisRange paddedRange(double lo, double hi, double margin = 0.02);

/// Tick positions inside `range` at the nice step of niceRange.
std::vector<double> linearTicks(const AxisRange& range, int target_ticks = 5);

/// Decades 10^k covering the positive [lo, hi] (log10 bounds).
AxisRange logRange(double lo, double hi);

/// Tick values 10^k inside a log range (given as log10 bounds); with fewer
/// than three decades also 2 and 5 times them.
std::vector<double> logTicks(const AxisRange& log10_range);

/// A short label: up to 4 significant digits, no trailing zeros.
std::string tickLabel(double value);

}  // namespace pmap::report
