#include "pmap/eval/texture_quality.h"

#include <cmath>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "pmap/common/error.h"
#include "pmap/eval/csv_row.h"
#include "pmap/eval/map_files.h"

namespace pmap::eval {
namespace fs = std::filesystem;

namespace {

const char* const kHeader =
    "file,surface_id,tile,width_px,height_px,x0,y0,z0,x1,y1,z1,x2,y2,z2,x3,y3,z3";
constexpr std::size_t kColumns = 17;
constexpr double kPlaneDistanceM = 0.15;  // poster and texture planes must be this close
constexpr double kMinNormalCos = 0.966;   // and within 15 degrees

MapTexture parseRow(const std::string& line, const std::string& where, const fs::path& dir) {
  const std::vector<std::string> fields = splitCsv(line);
  const RowParser row(fields, where);
  if (fields.size() != kColumns) {
    row.fail("expected " + std::to_string(kColumns) + " comma-separated columns, got " +
             std::to_string(fields.size()));
  }
  MapTexture t;
  t.file = fields[0];
  t.surface_id = static_cast<int>(row.count(1, "surface_id"));
  t.tile = static_cast<int>(row.count(2, "tile"));
  const std::int64_t w = row.count(3, "width_px"), h = row.count(4, "height_px");
  for (std::size_t k = 0; k < 4; ++k) {
    t.corners[k] = {row.number(5 + 3 * k), row.number(6 + 3 * k), row.number(7 + 3 * k)};
  }
  const fs::path image = dir / t.file;
  t.image = cv::imread(image.string(), cv::IMREAD_COLOR);
  if (t.image.empty()) {
    row.fail("texture image " + image.string() + " cannot be read");
  }
  if (t.image.cols != w || t.image.rows != h) {
    row.fail(image.string() + " is " + std::to_string(t.image.cols) + "x" +
             std::to_string(t.image.rows) + ", not " + std::to_string(w) + "x" + std::to_string(h));
  }
  return t;
}

// A texture in the ground-truth frame, ready for point lookups.
struct PlacedTexture {
  const MapTexture* texture;
  Eigen::Vector3d origin, u, v, normal;
  double length_u, length_v;

