// `import c2f;` beside the third-party headers a vision program includes: the standard
// library, Eigen and OpenCV. Built twice: with the headers included before the import (the
// order clang's documentation recommends) and, with C2F_INCLUDES_AFTER_IMPORT, after it
// (docs/design-notes.md). TSGO costs of a synthetic pair go through Eigen and cv::Mat.

#ifdef C2F_INCLUDES_AFTER_IMPORT
import c2f;
#endif

#include <Eigen/Core>
#include <cmath>
#include <cstdio>
#include <opencv2/core.hpp>
#include <vector>

#ifndef C2F_INCLUDES_AFTER_IMPORT
import c2f;
#endif

int main() {
  cv::Mat left(24, 32, CV_8UC3), right;
  cv::randu(left, cv::Scalar::all(0), cv::Scalar::all(255));
  right = cv::Mat::zeros(left.size(), left.type());
  left(cv::Rect(2, 0, 30, 24)).copyTo(right(cv::Rect(0, 0, 30, 24)));  // disparity 2
  c2f::vision::TsgoOptions options;
  options.labels = 5;
  const c2f::PairwiseEnergy energy =
      c2f::vision::tsgo_energy(c2f::vision::tsgo_cost(left, right, options), options);
  // The unaries as an Eigen matrix: the cheapest label of most pixels is the true disparity.
  Eigen::MatrixXd unaries(static_cast<Eigen::Index>(energy.num_variables()), energy.num_labels());
  for (std::size_t v = 0; v < energy.num_variables(); ++v)
    for (c2f::Label l = 0; l < energy.num_labels(); ++l)
      unaries(static_cast<Eigen::Index>(v), l) = energy.unary(v, l);
  std::vector<int> votes(5, 0);
  for (Eigen::Index v = 0; v < unaries.rows(); ++v) {
    Eigen::Index best = 0;
    unaries.row(v).minCoeff(&best);
    ++votes[static_cast<std::size_t>(best)];
  }
  std::printf("pixels per cheapest label: %d %d %d %d %d\n", votes[0], votes[1], votes[2], votes[3],
              votes[4]);
  return votes[2] * 2 > static_cast<int>(energy.num_variables()) ? 0 : 1;
}
