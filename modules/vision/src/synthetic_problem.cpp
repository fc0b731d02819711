#include "c2f/vision/synthetic_problem.hpp"

#include "c2f/support/memory_need.hpp"
#include "c2f/support/output_file.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <random>
#include <stdexcept>

namespace c2f::vision {

SyntheticProblem make_synthetic_problem(const SyntheticSpec& spec) {
  if (spec.shape.width < 2 || spec.shape.height < 2) {
    throw std::invalid_argument("synthetic problem: width and height must be >= 2");
  }
  if (spec.num_labels < 2) throw std::invalid_argument("synthetic problem: labels must be >= 2");
  // Sizes checked before any arithmetic on them can wrap (each side at most 2^16), then the
  // memory: unaries (8 bytes per pixel and label), two edges per pixel (~64 bytes) and the
  // truth, the noisy image and ICM's labelings (~16 bytes).
  constexpr std::size_t kMaxSide = std::size_t{1} << 16;
  if (spec.shape.width > kMaxSide || spec.shape.height > kMaxSide) {
    throw std::invalid_argument("synthetic problem: " + std::to_string(spec.shape.width) + "x" +
                                std::to_string(spec.shape.height) +
                                " pixels: each side must be at most 65536");
  }
  const std::size_t pixels = spec.shape.width * spec.shape.height;
  require_memory("synthetic problem: " + std::to_string(spec.shape.width) + "x" +
                     std::to_string(spec.shape.height) + " pixels with " +
                     std::to_string(spec.num_labels) + " labels",
                 checked_product({pixels, static_cast<std::size_t>(spec.num_labels) * 8 + 80}));
  if (spec.num_shapes < 0) throw std::invalid_argument("synthetic problem: shapes must be >= 0");
  if (!(spec.noise_sigma >= 0.0) || !std::isfinite(spec.noise_sigma)) {
    throw std::invalid_argument("synthetic problem: noise must be finite and >= 0");
  }
  if (!(spec.smoothness >= 0.0) || !std::isfinite(spec.smoothness)) {
    throw std::invalid_argument("synthetic problem: smoothness must be finite and >= 0");
  }
  const std::size_t w = spec.shape.width;
  const std::size_t h = spec.shape.height;
  std::mt19937_64 rng(spec.seed);
  std::uniform_int_distribution<Label> label(0, spec.num_labels - 1);
  Labeling truth(spec.shape.size(), label(rng));
  for (int s = 0; s < spec.num_shapes; ++s) {
    std::uniform_real_distribution<double> fx(0.0, static_cast<double>(w));
    std::uniform_real_distribution<double> fy(0.0, static_cast<double>(h));
    const double cx = fx(rng), cy = fy(rng);
    const double rx = fx(rng) / 4 + 2, ry = fy(rng) / 4 + 2;
    const bool disc = s % 2 == 1;
    const Label l = label(rng);
    for (std::size_t y = 0; y < h; ++y) {
      for (std::size_t x = 0; x < w; ++x) {
        const double dx = (static_cast<double>(x) - cx) / rx;
        const double dy = (static_cast<double>(y) - cy) / ry;
        const bool inside =
            disc ? dx * dx + dy * dy <= 1.0 : std::abs(dx) <= 1.0 && std::abs(dy) <= 1.0;
        if (inside) truth[y * w + x] = l;
      }
    }
  }
  const auto L = static_cast<std::size_t>(spec.num_labels);
  std::normal_distribution<double> noise(0.0, spec.noise_sigma);
  std::vector<double> unaries(spec.shape.size() * L);
  const double cap = 4.0 * std::max(1.0, spec.noise_sigma * spec.noise_sigma);
  for (std::size_t v = 0; v < truth.size(); ++v) {
    const double observed = truth[v] + noise(rng);
    for (std::size_t l = 0; l < L; ++l) {
      const double d = static_cast<double>(l) - observed;
      unaries[v * L + l] =
          std::min(d * d, cap) / std::max(1.0, spec.noise_sigma * spec.noise_sigma);
    }
  }
  PairwiseEnergy energy =
      make_grid_energy(spec.shape, Connectivity::four, spec.num_labels, std::move(unaries),
                       PairwiseTerm::truncated_linear(spec.truncation),
                       [&](VariableIndex, VariableIndex) { return spec.smoothness; });
  return {std::move(truth), std::move(energy)};
}

void write_label_pgm(const std::string& path, std::span<const Label> labeling, GridShape shape,
                     int num_labels) {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw std::runtime_error("cannot open '" + path + "' for writing");
  out << "P5\n" << shape.width << ' ' << shape.height << "\n255\n";
  for (const Label l : labeling) {
    out.put(static_cast<char>(num_labels > 1 ? l * 255 / (num_labels - 1) : 0));
  }
  close_checked(out, path);
}

}  // namespace c2f::vision