  // Bilinear colour at world point p when p lies on the texture.
  bool sample(const Eigen::Vector3d& p, cv::Vec3d& out) const {
    const Eigen::Vector3d d = p - origin;
    const double s = d.dot(u) / length_u, t = d.dot(v) / length_v;
    if (s < 0 || s > 1 || t < 0 || t > 1) {
      return false;
    }
    const cv::Mat& img = texture->image;
    const double x = std::clamp(s * img.cols - 0.5, 0.0, img.cols - 1.0);
    const double y = std::clamp((1 - t) * img.rows - 0.5, 0.0, img.rows - 1.0);
    const int x0 = static_cast<int>(x), y0 = static_cast<int>(y);
    const int x1 = std::min(img.cols - 1, x0 + 1), y1 = std::min(img.rows - 1, y0 + 1);
    const double fx = x - x0, fy = y - y0;
    for (int k = 0; k < 3; ++k) {
      out[k] =
          (1 - fy) * ((1 - fx) * img.at<cv::Vec3b>(y0, x0)[k] + fx * img.at<cv::Vec3b>(y0, x1)[k]) +
          fy * ((1 - fx) * img.at<cv::Vec3b>(y1, x0)[k] + fx * img.at<cv::Vec3b>(y1, x1)[k]);
    }
    return true;
  }
  double pixelsPerM() const { return texture->image.cols / length_u; }
};

std::vector<PlacedTexture> placeTextures(const std::vector<MapTexture>& textures,
                                         const Rigid2D& map_to_gt) {
  std::vector<PlacedTexture> out;
  for (const MapTexture& t : textures) {
    PlacedTexture p{&t, map_to_gt.apply(t.corners[0]), {}, {}, {}, 0, 0};
    const Eigen::Vector3d eu = map_to_gt.apply(t.corners[1]) - p.origin;
    const Eigen::Vector3d ev = map_to_gt.apply(t.corners[3]) - p.origin;
    p.length_u = eu.norm();
    p.length_v = ev.norm();
    if (p.length_u > 0 && p.length_v > 0) {
      p.u = eu / p.length_u;
      p.v = ev / p.length_v;
      p.normal = p.u.cross(p.v).normalized();
      out.push_back(p);
    }
  }
  return out;
}

// PSNR of x (reference) against y mapped by a per-channel least-squares
// gain and offset.
double fittedPsnr(const std::vector<cv::Vec3d>& x, const std::vector<cv::Vec3d>& y) {
  const double n = static_cast<double>(x.size());
  double sse = 0;
  for (int k = 0; k < 3; ++k) {
    double mx = 0, my = 0;
    for (std::size_t i = 0; i < x.size(); ++i) {
      mx += x[i][k], my += y[i][k];
    }
    mx /= n, my /= n;
    double sxy = 0, syy = 0;
    for (std::size_t i = 0; i < x.size(); ++i) {
      sxy += (x[i][k] - mx) * (y[i][k] - my);
      syy += (y[i][k] - my) * (y[i][k] - my);
    }
    const double a = syy > 0 ? sxy / syy : 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
      const double e = x[i][k] - (mx + a * (y[i][k] - my));
      sse += e * e;
    }
  }
  const double mse = sse / (3 * n);
  return mse > 0 ? 10 * std::log10(255.0 * 255.0 / mse) : 99.0;
}

// The poster's geometry and its image box-filtered to `ppm`.
struct PosterGrid {
  Eigen::Vector3d origin, u, v;
  double width_m = 0, height_m = 0;
  cv::Mat reference;  // CV_8UC3, row 0 = top edge

