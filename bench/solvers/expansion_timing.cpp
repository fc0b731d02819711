// c2f-bench-expansion: alpha-expansion on a Middlebury energy with each max-flow backend.
// Time of the first full sweep (one move per label) and to convergence (a whole sweep without
// a change), for a Potts term (submodular moves) and the TSGO step term (QPBO moves). The
// energy: Teddy (2003, quarter size) with a truncated absolute-difference cost volume.
//
// Usage: c2f-bench-expansion [DATA_DIR] [--labels L] [--max-sweeps S]
//   DATA_DIR defaults to ../shared/data (the repository's sibling shared folder).

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>

#include "c2f/c2f.hpp"
#ifdef C2F_HAVE_KOLMOGOROV_MAXFLOW
#include "c2f/adapters/maxflow/kolmogorov_maxflow.hpp"
#endif

namespace {

using namespace c2f;
using Clock = std::chrono::steady_clock;

struct Result {
  double first_sweep_s = 0.0;
  double converge_s = 0.0;
  int sweeps = 0;
  bool converged = false;
  double start_energy = 0.0;
  double final_energy = 0.0;
  double flow_share = 0.0;
  double qpbo_share = 0.0;
};

template <class Backend>
Result run(const PairwiseEnergy& energy, int max_sweeps) {
  ExpansionSolver<Backend> solver;
  const auto start_labeling = initial_labeling(energy, InitialLabeling::unary_argmin);
  const auto t0 = Clock::now();
  solver.bind(energy, start_labeling);
  Result result;
  result.start_energy = solver.energy();
  double flow_seconds = 0.0;
  long moves = 0, qpbo_moves = 0;
  for (int sweep = 0; sweep < max_sweeps; ++sweep) {
    bool changed = false;
    for (std::size_t m = 0; m < solver.steps_per_sweep(energy.num_labels()); ++m) {
      solver.step();
      changed = changed || solver.last_step().improved;
      flow_seconds += solver.last_step().flow_seconds;
      qpbo_moves += solver.last_step().used_qpbo;
      ++moves;
    }
    ++result.sweeps;
    const double elapsed = std::chrono::duration<double>(Clock::now() - t0).count();
    if (sweep == 0) result.first_sweep_s = elapsed;
    std::fprintf(stderr, "  sweep %d: energy %.3f at %.2f s\n", sweep + 1, solver.energy(),
                 elapsed);
    if (!changed) {
      result.converged = true;
      break;
    }
  }
  result.converge_s = std::chrono::duration<double>(Clock::now() - t0).count();
  result.final_energy = solver.energy();
  result.flow_share = flow_seconds / result.converge_s;
  result.qpbo_share = static_cast<double>(qpbo_moves) / static_cast<double>(moves);
  return result;
}

void print_row(const char* term, const char* backend, const Result& r) {
  std::printf("| %s | %s | %.2f | %.2f | %d%s | %.3f | %.3f | %.0f%% | %.0f%% |\n", term, backend,
              r.first_sweep_s, r.converge_s, r.sweeps, r.converged ? "" : " (cap)", r.start_energy,
              r.final_energy, 100 * r.flow_share, 100 * r.qpbo_share);
}

}  // namespace

int main(int argc, char** argv) {
  std::string data = "../shared/data";
  int num_labels = 60;
  int max_sweeps = 8;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--labels" && i + 1 < argc) {
      num_labels = std::stoi(argv[++i]);
    } else if (arg == "--max-sweeps" && i + 1 < argc) {
      max_sweeps = std::stoi(argv[++i]);
    } else if (arg == "--help" || arg == "-h") {
      std::cout << "usage: c2f-bench-expansion [DATA_DIR] [--labels L] [--max-sweeps S]\n";
      return 0;
    } else {
      data = arg;
    }
  }
  try {
    const std::string scene = data + "/middlebury/2003/Teddy";
    const cv::Mat left = vision::load_colour_image(scene + "/left.png");
    const cv::Mat right = vision::load_colour_image(scene + "/right.png");
    const GridShape shape{static_cast<std::size_t>(left.cols), static_cast<std::size_t>(left.rows)};
    const auto unaries = vision::absolute_difference_cost(left, right, num_labels, 20.0);
    std::printf("Teddy %zux%zu, %d labels, truncated AD cost (20), 4-connected\n\n", shape.width,
                shape.height, num_labels);
    std::printf(
        "| term | backend | first sweep (s) | to convergence (s) | sweeps | start energy | final "
        "energy | "
        "in max-flow | QPBO moves |\n|---|---|---|---|---|---|---|---|---|\n");
    struct TermCase {
      const char* name;
      PairwiseTerm term;
      double weight;
    };
    for (const TermCase& c : {TermCase{"Potts (w=8)", PairwiseTerm::potts(), 8.0},
                              TermCase{"TSGO step (w=16)", PairwiseTerm::tsgo_step(), 16.0}}) {
      const PairwiseEnergy energy =
          make_grid_energy(shape, Connectivity::four, num_labels, unaries, c.term,
                           [&](VariableIndex, VariableIndex) { return c.weight; });
      std::fprintf(stderr, "%s, Boost:\n", c.name);
      const Result boost = run<BoostMaxFlow>(energy, max_sweeps);
      print_row(c.name, "Boost BK", boost);
#ifdef C2F_HAVE_KOLMOGOROV_MAXFLOW
      std::fprintf(stderr, "%s, libmaxflow:\n", c.name);
      const Result kolmogorov = run<KolmogorovMaxFlow>(energy, max_sweeps);
      print_row(c.name, "libmaxflow", kolmogorov);
      std::printf("| %s | ratio Boost/libmaxflow | %.2f | %.2f | | | | | |\n", c.name,
                  boost.first_sweep_s / kolmogorov.first_sweep_s,
                  boost.converge_s / kolmogorov.converge_s);
#endif
      std::fflush(stdout);
    }
  } catch (const std::exception& error) {
    std::cerr << "c2f-bench-expansion: error: " << error.what() << "\n";
    return 2;
  }
  return 0;
}
