#include "c2f/core/visit_order.hpp"

#include "c2f/support/enum_names.hpp"

namespace c2f {

std::string_view to_string(VisitOrder order) {
  switch (order) {
    case VisitOrder::sequential:
      return "sequential";
    case VisitOrder::random:
      return "random";
    case VisitOrder::frequency:
      return "frequency";
  }
  return "unknown";
}

VisitOrder visit_order_from_string(std::string_view text) {
  constexpr VisitOrder kAll[] = {VisitOrder::sequential, VisitOrder::random, VisitOrder::frequency};
  return enum_from_string(text, kAll, "visit order");
}

}  // namespace c2f
