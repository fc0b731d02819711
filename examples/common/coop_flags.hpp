#pragma once
// The options that set a cooperative cut's parameters and its data preparation, shared by the
// tools that build a CoopEnergy (c2f-segment, c2f-bench-segment, c2f-bench-published):
// --lambda, --theta and --alpha, and the ranges they accept (the benchmarks' parameter lists
// are checked against them); --classes, --kmeans, --gmm-seed and --edge-seed.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>

#include "c2f/cooperative/coop_energy.hpp"
#include "c2f/vision/segmentation/segmentation_energy.hpp"
#include "tool_options.hpp"

namespace c2f::examples {

inline constexpr RealRange kLambdaRange{0.0, 1e6};
inline constexpr RealRange kThetaRange{0.0, 1e6};
inline constexpr RealRange kAlphaRange{0.0, 1.0, false, true};

/// Declares --lambda, --theta and --alpha in `options`; `parameters` receives their values (it
/// must outlive options.parse()) and holds the defaults the help shows.
inline ToolOptions& declare_coop_parameters(ToolOptions& options, CoopParameters& parameters) {
  return options.real("lambda", &parameters.lambda, kLambdaRange, "weight of the pairwise part")
      .real("theta", &parameters.theta, kThetaRange,
            "breakpoint of the concave costs, fraction of a class's weight")
      .real("alpha", &parameters.alpha, kAlphaRange,
            "slope of the concave costs after the breakpoint");
}

/// What the data preparation's flags set; `resolved()` is the DataPreparation they name.
struct PreparationFlags {
  int classes = 10;
  std::string kmeans = "plusplus";
  std::uint64_t gmm_seed = 27;
  std::uint64_t edge_seed = 27;
  /// Threads of both k-means runs and of the labels' colour models (0: the machine's cores;
  /// the result is the same for every count). Declared by the tools that have --threads.
  int threads = 0;

  /// Throws std::invalid_argument naming --kmeans for a variant it does not know.
  [[nodiscard]] vision::DataPreparation resolved() const {
    const auto options = [&](std::uint64_t seed) {
      vision::KMeansOptions chosen = with_flag("--kmeans", [&] {
        if (kmeans == "reference") return vision::reference_kmeans(seed);
        if (kmeans == "plusplus") return vision::plus_plus_kmeans(seed);
        throw std::invalid_argument("expected reference or plusplus, got '" + kmeans + "'");
      });
      chosen.threads = threads;
      return chosen;
    };
    return {classes, options(gmm_seed), options(edge_seed)};
  }
};

/// Declares --classes, --kmeans, --gmm-seed and --edge-seed in `options`; `flags` receives
/// their values (it must outlive options.parse()) and holds the defaults the help shows.
inline ToolOptions& declare_data_preparation(ToolOptions& options, PreparationFlags& flags) {
  constexpr IntegerRange kSeeds{0, std::numeric_limits<long long>::max()};
  return options.integer("classes", &flags.classes, {1, 256}, "edge classes K (k-means)")
      .text("kmeans", &flags.kmeans,
            "how both k-means runs cluster: plusplus (k-means++ start, batch rounds only: lower "
            "errors out of sample, docs/results.md) or reference (the released code's MATLAB "
            "k-means: K random data points to start, batch rounds, then single-point moves)")
      .integer("gmm-seed", &flags.gmm_seed, kSeeds,
               "seed of the k-means that starts each label's colour GMM (the reference's was "
               "unseeded: its unaries were one random draw)")
      .integer("edge-seed", &flags.edge_seed, kSeeds,
               "seed of the k-means that makes the edge classes");
}

}  // namespace c2f::examples
