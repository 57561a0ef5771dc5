#include "pmap/config/command_line.h"

#include <mrpt/3rdparty/tclap/StdOutput.h>

#include <vector>

#include "pmap/common/error.h"

namespace pmap::config {
namespace {

/// Prints usage and version like TCLAP, but records failures instead.
class RecordingOutput : public TCLAP::StdOutput {
 public:
  void failure(TCLAP::CmdLineInterface&, TCLAP::ArgException& e) override {
    failed = true;
    message = (e.argId().empty() ? std::string() : e.argId() + ": ") + e.error();
  }
  bool failed = false;
  std::string message;
};

}  // namespace

bool parseCommandLine(TCLAP::CmdLine& cmd, int argc, const char* const* argv) {
  RecordingOutput output;
  cmd.setOutput(&output);
  std::vector<const char*> args(argv, argv + argc);
  const bool ok = cmd.parse(argc, args.data());
  if (output.failed) {
    throw ConfigError("usage: " + output.message + " (see --help)");
  }
  return ok;
}

}  // namespace pmap::config
