#pragma once
// The headline comparison of an anytime run with its flat baseline, computed one way for every
// benchmark: when the run first reaches the flat run's final energy (exactly, and within
// kEnergyBand of it), and the mean error of both at random deadlines.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "support/anytime_trace.hpp"

namespace c2f::bench {

/// One finished run as the comparison reads it: its trace, final energy and run-clock seconds.
struct AnytimeRun {
  const std::vector<TracePoint>& trace;
  double energy = 0.0;
  double seconds = 0.0;
};

struct AnytimeComparison {
  double reach_seconds =
      std::nan("");                   ///< first time the run's energy <= flat's final (NaN: never)
  double reach_ratio = std::nan("");  ///< reach_seconds / flat's seconds
  /// first time the run's energy <= flat's final + kEnergyBand * |flat's final| (NaN: never)
  double band_seconds = std::nan("");
  double band_ratio = std::nan("");  ///< band_seconds / flat's seconds
  double flat_error = 0.0;           ///< flat's mean error at the deadlines
  double run_error = 0.0;            ///< the run's mean error at the same deadlines
};

/// "Reaches flat's final energy" within this fraction of it: runs that end on different
/// minimum cuts of equal quality differ by 1e-5 or so, which an exact comparison calls a loss.
inline constexpr double kEnergyBand = 1e-4;

/// The deadlines: kDeadlines draws, uniform over [0, the longer run's seconds], from a seeded
/// generator (the same deadlines for both runs).
inline constexpr int kDeadlines = 20;
inline constexpr std::uint64_t kDeadlineSeed = 20261121;

/// `run` against `flat`: time to reach flat's final energy and the mean errors (error_at) at
/// kDeadlines random deadlines drawn with `seed`.
inline AnytimeComparison compare_anytime(const AnytimeRun& flat, const AnytimeRun& run,
                                         std::uint64_t seed = kDeadlineSeed) {
  AnytimeComparison result;
  for (const TracePoint& p : run.trace) {
    if (p.energy <= flat.energy) {
      result.reach_seconds = p.time;
      break;
    }
  }
  result.reach_ratio = result.reach_seconds / flat.seconds;
  const double band = flat.energy + kEnergyBand * std::abs(flat.energy);
  for (const TracePoint& p : run.trace) {
    if (p.energy <= band) {
      result.band_seconds = p.time;
      break;
    }
  }
  result.band_ratio = result.band_seconds / flat.seconds;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> deadline(0.0, std::max(flat.seconds, run.seconds));
  double flat_sum = 0.0, run_sum = 0.0;
  for (int i = 0; i < kDeadlines; ++i) {
    const double t = deadline(rng);
    flat_sum += error_at(flat.trace, t);
    run_sum += error_at(run.trace, t);
  }
  result.flat_error = flat_sum / kDeadlines;
  result.run_error = run_sum / kDeadlines;
  return result;
}

}  // namespace c2f::bench
