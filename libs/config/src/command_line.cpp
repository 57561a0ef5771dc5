#include "pmap/config/command_line.h"

#include <mrpt/3rdparty/tclap/StdOutput.h>

#include <vector>

#include "pmap/common/error.h"
#include "pmap/common/text.h"

namespace pmap::config {
namespace {

/// Prints usage and version like TCLAP, but records failures instead.
class RecordingOutput : public TCLAP::StdOutput {
 public:
  void failure(TCLAP::CmdLineInterface&, TCLAP::ArgException& e) override {
    failed = true;
    const std::string arg = trim(e.argId());
    message = (arg.empty() ? std::string() : arg + ": ") + trim(e.error());
  }
  bool failed = false;
  std::string message;
};

}  // namespace

bool parseCommandLine(TCLAP::CmdLine& cmd, int argc, const char* const* argv) {
  RecordingOutput output;
  delete cmd.getOutput();  // MRPT's TCLAP::CmdLine::setOutput() leaks the default output
  cmd.setOutput(&output);
  std::vector<const char*> args(argv, argv + argc);
  const bool ok = cmd.parse(argc, args.data());
  if (output.failed) {
    std::string missing;  // TCLAP does not say which required argument is missing
    for (const TCLAP::Arg* arg : cmd.getArgList()) {
      if (arg->isRequired() && !arg->isSet()) {
        missing += (missing.empty() ? "" : ", ") + arg->longID();
      }
    }
    throw ConfigError("usage: " + output.message +
                      (missing.empty() ? "" : " (required: " + missing + ")") + " (see --help)");
  }
  return ok;
}

}  // namespace pmap::config
