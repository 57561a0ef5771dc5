#include "pmap/sim/poster_art.h"

#include <algorithm>
#include <opencv2/imgproc.hpp>

#include "pmap/sim/rng.h"

namespace pmap::sim {
namespace {

cv::Scalar randomColour(Rng& rng, int lo, int hi) {
  return cv::Scalar(rng.uniformInt(lo, hi), rng.uniformInt(lo, hi), rng.uniformInt(lo, hi));
}

void drawStripes(cv::Mat& img, Rng& rng, int y0, int y1) {
  const int stripes = rng.uniformInt(5, 12);
  const cv::Scalar a = randomColour(rng, 20, 235);
  const cv::Scalar b = randomColour(rng, 20, 235);
  const int w = img.cols;
  const int skew = rng.uniformInt(-w / 4, w / 4);
  for (int i = 0; i < stripes; ++i) {
    const int x0 = i * w / stripes;
    const int x1 = (i + 1) * w / stripes;
    const cv::Point pts[4] = {{x0, y0}, {x1, y0}, {x1 + skew, y1}, {x0 + skew, y1}};
    cv::fillConvexPoly(img, pts, 4, (i % 2) ? a : b, cv::LINE_8);
  }
}

void drawShapes(cv::Mat& img, Rng& rng, int y0, int y1) {
  const int shapes = rng.uniformInt(3, 6);
  const int w = img.cols;
  const int h = std::max(1, y1 - y0);
  for (int i = 0; i < shapes; ++i) {
    const cv::Scalar colour = randomColour(rng, 0, 255);
    const cv::Point c(rng.uniformInt(0, w - 1), y0 + rng.uniformInt(0, h - 1));
    const int r = std::max(3, rng.uniformInt(h / 8, h / 3));
    switch (rng.uniformInt(0, 2)) {
      case 0:
        cv::circle(img, c, r, colour, cv::FILLED, cv::LINE_8);
        break;
      case 1:
        cv::rectangle(img, cv::Rect(c.x - r, c.y - r / 2, 2 * r, r), colour, cv::FILLED);
        break;
      default: {
        const cv::Point tri[3] = {{c.x, c.y - r}, {c.x - r, c.y + r}, {c.x + r, c.y + r}};
        cv::fillConvexPoly(img, tri, 3, colour, cv::LINE_8);
      }
    }
  }
}

/// Lines of "words": dark blocks of random widths, a bigger title line first.
void drawText(cv::Mat& img, Rng& rng, int y0, int y1) {
  const int margin = std::max(2, img.cols / 20);
  const cv::Scalar ink = randomColour(rng, 0, 60);
  int y = y0;
  bool title = true;
  while (true) {
    const int line_h = std::max(2, img.rows / (title ? 14 : 30));
    if (y + line_h > y1) {
      break;
    }
    int x = margin;
    const int line_end = img.cols - margin - (title ? 0 : rng.uniformInt(0, img.cols / 4));
    while (x < line_end) {
      const int word = std::min(line_end - x, line_h * rng.uniformInt(2, 7) / 2);
      cv::rectangle(img, cv::Rect(x, y, std::max(1, word), line_h), ink, cv::FILLED);
      x += word + std::max(2, line_h / 2);
    }
    y += line_h * (title ? 2 : 1) + std::max(2, line_h / 2);
    title = false;
  }
}

}  // namespace

cv::Mat generatePosterImage(int width_px, int height_px, std::uint64_t seed) {
  Rng rng(seed);
  cv::Mat img(height_px, width_px, CV_8UC3, randomColour(rng, 170, 250));
  const int h = height_px;
  drawStripes(img, rng, 0, h / 4);
  drawShapes(img, rng, h / 4, h / 2);
  drawText(img, rng, h / 2 + h / 20, h - h / 20);
  const int border = std::max(2, std::min(width_px, height_px) / 40);
  cv::rectangle(img, cv::Rect(0, 0, width_px, height_px), randomColour(rng, 0, 80), border);
  return img;
}

}  // namespace pmap::sim
