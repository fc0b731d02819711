#include "c2f/vision/stereo/tsgo_bilateral.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>

#include "c2f/core/parallel_for.hpp"

namespace c2f::vision {

ColourClusters median_cut_clusters(const cv::Mat& image, int levels, int threads) {
  if (image.empty() || image.type() != CV_8UC3) {
    throw std::invalid_argument("median_cut_clusters: the image must be non-empty 8-bit 3-channel");
  }
  if (levels < 0 || levels > 20)
    throw std::invalid_argument("median_cut_clusters: levels must be in [0, 20]");
  const auto n = static_cast<std::size_t>(image.total());
  // The pixels' channels in raster order, so that a key costs no index arithmetic.
  std::array<std::vector<std::uint8_t>, 3> channels;
  for (auto& values : channels) values.resize(n);
  for (int y = 0, pixel = 0; y < image.rows; ++y) {
    for (int x = 0; x < image.cols; ++x, ++pixel) {
      const cv::Vec3b& colour = image.at<cv::Vec3b>(y, x);
      for (int c = 0; c < 3; ++c) channels[c][static_cast<std::size_t>(pixel)] = colour[c];
    }
  }
  // Clusters as consecutive ranges of one permutation of the pixels (raster order at first).
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::vector<std::size_t> bounds{0, n};
  for (int level = 0; level < levels; ++level) {
    const std::vector<std::uint8_t>& value = channels[static_cast<std::size_t>((level + 1) % 3)];
    const std::size_t count = bounds.size() - 1;
    // Each cluster sorts its own range by (value, pixel index): a strict total order, so the
    // permutation is the same whatever sorts it and whichever thread does.
    parallel_for(
        count,
        [&](std::size_t k) {
          std::vector<std::uint64_t> keys(bounds[k + 1] - bounds[k]);
          for (std::size_t i = 0; i < keys.size(); ++i) {
            const auto pixel = static_cast<std::uint32_t>(order[bounds[k] + i]);
            keys[i] = (std::uint64_t{value[pixel]} << 32) | pixel;
          }
          std::sort(keys.begin(), keys.end());
          for (std::size_t i = 0; i < keys.size(); ++i)
            order[bounds[k] + i] = static_cast<int>(keys[i] & 0xFFFFFFFFU);
        },
        threads);
    std::vector<std::size_t> next{0};
    for (std::size_t k = 0; k < count; ++k) {
      next.push_back(bounds[k] + (bounds[k + 1] - bounds[k]) / 2);
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
      const auto pixel = static_cast<std::size_t>(order[i]);
      clusters.cluster_of[pixel] = static_cast<int>(k);
      clusters.means[k] += cv::Vec3d(channels[0][pixel], channels[1][pixel], channels[2][pixel]);
      ++clusters.sizes[k];
    }
    if (clusters.sizes[k] > 0) clusters.means[k] *= 1.0 / clusters.sizes[k];
  }
  return clusters;
}

namespace {

struct Splat {
  std::size_t gx, gy;
  double fx, fy;
};

struct RangeNeighbour {
  std::size_t cluster;
  double weight;
};

/// Sorted lists of cluster ids, one per grid node, stored end to end: node n's list is
/// ids[offset[n] .. offset[n + 1]). An entry's index in `ids` is its slot.
struct NodeLists {
  std::vector<std::size_t> offset;
  std::vector<std::size_t> ids;

