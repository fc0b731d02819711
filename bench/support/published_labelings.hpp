#pragma once
// The coopCuts authors' published multi-label segmentations in the shared data, and the
// descent that says how far a labeling is from a local minimum of a cooperative-cut energy.

#include <algorithm>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

#include "c2f/adapters/coop/coop_solver.hpp"
#include "c2f/cooperative/coop_energy.hpp"
#include "c2f/core/labeling.hpp"

namespace c2f::bench {

/// The published labeling of `method` (alphaExpResult or coopResult) for image `name`.
inline std::string published_result_path(const std::filesystem::path& set, const std::string& name,
                                         const std::string& method) {
  return (set / "results" / (name + "_" + method + ".png")).string();
}

/// The images of the multi-label set folder `set` (coopcuts_folder(data, "multilabel")) that
/// have both published results, results/NAME_alphaExpResult.png and results/NAME_coopResult.png
/// (drawn in the GT's colours), in name order. Throws std::invalid_argument naming --data when
/// the folder has no seeds or results folder, or no image has both results.
inline std::vector<std::string> images_with_results(const std::filesystem::path& set) {
  std::error_code error;
  for (const char* folder : {"seeds", "results"}) {
    if (!std::filesystem::is_directory(set / folder, error))
      throw std::invalid_argument("--data: no folder '" + (set / folder).string() + "'");
  }
  const auto has_result = [&](const std::string& name, const char* method) {
    return std::filesystem::is_regular_file(published_result_path(set, name, method), error);
  };
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(set / "seeds")) {
    const std::string name = entry.path().stem().string();
    const bool has_results = has_result(name, "alphaExpResult") && has_result(name, "coopResult");
    if (entry.path().extension() == ".png" && has_results) names.push_back(name);
  }
  std::sort(names.begin(), names.end());
  if (names.empty())
    throw std::invalid_argument("--data: no image of '" + set.string() + "' has published results");
  return names;
}

/// Majorise-minimise descent from `start` until a step no longer lowers the energy. Under the
/// model that produced a labeling, this barely moves it: our greedy's converged labelings do
/// not move at all.
inline Labeling descend_from(const CoopEnergy& energy, const Labeling& start) {
  CoopSolverOptions options;
  options.strategy = AuxStrategy::mm;
  CoopSolver solver(options);
  solver.bind(energy, start);
  double before = solver.energy();
  while (solver.step() < before) before = solver.energy();
  return Labeling(solver.labeling().begin(), solver.labeling().end());
}

}  // namespace c2f::bench
