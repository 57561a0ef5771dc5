// Deterministic random numbers for the simulator: std::mt19937_64 with our own
// uniform and Box-Muller normal draws (std::normal_distribution differs between
// standard libraries), and seeds derived per purpose so that each stream
// (laser noise of cycle k, image noise of frame j, poster art) is independent
// of the others and of flags such as --no-cameras.
#pragma once

#include <cstdint>
#include <random>
#include <string_view>

namespace pmap::sim {

/// Mixes `seed`, a stream name and an index into a new seed (FNV-1a + SplitMix64).
std::uint64_t deriveSeed(std::uint64_t seed, std::string_view stream, std::uint64_t index = 0);

class Rng {
 public:
  explicit Rng(std::uint64_t seed) : engine_(seed) {}

  /// Uniform in [0, 1), 53 random bits.
  double uniform();
  /// Uniform in [lo, hi).
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  /// Uniform integer in [lo, hi] (inclusive).
  int uniformInt(int lo, int hi);
  /// Standard normal (Box-Muller, the second value of each pair is kept).
  double normal();
  /// true or false with probability 1/2.
  bool coin() { return (engine_() >> 63) != 0; }

 private:
  std::mt19937_64 engine_;
  bool has_spare_ = false;
  double spare_ = 0.0;
};

}  // namespace pmap::sim
