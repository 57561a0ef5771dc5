// Opening a viewer.html in headless Chromium through
// tools/viewer/screenshot.js, for the tests (needs Debian's chromium and
// tools/viewer/node_modules).
#pragma once

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <sstream>
#include <string>
#include <vector>

namespace pmap::test {

struct BrowserTools {
  std::string node;       ///< node executable
  std::string chromium;   ///< Chromium executable (PMAP_CHROMIUM overrides it)
  std::string tools_dir;  ///< tools/viewer
};

/// Grey-level standard deviation below which a canvas counts as blank.
constexpr double kMinCanvasStddev = 8.0;

inline std::string readAll(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

/// The Chromium to use: $PMAP_CHROMIUM, else the configured one.
inline std::string chromium(const BrowserTools& tools) {
  if (const char* env = std::getenv("PMAP_CHROMIUM")) {
    return env;
  }
  return tools.chromium;
}

/// Empty when the browser tools are there, else what to install.
inline std::string missingBrowserTools(const BrowserTools& tools) {
  if (chromium(tools).empty() || !std::filesystem::exists(chromium(tools))) {
    return "chromium not found: install Debian's chromium (apt-get install chromium) or set "
           "PMAP_CHROMIUM";
  }
  if (!std::filesystem::exists(std::filesystem::path(tools.tools_dir) / "node_modules" /
                               "playwright-core")) {
    return "playwright-core missing: run npm ci --prefix tools/viewer";
  }
  return {};
}

/// Runs screenshot.js (ticking the points toggle); returns its exit status
/// (-1: killed), its output in `log`.
inline int runScreenshot(const BrowserTools& tools, const std::filesystem::path& html,
                         const std::filesystem::path& png, const std::filesystem::path& report,
                         std::string& log) {
  const std::filesystem::path log_file = report.string() + ".log";
  const std::string command = "PMAP_CHROMIUM='" + chromium(tools) + "' '" + tools.node + "' '" +
                              tools.tools_dir + "/screenshot.js' '" + html.string() + "' '" +
                              png.string() + "' --points --report '" + report.string() + "' > '" +
                              log_file.string() + "' 2>&1";
  const int status = std::system(command.c_str());
  log = readAll(log_file);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/// Runs probe.js with `steps` (doc/viewer.md, tools/viewer/probe.js); returns
/// its exit status (-1: killed), its output in `log`.
inline int runProbe(const BrowserTools& tools, const std::filesystem::path& html,
                    const std::filesystem::path& report, const std::vector<std::string>& steps,
                    std::string& log) {
  const std::filesystem::path log_file = report.string() + ".log";
  std::string command = "PMAP_CHROMIUM='" + chromium(tools) + "' '" + tools.node + "' '" +
                        tools.tools_dir + "/probe.js' '" + html.string() + "' '" + report.string() +
                        "'";
  for (const std::string& step : steps) {
    command += " '" + step + "'";
  }
  command += " > '" + log_file.string() + "' 2>&1";
  const int status = std::system(command.c_str());
  log = readAll(log_file);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/// Grey-level standard deviation of the canvas in the screenshot, HUD masked out.
inline double canvasStddev(const std::filesystem::path& png, const nlohmann::json& report) {
  const cv::Mat image = cv::imread(png.string(), cv::IMREAD_GRAYSCALE);
  const auto box = [](const nlohmann::json& r) {
    return cv::Rect(r["x"].get<int>(), r["y"].get<int>(), r["width"].get<int>(),
                    r["height"].get<int>());
  };
  const cv::Rect canvas = box(report["canvas"]) & cv::Rect(0, 0, image.cols, image.rows);
  if (canvas.area() == 0) {
    return 0.0;
  }
  cv::Mat mask(image.size(), CV_8U, cv::Scalar(0));
  mask(canvas).setTo(255);
  mask(box(report["hud"]) & canvas).setTo(0);
  cv::Scalar mean, stddev;
  cv::meanStdDev(image, mean, stddev, mask);
  return stddev[0];
}

}  // namespace pmap::test
