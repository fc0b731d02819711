#include "coop_relaxation.hpp"

#include <ceres/gradient_problem.h>
#include <ceres/gradient_problem_solver.h>
#include <ceres/jet.h>
#include <glog/logging.h>

#include <algorithm>
#include <cmath>

namespace c2f::detail {

namespace {

/// The smooth concave surrogate of F_g(s) = min(s, alpha s + (1 - alpha) b): the soft minimum
/// -t log(exp(-s / t) + exp(-(alpha s + (1 - alpha) b) / t)), never above F_g; the exact
/// minimum when t = 0 (a class without weight). Any scalar type (double, ceres::Jet).
struct SoftConcaveCost {
  double alpha;
  double breakpoint;
  double temperature;

  template <class T>
  T operator()(const T& s) const {
    const T flat = alpha * s + (1.0 - alpha) * breakpoint;
    const T low = s < flat ? s : flat;
    if (temperature <= 0.0) return low;
    using std::exp;
    using std::log;
    return low -
           temperature * log(exp(-(s - low) / temperature) + exp(-(flat - low) / temperature));
  }
};

/// The relaxed energy over logits z (pixels x labels): p = softmax per pixel,
///   f(z) = sum p phi + lambda [ sum_{l, g < K} F~_g(S~_lg) + sum_l S~_lK ]
///   S~_lg = sum_e sum_{(g, w) on u's side} w/2 p_ul (1 - p_vl) + (v's side) w/2 p_vl (1 - p_ul)
class RelaxedEnergy final : public ceres::FirstOrderFunction {
 public:
  RelaxedEnergy(const CoopEnergy& energy, double smoothing) : energy_(energy) {
    const int K = energy.num_classes();
    for (int g = 0; g < K; ++g) {
      const double b = energy.breakpoint(g);
      costs_.push_back({energy.parameters().alpha, b, smoothing * b});
    }
  }

  int NumParameters() const override {
    return static_cast<int>(energy_.num_variables()) * energy_.num_labels();
  }

  bool Evaluate(const double* z, double* cost, double* gradient) const override {
    const std::size_t n = energy_.num_variables();
    const auto L = static_cast<std::size_t>(energy_.num_labels());
    const auto K = static_cast<std::size_t>(energy_.num_classes());
    const double lambda = energy_.parameters().lambda;
    probabilities(z, p_);
    sizes_ = relaxed_cut_sizes(p_);
    double value = 0.0;
    for (std::size_t i = 0; i < n * L; ++i) value += p_[i] * energy_.unaries()[i];
    double pairwise = 0.0;
    slopes_.assign(L * (K + 1), 1.0);  // dF~/dS per (label, class); class K is linear
    for (std::size_t l = 0; l < L; ++l) {
      for (std::size_t g = 0; g < K; ++g) {
        const ceres::Jet<double, 1> s(sizes_[l * (K + 1) + g], 0);
        const ceres::Jet<double, 1> f = costs_[g](s);
        pairwise += f.a;
        slopes_[l * (K + 1) + g] = f.v[0];
      }
      pairwise += sizes_[l * (K + 1) + K];
    }
    *cost = value + lambda * pairwise;
    if (gradient == nullptr) return true;

    // d f / d p, then through the softmax.
    grad_p_.assign(energy_.unaries().begin(), energy_.unaries().end());
    for (const CoopEdge& edge : energy_.edges()) {
      const double* pu = &p_[edge.u * L];
      const double* pv = &p_[edge.v * L];
      for (std::size_t l = 0; l < L; ++l) {
        double du = 0.0, dv = 0.0;
        for (const ClassWeight& entry : energy_.u_side(edge))
          du += 0.5 * entry.weight * slopes_[l * (K + 1) + entry.edge_class];
        for (const ClassWeight& entry : energy_.v_side(edge))
          dv += 0.5 * entry.weight * slopes_[l * (K + 1) + entry.edge_class];
        grad_p_[edge.u * L + l] += lambda * (du * (1.0 - pv[l]) - dv * pv[l]);
        grad_p_[edge.v * L + l] += lambda * (dv * (1.0 - pu[l]) - du * pu[l]);
      }
    }
    for (std::size_t i = 0; i < n; ++i) {
      double mean = 0.0;
      for (std::size_t l = 0; l < L; ++l) mean += p_[i * L + l] * grad_p_[i * L + l];
      for (std::size_t l = 0; l < L; ++l)
        gradient[i * L + l] = p_[i * L + l] * (grad_p_[i * L + l] - mean);
    }
    return true;
  }

