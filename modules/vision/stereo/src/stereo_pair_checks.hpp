#pragma once
// Input checks shared by the stereo data terms (internal to the stereo module).

#include <opencv2/core.hpp>
#include <string>

namespace c2f::vision::detail {

/// Throws std::invalid_argument, prefixed by `who`, unless both views are 8-bit 3-channel
/// images of one size.
void require_colour_pair(const cv::Mat& left, const cv::Mat& right, const char* who);

/// Throws std::invalid_argument "<what> is WxH, the views are WxH" unless `image` has the
/// views' size (nothing is resized to fit).
void require_view_size(const cv::Mat& image, const cv::Mat& views, const std::string& what);

/// Throws std::invalid_argument naming `what` when `gt` (CV_32F, NaN unknown) has no known
/// pixel: nothing could be evaluated against it.
void require_known_pixel(const cv::Mat& gt, const std::string& what);

}  // namespace c2f::vision::detail
