// Issue 15: the calibrated wheel odometry (odometry_model.h). The fit
// recovers a known scale, turn and heading drift from the edges' estimates,
// shrugs off a slipping wheel, forgets an old calibration, and its prior is
// the corrected motion with a covariance that shrinks as edges come in; the
// points' own estimate is what the refinement's solve was made of.
#include "pmap/poses/odometry_model.h"

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <cmath>
#include <random>
#include <vector>

namespace pmap::poses {
namespace {

constexpr double kDeg = M_PI / 180.0;

// A keyframe edge: `length_m` driven in kSubsteps readings, turning `turn`
// rad on the way (each reading forward, then a share of the turn).
constexpr int kSubsteps = 10;
struct EdgeMotion {
  double length_m = 0.5;
  double turn = 0.0;
};

Pose2 substep(const EdgeMotion& m) {
  return {m.length_m / kSubsteps, 0.0, m.turn / kSubsteps};
}

// The true relative pose of each edge.
std::vector<Pose2> truthOf(const std::vector<EdgeMotion>& edges) {
  std::vector<Pose2> out;
  for (const EdgeMotion& m : edges) {
    Pose2 p;
    for (int i = 0; i < kSubsteps; ++i) {
      p = compose(p, substep(m));
    }
    out.push_back(p);
  }
  return out;
}

// The odometry of a robot whose wheels measure distances (1 + scale_error)
// too long, turns (1 + turn_error) too large, and which drifts
// drift_rad_per_m per metre (the simulator's model, with a turn error on
// top), reading kSubsteps times per edge. Returns the samples at the edges'
// ends.
struct BiasedOdometry {
  double scale_error = 0.02;
  double turn_error = 0.03;
  double drift_rad_per_m = 1.0 * kDeg;
  std::vector<OdometrySample> drive(const std::vector<EdgeMotion>& edges,
                                    OdometrySample start = {}) const {
    std::vector<OdometrySample> out{start};
    for (const EdgeMotion& m : edges) {
      OdometrySample s = out.back();
      for (int i = 0; i < kSubsteps; ++i) {
        const Pose2 step = substep(m);
        const double d = std::hypot(step.x, step.y);
        const Pose2 measured{(1 + scale_error) * step.x, (1 + scale_error) * step.y,
                             (1 + turn_error) * step.theta + drift_rad_per_m * d};
        s.pose = compose(s.pose, measured);
        s.path_m += (1 + scale_error) * d;
      }
      out.push_back(s);
    }
    return out;
  }
  /// The calibration that undoes it: true = (1 + a) odometry, ...
  double a() const { return 1.0 / (1.0 + scale_error) - 1.0; }
  double g() const { return 1.0 / (1.0 + turn_error) - 1.0; }
  /// (the drift per metre of odometry path, of the true turn: it is
  /// undone with the turn error)
  double b() const { return -drift_rad_per_m / ((1.0 + scale_error) * (1.0 + turn_error)); }
};

// 0.5 m keyframe edges along a path that turns now and then.
std::vector<EdgeMotion> wigglyPath(int n) {
  std::vector<EdgeMotion> edges;
  for (int i = 0; i < n; ++i) {
    const double turn = (i % 20 < 3) ? 20.0 * kDeg * (i % 40 < 20 ? 1 : -1) : 0.0;
    edges.push_back({0.5, turn});
  }
  return edges;
}

Eigen::Matrix3d goodMatch() {  // 1 cm, 1 cm, 0.1 deg
  return Eigen::Vector3d(1e4, 1e4, 1.0 / std::pow(0.1 * kDeg, 2)).asDiagonal();
}

// A drive: its edges, their true motions and the odometry at their ends.
struct Drive {
  std::vector<EdgeMotion> path;
  std::vector<Pose2> steps;
  std::vector<OdometrySample> samples;
};

Drive run(const BiasedOdometry& odo, std::vector<EdgeMotion> path) {
  Drive r{std::move(path), {}, {}};
  r.steps = truthOf(r.path);
  r.samples = odo.drive(r.path);
  return r;
}

// A model fitted to every edge of `r`, the points having seen the truth.
OdometryModel fitted(const Drive& r) {
  OdometryModel model;
  for (std::size_t i = 0; i < r.steps.size(); ++i) {
    model.addEdge(r.samples[i], r.samples[i + 1], r.steps[i], goodMatch());
  }
  return model;
}

TEST(OdometryModel, FitRecoversTheSystematicErrors) {
  const BiasedOdometry odo;
  const Drive r = run(odo, wigglyPath(200));
  const std::vector<Pose2>& steps = r.steps;
  const std::vector<OdometrySample>& samples = r.samples;
  const OdometryModel model = fitted(r);
  const OdometryCalibration& c = model.calibration();
  EXPECT_EQ(c.edges, steps.size());
  // Noise-free edges: the model (O1) turns the translation by half the
  // heading correction, the limit of many readings; with ten readings per
  // edge the exact share is 0.45: 0.2 mm across a straight 0.5 m edge, 0.5
  // mm across one that turns 20 deg.
  EXPECT_NEAR(c.scale, odo.a(), 2e-4);
  EXPECT_NEAR(c.turn, odo.g(), 2e-3);
  EXPECT_NEAR(c.drift_rad_per_m, odo.b(), 0.005 * kDeg);
  // ... and the prior it hands on is the true motion.
  for (std::size_t i = 0; i < steps.size(); i += 17) {
    const MotionPrior p = model.prior(samples[i], samples[i + 1]);
    EXPECT_NEAR(p.mean.x, steps[i].x, 2e-4);
    EXPECT_NEAR(p.mean.y, steps[i].y, 1e-3);
    EXPECT_NEAR(p.mean.theta, steps[i].theta, 0.01 * kDeg);
  }
}

TEST(OdometryModel, CovarianceShrinksAsEdgesComeIn) {
  const Drive r = run(BiasedOdometry{}, wigglyPath(100));
  const OdometryModel fresh;
  const MotionPrior before = fresh.prior(r.samples[0], r.samples[1]);
  EXPECT_NEAR(std::sqrt(fresh.calibration().covariance(0, 0)), OdometryModelOptions{}.scale_sigma,
              1e-12);
  const OdometryModel model = fitted(r);
  const MotionPrior after = model.prior(r.samples[0], r.samples[1]);
  EXPECT_LT(model.calibration().covariance(0, 0),
            0.01 * std::pow(OdometryModelOptions{}.scale_sigma, 2));
  // Tighter along the motion once the scale is known; never tighter than
  // the random part (O2) alone.
  EXPECT_GT(after.information(0, 0), 10.0 * before.information(0, 0));
  EXPECT_LE(after.information(0, 0), 1.0 / std::pow(OdometryModelOptions{}.noise_min_m, 2) + 1e-6);
}

TEST(OdometryModel, ASlippingWheelBarelyMovesTheCalibration) {
  const Drive r = run(BiasedOdometry{}, wigglyPath(200));
  const OdometryModel clean = fitted(r);
  OdometryModel slipping;
  for (std::size_t i = 0; i < r.steps.size(); ++i) {
    // every 25th edge the wheels spun: the points saw no motion at all
    const Pose2 seen = i % 25 == 7 ? Pose2{} : r.steps[i];
    slipping.addEdge(r.samples[i], r.samples[i + 1], seen, goodMatch());
  }
  // Huber bounds each slip's pull (a plain least-squares fit moves the
  // scale by about 4 %, the slips' share of the distance).
  EXPECT_NEAR(slipping.calibration().scale, clean.calibration().scale, 3e-3);
  EXPECT_NEAR(slipping.calibration().drift_rad_per_m, clean.calibration().drift_rad_per_m,
              0.02 * kDeg);
}

TEST(OdometryModel, AnOldCalibrationIsForgotten) {
  OdometryModelOptions options;
  options.calibration_path_m = 50.0;
  OdometryModel model(options);
  BiasedOdometry first, second;
  second.scale_error = -0.03;  // new tyres
  const std::vector<EdgeMotion> path = wigglyPath(300);
  const std::vector<Pose2> steps = truthOf(path);
  const std::vector<OdometrySample> a = first.drive(path);
  for (std::size_t i = 0; i < 150; ++i) {
    model.addEdge(a[i], a[i + 1], steps[i], goodMatch());
  }
  EXPECT_NEAR(model.calibration().scale, first.a(), 1e-3);
  // The second half continues from the first's last sample.
  const std::vector<OdometrySample> b = second.drive({path.begin() + 150, path.end()}, a[150]);
  for (std::size_t i = 0; i + 1 < b.size(); ++i) {
    model.addEdge(b[i], b[i + 1], steps[150 + i], goodMatch());
  }
  EXPECT_NEAR(model.calibration().scale, second.a(), 1e-3);
  // 50 m of odometry path, 0.485 m per edge
  EXPECT_LE(model.calibration().edges, 50.0 / (0.5 * (1 + second.scale_error)) + 1);
}

TEST(OdometryModel, AStraightCorridorSaysNothingAboutTheTurnScale) {
  // Along a corridor without turns the turn scale is all but unobservable
  // (the odometry's own drift is its only turn): it stays near its prior.
  const BiasedOdometry odo;
  const OdometryModel model = fitted(run(odo, std::vector<EdgeMotion>(100, EdgeMotion{0.5, 0.0})));
  // The odometry's only turn is its drift, so the turn scale and the drift
  // are one unknown: with the turn scale at its prior (0) the drift is all
  // of it.
  EXPECT_NEAR(model.calibration().drift_rad_per_m, -odo.drift_rad_per_m / (1 + odo.scale_error),
              0.005 * kDeg);
  EXPECT_NEAR(model.calibration().turn, 0.0, 0.005);
  EXPECT_GT(std::sqrt(model.calibration().covariance(1, 1)),
            0.5 * OdometryModelOptions{}.turn_sigma);
}

// A quadratic refinement: the data's minimum Z with information H and a
// prior (x0, L0) give the solution x; dataEstimate takes the prior out
// again, and fuse puts a prior back in.
TEST(OdometryModel, DataEstimateUndoesThePriorAndFuseRedoesIt) {
  std::mt19937 rng(5);
  std::normal_distribution<double> n(0.0, 1.0);
  for (int trial = 0; trial < 20; ++trial) {
    Eigen::Matrix3d a;
    for (int i = 0; i < 9; ++i) {
      a(i / 3, i % 3) = n(rng);
    }
    Eigen::Matrix3d h = a * a.transpose() * 100.0;
    if (trial % 2 == 1) {  // a corridor: nothing along x
      h.row(0).setZero();
      h.col(0).setZero();
    }
    const Pose2 z{n(rng), n(rng), 0.1 * n(rng)};
    const MotionPrior prior{{n(rng), n(rng), 0.1 * n(rng)},
                            Eigen::Vector3d(50.0, 80.0, 400.0).asDiagonal()};
    const Pose2 x = fuse(z, h, prior);
    const Pose2 back = dataEstimate(x, h, prior.mean, prior.information);
    // Where the points see, the data's own minimum comes back; where they
    // do not (corridor), x stays.
    if (trial % 2 == 0) {
      EXPECT_NEAR(back.x, z.x, 1e-9);
    } else {
      EXPECT_NEAR(back.x, x.x, 1e-9);
    }
    EXPECT_NEAR(back.y, z.y, 1e-9);
    EXPECT_NEAR(back.theta, z.theta, 1e-9);
    // With the same prior, fusing the data's estimate again gives x.
    const Pose2 again = fuse(back, h, prior);
    EXPECT_NEAR(again.x, x.x, 1e-9);
    EXPECT_NEAR(again.y, x.y, 1e-9);
    EXPECT_NEAR(again.theta, x.theta, 1e-9);
  }
}

TEST(OdometryModel, EdgesAreMadeAgainWithTheNewCalibration) {
  // An edge made with an uncalibrated prior and remade with the fitted one
  // moves towards the truth where the points do not see (along a corridor).
  const Drive r = run(BiasedOdometry{}, wigglyPath(200));
  const std::vector<Pose2>& steps = r.steps;
  const std::vector<OdometrySample>& samples = r.samples;
  const OdometryModel fresh, calibrated = fitted(r);
  PoseGraph graph;
  graph.addNode({});
  graph.addNode({});
  const Eigen::Matrix3d corridor = Eigen::Vector3d(0.0, 1e4, 1e6).asDiagonal();
  const MotionPrior raw = fresh.prior(samples[0], samples[1]);
  PoseEdge e;
  e.from = 0;
  e.to = 1;
  e.measurement = fuse(steps[0], corridor, raw);
  e.information = 0.03 * corridor + raw.information;
  graph.addEdge(e);
  EXPECT_GT(std::abs(graph.edges()[0].measurement.x - steps[0].x), 5e-3);  // 2 % of 0.5 m
  OdometryEdges edges;
  edges.add({0, samples[0], samples[1],
             dataEstimate(e.measurement, corridor, raw.mean, raw.information), corridor});
  edges.remake(calibrated, 0.03, graph);
  EXPECT_NEAR(graph.edges()[0].measurement.x, steps[0].x, 5e-4);
  EXPECT_NEAR(graph.edges()[0].measurement.y, steps[0].y, 5e-4);
  // The information is the refinement's: the points' share plus the prior.
  const MotionPrior now = calibrated.prior(samples[0], samples[1]);
  EXPECT_TRUE(graph.edges()[0].information.isApprox(0.03 * corridor + now.information, 1e-9));
}

TEST(OdometryModelOptions, ValidateRejectsNonsense) {
  std::string why;
  EXPECT_TRUE(OdometryModelOptions{}.validate(&why)) << why;
  OdometryModelOptions o;
  o.noise_fraction = 0.0;
  EXPECT_FALSE(o.validate(&why));
  o = {};
  o.calibration_path_m = std::nan("");
  EXPECT_FALSE(o.validate(&why));
  o = {};
  o.noise_turn_fraction = 1.5;
  EXPECT_FALSE(o.validate(&why));
  o = {};
  o.scale_sigma = 2.0;
  EXPECT_FALSE(o.validate(&why));
  o = {};
  o.huber_chi = -1.0;
  EXPECT_FALSE(o.validate(&why));
  EXPECT_FALSE(why.empty());
}

}  // namespace
}  // namespace pmap::poses
