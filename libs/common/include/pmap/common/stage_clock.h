// Exclusive wall time per stage of a run: time spent in a nested stage (the
// online EM inside point placing) counts for that stage only, so the stages
// add up to the total (summary.json timing_s).
//
//   StageClock clock;
//   { auto s = clock.enter(Stage::kRead); ... }
#pragma once

#include <array>
#include <chrono>
#include <cstddef>

namespace pmap {

enum class Stage : std::size_t {
  kOther = 0,  ///< everything not in a named stage (setup, configuration)
  kRead,       ///< decoding the input
  kPoses,      ///< ICP and pose handling
  kMap,        ///< extracting, placing and meshing points
  kEm,         ///< the EM planar mapper
  kRefine,     ///< fusion and the Ceres refinement
  kTexture,    ///< the map model and its camera textures
  kWrite,      ///< writing the outputs
  kCount
};

/// The stage's key in summary.json's timing_s.
const char* stageKey(Stage stage);

class StageClock {
 public:
  using Clock = std::chrono::steady_clock;

  StageClock();

  /// While alive, time goes to `stage`; then back to the enclosing one.
  class Scope {
   public:
    Scope(StageClock& clock, Stage stage);
    ~Scope();
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;

   private:
    StageClock& clock_;
    Stage previous_;
  };
  [[nodiscard]] Scope enter(Stage stage) { return Scope(*this, stage); }

  /// Seconds spent in `stage` so far (the running one included).
  double seconds(Stage stage) const;
  /// Seconds since construction: the sum of every stage's seconds.
  double total() const;

 private:
  void switchTo(Stage stage);

  std::array<double, static_cast<std::size_t>(Stage::kCount)> seconds_{};
  Stage current_ = Stage::kOther;
  Clock::time_point since_;
  Clock::time_point start_;
};

}  // namespace pmap
