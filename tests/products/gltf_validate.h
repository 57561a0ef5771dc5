// Running the Khronos glTF validator (npm gltf-validator, through
// tools/web/validate-gltf.js) on a file, for the tests.
#pragma once

#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>

namespace pmap::test {

struct Validation {
  int exit_code = -1;
  std::string output;
  nlohmann::json report;  ///< numErrors, numWarnings, numInfos, numHints, messages
};

/// Empty when `node` and `web_tools_dir`/node_modules are there, else what to do.
inline std::string missingValidator(const std::string& node, const std::string& web_tools_dir) {
  if (node.empty() || node.find("NOTFOUND") != std::string::npos ||
      !std::filesystem::exists(node)) {
    return "node not found: install Node.js (Debian: apt-get install nodejs) and rerun cmake";
  }
  if (!std::filesystem::exists(std::filesystem::path(web_tools_dir) / "node_modules" /
                               "gltf-validator")) {
    return web_tools_dir +
           "/node_modules is missing: run `npm ci --prefix tools/web` in the "
           "source tree";
  }
  return {};
}

inline Validation validateGltf(const std::string& node, const std::string& web_tools_dir,
                               const std::filesystem::path& glb) {
  Validation v;
  const std::string command =
      "'" + node + "' '" + web_tools_dir + "/validate-gltf.js' '" + glb.string() + "' 2>&1";
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) {
    return v;
  }
  char buf[4096];
  for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, pipe)) > 0;) {
    v.output.append(buf, n);
  }
  const int status = ::pclose(pipe);
  v.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  v.report = nlohmann::json::parse(v.output, nullptr, /*allow_exceptions=*/false);
  std::cout << glb.filename().string() << ": " << v.output << "\n";  // warnings and infos
  return v;
}

}  // namespace pmap::test