  [[nodiscard]] std::size_t size() const { return ids.size(); }
  /// The slot of cluster c in node n's list (c must be in it).
  [[nodiscard]] std::size_t slot(std::size_t n, std::size_t c) const {
    const auto first = ids.begin() + static_cast<std::ptrdiff_t>(offset[n]);
    const auto last = ids.begin() + static_cast<std::ptrdiff_t>(offset[n + 1]);
    return static_cast<std::size_t>(std::lower_bound(first, last, c) - ids.begin());
  }
};

/// The lists sorted and without repeats (each list by one task on `threads` threads), end to
/// end in list order.
NodeLists flattened(std::vector<std::vector<std::size_t>> lists, int threads) {
  parallel_for(
      lists.size(),
      [&](std::size_t n) {
        std::sort(lists[n].begin(), lists[n].end());
        lists[n].erase(std::unique(lists[n].begin(), lists[n].end()), lists[n].end());
      },
      threads);
  NodeLists flat;
  flat.offset.reserve(lists.size() + 1);
  flat.offset.push_back(0);
  for (const auto& list : lists) {
    flat.ids.insert(flat.ids.end(), list.begin(), list.end());
    flat.offset.push_back(flat.ids.size());
  }
  return flat;
}

/// Each node's window list: the union of `lists` over the nodes `step` apart within +-2 of it
/// (step gw: the column window of the blur along y; step 1: the row window along x).
NodeLists window_union(const NodeLists& lists, std::size_t gw, std::size_t gh, bool along_y,
                       int threads) {
  std::vector<std::vector<std::size_t>> unions(gw * gh);
  parallel_for(
      gh,
      [&](std::size_t gy) {
        for (std::size_t gx = 0; gx < gw; ++gx) {
          const std::size_t centre = along_y ? gy : gx, size = along_y ? gh : gw;
          auto& list = unions[gy * gw + gx];
          for (std::size_t t = centre >= 2 ? centre - 2 : 0; t <= std::min(centre + 2, size - 1);
               ++t) {
            const std::size_t n = along_y ? t * gw + gx : gy * gw + t;
            list.insert(list.end(),
                        lists.ids.begin() + static_cast<std::ptrdiff_t>(lists.offset[n]),
                        lists.ids.begin() + static_cast<std::ptrdiff_t>(lists.offset[n + 1]));
          }
        }
      },
      threads);
  return flattened(std::move(unions), threads);
}

/// For every entry of `from` (node n, cluster c) and each of the 5 taps j (the node at offset
/// j - 2 along the axis): the slot of c in that node's `to` list, or kNone off the grid.
constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

std::vector<std::array<std::uint32_t, 5>> tap_targets(const NodeLists& from, const NodeLists& to,
                                                      std::size_t gw, std::size_t gh, bool along_y,
                                                      int threads) {
  std::vector<std::array<std::uint32_t, 5>> targets(from.size());
  parallel_for(
      gh,
      [&](std::size_t gy) {
        for (std::size_t gx = 0; gx < gw; ++gx) {
          const std::size_t n = gy * gw + gx;
          for (std::size_t e = from.offset[n]; e < from.offset[n + 1]; ++e) {
            for (int j = 0; j < 5; ++j) {
              const long tx = static_cast<long>(gx) + (along_y ? 0 : j - 2);
              const long ty = static_cast<long>(gy) + (along_y ? j - 2 : 0);
              targets[e][static_cast<std::size_t>(j)] =
                  tx < 0 || ty < 0 || tx >= static_cast<long>(gw) || ty >= static_cast<long>(gh)
                      ? kNone
                      : static_cast<std::uint32_t>(to.slot(
                            static_cast<std::size_t>(ty) * gw + static_cast<std::size_t>(tx),
                            from.ids[e]));
            }
          }
        }
      },
      threads);
  return targets;
}

/// One thread's memory for smoothing slices: the grid's entries that can be non-zero after
/// each pass (splatted, blurred along y, blurred along x, mixed), stored compactly, and a
/// buffer of one value per cluster (zero between uses).
struct Workspace {
  std::vector<double> splatted, blurred_y, blurred, mixed, node;
};

/// The cross-bilateral smoothing of image-sized slices, with everything that does not depend on
/// the slice computed once. The grid has one entry per node and cluster, but an entry can only
/// be non-zero after a pass when a pixel of that cluster splats near the node: per node, the
/// clusters splatted there, then their unions over the blur windows along y and along x. Only
/// those entries are stored and computed. Each is the sum of the same terms, in the same order,
/// as the dense grid's (the terms left out are products with exact zeros, and every value is
/// >= 0, so leaving them out changes no bit). The lists and slots are computed on `threads`
/// threads, each node's or pixel's by one task: the same for every count.
class SliceSmoother {
 public:
  SliceSmoother(const ColourClusters& clusters, std::vector<std::vector<RangeNeighbour>> neighbours,
                std::size_t width, std::size_t height, int cell, int threads)
      : neighbours_(std::move(neighbours)),
        gw_((width - 1) / static_cast<std::size_t>(cell) + 2),
        gh_((height - 1) / static_cast<std::size_t>(cell) + 2),
        clusters_(clusters.means.size()) {
    std::vector<Splat> splats(width * height);
    const auto size = static_cast<double>(cell);
    for (std::size_t y = 0; y < height; ++y) {
      for (std::size_t x = 0; x < width; ++x) {
        const double sx = static_cast<double>(x) / size, sy = static_cast<double>(y) / size;
        const auto gx = static_cast<std::size_t>(sx), gy = static_cast<std::size_t>(sy);
        splats[y * width + x] = {gx, gy, sx - static_cast<double>(gx),
                                 sy - static_cast<double>(gy)};
      }
    }
    const auto corners = [&](const Splat& s) {
      return std::array<std::size_t, 4>{s.gy * gw_ + s.gx, s.gy * gw_ + s.gx + 1,
                                        (s.gy + 1) * gw_ + s.gx, (s.gy + 1) * gw_ + s.gx + 1};
    };
    std::vector<std::vector<std::size_t>> lists(gw_ * gh_);
    for (std::size_t p = 0; p < splats.size(); ++p) {
      for (const std::size_t n : corners(splats[p]))
        lists[n].push_back(static_cast<std::size_t>(clusters.cluster_of[p]));
    }
    splatted_ = flattened(std::move(lists), threads);
    blurred_y_ = window_union(splatted_, gw_, gh_, true, threads);
    blurred_ = window_union(blurred_y_, gw_, gh_, false, threads);
    y_targets_ = tap_targets(splatted_, blurred_y_, gw_, gh_, true, threads);
    x_targets_ = tap_targets(blurred_y_, blurred_, gw_, gh_, false, threads);
    pixels_.resize(splats.size());
    parallel_for(
        height,
        [&](std::size_t y) {
          for (std::size_t p = y * width; p < (y + 1) * width; ++p) {
            const Splat& s = splats[p];
            const auto c = static_cast<std::size_t>(clusters.cluster_of[p]);
            const auto nodes = corners(s);
            PixelSplat& pixel = pixels_[p];
            for (std::size_t k = 0; k < 4; ++k)
              pixel.slot[k] = static_cast<std::uint32_t>(splatted_.slot(nodes[k], c));
            pixel.weight = {(1 - s.fx) * (1 - s.fy), s.fx * (1 - s.fy), (1 - s.fx) * s.fy,
                            s.fx * s.fy};
          }
        },
        threads);
  }

