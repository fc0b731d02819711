#pragma once
// The options that set a cooperative cut's parameters, shared by the tools that build a
// CoopEnergy (c2f-segment, c2f-bench-segment, c2f-bench-published): --lambda, --theta and
// --alpha, and the ranges they accept (c2f-bench-published-fit checks its lists against them).

#include "c2f/vision/segmentation/coop_energy.hpp"
#include "tool_options.hpp"

namespace c2f::examples {

inline constexpr RealRange kLambdaRange{0.0, 1e6};
inline constexpr RealRange kThetaRange{0.0, 1e6};
inline constexpr RealRange kAlphaRange{0.0, 1.0, false, true};

/// Declares --lambda, --theta and --alpha in `options`; `parameters` receives their values (it
/// must outlive options.parse()) and holds the defaults the help shows.
inline ToolOptions& declare_coop_parameters(ToolOptions& options,
                                            vision::CoopParameters& parameters) {
  return options.real("lambda", &parameters.lambda, kLambdaRange, "weight of the pairwise part")
      .real("theta", &parameters.theta, kThetaRange,
            "breakpoint of the concave costs, fraction of a class's weight")
      .real("alpha", &parameters.alpha, kAlphaRange,
            "slope of the concave costs after the breakpoint");
}

}  // namespace c2f::examples
