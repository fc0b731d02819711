#include "c2f/vision/stereo/tsgo_bilateral.hpp"

#include <algorithm>
#include <array>
#include <barrier>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <limits>
#include <numeric>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>

#include "c2f/core/default_init_allocator.hpp"
#include "c2f/support/parallel_for.hpp"

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
  // Clusters as consecutive ranges of one permutation of the pixels: cluster k of a level is
  // order[bounds[k] .. bounds[k + 1]). Each level is one counting sort of all pixels by the key
  // (cluster, value), pixels taken in raster order, so that within a cluster the members are
  // ordered by value and equal values by pixel index: each cluster's range is sorted by
  // (value, pixel), then split in halves, the first half becoming cluster 2k, the second 2k + 1.
  std::vector<std::uint32_t> cluster_of(n, 0), order(n);
  std::iota(order.begin(), order.end(), 0U);
  std::vector<std::size_t> bounds{0, n};
  std::vector<std::size_t> next_slot;
  constexpr std::size_t kValues = 256;
  for (int level = 0; level < levels; ++level) {
    const std::vector<std::uint8_t>& value = channels[static_cast<std::size_t>((level + 1) % 3)];
    const std::size_t count = bounds.size() - 1;
    const auto key = [&](std::size_t pixel) { return cluster_of[pixel] * kValues + value[pixel]; };
    next_slot.assign(count * kValues + 1, 0);
    for (std::size_t pixel = 0; pixel < n; ++pixel) ++next_slot[key(pixel) + 1];
    std::partial_sum(next_slot.begin(), next_slot.end(), next_slot.begin());
    for (std::size_t pixel = 0; pixel < n; ++pixel)
      order[next_slot[key(pixel)]++] = static_cast<std::uint32_t>(pixel);
    std::vector<std::size_t> next{0};
    for (std::size_t k = 0; k < count; ++k) {
      next.push_back(bounds[k] + (bounds[k + 1] - bounds[k]) / 2);
      next.push_back(bounds[k + 1]);
    }
    bounds = std::move(next);
    parallel_for(
        bounds.size() - 1,
        [&](std::size_t k) {
          for (std::size_t i = bounds[k]; i < bounds[k + 1]; ++i)
            cluster_of[order[i]] = static_cast<std::uint32_t>(k);
        },
        threads);
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

/// No slot: the list has no such entry (or the node is off the grid).
constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

/// A cluster's index (clusters number at most 2^20).
using ClusterId = std::uint32_t;

/// Sorted lists of cluster ids, one per grid node, stored end to end: node n's list is
/// ids[offset[n] .. offset[n + 1]). An entry's index in `ids` is its slot.
struct NodeLists {
  std::vector<std::size_t> offset;
  std::vector<ClusterId> ids;

  [[nodiscard]] std::size_t size() const { return ids.size(); }
  /// Node n's list.
  [[nodiscard]] std::span<const ClusterId> of(std::size_t n) const {
    return {ids.data() + offset[n], offset[n + 1] - offset[n]};
  }
  /// The slot of cluster c in node n's list, or kNone when the list does not hold c.
  [[nodiscard]] std::uint32_t find(std::size_t n, std::size_t c) const {
    const std::span<const ClusterId> list = of(n);
    const auto found = std::lower_bound(list.begin(), list.end(), c);
    return found != list.end() && *found == c
               ? static_cast<std::uint32_t>(offset[n] +
                                            static_cast<std::size_t>(found - list.begin()))
               : kNone;
  }
};

/// The lists end to end in list order (each copied by one task on `threads` threads); each
/// must already be sorted and without repeats.
NodeLists concatenated(const std::vector<std::vector<ClusterId>>& lists, int threads) {
  NodeLists flat;
  flat.offset.reserve(lists.size() + 1);
  flat.offset.push_back(0);
  for (const auto& list : lists) flat.offset.push_back(flat.offset.back() + list.size());
  flat.ids.resize(flat.offset.back());
  parallel_for(
      lists.size(),
      [&](std::size_t n) {
        std::copy(lists[n].begin(), lists[n].end(),
                  flat.ids.begin() + static_cast<std::ptrdiff_t>(flat.offset[n]));
      },
      threads);
  return flat;
}

/// The lists sorted and without repeats (each list by one task on `threads` threads), end to
/// end in list order.
NodeLists flattened(std::vector<std::vector<ClusterId>> lists, int threads) {
  parallel_for(
      lists.size(),
      [&](std::size_t n) {
        std::sort(lists[n].begin(), lists[n].end());
        lists[n].erase(std::unique(lists[n].begin(), lists[n].end()), lists[n].end());
      },
      threads);
  return concatenated(lists, threads);
}

/// The union of up to 5 sorted lists without repeats, sorted, appended to `out`: a merge that
/// takes the smallest head each step.
void merge_union(std::span<const std::span<const ClusterId>> lists, std::vector<ClusterId>& out) {
  std::array<std::span<const ClusterId>, 5> rest{};
  std::size_t count = 0, total = 0;
  for (const std::span<const ClusterId> list : lists) {
    if (!list.empty()) rest[count++] = list;
    total += list.size();
  }
  out.reserve(out.size() + total);
  while (count > 0) {
    ClusterId smallest = rest[0].front();
    for (std::size_t k = 1; k < count; ++k) smallest = std::min(smallest, rest[k].front());
    out.push_back(smallest);
    for (std::size_t k = 0; k < count;) {
      if (rest[k].front() == smallest) rest[k] = rest[k].subspan(1);
      if (rest[k].empty()) {
        rest[k] = rest[--count];
      } else {
        ++k;
      }
    }
  }
}

/// Each node's window list: the union of `lists` over the nodes `step` apart within +-2 of it
/// (step gw: the column window of the blur along y; step 1: the row window along x).
NodeLists window_union(const NodeLists& lists, std::size_t gw, std::size_t gh, bool along_y,
                       int threads) {
  std::vector<std::vector<ClusterId>> unions(gw * gh);
  parallel_for(
      gh,
      [&](std::size_t gy) {
        for (std::size_t gx = 0; gx < gw; ++gx) {
          const std::size_t centre = along_y ? gy : gx, size = along_y ? gh : gw;
          std::array<std::span<const ClusterId>, 5> windows;
          std::size_t count = 0;
          for (std::size_t t = centre >= 2 ? centre - 2 : 0; t <= std::min(centre + 2, size - 1);
               ++t) {
            windows[count++] = lists.of(along_y ? t * gw + gx : gy * gw + t);
          }
          merge_union(std::span(windows.data(), count), unions[gy * gw + gx]);
        }
      },
      threads);
  return concatenated(unions, threads);
}

/// For every entry of `to` (node n, cluster c) and each of the 5 taps j: the slot of c in the
/// `from` list of the node at offset j - 2 along the axis, or kNone when that node is off the
/// grid or its list does not hold c. Both lists are sorted: one merge per node and tap.
DefaultInitVector<std::array<std::uint32_t, 5>> tap_sources(const NodeLists& to,
                                                            const NodeLists& from, std::size_t gw,
                                                            std::size_t gh, bool along_y,
                                                            int threads) {
  DefaultInitVector<std::array<std::uint32_t, 5>> sources(to.size());
  parallel_for(
      gh,
      [&](std::size_t gy) {
        for (std::size_t gx = 0; gx < gw; ++gx) {
          const std::size_t n = gy * gw + gx;
          for (std::size_t j = 0; j < 5; ++j) {
            const long sx = static_cast<long>(gx) + (along_y ? 0 : static_cast<long>(j) - 2);
            const long sy = static_cast<long>(gy) + (along_y ? static_cast<long>(j) - 2 : 0);
            const bool off_grid =
                sx < 0 || sy < 0 || sx >= static_cast<long>(gw) || sy >= static_cast<long>(gh);
            const std::size_t m =
                off_grid ? 0 : static_cast<std::size_t>(sy) * gw + static_cast<std::size_t>(sx);
            std::size_t k = off_grid ? 0 : from.offset[m];
            const std::size_t end = off_grid ? 0 : from.offset[m + 1];
            for (std::size_t e = to.offset[n]; e < to.offset[n + 1]; ++e) {
              while (k < end && from.ids[k] < to.ids[e]) ++k;
              sources[e][j] =
                  k < end && from.ids[k] == to.ids[e] ? static_cast<std::uint32_t>(k) : kNone;
            }
          }
        }
      },
      threads);
  return sources;
}

/// The grid's values and arithmetic: float, each product and sum rounded to float. The
/// filter's time is bounded by its memory traffic, which float halves against double (full-size
/// Aloe: 8.5 s instead of 11.5 s on 2 threads); the result is within a few float roundings of
/// the filter in double (tested against the dense grid in double).
using Value = float;

/// The blur's taps along each axis (a spatial sigma of one cell, 5 nodes wide).
const std::array<Value, 5> kTaps = {Value(std::exp(-2.0)), Value(std::exp(-0.5)), Value(1.0),
                                    Value(std::exp(-0.5)), Value(std::exp(-2.0))};

/// Slices smoothed together: every grid entry holds one value per lane (label), side by side
/// (64 bytes), so that each scattered access of a pass serves all of them.
constexpr std::size_t kLanes = 16;

/// How many pixels ahead the passes over the volume prefetch: consecutive pixels' lanes are a
/// row of labels apart, a stride the hardware prefetchers do not follow across pages.
constexpr std::size_t kPrefetchAhead = 16;

/// The memory for smoothing slices, in grid entries of kLanes values each, shared by a team;
/// allocated unwritten (every pass writes each entry it owns before anything reads it).
struct Workspace {
  DefaultInitVector<Value>
      splatted;  ///< the splatted entries, then the mixed ones (read() reads them)
  DefaultInitVector<Value> blurred_y;  ///< the entries blurred along y
  std::vector<DefaultInitVector<Value>>
      node_blurred;  ///< per member, one node's entries blurred along x
};

/// Member m's share [share(total, m, members), share(total, m + 1, members)) of `total` items.
std::size_t share(std::size_t total, std::size_t m, std::size_t members) {
  return total * m / members;
}

/// The cross-bilateral smoothing of image-sized slices, with everything that does not depend on
/// the slice computed once. The grid has one entry per node and cluster; only the entries the
/// result depends on are stored and computed, each pulling its terms:
/// - splatted: per node, the clusters of the pixels that splat there;
/// - blurred along x (`needed_x`): per node, the range neighbours of its splatted clusters
///   whose blurred entry can be non-zero (a splatted entry within 2 nodes along x and y);
/// - blurred along y (`needed_y`): per node, the clusters some needed_x entry within 2 nodes
///   along x reads, where a splatted entry within 2 nodes along y can make them non-zero.
/// Each entry is the sum of the same terms, in the same order, as the dense grid's (the terms
/// left out are products with exact zeros, and every value is >= 0, so leaving them out changes
/// no bit). The lists and slots are computed on `threads` threads, each node's or pixel's by one
/// task: the same for every count.
class SliceSmoother {
 public:
  SliceSmoother(const ColourClusters& clusters,
                const std::vector<std::vector<RangeNeighbour>>& neighbours, std::size_t width,
                std::size_t height, int cell, int threads)
      : gw_((width - 1) / static_cast<std::size_t>(cell) + 2),
        gh_((height - 1) / static_cast<std::size_t>(cell) + 2),
        width_(width),
        row_node_(height) {
    std::vector<Splat> splats(width * height);
    const auto size = static_cast<double>(cell);
    for (std::size_t y = 0; y < height; ++y) {
      for (std::size_t x = 0; x < width; ++x) {
        const double sx = static_cast<double>(x) / size, sy = static_cast<double>(y) / size;
        const auto gx = static_cast<std::size_t>(sx), gy = static_cast<std::size_t>(sy);
        splats[y * width + x] = {gx, gy, sx - static_cast<double>(gx),
                                 sy - static_cast<double>(gy)};
      }
      row_node_[y] = splats[y * width].gy;
    }
    const auto corners = [&](const Splat& s) {
      return std::array<std::size_t, 4>{s.gy * gw_ + s.gx, s.gy * gw_ + s.gx + 1,
                                        (s.gy + 1) * gw_ + s.gx, (s.gy + 1) * gw_ + s.gx + 1};
    };
    std::vector<std::vector<ClusterId>> lists(gw_ * gh_);
    for (std::size_t p = 0; p < splats.size(); ++p) {
      for (const std::size_t n : corners(splats[p]))
        lists[n].push_back(static_cast<ClusterId>(clusters.cluster_of[p]));
    }
    splatted_ = flattened(std::move(lists), threads);
    const NodeLists blurred_y = window_union(splatted_, gw_, gh_, true, threads);
    needed_x_ = needed_blurred(neighbours, blurred_y, threads);
    needed_y_ = needed_blurred_y(blurred_y, threads);
    y_sources_ = tap_sources(needed_y_, splatted_, gw_, gh_, true, threads);
    x_sources_ = tap_sources(needed_x_, needed_y_, gw_, gh_, false, threads);
    mix_terms(neighbours, threads);
    pixels_.resize(splats.size());
    parallel_for(
        height,
        [&](std::size_t y) {
          for (std::size_t p = y * width; p < (y + 1) * width; ++p) {
            const Splat& s = splats[p];
            const auto c = static_cast<std::size_t>(clusters.cluster_of[p]);
            const auto nodes = corners(s);
            PixelSplat& pixel = pixels_[p];
            for (std::size_t k = 0; k < 4; ++k) pixel.slot[k] = splatted_.find(nodes[k], c);
            pixel.weight = {Value((1 - s.fx) * (1 - s.fy)), Value(s.fx * (1 - s.fy)),
                            Value((1 - s.fx) * s.fy), Value(s.fx * s.fy)};
          }
        },
        threads);
  }

  /// The grid's node rows: a team has at most this many members.
  [[nodiscard]] std::size_t node_rows() const { return gh_; }

  /// The workspace of a team of `members`.
  [[nodiscard]] Workspace workspace(std::size_t members) const {
    std::size_t node_entries = 0;
    for (std::size_t n = 0; n + 1 < needed_x_.offset.size(); ++n)
      node_entries = std::max(node_entries, needed_x_.offset[n + 1] - needed_x_.offset[n]);
    Workspace space{DefaultInitVector<Value>(splatted_.size() * kLanes),
                    DefaultInitVector<Value>(needed_y_.size() * kLanes),
                    std::vector<DefaultInitVector<Value>>(members)};
    // Each sized on its own: copies of one unwritten buffer would read its unset values.
    for (DefaultInitVector<Value>& buffer : space.node_blurred)
      buffer.resize(node_entries * kLanes);
    return space;
  }

  /// Smooths `count` slices at once, slice k's value at pixel p being values[p * stride + k],
  /// plus, when `with_ones`, the constant slice 1 in lane `count` (count + with_ones <= kLanes),
  /// and leaves them in `space` (read() reads them). Each lane's arithmetic is the one-slice
  /// filter's, term for term and in the same order; the remaining lanes hold zeros. Called by
  /// every member m of a team of `members` threads (run_team) with the same arguments; each
  /// pass is split into the members' shares, which write disjoint entries, and `sync` (a
  /// barrier of `members`) ends each pass, so every entry is the same sum in the same order
  /// whatever the team's size.
  void smooth(const float* values, std::size_t stride, std::size_t count, bool with_ones,
              Workspace& space, std::size_t m, std::size_t members, std::barrier<>& sync) const {
    // Splat: each pixel's values into its cluster at the 4 surrounding nodes, pixels in order.
    // Member m owns the entries of node rows [r0, r1) and takes the pixel rows that splat
    // there (a pixel splats into its node row and the next), adding only into its own rows.
    const std::size_t r0 = share(gh_, m, members), r1 = share(gh_, m + 1, members);
    const auto entry = [&](std::size_t slot) {
      return space.splatted.begin() + static_cast<std::ptrdiff_t>(slot * kLanes);
    };
    std::fill(entry(splatted_.offset[r0 * gw_]), entry(splatted_.offset[r1 * gw_]), Value{0});
    const auto row = [&](auto before) {
      return static_cast<std::size_t>(
          std::partition_point(row_node_.begin(), row_node_.end(), before) - row_node_.begin());
    };
    const std::size_t y0 = row([&](std::size_t g) { return g + 1 < r0; });
    const std::size_t y1 = row([&](std::size_t g) { return g < r1; });
    std::array<Value, kLanes> value{};
    if (with_ones) value[count] = Value{1};
    for (std::size_t y = y0; y < y1; ++y) {
      // Corners 0 and 1 are in the pixel's node row, 2 and 3 in the next.
      const std::size_t first_corner = row_node_[y] >= r0 ? 0 : 2;
      const std::size_t end_corner = row_node_[y] + 1 < r1 ? 4 : 2;
      const std::size_t end = (y + 1) * width_;
      for (std::size_t p = y * width_; p < end; ++p) {
        if (count > 0 && p + kPrefetchAhead < pixels_.size())
          __builtin_prefetch(values + (p + kPrefetchAhead) * stride);
        for (std::size_t k = 0; k < count; ++k) value[k] = values[p * stride + k];
        const PixelSplat& pixel = pixels_[p];
        for (std::size_t c = first_corner; c < end_corner; ++c) {
          // A local copy: a store through `target` cannot change it, so the lanes vectorise.
          const Value weight = pixel.weight[c];
          Value* target = space.splatted.data() + pixel.slot[c] * kLanes;
          for (std::size_t k = 0; k < kLanes; ++k) target[k] += weight * value[k];
        }
      }
    }
    sync.arrive_and_wait();
    // Blurred along y: member m's share of the entries.
    const std::size_t blurred = y_sources_.size();
    for (std::size_t i = share(blurred, m, members); i < share(blurred, m + 1, members); ++i)
      blur_entry(space.splatted, y_sources_[i], space.blurred_y.data() + i * kLanes);
    sync.arrive_and_wait();
    // Then along x, and mixed: each splatted entry gathers its range neighbours' entries
    // blurred along x at its node. Node by node, since only a node's own mixed entries read
    // its entries blurred along x: those stay in a buffer of one node's size, and the mixed
    // entries replace the splatted ones, which nothing reads after the blur along y. Member m
    // starts at the node that holds the first entry of its share of the x-blurred entries.
    const auto first_node = [&](std::size_t k) {
      if (k == members) return gw_ * gh_;
      return static_cast<std::size_t>(std::lower_bound(needed_x_.offset.begin(),
                                                       needed_x_.offset.end(),
                                                       share(needed_x_.size(), k, members)) -
                                      needed_x_.offset.begin());
    };
    Value* node_blurred = space.node_blurred[m].data();
    for (std::size_t n = first_node(m); n < first_node(m + 1); ++n) {
      const std::size_t base = needed_x_.offset[n];
      for (std::size_t i = base; i < needed_x_.offset[n + 1]; ++i)
        blur_entry(space.blurred_y, x_sources_[i], node_blurred + (i - base) * kLanes);
      for (std::size_t e = splatted_.offset[n]; e < splatted_.offset[n + 1]; ++e) {
        std::array<Value, kLanes> sum{};
        for (std::size_t t = mix_offset_[e]; t < mix_offset_[e + 1]; ++t) {
          const Value* source = node_blurred + (mix_[t].slot - base) * kLanes;
          for (std::size_t k = 0; k < kLanes; ++k) sum[k] += mix_[t].weight * source[k];
        }
        std::copy(sum.begin(), sum.end(), space.splatted.data() + e * kLanes);
      }
    }
    sync.arrive_and_wait();
  }

  /// Pixel p's values of the smoothed slices (lane k: slice k): its cluster's bilinear
  /// interpolation.
  void read(const Workspace& space, std::size_t p, std::array<Value, kLanes>& out) const {
    const PixelSplat& pixel = pixels_[p];
    const Value* corner[4];
    for (std::size_t c = 0; c < 4; ++c) corner[c] = space.splatted.data() + pixel.slot[c] * kLanes;
    const std::array<Value, 4> weight = pixel.weight;  // not reloaded after each store to out
    for (std::size_t k = 0; k < kLanes; ++k) {
      out[k] = weight[0] * corner[0][k] + weight[1] * corner[1][k] + weight[2] * corner[2][k] +
               weight[3] * corner[3][k];
    }
  }

 private:
  /// A pixel's 4 corner entries (slots of its cluster in the corner nodes' splatted lists, in
  /// the order top-left, top-right, bottom-left, bottom-right) and their bilinear weights.
  struct PixelSplat {
    std::array<std::uint32_t, 4> slot;
    std::array<Value, 4> weight;
  };

  /// A term of a mixed entry: a blurred entry (its slot in needed_x) and its range weight.
  struct MixTerm {
    std::uint32_t slot;
    Value weight;
  };

  /// Per node, the range neighbours of its splatted clusters that are in the blur window along
  /// x of `blurred_y` (else their blurred entry there is an exact zero).
  [[nodiscard]] NodeLists needed_blurred(const std::vector<std::vector<RangeNeighbour>>& neighbours,
                                         const NodeLists& blurred_y, int threads) const {
    std::vector<std::vector<ClusterId>> lists(gw_ * gh_);
    parallel_for(
        gh_,
        [&](std::size_t gy) {
          for (std::size_t gx = 0; gx < gw_; ++gx) {
            const std::size_t n = gy * gw_ + gx;
            for (std::size_t e = splatted_.offset[n]; e < splatted_.offset[n + 1]; ++e) {
              for (const RangeNeighbour& other : neighbours[splatted_.ids[e]]) {
                for (std::size_t tx = gx >= 2 ? gx - 2 : 0; tx <= std::min(gx + 2, gw_ - 1); ++tx) {
                  if (blurred_y.find(gy * gw_ + tx, other.cluster) != kNone) {
                    lists[n].push_back(static_cast<ClusterId>(other.cluster));
                    break;
                  }
                }
              }
            }
          }
        },
        threads);
    return flattened(std::move(lists), threads);
  }

  /// Per node, the clusters of its `blurred_y` list that a needed_x entry within 2 nodes along
  /// x reads.
  [[nodiscard]] NodeLists needed_blurred_y(const NodeLists& blurred_y, int threads) const {
    const NodeLists read = window_union(needed_x_, gw_, gh_, false, threads);
    std::vector<std::vector<ClusterId>> lists(gw_ * gh_);
    parallel_for(
        gw_ * gh_,
        [&](std::size_t n) {
          const auto a = read.of(n), b = blurred_y.of(n);
          std::set_intersection(a.begin(), a.end(), b.begin(), b.end(),
                                std::back_inserter(lists[n]));
        },
        threads);
    return concatenated(lists, threads);  // intersections of sorted lists are sorted
  }

  /// The terms of every splatted entry's mix: its cluster's range neighbours (in their order)
  /// that have a needed_x entry at its node.
  void mix_terms(const std::vector<std::vector<RangeNeighbour>>& neighbours, int threads) {
    std::vector<std::vector<MixTerm>> per_node(gw_ * gh_);
    std::vector<std::uint32_t> counts(splatted_.size());
    parallel_for(
        gw_ * gh_,
        [&](std::size_t n) {
          for (std::size_t e = splatted_.offset[n]; e < splatted_.offset[n + 1]; ++e) {
            for (const RangeNeighbour& other : neighbours[splatted_.ids[e]]) {
              const std::uint32_t slot = needed_x_.find(n, other.cluster);
              if (slot == kNone) continue;
              per_node[n].push_back({slot, Value(other.weight)});
              ++counts[e];
            }
          }
        },
        threads);
    mix_offset_.assign(splatted_.size() + 1, 0);
    for (std::size_t e = 0; e < splatted_.size(); ++e)
      mix_offset_[e + 1] = mix_offset_[e] + counts[e];
    // Node n's terms are those of its entries, which start at its first slot.
    mix_.resize(mix_offset_.back());
    parallel_for(
        gw_ * gh_,
        [&](std::size_t n) {
          std::copy(per_node[n].begin(), per_node[n].end(),
                    mix_.begin() + static_cast<std::ptrdiff_t>(mix_offset_[splatted_.offset[n]]));
        },
        threads);
  }

  /// One entry of a blur along an axis with taps [e^-2, e^-1/2, 1, e^-1/2, e^-2]: out = the sum
  /// over j = 0..4 of tap[j] * in[sources[j]], the present terms added in the order of j.
  static void blur_entry(const DefaultInitVector<Value>& in,
                         const std::array<std::uint32_t, 5>& sources, Value* out) {
    std::array<Value, kLanes> sum{};
    for (std::size_t j = 0; j < 5; ++j) {
      if (sources[j] == kNone) continue;
      const Value* source = in.data() + sources[j] * kLanes;
      for (std::size_t k = 0; k < kLanes; ++k) sum[k] += kTaps[j] * source[k];
    }
    std::copy(sum.begin(), sum.end(), out);
  }

  std::size_t gw_, gh_, width_;
  std::vector<std::size_t> row_node_;  ///< per pixel row, its node row (non-decreasing)
  NodeLists splatted_, needed_x_, needed_y_;
  DefaultInitVector<std::array<std::uint32_t, 5>> y_sources_, x_sources_;
  std::vector<std::size_t> mix_offset_;
  DefaultInitVector<MixTerm> mix_;
  DefaultInitVector<PixelSplat> pixels_;
};

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
  // Range neighbours of every non-empty cluster (including itself, weight 1), in cluster order.
  // Candidates first: the clusters whose green mean is within the cutoff (a looser bound by a
  // relative 1e-9, so that no pair the exact test keeps is left out by rounding), found in the
  // clusters sorted by green; each candidate then takes the exact test. Each cluster's list is
  // built by one task: the same for any thread count.
  std::vector<std::vector<RangeNeighbour>> neighbours(q);
  const double cutoff = options.cutoff_sigmas * options.colour_sigma;
  const double candidate_bound = cutoff * (1.0 + 1e-9);
  std::vector<std::size_t> by_green;
  for (std::size_t k = 0; k < q; ++k)
    if (clusters.sizes[k] > 0) by_green.push_back(k);
  const auto green = [&](std::size_t k) { return clusters.means[k][1]; };
  std::stable_sort(by_green.begin(), by_green.end(),
                   [&](std::size_t a, std::size_t b) { return green(a) < green(b); });
  parallel_for(
      q,
      [&](std::size_t a) {
        if (clusters.sizes[a] == 0) return;
        const auto first = std::partition_point(
            by_green.begin(), by_green.end(),
            [&](std::size_t k) { return green(k) < green(a) - candidate_bound; });
        const auto last = std::partition_point(first, by_green.end(), [&](std::size_t k) {
          return green(k) <= green(a) + candidate_bound;
        });
        std::vector<std::size_t> candidates(first, last);
        std::sort(candidates.begin(), candidates.end());
        for (const std::size_t b : candidates) {
          const double distance = cv::norm(clusters.means[a] - clusters.means[b]);
          if (distance > cutoff) continue;
          const double r = std::round(distance);
          neighbours[a].push_back(
              {b, std::exp(-r * r / (2.0 * options.colour_sigma * options.colour_sigma))});
        }
      },
      options.threads);
  const std::size_t w = volume.width(), h = volume.height(), pixels = w * h;
  const SliceSmoother smoother(clusters, neighbours, w, h, options.cell, options.threads);
  // Blocks of kLanes labels, each filtered straight from the pixel-major volume (a pixel's
  // labels of a block are side by side) by a team of threads that split each pass (smooth())
  // and then the pixels; every label's arithmetic is the same whatever the team's size, so the
  // volume does not depend on the thread count, and the work of each block divides evenly
  // (blocks handed to threads whole left one thread idle at the end whenever their number
  // was odd). The first unit of work is the denominator (the smoothed constant slice), in the
  // spare lane of the last label block when it has one, else alone.
  const auto labels = static_cast<std::size_t>(volume.labels());
  const std::size_t blocks = (labels + kLanes - 1) / kLanes;
  const bool spare_lane = labels % kLanes != 0;
  // Unit 0: the denominator (with label block blocks - 1 when it has a spare lane); unit u >= 1:
  // label block u - 1.
  const std::size_t units = spare_lane ? blocks : blocks + 1;
  const std::size_t members =
      std::min<std::size_t>(resolved_threads(options.threads), smoother.node_rows());
  const std::span<float> costs = volume.values();
  std::vector<Value> denominator(pixels);
  Workspace space = smoother.workspace(members);
  std::barrier sync(static_cast<std::ptrdiff_t>(members));
  run_team(members, [&](std::size_t m) noexcept {
    std::array<Value, kLanes> out{};
    const std::size_t p0 = share(pixels, m, members), p1 = share(pixels, m + 1, members);
    for (std::size_t unit = 0; unit < units; ++unit) {
      const bool with_ones = unit == 0;
      const bool with_labels = unit > 0 || spare_lane;
      const std::size_t block = unit > 0 ? unit - 1 : blocks - 1;
      const std::size_t first = block * kLanes;
      const std::size_t count = with_labels ? std::min(kLanes, labels - first) : 0;
      smoother.smooth(costs.data() + first, labels, count, with_ones, space, m, members, sync);
      for (std::size_t p = p0; p < p1; ++p) {
        if (count > 0 && p + kPrefetchAhead < p1)
          __builtin_prefetch(costs.data() + (p + kPrefetchAhead) * labels + first, 1);
        smoother.read(space, p, out);
        if (with_ones) denominator[p] = out[count];
        for (std::size_t k = 0; k < count; ++k)
          costs[p * labels + first + k] =
              static_cast<float>(static_cast<double>(out[k]) / static_cast<double>(denominator[p]));
      }
      sync.arrive_and_wait();  // the next unit's splat overwrites the entries this one read
    }
  });
}

}  // namespace c2f::vision
