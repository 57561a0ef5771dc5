// How the simulated cameras turn a rendered view into an image file: lens
// (distortion, vignetting), per-frame blur and exposure, sensor noise. Every
// per-frame value is drawn uniformly from a closed interval [lo, hi] (lo == hi:
// fixed). Grey levels (DN) are on the 0..255 scale of the written image. The
// whole model is described in doc/simulator.md ("Image formation").
#pragma once

#include <array>
#include <string>

namespace pmap::sim {

/// A closed interval [lo, hi] a per-frame value is drawn from uniformly.
using Interval = std::array<double, 2>;

/// Sensor noise, per channel, independent between pixels and frames:
/// variance (DN^2) = read_sigma_dn^2 + signal_dn * 255 / full_well_e
/// (shot noise of a sensor whose full scale 255 collects full_well_e electrons).
struct CameraNoiseOptions {
  double read_sigma_dn = 1.5;   ///< read noise, grey levels, in [0, 50]
  double full_well_e = 6000.0;  ///< electrons at grey level 255, in [100, 1e7]
  bool validate(std::string* why) const;
};

/// Per-frame exposure (auto-exposure hunting): out = clip(gain * signal +
/// offset_dn), then the tone curve 255 * (out / 255)^(1 / gamma).
struct CameraExposureOptions {
  Interval gain{{0.8, 1.2}};       ///< each in (0, 10]
  Interval offset_dn{{0.0, 0.0}};  ///< black-level offset, grey levels, each in [-100, 100]
  Interval gamma{{1.0, 1.0}};      ///< tone-curve exponent, each in [0.2, 5]
  bool validate(std::string* why) const;
};

/// Per-frame blur. Every frame gets a Gaussian point-spread function of the
/// lens, sigma drawn from psf_sigma_px (the renderer already integrates poster
/// pixels over their area); a share `blurred_fraction` of the
/// frames gets a blur event on top: defocus (a second Gaussian, sigmas added in
/// quadrature) or, with probability `motion_share`, a horizontal motion streak.
struct CameraBlurOptions {
  Interval psf_sigma_px{{0.2, 0.5}};      ///< pixels, each in [0, 10]
  double blurred_fraction = 0.3;          ///< in [0, 1]
  Interval defocus_sigma_px{{1.0, 2.5}};  ///< pixels, each in [0, 20]
  double motion_share = 0.5;              ///< in [0, 1]
  Interval motion_length_px{{3.0, 8.0}};  ///< streak length, pixels, each in [0, 100]
  bool validate(std::string* why) const;
};

/// The lens, fixed per camera.
struct CameraLensOptions {
  /// Relative light loss at the image corners: the signal is multiplied by
  /// 1 - vignetting * (r / r_corner)^2, r = distance to the principal point. In [0, 0.9].
  double vignetting = 0.25;
  /// Radial-tangential (plumb bob) coefficients k1, k2, p1, p2, k3, as MRPT's
  /// TCamera::dist and OpenCV; all zero = an ideal pinhole. |k_i| <= 10, |p_i| <= 0.1.
  std::array<double, 5> distortion{{0.0, 0.0, 0.0, 0.0, 0.0}};
  bool hasDistortion() const;
  bool validate(std::string* why) const;
};

}  // namespace pmap::sim
