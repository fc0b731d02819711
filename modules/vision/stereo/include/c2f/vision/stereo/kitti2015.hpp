#pragma once
// KITTI 2015 stereo pairs (as in ../shared/data/kitti2015): training/image_2/ID.png (left),
// training/image_3/ID.png (right) and training/disp_occ_0/ID.png (left-view GT, uint16 value
// / 256, 0 unknown; occluded pixels included). Scored as the benchmark scores them: D1, a pixel
// is bad when its error exceeds both 3 px and 5% of the true disparity, over all pixels with GT.

#include <string>

#include "c2f/vision/stereo/stereo_scene.hpp"

namespace c2f::vision {

/// The KITTI D1 measure (3 px and 5%; the 3 px follow a downscale).
ErrorMeasure kitti_d1_measure();

/// KITTI gives no disparity range: the label count the tools use for its pairs, which covers
/// the GT of the pairs in ../shared/data (largest 78.5 px) with room (docs/stereo.md).
inline constexpr int kKittiDefaultLabels = 128;

/// The pair `id` (e.g. "000000_10") under `root` (the folder holding training/), named
/// "kitti2015/ID", with its GT when disp_occ_0 has it and no occlusion mask (KITTI scores all
/// pixels). Throws naming a missing or unreadable file, or one of another size than the views.
StereoScene load_kitti2015_pair(const std::string& root, const std::string& id);

}  // namespace c2f::vision