  [[nodiscard]] Workspace workspace() const {
    return {std::vector<double>(splatted_.size()), std::vector<double>(blurred_y_.size()),
            std::vector<double>(blurred_.size()), std::vector<double>(splatted_.size()),
            std::vector<double>(clusters_, 0.0)};
  }

  /// Leaves the smoothed slice in `space` (read() reads it).
  void smooth(std::span<const double> slice, Workspace& space) const {
    // Splat: each pixel's value into its cluster at the 4 surrounding nodes, pixels in order.
    std::fill(space.splatted.begin(), space.splatted.end(), 0.0);
    for (std::size_t p = 0; p < pixels_.size(); ++p) {
      const PixelSplat& pixel = pixels_[p];
      for (std::size_t k = 0; k < 4; ++k)
        space.splatted[pixel.slot[k]] += pixel.weight[k] * slice[p];
    }
    blur_pass(space.splatted, splatted_, y_targets_, gw_, space.blurred_y);
    blur_pass(space.blurred_y, blurred_y_, x_targets_, 1, space.blurred);
    // Mix: each splatted entry gathers its range neighbours among the node's blurred entries.
    for (std::size_t n = 0; n < gw_ * gh_; ++n) {
      for (std::size_t e = blurred_.offset[n]; e < blurred_.offset[n + 1]; ++e)
        space.node[blurred_.ids[e]] = space.blurred[e];
      for (std::size_t e = splatted_.offset[n]; e < splatted_.offset[n + 1]; ++e) {
        double sum = 0.0;
        for (const RangeNeighbour& other : neighbours_[splatted_.ids[e]])
          sum += other.weight * space.node[other.cluster];
        space.mixed[e] = sum;
      }
      for (std::size_t e = blurred_.offset[n]; e < blurred_.offset[n + 1]; ++e)
        space.node[blurred_.ids[e]] = 0.0;
    }
  }

