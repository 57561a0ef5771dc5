#include "pmap/poses/loop_closure.h"

#include <mrpt/core/bits_math.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

namespace pmap::poses {
namespace {

using Clock = std::chrono::steady_clock;
double secondsSince(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

double distance(const Pose2& a, const Pose2& b) {
  return std::hypot(a.x - b.x, a.y - b.y);
}

// A scan taken at pose `p` (its points in p's frame), in the frame of `frame`.
Rays inFrame(const Pose2& frame, const Pose2& p, const std::vector<Eigen::Vector2d>& points) {
  return moved({Rays{Eigen::Vector2d::Zero(), points}}, between(frame, p)).front();
}

}  // namespace

bool LoopClosureOptions::validate(std::string* why) const {
  const double positive[] = {keyframe_distance_m,
                             keyframe_angle_deg,
                             min_loop_path_m,
                             search_radius_m,
                             max_search_radius_m,
                             search_angle_deg,
                             max_search_angle_deg,
                             submap_path_m,
                             query_path_m,
                             max_chi2,
                             loop_sigma_m,
                             loop_sigma_deg,
                             odometry_sigma_fraction,
                             odometry_sigma_deg,
                             loop_loss_scale};
  for (const double v : positive) {
    if (!(v > 0.0) || !std::isfinite(v)) {
      *why = "loop closure lengths, angles, windows, thresholds and scales must be finite and > 0";
      return false;
    }
  }
  if (!(search_growth >= 0.0) || !(search_angle_growth_deg_per_m >= 0.0)) {
    *why = "search_growth and search_angle_growth_deg_per_m must be >= 0";
    return false;
  }
  if (!(max_ambiguity > 0.0 && max_ambiguity <= 1.0) || !(ambiguity_distance_m >= 0.0)) {
    *why = "loop_max_ambiguity must be in (0, 1], loop_ambiguity_distance_m >= 0";
    return false;
  }
  if (!(min_score >= 0.0 && min_score <= 1.0) ||
      !(max_free_space_conflict >= 0.0 && max_free_space_conflict <= 1.0) ||
      !(min_same_side_ratio >= 0.0 && min_same_side_ratio <= 1.0) ||
      !(min_axis_ratio >= 0.0 && min_axis_ratio <= 1.0) || !(free_space_margin_m >= 0.0)) {
    *why =
        "loop_min_score, loop_max_free_space_conflict, loop_min_same_side_ratio and "
        "loop_min_axis_ratio must be in [0, 1], loop_free_space_margin_m >= 0";
    return false;
  }
  if (candidates_per_keyframe < 1 || candidates_per_keyframe > 100) {
    *why = "loop_candidates_per_keyframe must be in [1, 100]";
    return false;
  }
  if (search_latency_keyframes < 0 || search_latency_keyframes > 100) {
    *why = "loop_search_latency_keyframes must be in [0, 100]";
    return false;
  }
  if (!(front_map_radius_m >= 0.0) || !std::isfinite(front_map_radius_m)) {
    *why = "front_map_radius_m must be a finite number >= 0";
    return false;
  }
  if (!(front_map_spacing_m >= 0.0) || !std::isfinite(front_map_spacing_m)) {
    *why = "front_map_spacing_m must be a finite number >= 0";
    return false;
  }
  if (!(refine_map_path_m > 0.0) || !std::isfinite(refine_map_path_m)) {
    *why = "keyframe_refine_map_path_m must be a finite number > 0";
    return false;
  }
  return refine.validate(why) && odometry.validate(why) && path.validate(why);
}

LoopClosingBackEnd::LoopClosingBackEnd(LoopClosureOptions options, ScanMatchOptions match)
    : options_(options),
      match_options_(match),
      graph_(PoseGraphOptions{options.loop_loss_scale}),
      odometry_model_(options.odometry),
      path_constraints_(options.path, options.refine) {}

// Keyframes every keyframe_distance_m or keyframe_angle_deg of front-end
// motion; and, with odometry, when the wheels have gone twice that distance
// while the front end says less: a front end stalled along a featureless
// corridor (MRPT ICP) would otherwise make no keyframe, and the scans in
// between would follow its stalled pose (measured: 29.6 s, 12 m on the
// aliasing world, doc/poses.md).
bool LoopClosingBackEnd::isKeyframe(const Pose2& front,
                                    const std::optional<OdometrySample>& odometry) {
  if (keyframes_.empty()) {
    return true;
  }
  const Keyframe& last = keyframes_.back();
  if (distance(last.front, front) >= options_.keyframe_distance_m ||
      std::abs(wrapAngle(front.theta - last.front.theta)) >=
          mrpt::DEG2RAD(options_.keyframe_angle_deg)) {
    return true;
  }
  if (last.odometry && odometry &&
      odometry->path_m - last.odometry->path_m >= 2.0 * options_.keyframe_distance_m) {
    ++stats_.odometry_keyframes;
    return true;
  }
  return false;
}

bool LoopClosingBackEnd::addScan(double t, const Pose2& front, std::vector<Eigen::Vector2d> points,
                                 const std::optional<OdometrySample>& odometry) {
  if (have_front_) {
    path_m_ += distance(last_front_, front);
  }
  last_front_ = front;
  have_front_ = true;
  ++scans_;
  if (points.size() < 10) {
    return false;
  }
  if (!isKeyframe(front, odometry)) {
    if (options_.refine_keyframes && options_.refine_scans) {
      refineScan(points, front, odometry);
    }
    return false;
  }
  addKeyframe(t, front, std::move(points), odometry);
  return options_.enabled && closeLoop();
}

Pose2 LoopClosingBackEnd::corrected(const ScanAnchor& anchor, const Pose2& front) const {
  if (anchor.scan == 0) {  // taken before the first keyframe: it follows that one
    return compose(graph_.node(0), between(keyframes_.front().front, front));
  }
  return compose(compose(graph_.node(anchor.keyframe), anchor.in_keyframe),
                 between(anchor.front, front));
}

// A scan between keyframes: refined against the same line map as the next
// keyframe's edge, started from the last anchor moved by the front end's
// motion since, held to the front end's pose relative to the keyframe (a
// prior relative to the last anchor instead lets errors add up from scan
// to scan: doc/poses.md); if refined, it is the new anchor.
void LoopClosingBackEnd::refineScan(const std::vector<Eigen::Vector2d>& points, const Pose2& front,
                                    const std::optional<OdometrySample>& odometry) {
  // Not against the first keyframe's scan alone: at 5 cm range noise the
  // scans after it were pulled back towards it, 0.6 m in 1.2 s (measured
  // on the default world, doc/poses.md); from two keyframes on they were
  // not, and at 2 cm noise and on ACES it made no difference.
  if (keyframes_.size() < 2) {
    return;
  }
  const Pose2 guess = compose(anchor_.in_keyframe, between(anchor_.front, front));
  const MotionPrior prior = motionPrior(keyframes_[anchor_.keyframe], front, odometry);
  const RefinedPose r =
      refinePose(recentMap(), points, guess, prior.mean, prior.information, options_.refine);
  if (r.refined) {
    ++stats_.refined_scans;
    anchor_ = {scans_, anchor_.keyframe, front, r.pose};
  }
}

const LineMap& LoopClosingBackEnd::recentMap() {
  if (!recent_map_) {
    const std::size_t last = newest();
    std::vector<Rays> map_scans;
    for (std::size_t i = last + 1; i-- > 0;) {
      if (keyframes_[last].path_m - keyframes_[i].path_m > options_.refine_map_path_m) {
        break;
      }
      map_scans.push_back(inFrame(graph_.node(last), graph_.node(i), keyframes_[i].points));
    }
    recent_map_ = std::make_unique<LineMap>(map_scans, options_.refine);
  }
  return *recent_map_;
}

void LoopClosingBackEnd::addKeyframe(double t, const Pose2& front,
                                     std::vector<Eigen::Vector2d> points,
                                     const std::optional<OdometrySample>& odometry) {
  Keyframe k{t, front, path_m_, std::move(points), odometry};
  const std::size_t id = keyframes_.size();
  anchor_ = {scans_, id, front, Pose2{}};
  if (id == 0) {
    graph_.addNode(front);
    keyframes_.push_back(std::move(k));
    ++stats_.keyframes;
    return;
  }
  PoseEdge e;
  e.from = id - 1;
  e.to = id;
  e.measurement = between(keyframes_[id - 1].front, front);
  e.information = odometryInformation(keyframes_[id - 1].front, front);
  if (options_.refine_keyframes && refineEdge(keyframes_[id - 1], k, e)) {
    ++stats_.refined_edges;
  }
  // Its estimate: the newest keyframe's pose, moved by the edge.
  graph_.addNode(compose(graph_.node(id - 1), e.measurement));
  keyframes_.push_back(std::move(k));
  ++stats_.keyframes;
  graph_.addEdge(e);
  recent_map_.reset();
  if (options_.refine_keyframes) {
    path_constraints_.add(id, keyframes_, graph_);
  }
}

// The edge from the newest keyframe `from` to a new one `to`, refined
// against the keyframes of the last refine_map_path_m of path (placed with
// the graph's poses, in the newest keyframe's frame), started from the
// front end's relative pose and held to the motion prior; unrefined, the
// edge is the prior. With calibrated odometry, the points' own estimate of
// the motion refits the calibration.
bool LoopClosingBackEnd::refineEdge(const Keyframe& from, const Keyframe& to, PoseEdge& edge) {
  const MotionPrior prior = motionPrior(from, to.front, to.odometry);
  const RefinedPose r = refinePose(recentMap(), to.points, edge.measurement, prior.mean,
                                   prior.information, options_.refine);
  edge.measurement = r.refined ? r.pose : prior.mean;
  edge.information = r.information;  // the prior's when not refined
  if (usesOdometry(from, to.odometry)) {
    // The edge is added next (addKeyframe): its index is the graph's size.
    OdometryEdges::Term term{graph_.edges().size(), *from.odometry, *to.odometry, prior.mean,
                             Eigen::Matrix3d::Zero()};
    if (r.refined) {
      term.data = dataEstimate(r.pose, r.data_information, prior.mean, prior.information);
      term.data_information = r.data_information;
      odometry_model_.addEdge(term.from, term.to, term.data,
                              options_.refine.information_scale * r.data_information);
    }
    odometry_edges_.add(term);
  }
  return r.refined;
}

bool LoopClosingBackEnd::usesOdometry(const Keyframe& from,
                                      const std::optional<OdometrySample>& odometry) const {
  return options_.odometry.enabled && options_.refine_keyframes && from.odometry && odometry;
}

// What a refinement from keyframe `from` to the front-end pose `front` is
// held to: the calibrated odometry (odometry_model.h) when there is
// odometry, otherwise the front end's relative pose.
MotionPrior LoopClosingBackEnd::motionPrior(const Keyframe& from, const Pose2& front,
                                            const std::optional<OdometrySample>& odometry) const {
  if (usesOdometry(from, odometry)) {
    return odometry_model_.prior(*from.odometry, *odometry);
  }
  return {between(from.front, front), odometryInformation(from.front, front)};
}

// What the front end's relative pose is worth: odometry_sigma_fraction of
// the distance moved (at least 1 cm), odometry_sigma_deg plus a twentieth of
// the turn.
Eigen::Matrix3d LoopClosingBackEnd::odometryInformation(const Pose2& from, const Pose2& to) const {
  const Pose2 z = between(from, to);
  const double sigma_t = std::max(0.01, options_.odometry_sigma_fraction * std::hypot(z.x, z.y));
  const double sigma_r = mrpt::DEG2RAD(options_.odometry_sigma_deg) + 0.05 * std::abs(z.theta);
  return Eigen::Vector3d(1.0 / (sigma_t * sigma_t), 1.0 / (sigma_t * sigma_t),
                         1.0 / (sigma_r * sigma_r))
      .asDiagonal();
}

std::vector<Eigen::Vector2d> LoopClosingBackEnd::localMap(const Pose2& centre, double radius_m,
                                                          const Pose2& frame,
                                                          double spacing_m) const {
  std::vector<Eigen::Vector2d> out;
  for (std::size_t k = 0; k < keyframes_.size(); ++k) {
    if (distance(graph_.node(k), centre) > radius_m) {
      continue;
    }
    const Pose2 to_frame = between(frame, graph_.node(k));
    const Eigen::Rotation2Dd r(to_frame.theta);
    const Eigen::Vector2d t(to_frame.x, to_frame.y);
    const Eigen::Vector2d* last = nullptr;
    for (const Eigen::Vector2d& p : keyframes_[k].points) {
      if (last == nullptr || (p - *last).norm() >= spacing_m) {
        out.push_back(r * p + t);
        last = &p;
      }
    }
  }
  return out;
}

std::vector<std::size_t> LoopClosingBackEnd::candidates(double radius) const {
  const std::size_t k = newest();
  const Pose2& now = graph_.node(k);
  std::vector<std::pair<double, std::size_t>> near;
  for (std::size_t j = 0; j < k; ++j) {
    if (keyframes_[k].path_m - keyframes_[j].path_m < options_.min_loop_path_m) {
      break;  // keyframes are in path order: the rest are too recent
    }
    const double d = distance(graph_.node(j), now);
    if (d <= radius) {
      near.emplace_back(d, j);
    }
  }
  std::sort(near.begin(), near.end());
  // The nearest ones, spread along the path (one per submap's half-length).
  std::vector<std::size_t> out;
  for (const auto& near_one : near) {
    const std::size_t j = near_one.second;  // (clang 14 cannot capture a structured binding)
    const bool spread = std::none_of(out.begin(), out.end(), [&](std::size_t o) {
      return std::abs(keyframes_[o].path_m - keyframes_[j].path_m) < 0.5 * options_.submap_path_m;
    });
    if (spread) {
      out.push_back(j);
    }
    if (static_cast<int>(out.size()) >= options_.candidates_per_keyframe) {
      break;
    }
  }
  return out;
}

// The scans of the keyframes within half_path_m (along the path) of
// `centre`, in centre's frame: placed with the graph's poses (optimised), or
// with the front end's (the query: locally consistent, just seen).
std::vector<Rays> LoopClosingBackEnd::scansAround(std::size_t centre, double half_path_m,
                                                  bool optimised, bool only_older) const {
  std::vector<Rays> out;
  const double at = keyframes_[centre].path_m;
  for (std::size_t i = 0; i < keyframes_.size(); ++i) {
    const double d = keyframes_[i].path_m - at;
    if (std::abs(d) > half_path_m || (only_older && d > 0)) {
      continue;
    }
    out.push_back(
        optimised ? inFrame(graph_.node(centre), graph_.node(i), keyframes_[i].points)
                  : inFrame(keyframes_[centre].front, keyframes_[i].front, keyframes_[i].points));
  }
  return out;
}

// The search window, the candidates with their submaps and the query, as
// the graph is now.
LoopSearch LoopClosingBackEnd::prepareSearch() const {
  LoopSearch s;
  s.newest = newest();
  const double since = path_m_ - path_at_last_closure_;
  s.radius_m = std::min(options_.max_search_radius_m,
                        options_.search_radius_m + options_.search_growth * since);
  s.angle_deg =
      std::min(options_.max_search_angle_deg,
               options_.search_angle_deg + options_.search_angle_growth_deg_per_m * since);
  for (const std::size_t j : candidates(s.radius_m)) {
    s.candidates.push_back({j, between(graph_.node(j), graph_.node(s.newest)),
                            scansAround(j, 0.5 * options_.submap_path_m, true, false)});
  }
  // The query (the newest keyframe's recent scans) is the same for every
  // candidate.
  if (!s.candidates.empty()) {
    s.query = scansAround(s.newest, options_.query_path_m, false, true);
  }
  return s;
}

// The job of the newest keyframe's search, with a copy of the graph as it
// is now when there is a candidate. Its loop, if any, is tested on that copy
// with the loops that the jobs still pending now keep (the front end will
// have applied them by the time it applies this one).
std::function<LoopOutcome()> LoopClosingBackEnd::prepareJob() {
  LoopSearch search = prepareSearch();
  std::optional<PoseGraph> graph;
  if (!search.candidates.empty()) {
    graph = graph_;
  }
  const std::size_t job = jobs_;  // counted once queued (closeLoop)
  const std::size_t first_pending = job - pending_.size();
  return [search = std::move(search), graph = std::move(graph), options = options_,
          match = match_options_, job, first_pending, kept = kept_by_jobs_]() mutable {
    std::deque<KeptLoops::Loop>& loops = kept->loops;
    while (!loops.empty() && loops.front().job < first_pending) {
      loops.pop_front();  // in the graph of every job from now on
    }
    LoopOutcome out;
    out.search = runLoopSearch(search, options, match);
    if (!out.search.found || !graph) {
      return out;
    }
    for (const KeptLoops::Loop& l : loops) {
      keepLoop(*graph, l.edge, l.nodes);
    }
    out.test = testLoop(std::move(*graph), out.search.edge);
    if (out.test->keeps(options.max_chi2)) {
      loops.push_back({job, out.search.edge, out.test->nodes});
    }
    return out;
  };
}

namespace {

// LoopClosureOptions::verify_worker_tests: the worker's test against one
// made now on `graph`. The two solves stop on Ceres' tolerances on problems
// of different sizes: on the ring of LoopClosure.TheWorkersLoopTestsAre
// TheBackEndsOwn their nodes differed by up to 0.64 mm and their
// innovations by 1.4e-5; with the kept loops of pending jobs left out of the
// copy (the error this guards against) the second loop's already differed by
// 19 mm and 0.27.
void verifyWorkerTest(const PoseGraph& graph, const PoseEdge& edge, const LoopTest& worker) {
  const LoopTest here = testLoop(graph, edge);
  double worst = 0.0;
  for (std::size_t i = 0; i < worker.nodes.size(); ++i) {
    const Pose2 d = between(here.nodes[i], worker.nodes[i]);
    worst = std::max({worst, std::abs(d.x), std::abs(d.y), std::abs(d.theta)});
  }
  if (worker.nodes.size() > here.nodes.size() || worst > 5e-3 ||
      std::abs(worker.innovation - here.innovation) > 1e-2 + 1e-3 * here.innovation) {
    throw std::logic_error(
        "the worker tested loop " + std::to_string(edge.from) + " -> " + std::to_string(edge.to) +
        " on another graph: innovation " + std::to_string(worker.innovation) + " against " +
        std::to_string(here.innovation) + ", nodes up to " + std::to_string(worst) + " apart");
  }
}

}  // namespace

bool LoopClosingBackEnd::apply(const LoopOutcome& outcome) {
  const LoopSearchResult& r = outcome.search;
  stats_.candidates += r.candidates;
  stats_.rejected_match += r.rejected_match;
  stats_.rejected_ambiguous += r.rejected_ambiguous;
  stats_.rejected_free_space += r.rejected_free_space;
  stats_.axis_only += r.axis_only;
  stats_.search_s += r.search_s;
  if (!r.found) {
    return false;
  }
  if (!outcome.test) {  // a found loop had a candidate, hence a copy of the graph
    throw std::logic_error("a loop found without its test");
  }
  const LoopTest& test = *outcome.test;
  if (options_.verify_worker_tests) {
    verifyWorkerTest(graph_, r.edge, test);
  }
  stats_.solve_s += test.solve_s;
  if (!test.keeps(options_.max_chi2)) {
    ++stats_.rejected_chi2;
    return false;
  }
  const std::size_t k = r.edge.to;
  const Pose2 before = graph_.node(k);
  keepLoop(graph_, r.edge, test.nodes);
  closures_.push_back({r.edge.from, k, keyframes_[r.edge.from].t, keyframes_[k].t, r.match.pose,
                       r.match.score, distance(before, graph_.node(k)), 1000.0 * test.solve_s,
                       r.free_axis});
  ++stats_.accepted;
  path_at_last_closure_ = path_m_;
  recent_map_.reset();
  return true;
}

// Synchronous: search and apply now. With a worker: queue this keyframe's
// search on it (one job at a time, in keyframe order), and apply, in order,
// the searches whose keyframes are search_latency_keyframes old (waiting for
// them if need be). Either way the result depends only on the input, not
// on the worker's speed.
bool LoopClosingBackEnd::closeLoop() {
  const auto latency = static_cast<std::size_t>(options_.search_latency_keyframes);
  if (latency == 0) {
    const LoopOutcome outcome = prepareJob()();
    ++jobs_;
    return apply(outcome);
  }
  pending_.push_back(worker_.submit(prepareJob()));
  ++jobs_;
  return pending_.size() > latency && applyOldest();
}

bool LoopClosingBackEnd::applyOldest() {
  const auto t0 = Clock::now();
  // Out of the queue before get(): a search that threw leaves no future
  // without a state behind.
  std::future<LoopOutcome> oldest = std::move(pending_.front());
  pending_.pop_front();
  const LoopOutcome r = oldest.get();
  stats_.wait_s += secondsSince(t0);
  return apply(r);
}

bool LoopClosingBackEnd::finish() {
  bool moved = false;
  while (!pending_.empty()) {
    moved = applyOldest() || moved;
  }
  return finalSolve() || moved;
}

// At the end of the input: the keyframe edges held to the odometry made
// again with the calibration fitted by then (the early edges had a cruder
// one), the path constraints added, and the graph solved with them (or,
// with neither loops nor constraints, the chain composed again).
bool LoopClosingBackEnd::finalSolve() {
  if (odometry_edges_.empty() && path_constraints_.edges().empty()) {
    return false;
  }
  odometry_edges_.remake(odometry_model_, options_.refine.information_scale, graph_);
  for (const PoseEdge& e : path_constraints_.edges()) {
    graph_.addEdge(e);
  }
  stats_.path_constraints = path_constraints_.edges().size();
  stats_.path_constraints_rejected = path_constraints_.rejected();
  if (graph_.hasLoops()) {
    const auto t0 = Clock::now();
    graph_.optimize();
    stats_.solve_s += secondsSince(t0);
  } else {
    for (const PoseEdge& e : graph_.edges()) {
      graph_.setNode(e.to, compose(graph_.node(e.from), e.measurement));
    }
  }
  recent_map_.reset();
  return true;
}

// Which loops are kept: solved with the loop under a plain quadratic cost,
// the graph must agree with it. The loop's innovation, the rise of the
// objective when the graph follows it,
// 2 (F_after - F_before) = e^T (Sigma_graph + Sigma_loop)^-1 e for linear
// Gaussian edges (e: the loop's error against the graph's estimate, Sigma_graph
// the covariance of the two keyframes' relative pose), must be at most
// max_chi2. Under the robust loss instead, the solve stayed where it was
// for a true loop after metres of drift as often as it followed it (ACES: a
// 1.3 m closure refused at chi2 180-390 in one run, accepted at 0.06 in
// another).
LoopTest testLoop(PoseGraph graph, const PoseEdge& edge) {
  const auto t0 = Clock::now();
  LoopTest t;
  const double cost_before = graph.cost();
  PoseEdge tested = edge;
  tested.robust = false;
  graph.addEdge(tested);
  graph.optimize();
  t.innovation = 2.0 * (graph.cost() - cost_before);
  t.nodes.resize(graph.size());
  for (std::size_t i = 0; i < graph.size(); ++i) {
    t.nodes[i] = graph.node(i);
  }
  t.solve_s = secondsSince(t0);
  return t;
}

void keepLoop(PoseGraph& graph, const PoseEdge& edge, const std::vector<Pose2>& nodes) {
  PoseEdge kept = edge;
  kept.robust = true;
  graph.addEdge(kept);
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    graph.setNode(i, nodes[i]);
  }
  const std::vector<PoseEdge>& edges = graph.edges();
  for (std::size_t i = nodes.size(); i < graph.size(); ++i) {
    // Its keyframe edge (addKeyframe), searched from the newest edge back.
    std::size_t e = edges.size();
    while (e-- > 0 && (edges[e].loop || edges[e].to != i || edges[e].from + 1 != i)) {
    }
    if (e >= edges.size()) {
      throw std::logic_error("a keyframe without its edge");
    }
    graph.setNode(i, compose(graph.node(i - 1), edges[e].measurement));
  }
}

}  // namespace pmap::poses
