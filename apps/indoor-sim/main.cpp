// indoor-sim: synthetic buildings with exact ground truth (doc/simulator.md).
// A thin shell over pmap::sim::IndoorSimApp; exit codes: 0 ok, 1 usage or
// configuration error, 2 input error, 4 output error; interrupted by SIGINT,
// SIGTERM or SIGHUP: ends by that signal once the temporaries are removed.
#include <exception>
#include <iostream>

#include "pmap/common/error.h"
#include "pmap/common/interrupt.h"
#include "pmap/sim/indoor_sim_app.h"

int main(int argc, char** argv) {
  try {
    pmap::sim::IndoorSimApp app;
    if (!app.initialize(argc, argv)) {
      return 0;  // --help / --version
    }
    app.run();
    return 0;
  } catch (const pmap::Interrupted& e) {
    std::cerr << "indoor-sim: " << e.what()
              << ": stopped; the previous outputs are unchanged, temporary files removed\n";
    return pmap::reraiseWithDefaultAction(e.signalNumber());
  } catch (const pmap::Error& e) {
    std::cerr << "indoor-sim: error: " << e.what() << "\n";
    return e.exitCode();
  } catch (const std::bad_alloc&) {
    std::cerr << "indoor-sim: error: out of memory\n";
    return static_cast<int>(pmap::ExitCode::kProcessing);
  } catch (const std::exception& e) {
    std::cerr << "indoor-sim: error: " << e.what() << "\n";
    return static_cast<int>(pmap::ExitCode::kProcessing);
  }
}
