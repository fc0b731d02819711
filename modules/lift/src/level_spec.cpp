#include "c2f/lift/level_spec.hpp"

#include "c2f/support/number_text.hpp"

namespace c2f {

namespace {

struct LevelText {
  std::string operator()(const ColourPassingLevel& l) const {
    return "cp:" + std::to_string(l.labels) + "," + std::to_string(l.iterations);
  }
  std::string operator()(const LocalGroupingLevel& l) const {
    return "local:" + std::to_string(l.labels) + "," + std::to_string(l.iterations);
  }
  std::string operator()(const ThresholdLevel& l) const {
    return "threshold:" + format_real(l.tau) +
           (l.radius != 1 ? "," + std::to_string(l.radius) : "");
  }
  std::string operator()(const SlicLevel& l) const {
    return "slic:" + std::to_string(l.region_size);
  }
  std::string operator()(const AggregatedLevel& l) const {
    if (l.max_radius <= l.radius) return "agg:" + std::to_string(l.radius);
    return "agg:" + std::to_string(l.radius) + "," + std::to_string(l.max_radius) + "," +
           format_real(l.max_share);
  }
  std::string operator()(const BlockLevel& l) const { return "blocks:" + std::to_string(l.size); }
};

}  // namespace

int LevelSpec::labels_needed() const {
  if (const auto* cp = std::get_if<ColourPassingLevel>(&partition)) return cp->labels;
  if (const auto* local = std::get_if<LocalGroupingLevel>(&partition)) return local->labels;
  return 0;
}

std::string LevelSpec::to_string() const {
  return std::visit(LevelText{}, partition) + (connected ? "/cc" : "");
}

}  // namespace c2f
