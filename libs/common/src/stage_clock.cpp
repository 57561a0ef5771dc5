#include "pmap/common/stage_clock.h"

namespace pmap {

const char* stageKey(Stage stage) {
  static const char* const kKeys[] = {"other", "read",   "pose",    "map",
                                      "em",    "refine", "texture", "write"};
  return kKeys[static_cast<std::size_t>(stage)];
}

StageClock::StageClock() : since_(Clock::now()), start_(since_) {}

StageClock::Scope::Scope(StageClock& clock, Stage stage)
    : clock_(clock), previous_(clock.current_) {
  clock_.switchTo(stage);
}

StageClock::Scope::~Scope() {
  clock_.switchTo(previous_);
}

void StageClock::switchTo(Stage stage) {
  const Clock::time_point now = Clock::now();
  seconds_[static_cast<std::size_t>(current_)] +=
      std::chrono::duration<double>(now - since_).count();
  since_ = now;
  current_ = stage;
}

double StageClock::seconds(Stage stage) const {
  double s = seconds_[static_cast<std::size_t>(stage)];
  if (stage == current_) {
    s += std::chrono::duration<double>(Clock::now() - since_).count();
  }
  return s;
}

double StageClock::total() const {
  double sum = 0;
  for (std::size_t i = 0; i < seconds_.size(); ++i) {
    sum += seconds(static_cast<Stage>(i));
  }
  return sum;
}

}  // namespace pmap
