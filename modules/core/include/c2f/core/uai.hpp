#pragma once
// Import and export of PairwiseEnergy in the UAI format of the UAI inference competitions
// (a MARKOV network: variables with cardinalities, factor scopes, then factor tables of
// non-negative potentials, the last scope variable changing fastest), as read by toulbar2 and
// other MAP solvers. Costs and potentials are related by cost = -ln(potential).

#include <iosfwd>
#include <string>
#include <string_view>

#include "c2f/core/pairwise_energy.hpp"

namespace c2f {

/// Reads a MARKOV network whose variables all have the same cardinality and whose factors
/// have one or two variables. Unary factors of a variable are summed; each pairwise factor
/// becomes an edge of weight 1 with a table term (identical tables share one term). Throws
/// std::invalid_argument naming `source` and the offending token or factor for a malformed
/// file, a zero or negative potential (infinite cost), mixed cardinalities, factors of other
/// arity, counts larger than the file can hold or than 8 GiB of unary costs, and any data after
/// the last table. Reads the whole stream before parsing.
PairwiseEnergy read_uai(std::istream& in, std::string_view source = "<stream>");
/// read_uai on a file; throws std::runtime_error naming the path when it cannot be opened.
PairwiseEnergy read_uai_file(const std::string& path);

/// Writes one unary factor per variable and one pairwise factor per edge (table
/// weight * cost(a, b)) as potentials exp(-(cost - the factor's lowest cost)) with 17
/// significant digits, all in (0, 1]. Reading the file back gives the energy minus the sum of
/// the factors' lowest costs: every energy difference is kept (to rounding), whatever the
/// costs' magnitude. Throws std::invalid_argument when two costs of one factor lie more than
/// about 708 apart (their potentials' ratio leaves the normal double range).
void write_uai(const PairwiseEnergy& energy, std::ostream& out);
/// write_uai to a file; throws std::runtime_error naming the path on failure.
void write_uai_file(const PairwiseEnergy& energy, const std::string& path);

}  // namespace c2f
