#include "pmap/sim/indoor_sim_app.h"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <cstring>

#include "pmap/common/error.h"
#include "pmap/common/interrupt.h"
#include "sim_test_support.h"

namespace pmap::sim {
namespace {

namespace fs = std::filesystem;

std::string configErrorOf(const std::vector<std::string>& args) {
  try {
    IndoorSimApp app;
    app.initialize(args);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

// The built indoor-sim as a child process (tests of what only a real process
// shows: signals, exit status).
struct Child {
  pid_t pid = -1;
  int wait() const {
    int status = 0;
    ::waitpid(pid, &status, 0);
    return status;
  }
};

/// Writes `n` in decimal into `out` (async-signal-safe, for the forked child).
void appendDecimal(char* out, long n) {
  char digits[24];
  int len = 0;
  do {
    digits[len++] = static_cast<char>('0' + n % 10);
    n /= 10;
  } while (n > 0);
  while (*out != '\0') {
    ++out;
  }
  while (len > 0) {
    *out++ = digits[--len];
  }
  *out = '\0';
}

/// Starts bin/indoor-sim with `args`, stderr to `stderr_file`. If `blocker` is
/// set, the child first creates the non-empty directory "<blocker><its pid>"
/// (a name only known once the child exists).
Child spawnIndoorSim(const std::vector<std::string>& args, const fs::path& stderr_file,
                     const std::string& blocker = "") {
  const std::string program = std::string(PMAP_BINARY_DIR) + "/bin/indoor-sim";
  std::vector<const char*> argv = {program.c_str()};
  for (const std::string& a : args) {
    argv.push_back(a.c_str());
  }
  argv.push_back(nullptr);
  const std::string err = stderr_file.string();
  char blocker_path[4096] = {};
  if (blocker.size() + 40 > sizeof(blocker_path)) {
    ADD_FAILURE() << "blocker path too long";
    return {};
  }
  std::copy(blocker.begin(), blocker.end(), blocker_path);
  Child child;
  child.pid = ::fork();
  if (child.pid < 0) {
    ADD_FAILURE() << "fork failed";
  } else if (child.pid == 0) {  // only async-signal-safe calls until exec
    // As launched from a terminal, whatever ctest's parent ignored or blocked.
    sigset_t none;
    sigemptyset(&none);
    ::sigprocmask(SIG_SETMASK, &none, nullptr);
    for (const int s : {SIGINT, SIGTERM, SIGHUP}) {
      ::signal(s, SIG_DFL);
    }
    if (!blocker.empty()) {
      appendDecimal(blocker_path, static_cast<long>(::getpid()));
      ::mkdir(blocker_path, 0755);
      const std::size_t n = std::strlen(blocker_path);
      std::memcpy(blocker_path + n, "/keep", 6);
      ::mkdir(blocker_path, 0755);
    }
    const int fd = ::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(fd, STDERR_FILENO);
    ::execv(program.c_str(), const_cast<char* const*>(argv.data()));
    ::_exit(127);
  }
  return child;
}

int exitCodeOf(int status) {
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(IndoorSimApp, ParsesTheCommandLine) {
  IndoorSimApp app;
  ASSERT_TRUE(app.initialize({"indoor-sim", "--out", "x/run", "--seed", "12", "--sigma", "0.05",
                              "--format", "sf", "--duration", "2.5", "--no-cameras", "--quiet"}));
  EXPECT_EQ(app.options().seed, 12u);
  EXPECT_EQ(app.options().sigma_m, 0.05);
  EXPECT_EQ(app.options().format, RawlogFormat::kSensoryFrames);
  EXPECT_EQ(app.options().duration_s, 2.5);
  EXPECT_FALSE(app.options().cameras);
  EXPECT_FALSE(app.options().progress);
  // Without --world: the bundled default world of the source tree.
  EXPECT_EQ(app.options().world_file,
            std::filesystem::path(PMAP_SOURCE_DIR) / "config/worlds/default.json");
}

TEST(IndoorSimApp, HelpPrintsAndStops) {
  IndoorSimApp app;
  testing::internal::CaptureStdout();
  EXPECT_FALSE(app.initialize({"indoor-sim", "--help"}));
  EXPECT_NE(testing::internal::GetCapturedStdout().find("--out"), std::string::npos);
}

TEST(IndoorSimApp, UsageErrorsAreOneLineConfigErrors) {
  EXPECT_NE(configErrorOf({"indoor-sim"}).find("required: --out <PREFIX>"), std::string::npos);
  EXPECT_NE(configErrorOf({"indoor-sim", "--out", "x", "--seed", "-3"}).find("--seed"),
            std::string::npos);
  EXPECT_NE(configErrorOf({"indoor-sim", "--out", "x", "--sigma", "2cm"}).find("--sigma"),
            std::string::npos);
  EXPECT_NE(configErrorOf({"indoor-sim", "--out", "x", "--format", "raw"}), "");
  EXPECT_NE(configErrorOf({"indoor-sim", "--out", "x", "--bogus"}), "");
  EXPECT_NE(configErrorOf({"indoor-sim", "--out", "x", "--duration", "0"}), "");
  for (const auto& e : {configErrorOf({"indoor-sim"}), configErrorOf({"indoor-sim", "--out"})}) {
    EXPECT_EQ(e.find('\n'), std::string::npos) << e;
  }
}

TEST(IndoorSimApp, ErrorsCarryTheirExitCodes) {
  const auto dir = test::freshDir("app_errors");
  IndoorSimApp missing_world;
  ASSERT_TRUE(missing_world.initialize(
      {"indoor-sim", "--world", (dir / "none.json").string(), "--out", (dir / "r").string()}));
  try {
    missing_world.run();
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.exitCode(), 1);
  }
  const std::string world = test::writeText(dir / "tiny.json", test::tinyWorldJson()).string();
  IndoorSimApp unwritable;
  ASSERT_TRUE(unwritable.initialize(
      {"indoor-sim", "--world", world, "--out", "/proc/pmap-no-such-dir/r", "--quiet"}));
  try {
    unwritable.run();
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.exitCode(), 4);
  }
}

TEST(IndoorSimApp, RunsAShortSimulation) {
  const auto dir = test::freshDir("app_run");
  const std::string world = test::writeText(dir / "tiny.json", test::tinyWorldJson()).string();
  IndoorSimApp app;
  ASSERT_TRUE(app.initialize({"indoor-sim", "--world", world, "--out", (dir / "r").string(),
                              "--duration", "1", "--quiet"}));
  const SimulationSummary s = app.run();
  EXPECT_EQ(s.cycles, 5u);
  for (const char* f : {"r.rawlog", "r.gt.json", "r.poses.txt", "r_Images"}) {
    EXPECT_TRUE(std::filesystem::exists(dir / f)) << f;
  }
}

// SIGTERM / SIGINT / SIGHUP to a real indoor-sim while it writes: it removes its
// temporaries, keeps the earlier set byte for byte and ends by that signal.
class IndoorSimSignal : public ::testing::TestWithParam<int> {};

TEST_P(IndoorSimSignal, Item12_SignalLeavesNoTemporaries) {
  const int signal_number = GetParam();
  const auto dir = test::freshDir("app_signal_" + std::to_string(signal_number));
  const fs::path out = dir / "out";
  const std::string world = test::writeText(dir / "tiny.json", test::tinyWorldJson()).string();
  const Child first = spawnIndoorSim(
      {"--world", world, "--duration", "1", "--quiet", "--out", (out / "run").string()},
      dir / "first.err");
  ASSERT_EQ(exitCodeOf(first.wait()), 0) << test::readBytes(dir / "first.err");
  const auto before = test::snapshot(out);
  ASSERT_EQ(before.count("run.rawlog"), 1u);

  // The default world with cameras runs for seconds: long after its
  // temporaries appear.
  const Child child = spawnIndoorSim({"--quiet", "--out", (out / "run").string()}, dir / "err");
  const std::string pid = std::to_string(child.pid);
  const fs::path rawlog_tmp = out / ("run.rawlog.tmp-" + pid);
  const fs::path images_tmp = out / ("run_Images.tmp-" + pid);
  bool running = true;
  for (int i = 0; i < 12000 && !(fs::exists(rawlog_tmp) && fs::exists(images_tmp)); ++i) {
    if (::waitpid(child.pid, nullptr, WNOHANG) != 0) {
      running = false;
      break;
    }
    ::usleep(10000);  // polling, bounded at 2 minutes; nothing asserted on time
  }
  ASSERT_TRUE(running) << "indoor-sim ended before its temporaries appeared: "
                       << test::readBytes(dir / "err");
  ASSERT_TRUE(fs::exists(rawlog_tmp) && fs::exists(images_tmp));
  ASSERT_EQ(::kill(child.pid, signal_number), 0);
  const int status = child.wait();

  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == signal_number) << "status " << status;
  EXPECT_EQ(test::snapshot(out), before);  // the old set whole, no temporary left
  EXPECT_NE(test::readBytes(dir / "err").find("interrupted by " + signalName(signal_number)),
            std::string::npos)
      << test::readBytes(dir / "err");
}

INSTANTIATE_TEST_SUITE_P(TermIntHup, IndoorSimSignal, ::testing::Values(SIGTERM, SIGINT, SIGHUP));

// A rename fails during the commit of a real run (the backup name of the
// gt.json, which carries the child's pid, is a non-empty directory): exit 4,
// one line naming the file, the earlier set whole, no temporary left.
TEST(IndoorSimApp, Item12_FailedRenameKeepsOldSet) {
  const auto dir = test::freshDir("app_failed_rename");
  const fs::path out = dir / "out";
  const std::string world = test::writeText(dir / "tiny.json", test::tinyWorldJson()).string();
  const std::vector<std::string> args = {"--world", world,   "--duration",          "1",
                                         "--quiet", "--out", (out / "run").string()};
  ASSERT_EQ(exitCodeOf(spawnIndoorSim(args, dir / "first.err").wait()), 0);
  auto expected = test::snapshot(out);

  std::vector<std::string> second = args;
  second[3] = "2";  // a different set
  const Child child = spawnIndoorSim(second, dir / "err", (out / "run.gt.json.old-").string());
  const int status = child.wait();
  const std::string blocker = "run.gt.json.old-" + std::to_string(child.pid);
  expected[blocker] = "<dir>";
  expected[blocker + "/keep"] = "<dir>";

  EXPECT_EQ(exitCodeOf(status), 4);
  EXPECT_EQ(test::snapshot(out), expected);
  const std::string err = test::readBytes(dir / "err");
  EXPECT_NE(err.find("indoor-sim: error: " + (out / "run.gt.json").string() +
                     ": cannot move the previous output aside"),
            std::string::npos)
      << err;
  EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
}

}  // namespace
}  // namespace pmap::sim
