#include "pmap/sim/camera_imaging_options.h"

#include <cmath>
#include <sstream>

namespace pmap::sim {
namespace {

bool fail(std::string* why, const std::string& message) {
  if (why != nullptr) {
    *why = message;
  }
  return false;
}

bool within(double v, double lo, double hi) {
  return std::isfinite(v) && v >= lo && v <= hi;
}

std::string number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

/// Both ends in [lo, hi] (or (lo, hi]) and interval[0] <= interval[1].
bool checkInterval(const Interval& interval, double lo, bool lo_open, double hi,
                   const std::string& key, std::string* why) {
  for (const double v : interval) {
    if (!within(v, lo, hi) || (lo_open && v == lo)) {
      return fail(why, key + ": values must be in " + (lo_open ? "(" : "[") + number(lo) + ", " +
                           number(hi) + "]");
    }
  }
  if (interval[0] > interval[1]) {
    return fail(why, key + ": the lower bound exceeds the upper bound");
  }
  return true;
}

}  // namespace

bool CameraNoiseOptions::validate(std::string* why) const {
  if (!within(read_sigma_dn, 0.0, 50.0)) {
    return fail(why, "noise.read_sigma_dn must be in [0, 50]");
  }
  if (!within(full_well_e, 100.0, 1.0e7)) {
    return fail(why, "noise.full_well_e must be in [100, 1e7]");
  }
  return true;
}

bool CameraExposureOptions::validate(std::string* why) const {
  return checkInterval(gain, 0.0, true, 10.0, "exposure.gain", why) &&
         checkInterval(offset_dn, -100.0, false, 100.0, "exposure.offset_dn", why) &&
         checkInterval(gamma, 0.2, false, 5.0, "exposure.gamma", why);
}

bool CameraBlurOptions::validate(std::string* why) const {
  if (!within(blurred_fraction, 0.0, 1.0)) {
    return fail(why, "blur.blurred_fraction must be in [0, 1]");
  }
  if (!within(motion_share, 0.0, 1.0)) {
    return fail(why, "blur.motion_share must be in [0, 1]");
  }
  return checkInterval(psf_sigma_px, 0.0, false, 10.0, "blur.psf_sigma_px", why) &&
         checkInterval(defocus_sigma_px, 0.0, false, 20.0, "blur.defocus_sigma_px", why) &&
         checkInterval(motion_length_px, 0.0, false, 100.0, "blur.motion_length_px", why);
}

bool CameraLensOptions::hasDistortion() const {
  for (const double c : distortion) {
    if (c != 0.0) {
      return true;
    }
  }
  return false;
}

bool CameraLensOptions::validate(std::string* why) const {
  if (!within(vignetting, 0.0, 0.9)) {
    return fail(why, "lens.vignetting must be in [0, 0.9]");
  }
  const double k1 = distortion[0], k2 = distortion[1], p1 = distortion[2], p2 = distortion[3],
               k3 = distortion[4];
  if (!within(k1, -10.0, 10.0) || !within(k2, -10.0, 10.0) || !within(k3, -10.0, 10.0)) {
    return fail(why, "lens.distortion: k1, k2 and k3 must be in [-10, 10]");
  }
  if (!within(p1, -0.1, 0.1) || !within(p2, -0.1, 0.1)) {
    return fail(why, "lens.distortion: p1 and p2 must be in [-0.1, 0.1]");
  }
  return true;
}

}  // namespace pmap::sim
