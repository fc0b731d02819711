#include "slic_clustering.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <limits>
#include <utility>

#include "c2f/support/parallel_for.hpp"

namespace c2f::vision::detail {

namespace {

/// The smallest SLICO colour scale m_k^2 (m_k = 10: SLIC's usual compactness).
constexpr float kMinColourScale = 100.0F;
/// Rows per task of the assignment step.
constexpr std::size_t kRowsPerTask = 16;

struct Centre {
  float l = 0, a = 0, b = 0, x = 0, y = 0;
};

/// A Lab image as three planes of floats, one per channel.
struct LabPlanes {
  int width = 0, height = 0;
  std::vector<float> l, a, b;

  explicit LabPlanes(const cv::Mat& lab)
      : width(lab.cols), height(lab.rows), l(lab.total()), a(lab.total()), b(lab.total()) {
    for (int y = 0; y < height; ++y) {
      const cv::Vec3b* row = lab.ptr<cv::Vec3b>(y);
      for (int x = 0; x < width; ++x) {
        const std::size_t v = static_cast<std::size_t>(y) * width + x;
        l[v] = row[x][0];
        a[v] = row[x][1];
        b[v] = row[x][2];
      }
    }
  }
  [[nodiscard]] std::size_t at(int x, int y) const {
    return static_cast<std::size_t>(y) * width + x;
  }
  [[nodiscard]] float colour_distance(std::size_t u, std::size_t v) const {
    const float dl = l[u] - l[v], da = a[u] - a[v], db = b[u] - b[v];
    return dl * dl + da * da + db * db;
  }
  /// The squared colour change across (x, y): its horizontal and vertical central differences.
  [[nodiscard]] float gradient(int x, int y) const {
    return colour_distance(at(x + 1, y), at(x - 1, y)) +
           colour_distance(at(x, y + 1), at(x, y - 1));
  }
};

/// Centres on a grid of region_size steps, each moved to the lowest gradient of its 3x3
/// neighbourhood (pixels with four neighbours only).
std::vector<Centre> seed_centres(const LabPlanes& image, int region_size) {
  const int across = std::max(1, (image.width + region_size / 2) / region_size);
  const int down = std::max(1, (image.height + region_size / 2) / region_size);
  const double step_x = static_cast<double>(image.width) / across;
  const double step_y = static_cast<double>(image.height) / down;
  std::vector<Centre> centres;
  centres.reserve(static_cast<std::size_t>(across) * down);
  for (int j = 0; j < down; ++j) {
    for (int i = 0; i < across; ++i) {
      int x = static_cast<int>(step_x * (i + 0.5));
      int y = static_cast<int>(step_y * (j + 0.5));
      float lowest = std::numeric_limits<float>::infinity();
      int best_x = x, best_y = y;
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          const int nx = x + dx, ny = y + dy;
          if (nx < 1 || ny < 1 || nx >= image.width - 1 || ny >= image.height - 1) continue;
          const float gradient = image.gradient(nx, ny);
          if (gradient < lowest) {
            lowest = gradient;
            best_x = nx;
            best_y = ny;
          }
        }
      }
      x = best_x;
      y = best_y;
      const std::size_t v = image.at(x, y);
      centres.push_back(
          {image.l[v], image.a[v], image.b[v], static_cast<float>(x), static_cast<float>(y)});
    }
  }
  return centres;
}

/// The clustering's state between its steps.
struct Clustering {
  const LabPlanes& image;
  int region_size;
  std::vector<Centre> centres;
  std::vector<float> colour_scale;  ///< 1 / m_k^2 per centre
  std::vector<std::int32_t> label;  ///< centre per pixel
  std::vector<float> distance;      ///< D to it (infinity: no centre near)
  std::vector<float> colour;        ///< dc^2 to it

  /// Every pixel to the nearest centre whose window holds it, rows [first, last).
  void assign_rows(int first, int last) {
    const int reach = region_size;
    const auto side = static_cast<float>(region_size);
    const float spatial_scale = 1.0F / (side * side);
    for (std::size_t k = 0; k < centres.size(); ++k) {
      const Centre centre = centres[k];
      const int centre_x = static_cast<int>(centre.x), centre_y = static_cast<int>(centre.y);
      const int y_begin = std::max(first, centre_y - reach);
      const int y_end = std::min(last, centre_y + reach + 1);
      const int x_begin = std::max(0, centre_x - reach);
      const int x_end = std::min(image.width, centre_x + reach + 1);
      const float scale = colour_scale[k];
      const auto id = static_cast<std::int32_t>(k);
      for (int y = y_begin; y < y_end; ++y) {
        const float dy = static_cast<float>(y) - centre.y;
        const float dy2 = dy * dy;
        const std::size_t row = static_cast<std::size_t>(y) * image.width;
        // Raw pointers to the row, and masks rather than a branch (which GCC 12 does not
        // turn into selects here): the loop vectorises.
        const float* __restrict l = image.l.data() + row;
        const float* __restrict a = image.a.data() + row;
        const float* __restrict b = image.b.data() + row;
        float* __restrict best = distance.data() + row;
        float* __restrict best_colour = colour.data() + row;
        std::int32_t* __restrict best_label = label.data() + row;
        for (int x = x_begin; x < x_end; ++x) {
          const float dl = l[x] - centre.l, da = a[x] - centre.a, db = b[x] - centre.b;
          const float dc = dl * dl + da * da + db * db;
          const float dx = static_cast<float>(x) - centre.x;
          const float d = dc * scale + (dx * dx + dy2) * spatial_scale;
          const float before = best[x];
          const std::int32_t nearer = -static_cast<std::int32_t>(d < before);  // all ones or 0
          best[x] = std::min(before, d);
          best_colour[x] =
              std::bit_cast<float>((std::bit_cast<std::int32_t>(dc) & nearer) |
                                   (std::bit_cast<std::int32_t>(best_colour[x]) & ~nearer));
          best_label[x] = (id & nearer) | (best_label[x] & ~nearer);
        }
      }
    }
  }

