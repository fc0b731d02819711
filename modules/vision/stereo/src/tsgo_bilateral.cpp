#include "c2f/vision/stereo/tsgo_bilateral.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>

#include "c2f/core/parallel_for.hpp"

namespace c2f::vision {

ColourClusters median_cut_clusters(const cv::Mat& image, int levels) {
  if (image.empty() || image.type() != CV_8UC3) {
    throw std::invalid_argument("median_cut_clusters: the image must be non-empty 8-bit 3-channel");
  }
  if (levels < 0 || levels > 20)
    throw std::invalid_argument("median_cut_clusters: levels must be in [0, 20]");
  const auto n = static_cast<std::size_t>(image.total());
  auto channel = [&](int pixel, int c) {
    return image.at<cv::Vec3b>(pixel / image.cols, pixel % image.cols)[c];
  };
  // Clusters as consecutive ranges of one permutation of the pixels (raster order at first).
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::vector<std::size_t> bounds{0, n};
  for (int level = 0; level < levels; ++level) {
    const int c = (level + 1) % 3;
    std::vector<std::size_t> next{0};
    for (std::size_t k = 0; k + 1 < bounds.size(); ++k) {
      const auto begin = order.begin() + static_cast<std::ptrdiff_t>(bounds[k]);
      const auto end = order.begin() + static_cast<std::ptrdiff_t>(bounds[k + 1]);
      // Stable by value, raster order among equal values.
      std::sort(begin, end, [&](int a, int b) {
        const auto va = channel(a, c), vb = channel(b, c);
        return va < vb || (va == vb && a < b);
      });
      const std::size_t half = bounds[k] + (bounds[k + 1] - bounds[k]) / 2;
      next.push_back(half);
      next.push_back(bounds[k + 1]);
    }
    bounds = std::move(next);
  }
  ColourClusters clusters;
  const std::size_t count = bounds.size() - 1;
  clusters.cluster_of.resize(n);
  clusters.means.assign(count, cv::Vec3d(0, 0, 0));
  clusters.sizes.assign(count, 0);
  for (std::size_t k = 0; k < count; ++k) {
    for (std::size_t i = bounds[k]; i < bounds[k + 1]; ++i) {
      const int pixel = order[i];
      clusters.cluster_of[static_cast<std::size_t>(pixel)] = static_cast<int>(k);
      clusters.means[k] += cv::Vec3d(image.at<cv::Vec3b>(pixel / image.cols, pixel % image.cols));
      ++clusters.sizes[k];
    }
    if (clusters.sizes[k] > 0) clusters.means[k] *= 1.0 / clusters.sizes[k];
  }
  return clusters;
}

namespace {

/// Grid storage: value[(node * clusters) + q], nodes row-major over gw x gh.
struct Grid {
  std::size_t gw, gh, clusters;
  std::vector<double> value;
  double& at(std::size_t gx, std::size_t gy, std::size_t q) {
    return value[(gy * gw + gx) * clusters + q];
  }
};

struct Splat {
  std::size_t gx, gy;
  double fx, fy;
};

/// The clusters each grid node can hold, sorted, at the three stages of one filtering: after the
/// splat (`splatted`: the clusters of the pixels whose splat reaches the node, which are also
/// the entries interpolate() reads), after the blur along y (`blurred_y`: the union over the
/// node's column window of +-2 nodes) and after the blur along x (`blurred`: the union of
/// `blurred_y` over the row window). Every other entry of a node is exactly zero at that stage,
/// so the passes below compute only these entries, each with the same terms in the same order
/// as the dense filter: the results are bit for bit the dense filter's.
struct ActiveClusters {
  std::vector<std::vector<std::size_t>> splatted, blurred_y, blurred;
};

std::vector<std::size_t> merged(const std::vector<std::vector<std::size_t>>& lists,
                                std::span<const std::size_t> nodes) {
  std::vector<std::size_t> all;
  for (const std::size_t n : nodes) all.insert(all.end(), lists[n].begin(), lists[n].end());
  std::sort(all.begin(), all.end());
  all.erase(std::unique(all.begin(), all.end()), all.end());
  return all;
}

ActiveClusters active_clusters(std::size_t gw, std::size_t gh, const std::vector<Splat>& splats,
                               const std::vector<int>& cluster_of) {
  ActiveClusters active;
  active.splatted.resize(gw * gh);
  for (std::size_t p = 0; p < splats.size(); ++p) {
    const Splat& s = splats[p];
    const auto q = static_cast<std::size_t>(cluster_of[p]);
    for (const std::size_t node : {s.gy * gw + s.gx, s.gy * gw + s.gx + 1, (s.gy + 1) * gw + s.gx,
                                   (s.gy + 1) * gw + s.gx + 1})
      active.splatted[node].push_back(q);
  }
  for (auto& list : active.splatted) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  const auto window = [](std::size_t centre, std::size_t size) {
    return std::pair{centre >= 2 ? centre - 2 : 0, std::min(centre + 2, size - 1)};
  };
  active.blurred_y.resize(gw * gh);
  active.blurred.resize(gw * gh);
  std::vector<std::size_t> nodes;
  for (std::size_t gy = 0; gy < gh; ++gy) {
    for (std::size_t gx = 0; gx < gw; ++gx) {
      nodes.clear();
      const auto [first, last] = window(gy, gh);
      for (std::size_t sy = first; sy <= last; ++sy) nodes.push_back(sy * gw + gx);
      active.blurred_y[gy * gw + gx] = merged(active.splatted, nodes);
    }
  }
  for (std::size_t gy = 0; gy < gh; ++gy) {
    for (std::size_t gx = 0; gx < gw; ++gx) {
      nodes.clear();
      const auto [first, last] = window(gx, gw);
      for (std::size_t sx = first; sx <= last; ++sx) nodes.push_back(gy * gw + sx);
      active.blurred[gy * gw + gx] = merged(active.blurred_y, nodes);
    }
  }
  return active;
}

/// The separable 5-tap Gaussian over the nodes (along y into `scratch`, then along x back into
/// the grid), on the active entries only. `scratch` has the grid's size and is zero outside
/// the blurred_y entries (it stays so: only those are ever written).
void blur(Grid& grid, std::vector<double>& scratch, const ActiveClusters& active) {
  static const double taps[5] = {std::exp(-2.0), std::exp(-0.5), 1.0, std::exp(-0.5),
                                 std::exp(-2.0)};
  const std::size_t q = grid.clusters;
  for (std::size_t gy = 0; gy < grid.gh; ++gy) {  // along y
    for (std::size_t gx = 0; gx < grid.gw; ++gx) {
      double* out = &scratch[(gy * grid.gw + gx) * q];
      for (const std::size_t c : active.blurred_y[gy * grid.gw + gx]) {
        double sum = 0.0;
        for (int k = -2; k <= 2; ++k) {
          const long sy = static_cast<long>(gy) + k;
          if (sy < 0 || sy >= static_cast<long>(grid.gh)) continue;
          sum += taps[k + 2] * grid.value[(static_cast<std::size_t>(sy) * grid.gw + gx) * q + c];
        }
        out[c] = sum;
      }
    }
  }
  for (std::size_t gy = 0; gy < grid.gh; ++gy) {  // along x
    for (std::size_t gx = 0; gx < grid.gw; ++gx) {
      double* out = &grid.value[(gy * grid.gw + gx) * q];
      for (const std::size_t c : active.blurred[gy * grid.gw + gx]) {
        double sum = 0.0;
        for (int k = -2; k <= 2; ++k) {
          const long sx = static_cast<long>(gx) + k;
          if (sx < 0 || sx >= static_cast<long>(grid.gw)) continue;
          sum += taps[k + 2] * scratch[(gy * grid.gw + static_cast<std::size_t>(sx)) * q + c];
        }
        out[c] = sum;
      }
    }
  }
}

struct RangeNeighbour {
  std::size_t cluster;
  double weight;
};

/// Each node's splatted entries become the range-weighted sum of the node's blurred clusters
/// (the only entries interpolate() reads). `node` is a zero buffer of q values between calls.
void mix_clusters(Grid& grid, const std::vector<std::vector<RangeNeighbour>>& neighbours,
                  const ActiveClusters& active, std::vector<double>& node) {
  const std::size_t q = grid.clusters;
  node.resize(q, 0.0);
  for (std::size_t n = 0; n < grid.gw * grid.gh; ++n) {
    double* values = &grid.value[n * q];
    for (const std::size_t c : active.blurred[n]) node[c] = values[c];
    for (const std::size_t c : active.splatted[n]) {
      double sum = 0.0;
      for (const RangeNeighbour& other : neighbours[c]) sum += other.weight * node[other.cluster];
      values[c] = sum;
    }
    for (const std::size_t c : active.blurred[n]) node[c] = 0.0;
  }
}

/// Zeroes every entry the last filtering may have written (the blurred ones).
void clear(Grid& grid, const ActiveClusters& active) {
  for (std::size_t n = 0; n < grid.gw * grid.gh; ++n) {
    double* values = &grid.value[n * grid.clusters];
    for (const std::size_t c : active.blurred[n]) values[c] = 0.0;
  }
}

double interpolate(const Grid& grid, const Splat& s, std::size_t q) {
  const std::size_t node = s.gy * grid.gw + s.gx, below = node + grid.gw;
  const std::vector<double>& v = grid.value;
  return (1 - s.fx) * (1 - s.fy) * v[node * grid.clusters + q] +
         s.fx * (1 - s.fy) * v[(node + 1) * grid.clusters + q] +
         (1 - s.fx) * s.fy * v[below * grid.clusters + q] +
         s.fx * s.fy * v[(below + 1) * grid.clusters + q];
}

void splat(Grid& grid, const Splat& s, std::size_t q, double value) {
  grid.at(s.gx, s.gy, q) += (1 - s.fx) * (1 - s.fy) * value;
  grid.at(s.gx + 1, s.gy, q) += s.fx * (1 - s.fy) * value;
  grid.at(s.gx, s.gy + 1, q) += (1 - s.fx) * s.fy * value;
  grid.at(s.gx + 1, s.gy + 1, q) += s.fx * s.fy * value;
}

/// One thread's memory for smoothing slices: the grid, the blur's scratch and the mixing
/// buffer (each as the passes above expect it between slices).
struct Workspace {
  Grid grid;
  std::vector<double> scratch, node;
  bool used = false;  ///< whether the grid holds a slice (clear() before the next)
};

/// Splat, blur and mix of one image-sized slice, with everything that does not depend on the
/// slice computed once.
class SliceSmoother {
 public:
  SliceSmoother(const ColourClusters& clusters, std::vector<std::vector<RangeNeighbour>> neighbours,
                std::size_t width, std::size_t height, int cell)
      : cluster_of_(clusters.cluster_of),
        neighbours_(std::move(neighbours)),
        gw_((width - 1) / static_cast<std::size_t>(cell) + 2),
        gh_((height - 1) / static_cast<std::size_t>(cell) + 2),
        clusters_(clusters.means.size()) {
    splats_.resize(width * height);
    const auto size = static_cast<double>(cell);
    for (std::size_t y = 0; y < height; ++y) {
      for (std::size_t x = 0; x < width; ++x) {
        const double sx = static_cast<double>(x) / size, sy = static_cast<double>(y) / size;
        const auto gx = static_cast<std::size_t>(sx), gy = static_cast<std::size_t>(sy);
        splats_[y * width + x] = {gx, gy, sx - static_cast<double>(gx),
                                  sy - static_cast<double>(gy)};
      }
    }
    active_ = active_clusters(gw_, gh_, splats_, cluster_of_);
  }