  Eigen::Vector3d cellCentre(int col, int row, const Eigen::Vector2d& shift_m) const {
    const double s = (col + 0.5) / reference.cols * width_m + shift_m.x();
    const double t = (reference.rows - row - 0.5) / reference.rows * height_m + shift_m.y();
    return origin + s * u + t * v;
  }
};

PosterGrid posterGrid(const GtPoster& poster, double ppm) {
  const cv::Mat image = cv::imread(poster.image.string(), cv::IMREAD_COLOR);
  if (image.empty()) {
    throw InputError(poster.image.string() + ": poster image of poster " +
                     std::to_string(poster.id) + " cannot be read");
  }
  PosterGrid g;
  g.origin = poster.corners[0];
  const Eigen::Vector3d eu = poster.corners[1] - poster.corners[0];
  const Eigen::Vector3d ev = poster.corners[3] - poster.corners[0];
  g.width_m = eu.norm(), g.height_m = ev.norm();
  g.u = eu / g.width_m, g.v = ev / g.height_m;
  const int w = std::max(1, static_cast<int>(std::lround(g.width_m * ppm)));
  const int h = std::max(1, static_cast<int>(std::lround(g.height_m * ppm)));
  cv::resize(image, g.reference, cv::Size(w, h), 0, 0, cv::INTER_AREA);
  return g;
}

// Reference and texture values of the poster's inner cells at one shift.
std::size_t samplePairs(const PosterGrid& g, const std::vector<const PlacedTexture*>& candidates,
                        const Eigen::Vector2d& shift_m, int margin, std::vector<cv::Vec3d>& ref,
                        std::vector<cv::Vec3d>& tex) {
  ref.clear(), tex.clear();
  std::size_t cells = 0;
  for (int row = margin; row < g.reference.rows - margin; ++row) {
    for (int col = margin; col < g.reference.cols - margin; ++col) {
      ++cells;
      const Eigen::Vector3d p = g.cellCentre(col, row, shift_m);
      cv::Vec3d value;
      for (const PlacedTexture* t : candidates) {
        if (t->sample(p, value)) {
          const cv::Vec3b r = g.reference.at<cv::Vec3b>(row, col);
          ref.emplace_back(r[0], r[1], r[2]);
          tex.push_back(value);
          break;
        }
      }
    }
  }
  return cells;
}

PosterScore scorePoster(const GtPoster& poster, const std::vector<PlacedTexture>& placed,
                        const TextureQualityOptions& options) {
  PosterScore score;
  score.poster_id = poster.id;
  const Eigen::Vector3d centre = 0.5 * (poster.corners[0] + poster.corners[2]);
  const Eigen::Vector3d normal = (poster.corners[1] - poster.corners[0])
                                     .cross(poster.corners[3] - poster.corners[0])
                                     .normalized();
  std::vector<const PlacedTexture*> candidates;
  cv::Vec3d unused;
  for (const PlacedTexture& t : placed) {
    if (std::abs(t.normal.dot(normal)) > kMinNormalCos &&
        std::abs((centre - t.origin).dot(t.normal)) < kPlaneDistanceM) {
      candidates.push_back(&t);
      if (score.surface_id < 0 &&
          t.sample(centre - (centre - t.origin).dot(t.normal) * t.normal, unused)) {
        score.surface_id = t.texture->surface_id;
        score.pixels_per_m = t.pixelsPerM();
      }
    }
  }
  if (score.surface_id < 0) {
    return score;
  }
  const PosterGrid grid = posterGrid(poster, score.pixels_per_m);
  // The outermost cells mix the poster's frame with the wall in the
  // texture's texels: left out, whatever the shift range, so that scores of
  // different searches compare the same cells.
  const int margin = 1;
  const int steps = static_cast<int>(std::floor(options.max_shift_px / options.shift_step_px));
  std::vector<cv::Vec3d> ref, tex;
  score.psnr_db = -1;
  for (int i = -steps; i <= steps; ++i) {
    for (int j = -steps; j <= steps; ++j) {
      const Eigen::Vector2d shift_px(i * options.shift_step_px, j * options.shift_step_px);
      const std::size_t cells =
          samplePairs(grid, candidates, shift_px / score.pixels_per_m, margin, ref, tex);
      if (ref.size() < 16) {
        continue;
      }
      const double psnr = fittedPsnr(ref, tex);
      if (i == 0 && j == 0) {
        score.psnr_unshifted_db = psnr;
        score.cells = cells;
        score.covered = static_cast<double>(ref.size()) / static_cast<double>(cells);
      }
      if (psnr > score.psnr_db) {
        score.psnr_db = psnr;
        score.shift_px = shift_px;
      }
    }
  }
  return score;
}

}  // namespace

std::vector<PosterScore> scorePosters(const GroundTruth& gt,
                                      const std::vector<MapTexture>& textures,
                                      const Rigid2D& map_to_gt,
                                      const TextureQualityOptions& options) {
  const std::vector<PlacedTexture> placed = placeTextures(textures, map_to_gt);
  std::vector<PosterScore> out;
  for (const GtPoster& p : gt.posters) {
    out.push_back(scorePoster(p, placed, options));
  }
  return out;
}

std::vector<MapTexture> readMapTextures(const fs::path& csv) {
  requireRegularFile(csv);
  std::ifstream in(csv);
  if (!in) {
    throw InputError(csv.string() + ": cannot open");
  }
  std::string line;
  if (!std::getline(in, line) || line != kHeader) {
    throw InputError(csv.string() + ":1: header is not '" + kHeader + "'");
  }
  std::vector<MapTexture> out;
  for (std::size_t n = 2; std::getline(in, line); ++n) {
    if (!line.empty()) {
      out.push_back(
          parseRow(line, csv.string() + ":" + std::to_string(n) + ": ", csv.parent_path()));
    }
  }
  return out;
}
}  // namespace pmap::eval
