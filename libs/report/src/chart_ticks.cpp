#include "pmap/report/chart_ticks.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace pmap::report {
namespace {

double niceStep(double span, int target_ticks) {
  const double raw = span / std::max(1, target_ticks);
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  for (const double m : {1.0, 2.0, 5.0}) {
    if (m * power >= raw * (1.0 - 1e-9)) {
      return m * power;
    }
  }
  return 10.0 * power;
}

AxisRange widenSingle(double v) {
  const double half = v == 0.0 ? 1.0 : 0.5 * std::abs(v);
  return {v - half, v + half};
}

}  // namespace

AxisRange niceRange(double lo, double hi, int target_ticks) {
  if (!(std::isfinite(lo) && std::isfinite(hi))) {
    return {0.0, 1.0};
  }
  AxisRange r{std::min(lo, hi), std::max(lo, hi)};
  if (r.hi - r.lo <= 1e-12 * std::max(1.0, std::abs(r.hi))) {
    r = widenSingle(r.lo);
  }
  // Spans below 0.1 % of the values are widened: four significant digits
  // then tell the ticks apart.
  const double min_span = 1e-3 * std::max(std::abs(r.lo), std::abs(r.hi));
  if (r.hi - r.lo < min_span) {
    const double mid = 0.5 * (r.lo + r.hi);
    r = {mid - 0.5 * min_span, mid + 0.5 * min_span};
  }
  const double step = niceStep(r.hi - r.lo, target_ticks);
  return {step * std::floor(r.lo / step), step * std::ceil(r.hi / step)};
}

AxisRange paddedRange(double lo, double hi, double margin) {
  if (!(std::isfinite(lo) && std::isfinite(hi))) {
    return {0.0, 1.0};
  }
  AxisRange r{std::min(lo, hi), std::max(lo, hi)};
  if (r.hi - r.lo <= 1e-12 * std::max(1.0, std::abs(r.hi))) {
    return widenSingle(r.lo);
  }
  const double pad = margin * (r.hi - r.lo);
  return {r.lo - pad, r.hi + pad};
}

std::vector<double> linearTicks(const AxisRange& range, int target_ticks) {
  const double step = niceStep(range.hi - range.lo, target_ticks);
  std::vector<double> ticks;
  const double first = step * std::ceil(range.lo / step - 1e-9);
  for (double v = first; v <= range.hi + 1e-9 * step; v += step) {
    ticks.push_back(std::abs(v) < 1e-12 * step ? 0.0 : v);
  }
  return ticks;
}

AxisRange logRange(double lo, double hi) {
  if (!(lo > 0.0 && hi > 0.0 && std::isfinite(lo) && std::isfinite(hi))) {
    return {0.0, 1.0};
  }
  AxisRange r{std::floor(std::log10(std::min(lo, hi))), std::ceil(std::log10(std::max(lo, hi)))};
  if (r.hi <= r.lo) {
    r.hi = r.lo + 1.0;
  }
  return r;
}

std::vector<double> logTicks(const AxisRange& log10_range) {
  const bool fine = log10_range.hi - log10_range.lo < 3.0;
  std::vector<double> ticks;
  for (double k = std::floor(log10_range.lo); k <= log10_range.hi; k += 1.0) {
    for (const double m : {1.0, 2.0, 5.0}) {
      if (m != 1.0 && !fine) {
        continue;
      }
      const double e = k + std::log10(m);
      if (e >= log10_range.lo - 1e-9 && e <= log10_range.hi + 1e-9) {
        ticks.push_back(m * std::pow(10.0, k));
      }
    }
  }
  return ticks;
}

std::string tickLabel(double value) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", value);
  return buf;
}

}  // namespace pmap::report
