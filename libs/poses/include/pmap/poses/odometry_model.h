// The wheel odometry as a motion prior for the pose graph (doc/poses.md,
// "Calibrated odometry"). Wheel odometry is smooth but biased: a wrong wheel
// radius scales every distance, unequal wheels turn the robot a little per
// metre, a wrong wheelbase scales every turn (the systematic errors of
// Borenstein and Feng's UMBmark, 1996). Scan matching is unbiased but, along
// a corridor, it has little to say. This model estimates the systematic part
// online from the refined keyframe edges, where the points do say something,
// and hands the corrected odometry on as the prior of the next edges.
//
// For an odometry increment U = (U_t, U_theta) between two readings, with
// the path l its readings drove, and a calibration c = (a, g, b):
//   phi(c) = g U_theta + b l                                (heading correction)
//   P(c)   = ( (1 + a) R(phi / 2) U_t ,  U_theta + phi )                  (O1)
// (the heading correction accrues along the way: the translation turns by
// half of it). The random part has standard deviations
//   sigma_t     = max(noise_min_m, noise_fraction l),
//   sigma_theta = max(noise_min_deg, noise_deg_per_m l) + noise_turn_fraction |U_theta|.  (O2)
// A refined keyframe edge gives the points' own estimate Z of the same motion
// with information W (the point-to-line Hessian times the edge's
// information_scale); c minimises
//   sum_e huber( (Z_e - P_e(c))^T W_e (Z_e - P_e(c)) ) + c^T N0 c               (O3)
// over the edges of the last calibration_path_m of path, N0 the prior
// (scale_sigma, turn_sigma, drift_sigma_deg_per_m, centred on no error).
// The prior handed on has mean P(c) and covariance
//   Sigma_noise + A Sigma_c A^T,  A = dP/dc,  Sigma_c = (sum_e w_e A_e^T W_e A_e + N0)^-1,  (O4)
// loose while the calibration is unknown, tighter as edges come in.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <deque>
#include <string>
#include <vector>

#include "pmap/poses/pose_graph.h"

namespace pmap::poses {

struct OdometryModelOptions {
  /// Keyframe edges and scans held to the calibrated odometry (when the log
  /// has odometry and keyframe edges are refined); false: to the front
  /// end's relative pose.
  bool enabled = true;
  double noise_fraction = 0.01;        ///< translation sigma per metre driven (eq. O2)
  double noise_min_m = 0.005;          ///< ... at least (m)
  double noise_deg_per_m = 0.2;        ///< heading sigma per metre driven (deg/m)
  double noise_min_deg = 0.1;          ///< ... at least (deg)
  double noise_turn_fraction = 0.05;   ///< ... plus this share of the turn
  double scale_sigma = 0.05;           ///< prior on the distance scale error a (fraction)
  double turn_sigma = 0.05;            ///< prior on the turn scale error g (fraction)
  double drift_sigma_deg_per_m = 2.0;  ///< prior on the heading drift b (deg/m)
  /// The calibration is fitted to the edges of this much recent path (m):
  /// an odometry may change over a long run (floors, tyres, load).
  double calibration_path_m = 300.0;
  double huber_chi = 3.0;  ///< edges whose whitened residual exceeds this weigh less
  bool validate(std::string* why) const;
};

/// The odometry at a pose-laser scan: the reading (in the odometry's own
/// frame) and the path its readings drove so far.
struct OdometrySample {
  Pose2 pose;
  double path_m = 0;
};

/// The systematic odometry errors: distance scale a, turn scale g, heading
/// drift b (rad per metre driven).
struct OdometryCalibration {
  double scale = 0;
  double turn = 0;
  double drift_rad_per_m = 0;
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();  ///< of (a, g, b)
  std::size_t edges = 0;                                 ///< edges it was fitted to
};

/// A motion prior: mean and information (x, y, theta).
struct MotionPrior {
  Pose2 mean;
  Eigen::Matrix3d information = Eigen::Matrix3d::Identity();
};

class OdometryModel {
 public:
  explicit OdometryModel(OdometryModelOptions options = {});

  /// The corrected motion from `from` to `to` and its information (O1, O4).
  MotionPrior prior(const OdometrySample& from, const OdometrySample& to) const;

  /// A refined edge between the samples `from` and `to`: the points' estimate
  /// `z` of the motion with information `w` (symmetric, positive
  /// semi-definite). The calibration is fitted again (O3).
  void addEdge(const OdometrySample& from, const OdometrySample& to, const Pose2& z,
               const Eigen::Matrix3d& w);

  const OdometryCalibration& calibration() const { return calibration_; }

 private:
  struct Edge {
    Eigen::Vector3d u;  ///< the raw increment (x, y, theta)
    double path_m = 0;  ///< path driven over it
    double end_path_m = 0;
    Eigen::Vector3d z;
    Eigen::Matrix3d w;
  };
  void fit();

  OdometryModelOptions options_;
  std::deque<Edge> edges_;
  OdometryCalibration calibration_;
};

/// The keyframe edges held to the calibrated odometry, with what each was
/// made of, so that they can be made again with a later calibration: an
/// edge is the product of the points' estimate and the odometry prior
/// (fuse), which with the calibration unchanged is the edge refined.
class OdometryEdges {
 public:
  struct Term {
    std::size_t edge = 0;  ///< index in the pose graph's edges
    OdometrySample from, to;
    Pose2 data;                                                  ///< the points' own estimate
    Eigen::Matrix3d data_information = Eigen::Matrix3d::Zero();  ///< full weight; zero: unrefined
  };
  void add(const Term& term);
  bool empty() const { return terms_.empty(); }
  /// Every edge made again with `model`'s calibration (its information
  /// information_scale * data + prior, as refinePose hands on).
  void remake(const OdometryModel& model, double information_scale, PoseGraph& graph) const;

 private:
  std::vector<Term> terms_;
};

/// The points' own estimate of a refined pose: x solved min |Z - x|^2_H +
/// |x - x0|^2_L0, so the data alone say Z = x + H^+ L0 (x - x0), H^+ the
/// pseudo-inverse over H's eigen-directions above 1e-9 of its largest
/// (along directions the points do not see, Z is x).
Pose2 dataEstimate(const Pose2& x, const Eigen::Matrix3d& h, const Pose2& x0,
                   const Eigen::Matrix3d& l0);

/// The product of the points' estimate `z` (information `h`) and a prior:
/// the pose that minimises |x - z|^2_h + |x - prior.mean|^2_prior.
Pose2 fuse(const Pose2& z, const Eigen::Matrix3d& h, const MotionPrior& prior);

}  // namespace pmap::poses
