#include "c2f/adapters/coop/coop_solver.hpp"

#include <ceres/gradient_problem.h>
#include <ceres/gradient_problem_solver.h>
#include <ceres/jet.h>
#include <glog/logging.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "c2f/adapters/graphcut/expansion.hpp"
#include "c2f/core/enum_names.hpp"

namespace c2f {

using vision::ClassWeight;
using vision::CoopAuxiliary;
using vision::CoopEdge;
using vision::CoopEnergy;

std::string_view to_string(AuxStrategy strategy) {
  switch (strategy) {
    case AuxStrategy::greedy:
      return "greedy";
    case AuxStrategy::mm:
      return "mm";
    case AuxStrategy::ceres:
      return "ceres";
  }
  return "unknown";
}

AuxStrategy aux_strategy_from_string(std::string_view text) {
  constexpr AuxStrategy kAll[] = {AuxStrategy::greedy, AuxStrategy::mm, AuxStrategy::ceres};
  return enum_from_string(text, kAll, "auxiliary-variable strategy");
}

std::string_view to_string(ExpansionStart start) {
  return start == ExpansionStart::zero ? "zero" : "current";
}

ExpansionStart expansion_start_from_string(std::string_view text) {
  constexpr ExpansionStart kAll[] = {ExpansionStart::zero, ExpansionStart::current};
  return enum_from_string(text, kAll, "expansion start");
}

std::string RelaxationOptions::validate() const {
  if (max_iterations < 1) return "relaxation.max_iterations must be >= 1";
  if (!(smoothing > 0.0 && smoothing <= 1.0)) return "relaxation.smoothing must be in (0, 1]";
  return {};
}

std::string CoopSolverOptions::validate() const {
  if (expansion_cycles < 1) return "expansion_cycles must be >= 1";
  return relaxation.validate();
}

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

/// The ceres strategy's work array: the logits of the relaxation.
struct CoopSolver::Relaxation {
  std::vector<double> logits;
};

CoopSolver::CoopSolver(CoopSolverOptions options) : options_(options) {
  if (const std::string problem = options_.validate(); !problem.empty())
    throw std::invalid_argument("CoopSolverOptions: " + problem);
}

CoopSolver::~CoopSolver() = default;
CoopSolver::CoopSolver(CoopSolver&&) noexcept = default;
CoopSolver& CoopSolver::operator=(CoopSolver&&) noexcept = default;

std::size_t CoopSolver::quiet_steps_to_converge(const CoopEnergy& energy) const noexcept {
  switch (options_.strategy) {
    case AuxStrategy::greedy:
      return static_cast<std::size_t>(energy.num_labels() * energy.num_classes()) + 1;
    case AuxStrategy::mm:
      return 1;
    case AuxStrategy::ceres:
      return 2;
  }
  return 1;
}

void CoopSolver::bind(const CoopEnergy& energy, std::span<const Label> start) {
  validate_labeling(start, energy.num_variables(), energy.num_labels(), "CoopSolver::bind: start");
  energy_ = &energy;
  labeling_.assign(start.begin(), start.end());
  value_ = energy.evaluate_unchecked(labeling_);
  if (h_.num_labels() != energy.num_labels() || h_.num_classes() != energy.num_classes()) {
    h_ = CoopAuxiliary(energy.num_labels(), energy.num_classes());
    last_kept_flip_ = -1;
  }
  // The greedy scan resumes just after the last flip it kept (the reference does so when it
  // switches to the original problem).
  const auto flips = static_cast<std::size_t>(energy.num_labels() * energy.num_classes());
  next_flip_ = last_kept_flip_ < 0 ? 0 : (static_cast<std::size_t>(last_kept_flip_) + 1) % flips;
  tried_unchanged_ = false;
  last_ = {};
  if (options_.strategy == AuxStrategy::ceres) {
    relaxation_ = std::make_unique<Relaxation>();
    relaxation_->logits.assign(
        energy.num_variables() * static_cast<std::size_t>(energy.num_labels()), 0.0);
  }
}

double CoopSolver::step() {
  if (energy_ == nullptr) throw std::logic_error("CoopSolver::step: call bind() first");
  last_ = {};
  switch (options_.strategy) {
    case AuxStrategy::greedy:
      greedy_step();
      break;
    case AuxStrategy::mm:
      mm_step();
      break;
    case AuxStrategy::ceres:
      ceres_step();
      break;
  }
  return value_;
}

Labeling CoopSolver::expand_for(const CoopAuxiliary& h, std::span<const Label> start) {
  const PairwiseEnergy pairwise = vision::pairwise_energy(*energy_, h);
  ExpansionSolver<> expansion;
  expansion.bind(pairwise, start);
  const std::size_t moves = expansion.quiet_steps_to_converge(pairwise);
  for (int cycle = 0; cycle < options_.expansion_cycles; ++cycle) {
    bool improved = false;
    for (std::size_t m = 0; m < moves; ++m) {
      expansion.step();
      improved = improved || expansion.last_step().improved;
      ++last_.expansion_moves;
    }
    if (!improved) break;
  }
  return Labeling(expansion.labeling().begin(), expansion.labeling().end());
}

void CoopSolver::keep_if_lower(Labeling candidate, const CoopAuxiliary& h) {
  const double candidate_value = energy_->evaluate_unchecked(candidate);
  if (!(candidate_value < value_)) return;
  for (std::size_t i = 0; i < candidate.size(); ++i) last_.changed += candidate[i] != labeling_[i];
  last_.improved = true;
  last_.aux_changes = h.differences(h_);
  labeling_ = std::move(candidate);
  value_ = candidate_value;
  h_ = h;
}

void CoopSolver::greedy_step() {
  CoopAuxiliary trial = h_;
  std::ptrdiff_t flip = -1;
  if (tried_unchanged_) {
    const int K = energy_->num_classes();
    flip = static_cast<std::ptrdiff_t>(next_flip_);
    const int label = static_cast<int>(next_flip_) / K;
    const int edge_class = static_cast<int>(next_flip_) % K;
    trial.set(label, edge_class, !trial.linear(label, edge_class));
    last_.flipped_label = label;
    last_.flipped_class = edge_class;
    next_flip_ = (next_flip_ + 1) % static_cast<std::size_t>(energy_->num_labels() * K);
  }
  tried_unchanged_ = true;
  const Labeling zero(labeling_.size(), 0);
  const std::span<const Label> start =
      options_.start == ExpansionStart::zero ? std::span<const Label>(zero) : labeling_;
  keep_if_lower(expand_for(trial, start), trial);
  if (last_.improved && flip >= 0) last_kept_flip_ = flip;
}

void CoopSolver::mm_step() {
  const CoopAuxiliary h = CoopAuxiliary::optimal_for(*energy_, labeling_);
  keep_if_lower(expand_for(h, labeling_), h);
}

namespace {
/// How far ahead the kept labeling's label starts in the logits (softmax: p = e^2 / (e^2 + L - 1)).
constexpr double kStartMargin = 2.0;
}  // namespace

void CoopSolver::ceres_step() {
  // Ceres reports line-search corner cases through glog warnings on stderr; the solver's
  // outcome is what matters here, so only glog errors are shown.
  FLAGS_minloglevel = std::max(FLAGS_minloglevel, static_cast<int>(google::GLOG_ERROR));
  const auto start = std::chrono::steady_clock::now();
  // Warm start: the logits of the previous step's solution, the labeling kept (its label ahead
  // by 2 at every variable).
  const auto L = static_cast<std::size_t>(energy_->num_labels());
  std::fill(relaxation_->logits.begin(), relaxation_->logits.end(), 0.0);
  for (std::size_t i = 0; i < labeling_.size(); ++i)
    relaxation_->logits[i * L + static_cast<std::size_t>(labeling_[i])] = kStartMargin;
  auto* objective = new RelaxedEnergy(*energy_, options_.relaxation.smoothing);
  ceres::GradientProblem problem(objective);  // takes ownership
  ceres::GradientProblemSolver::Options options;
  options.line_search_direction_type = ceres::LBFGS;
  options.max_num_iterations = options_.relaxation.max_iterations;
  options.logging_type = ceres::SILENT;
  ceres::GradientProblemSolver::Summary summary;
  ceres::Solve(options, problem, relaxation_->logits.data(), &summary);
  std::vector<double> p;
  objective->probabilities(relaxation_->logits.data(), p);
  const std::vector<double> sizes = objective->relaxed_cut_sizes(p);
  last_.relaxation_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  // h from the relaxed cut sizes of the cooperative classes (drop each label's class K).
  const auto K = static_cast<std::size_t>(energy_->num_classes());
  std::vector<double> cooperative;
  for (std::size_t i = 0; i < sizes.size(); ++i) {
    if (i % (K + 1) != K) cooperative.push_back(sizes[i]);
  }
  const CoopAuxiliary h =
      CoopAuxiliary::optimal_for(*energy_, std::span<const double>(cooperative));
  keep_if_lower(expand_for(h, labeling_), h);
}

}  // namespace c2f