  /// Each centre to its pixels' mean (pixels no window held keep their label and count for
  /// none); for SLICO each colour scale to its pixels' largest dc^2. Integer sums: exact.
  void update_centres(bool adaptive) {
    struct Sum {
      std::int64_t l = 0, a = 0, b = 0, x = 0, y = 0, count = 0;
      float largest = 0;
    };
    std::vector<Sum> sums(centres.size());
    for (int y = 0; y < image.height; ++y) {
      for (int x = 0; x < image.width; ++x) {
        const std::size_t v = image.at(x, y);
        if (distance[v] == std::numeric_limits<float>::infinity()) continue;
        Sum& sum = sums[static_cast<std::size_t>(label[v])];
        sum.l += static_cast<std::int64_t>(image.l[v]);
        sum.a += static_cast<std::int64_t>(image.a[v]);
        sum.b += static_cast<std::int64_t>(image.b[v]);
        sum.x += x;
        sum.y += y;
        ++sum.count;
        sum.largest = std::max(sum.largest, colour[v]);
      }
    }
    for (std::size_t k = 0; k < centres.size(); ++k) {
      const Sum& sum = sums[k];
      if (sum.count == 0) continue;
      const auto mean = [&sum](std::int64_t total) {
        return static_cast<float>(static_cast<double>(total) / static_cast<double>(sum.count));
      };
      centres[k] = {mean(sum.l), mean(sum.a), mean(sum.b), mean(sum.x), mean(sum.y)};
      if (adaptive) colour_scale[k] = 1.0F / std::max(kMinColourScale, sum.largest);
    }
  }
};

/// Numbers the 4-connected pieces of each cluster in scan order; a piece smaller than
/// min_size joins the piece numbered before it that touches its first pixel.
std::vector<std::int32_t> connected_superpixels(const std::vector<std::int32_t>& label, int width,
                                                int height, std::size_t min_size) {
  std::vector<std::int32_t> out(label.size(), -1);
  std::vector<std::size_t> piece;
  std::int32_t next = 0;
  constexpr std::array<int, 4> kDx{-1, 0, 1, 0}, kDy{0, -1, 0, 1};
  for (int y0 = 0; y0 < height; ++y0) {
    for (int x0 = 0; x0 < width; ++x0) {
      const std::size_t start = static_cast<std::size_t>(y0) * width + x0;
      if (out[start] >= 0) continue;
      std::int32_t before = -1;
      for (int d = 0; d < 4; ++d) {
        const int x = x0 + kDx[d], y = y0 + kDy[d];
        if (x < 0 || y < 0 || x >= width || y >= height) continue;
        const std::int32_t numbered = out[static_cast<std::size_t>(y) * width + x];
        if (numbered >= 0) before = numbered;
      }
      piece.assign(1, start);
      out[start] = next;
      for (std::size_t i = 0; i < piece.size(); ++i) {
        const int px = static_cast<int>(piece[i] % width), py = static_cast<int>(piece[i] / width);
        for (int d = 0; d < 4; ++d) {
          const int x = px + kDx[d], y = py + kDy[d];
          if (x < 0 || y < 0 || x >= width || y >= height) continue;
          const std::size_t v = static_cast<std::size_t>(y) * width + x;
          if (out[v] < 0 && label[v] == label[start]) {
            out[v] = next;
            piece.push_back(v);
          }
        }
      }
      if (piece.size() < min_size && before >= 0) {
        for (const std::size_t v : piece) out[v] = before;
      } else {
        ++next;
      }
    }
  }
  return out;
}

}  // namespace

std::vector<std::int32_t> slic_labels(const cv::Mat& lab, int region_size,
                                      const SlicOptions& options, int threads) {
  const LabPlanes image(lab);
  const bool adaptive = options.algorithm == SlicAlgorithm::slico;
  const float fixed_scale = 1.0F / (options.ruler * options.ruler);
  std::vector<Centre> centres = seed_centres(image, region_size);
  std::vector<float> colour_scale(centres.size(), adaptive ? 1.0F / kMinColourScale : fixed_scale);
  Clustering clustering{image,
                        region_size,
                        std::move(centres),
                        std::move(colour_scale),
                        std::vector<std::int32_t>(image.l.size(), 0),
                        {},
                        std::vector<float>(image.l.size(), 0.0F)};
  const auto rows = static_cast<std::size_t>(image.height);
  for (int iteration = 0; iteration < options.iterations; ++iteration) {
    clustering.distance.assign(image.l.size(), std::numeric_limits<float>::infinity());
    parallel_for_chunks(
        rows, kRowsPerTask,
        [&](std::size_t, std::size_t first, std::size_t last) {
          clustering.assign_rows(static_cast<int>(first), static_cast<int>(last));
        },
        threads);
    clustering.update_centres(adaptive);
  }
  const auto area = static_cast<std::size_t>(region_size) * static_cast<std::size_t>(region_size);
  const std::size_t min_size = area * static_cast<std::size_t>(options.min_element_percent) / 100;
  return connected_superpixels(clustering.label, image.width, image.height, min_size);
}

}  // namespace c2f::vision::detail