  /// Softmax per pixel.
  void probabilities(const double* z, std::vector<double>& p) const {
    const std::size_t n = energy_.num_variables();
    const auto L = static_cast<std::size_t>(energy_.num_labels());
    p.resize(n * L);
    for (std::size_t i = 0; i < n; ++i) {
      const double top = *std::max_element(z + i * L, z + i * L + L);
      double total = 0.0;
      for (std::size_t l = 0; l < L; ++l) total += p[i * L + l] = std::exp(z[i * L + l] - top);
      for (std::size_t l = 0; l < L; ++l) p[i * L + l] /= total;
    }
  }

  /// S~_lg for g <= K, row-major l * (K + 1) + g.
  std::vector<double> relaxed_cut_sizes(const std::vector<double>& p) const {
    const auto L = static_cast<std::size_t>(energy_.num_labels());
    const auto K = static_cast<std::size_t>(energy_.num_classes());
    std::vector<double> sizes(L * (K + 1), 0.0);
    for (const CoopEdge& edge : energy_.edges()) {
      const double* pu = &p[edge.u * L];
      const double* pv = &p[edge.v * L];
      for (std::size_t l = 0; l < L; ++l) {
        const double u_cut = pu[l] * (1.0 - pv[l]);
        const double v_cut = pv[l] * (1.0 - pu[l]);
        for (const ClassWeight& entry : energy_.u_side(edge))
          sizes[l * (K + 1) + entry.edge_class] += 0.5 * entry.weight * u_cut;
        for (const ClassWeight& entry : energy_.v_side(edge))
          sizes[l * (K + 1) + entry.edge_class] += 0.5 * entry.weight * v_cut;
      }
    }
    return sizes;
  }

 private:
  const CoopEnergy& energy_;
  std::vector<SoftConcaveCost> costs_;
  mutable std::vector<double> p_, sizes_, slopes_, grad_p_;
};

}  // namespace

std::vector<double> relaxed_cooperative_cut_sizes(const CoopEnergy& energy,
                                                  const RelaxationOptions& options,
                                                  std::vector<double>& logits) {
  // Ceres reports line-search corner cases through glog warnings on stderr; the solver's
  // outcome is what matters here, so only glog errors are shown.
  FLAGS_minloglevel = std::max(FLAGS_minloglevel, static_cast<int>(google::GLOG_ERROR));
  auto* objective = new RelaxedEnergy(energy, options.smoothing);
  ceres::GradientProblem problem(objective);  // takes ownership
  ceres::GradientProblemSolver::Options solver_options;
  solver_options.line_search_direction_type = ceres::LBFGS;
  solver_options.max_num_iterations = options.max_iterations;
  solver_options.logging_type = ceres::SILENT;
  ceres::GradientProblemSolver::Summary summary;
  ceres::Solve(solver_options, problem, logits.data(), &summary);
  std::vector<double> p;
  objective->probabilities(logits.data(), p);
  const std::vector<double> sizes = objective->relaxed_cut_sizes(p);
  // Drop each label's class K (linear): the cooperative classes' sizes, l * K + g.
  const auto K = static_cast<std::size_t>(energy.num_classes());
  std::vector<double> cooperative;
  for (std::size_t i = 0; i < sizes.size(); ++i) {
    if (i % (K + 1) != K) cooperative.push_back(sizes[i]);
  }
  return cooperative;
}

}  // namespace c2f::detail
