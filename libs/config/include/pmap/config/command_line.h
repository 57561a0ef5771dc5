// Command lines of the apps are parsed with TCLAP (MRPT's bundled copy), as
// MRPT's own tools do. MRPT's TCLAP prints parse errors itself and returns
// false for both errors and --help; this wrapper tells them apart and turns
// an error into one ConfigError line (exit code 1).
#pragma once

#include <mrpt/3rdparty/tclap/CmdLine.h>

namespace pmap::config {

/// Parses argv with `cmd`. Returns false when --help or --version was
/// printed (nothing to run). Throws ConfigError "usage: <arg>: <error>".
bool parseCommandLine(TCLAP::CmdLine& cmd, int argc, const char* const* argv);

}  // namespace pmap::config