  [[nodiscard]] Workspace workspace() const {
    const std::size_t size = gw_ * gh_ * clusters_;
    return {{gw_, gh_, clusters_, std::vector<double>(size, 0.0)},
            std::vector<double>(size, 0.0),
            {},
            false};
  }

  /// Leaves the smoothed slice in `space` (read() reads it).
  void smooth(std::span<const double> slice, Workspace& space) const {
    if (space.used) clear(space.grid, active_);
    space.used = true;
    for (std::size_t p = 0; p < splats_.size(); ++p)
      splat(space.grid, splats_[p], cluster(p), slice[p]);
    blur(space.grid, space.scratch, active_);
    mix_clusters(space.grid, neighbours_, active_, space.node);
  }

  /// Pixel p's value of the smoothed slice: its cluster's bilinear interpolation.
  [[nodiscard]] double read(const Workspace& space, std::size_t p) const {
    return interpolate(space.grid, splats_[p], cluster(p));
  }

 private:
  [[nodiscard]] std::size_t cluster(std::size_t p) const {
    return static_cast<std::size_t>(cluster_of_[p]);
  }

  const std::vector<int>& cluster_of_;
  std::vector<std::vector<RangeNeighbour>> neighbours_;
  std::size_t gw_, gh_, clusters_;
  std::vector<Splat> splats_;
  ActiveClusters active_;
};

/// Labels filtered per gather: one pass over the pixel-major volume moves this many labels of
/// every pixel (a cache line of doubles) into slices, and one pass moves them back.
constexpr int kLabelBlock = 8;

}  // namespace

void cross_bilateral_filter(CostVolume& volume, const cv::Mat& guide,
                            const BilateralOptions& options) {
  if (guide.type() != CV_8UC3 || static_cast<std::size_t>(guide.cols) != volume.width() ||
      static_cast<std::size_t>(guide.rows) != volume.height()) {
    throw std::invalid_argument(
        "cross_bilateral_filter: the guide must be an 8-bit colour image of the volume's size (" +
        std::to_string(volume.width()) + "x" + std::to_string(volume.height()) + ")");
  }
  if (options.cell < 1 || !(options.colour_sigma > 0.0) || !(options.cutoff_sigmas > 0.0)) {
    throw std::invalid_argument(
        "cross_bilateral_filter: cell, colour_sigma and cutoff_sigmas must be > 0");
  }
  const ColourClusters clusters = median_cut_clusters(guide, options.cluster_levels);
  const std::size_t q = clusters.means.size();
  // Range neighbours of every non-empty cluster (including itself, weight 1).
  std::vector<std::vector<RangeNeighbour>> neighbours(q);
  const double cutoff = options.cutoff_sigmas * options.colour_sigma;
  for (std::size_t a = 0; a < q; ++a) {
    if (clusters.sizes[a] == 0) continue;
    for (std::size_t b = 0; b < q; ++b) {
      if (clusters.sizes[b] == 0) continue;
      const double distance = cv::norm(clusters.means[a] - clusters.means[b]);
      if (distance > cutoff) continue;
      const double r = std::round(distance);
      neighbours[a].push_back(
          {b, std::exp(-r * r / (2.0 * options.colour_sigma * options.colour_sigma))});
    }
  }
  const std::size_t w = volume.width(), h = volume.height(), pixels = w * h;
  const SliceSmoother smoother(clusters, std::move(neighbours), w, h, options.cell);
  std::vector<double> denominator(pixels);
  {
    Workspace space = smoother.workspace();
    smoother.smooth(std::vector<double>(pixels, 1.0), space);
    for (std::size_t p = 0; p < pixels; ++p) denominator[p] = smoother.read(space, p);
  }
  // Blocks of labels, each filtered by one thread; every label's arithmetic is the same
  // whatever thread runs it, so the volume does not depend on the thread count.
  const auto labels = static_cast<std::size_t>(volume.labels());
  const std::size_t blocks = (labels + kLabelBlock - 1) / kLabelBlock;
  const std::size_t threads = std::min<std::size_t>(resolved_threads(options.threads), blocks);
  const std::span<double> costs = volume.values();
  parallel_for(
      threads,
      [&](std::size_t thread) {
        Workspace space = smoother.workspace();
        std::vector<double> slices(kLabelBlock * pixels);
        for (std::size_t block = thread; block < blocks; block += threads) {
          const std::size_t first = block * kLabelBlock;
          const std::size_t count = std::min<std::size_t>(kLabelBlock, labels - first);
          for (std::size_t p = 0; p < pixels; ++p) {
            for (std::size_t k = 0; k < count; ++k)
              slices[k * pixels + p] = costs[p * labels + first + k];
          }
          for (std::size_t k = 0; k < count; ++k) {
            const std::span<double> slice(slices.data() + k * pixels, pixels);
            smoother.smooth(slice, space);
            for (std::size_t p = 0; p < pixels; ++p)
              slice[p] = smoother.read(space, p) / denominator[p];
          }
          for (std::size_t p = 0; p < pixels; ++p) {
            for (std::size_t k = 0; k < count; ++k)
              costs[p * labels + first + k] = slices[k * pixels + p];
          }
        }
      },
      static_cast<int>(threads));
}

}  // namespace c2f::vision
