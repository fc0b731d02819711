// c2f-bench-published: the coopCuts authors' published segmentations scored under our energies.
//
//   c2f-bench-published [--data DIR] [--gmm-seed N] [--edge-seed N] [--classes K]
//                       [--lambda X] [--theta X] [--alpha X]
//
// For every multi-label coopCuts image with published results (coopcuts/runMultilabel/results:
// <image>_alphaExpResult.png and <image>_coopResult.png, drawn in the GT's colours), builds our
// cooperative-cut and Potts energies exactly as c2f-segment does (labels from the GT, default
// parameters) and prints one markdown row per published labeling: its cooperative-cut energy,
// its Potts energy and its pixel error against the GT. Comparing those energies with the
// energies our solvers reach (docs/history/results-2026-11.md) says whether a gap in pixel
// error comes from the optimiser (their labeling has the lower energy under our model) or from
// the model (ours has). The last columns say how far a published labeling is from a local minimum
// of the model: the energy and pixel error where majorise-minimise descent started from it stops.
// Under the model that produced a labeling, that descent should barely move it; `--lambda`,
// `--theta` and `--alpha` change the model to test other parameters.

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "c2f/c2f.hpp"
#include "coop_flags.hpp"
#include "support/coopcuts_files.hpp"
#include "support/published_labelings.hpp"
#include "tool_options.hpp"

using namespace c2f;
using namespace c2f::vision;

namespace {

struct PublishedCommand {
  std::string data = "../shared/data";
  examples::PreparationFlags preparation;
  CoopParameters parameters;
};

void print_scores(const std::filesystem::path& set, const std::string& name,
                  const PublishedCommand& command) {
  const SegmentationScene scene =
      load_segmentation_scene(bench::coopcuts_files(command.data, "multilabel", name));
  const SegmentationProblem problem =
      segmentation_problem(scene, command.parameters, command.preparation.resolved());
  for (const char* method : {"alphaExpResult", "coopResult"}) {
    const Labeling labeling =
        read_label_image(bench::published_result_path(set, name, method), scene);
    const Labeling descended = bench::descend_from(problem.coop, labeling);
    std::printf("| %s | %s | %.4f | %.4f | %.3f%% | %.4f | %.3f%% |\n", name.c_str(), method,
                problem.coop.evaluate(labeling), problem.potts.evaluate(labeling),
                100.0 * pixel_error(labeling, scene.truth), problem.coop.evaluate(descended),
                100.0 * pixel_error(descended, scene.truth));
  }
}

}  // namespace

int main(int argc, char** argv) {
  return examples::run_tool("c2f-bench-published", [&] {
    PublishedCommand command;
    examples::ToolOptions options(
        "c2f-bench-published: the coopCuts authors' published segmentations (alpha-expansion and "
        "cooperative cut) scored under our energies: energies and pixel error per image.\n\n"
        "Usage: c2f-bench-published [options]\n\nOptions");
    options.path("data", &command.data, "data root (coopcuts/runMultilabel)");
    examples::declare_data_preparation(options, command.preparation);
    examples::declare_coop_parameters(options, command.parameters);
    const auto arguments = options.parse(argc, argv, {"", 0});
    if (!arguments) return 0;
    const std::filesystem::path set = bench::coopcuts_folder(command.data, "multilabel");
    const std::vector<std::string> names = bench::images_with_results(set);
    std::printf(
        "| image | published labeling | cooperative-cut energy | Potts energy | pixel error | "
        "energy after mm descent from it | its pixel error |\n"
        "|---|---|---|---|---|---|---|\n");
    for (const std::string& name : names) print_scores(set, name, command);
    return 0;
  });
}
