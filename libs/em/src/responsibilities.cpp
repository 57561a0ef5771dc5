#include "pmap/em/responsibilities.h"

#include <cmath>
#include <limits>

#include "pmap/em/parallel.h"

namespace pmap::em {
namespace {

struct ChunkOut {
  std::vector<std::uint32_t> counts;
  std::vector<std::int32_t> surface;
  std::vector<double> score;
  double loglik = 0.0;
};

/// Concatenates the chunks' sparse rows (in point order) into `out` and
/// derives the weights e_ij = exp(s_ij - l_i).
void mergeChunks(const std::vector<ChunkOut>& chunks, std::size_t n, Responsibilities& out) {
  out.offsets.assign(n + 1, 0);
  out.surface.clear();
  out.score.clear();
  out.total_loglik = 0.0;
  std::size_t i = 0;
  for (const ChunkOut& co : chunks) {
    for (const std::uint32_t count : co.counts) {
      out.offsets[i + 1] = out.offsets[i] + count;
      ++i;
    }
    out.surface.insert(out.surface.end(), co.surface.begin(), co.surface.end());
    out.score.insert(out.score.end(), co.score.begin(), co.score.end());
    out.total_loglik += co.loglik;
  }
  out.weight.resize(out.score.size());
  for (std::size_t p = 0; p < n; ++p) {
    for (std::uint32_t k = out.offsets[p]; k < out.offsets[p + 1]; ++k) {
      out.weight[k] = std::exp(out.score[k] - out.loglik[p]);
    }
  }
}

}  // namespace

double logAddExp(double a, double b) {
  const double m = std::max(a, b);
  if (m == -std::numeric_limits<double>::infinity()) {
    return m;  // both terms are zero
  }
  return m + std::log(std::exp(a - m) + std::exp(b - m));
}

// E-step, eqs. (17)-(18): e_ij = exp(s_ij - l_i), e_i* = exp(s* - l_i), with
// l_i = log(exp(s*) + sum_k exp(s_ik)) computed by log-sum-exp, so that far
// points cannot underflow. A surface whose distance exceeds the cutoff has
// s_ij < s* + log(tolerance) and is skipped.
void computeResponsibilities(const std::vector<Eigen::Vector3d>& points,
                             const std::vector<Surface>& surfaces, const RectangleIndex& index,
                             const MeasurementModel& model, double tolerance, int threads,
                             Responsibilities& out) {
  const std::size_t n = points.size();
  const double s_star = model.outlierScore();
  const double min_score = s_star + std::log(tolerance);
  out.outlier.assign(n, 1.0);
  out.best.assign(n, -1);
  out.loglik.assign(n, s_star);
  std::vector<ChunkOut> chunks(chunkCount(n));
  forEachChunk(n, threads, [&](std::size_t c, std::size_t begin, std::size_t end) {
    ChunkOut& co = chunks[c];
    std::vector<std::int32_t> scratch;
    for (std::size_t i = begin; i < end; ++i) {
      const std::vector<std::int32_t>* cand = index.candidatesRef(points[i], scratch);
      std::uint32_t count = 0;
      double l = s_star;
      double best = s_star;
      static const std::vector<std::int32_t> kNone;
      for (const std::int32_t j : cand != nullptr ? *cand : kNone) {
        const double s = model.surfaceScore(surfaces[j].rect.squaredDistance(points[i]));
        if (s < min_score) {
          continue;
        }
        co.surface.push_back(j);
        co.score.push_back(s);
        ++count;
        l = logAddExp(l, s);
        if (s > best) {
          best = s;
          out.best[i] = j;
        }
      }
      co.counts.push_back(count);
      out.loglik[i] = l;
      out.outlier[i] = std::exp(s_star - l);
      co.loglik += l;
    }
  });
  mergeChunks(chunks, n, out);
}

}  // namespace pmap::em