  /// Pixel p's value of the smoothed slice: its cluster's bilinear interpolation.
  [[nodiscard]] double read(const Workspace& space, std::size_t p) const {
    const PixelSplat& pixel = pixels_[p];
    return pixel.weight[0] * space.mixed[pixel.slot[0]] +
           pixel.weight[1] * space.mixed[pixel.slot[1]] +
           pixel.weight[2] * space.mixed[pixel.slot[2]] +
           pixel.weight[3] * space.mixed[pixel.slot[3]];
  }

 private:
  /// A pixel's 4 corner entries (slots of its cluster in the corner nodes' splatted lists, in
  /// the order top-left, top-right, bottom-left, bottom-right) and their bilinear weights.
  struct PixelSplat {
    std::array<std::uint32_t, 4> slot;
    std::array<double, 4> weight;
  };

  /// One blur pass with taps [e^-2, e^-1/2, 1, e^-1/2, e^-2] along an axis (`stride` 1: x, gw:
  /// y): out[node] = sum over t = -2..2 of tap[t] * in[node + t * stride], the terms of each
  /// entry added in the order of t.
  void blur_pass(const std::vector<double>& in, const NodeLists& from,
                 const std::vector<std::array<std::uint32_t, 5>>& targets, std::size_t stride,
                 std::vector<double>& out) const {
    static const double taps[5] = {std::exp(-2.0), std::exp(-0.5), 1.0, std::exp(-0.5),
                                   std::exp(-2.0)};
    std::fill(out.begin(), out.end(), 0.0);
    // Output node n takes source node n + t * stride for t = -2..2 in turn; the source's
    // entry lands in n's list at the target of tap j = 2 - t (n is at offset -t from it).
    for (std::size_t n = 0; n < gw_ * gh_; ++n) {
      const std::size_t gx = n % gw_, gy = n / gw_;
      for (int t = -2; t <= 2; ++t) {
        const long along = stride == 1 ? static_cast<long>(gx) + t : static_cast<long>(gy) + t;
        if (along < 0 || along >= static_cast<long>(stride == 1 ? gw_ : gh_)) continue;
        const std::size_t source = stride == 1 ? gy * gw_ + static_cast<std::size_t>(along)
                                               : static_cast<std::size_t>(along) * gw_ + gx;
        const double tap = taps[t + 2];
        const auto j = static_cast<std::size_t>(2 - t);
        for (std::size_t e = from.offset[source]; e < from.offset[source + 1]; ++e)
          out[targets[e][j]] += tap * in[e];
      }
    }
  }

  std::vector<std::vector<RangeNeighbour>> neighbours_;
  std::size_t gw_, gh_, clusters_;
  NodeLists splatted_, blurred_y_, blurred_;
  std::vector<std::array<std::uint32_t, 5>> y_targets_, x_targets_;
  std::vector<PixelSplat> pixels_;
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
  const ColourClusters clusters =
      median_cut_clusters(guide, options.cluster_levels, options.threads);
  const std::size_t q = clusters.means.size();
  // Range neighbours of every non-empty cluster (including itself, weight 1).
  // Each cluster's list is built by one task, in cluster order: the same for any thread count.
  std::vector<std::vector<RangeNeighbour>> neighbours(q);
  const double cutoff = options.cutoff_sigmas * options.colour_sigma;
  parallel_for(
      q,
      [&](std::size_t a) {
        if (clusters.sizes[a] == 0) return;
        for (std::size_t b = 0; b < q; ++b) {
          if (clusters.sizes[b] == 0) continue;
          const double distance = cv::norm(clusters.means[a] - clusters.means[b]);
          if (distance > cutoff) continue;
          const double r = std::round(distance);
          neighbours[a].push_back(
              {b, std::exp(-r * r / (2.0 * options.colour_sigma * options.colour_sigma))});
        }
      },
      options.threads);
  const std::size_t w = volume.width(), h = volume.height(), pixels = w * h;
  const SliceSmoother smoother(clusters, std::move(neighbours), w, h, options.cell,
                               options.threads);
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
  const std::span<float> costs = volume.values();
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
              costs[p * labels + first + k] = static_cast<float>(slices[k * pixels + p]);
          }
        }
      },
      static_cast<int>(threads));
}

}  // namespace c2f::vision
