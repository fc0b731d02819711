#pragma once
// Input checks shared by the stereo data terms (internal to the stereo module).

#include <opencv2/core.hpp>

namespace c2f::vision::detail {

/// Throws std::invalid_argument, prefixed by `who`, unless both views are 8-bit 3-channel
/// images of one size.
void require_colour_pair(const cv::Mat& left, const cv::Mat& right, const char* who);

}  // namespace c2f::vision::detail
