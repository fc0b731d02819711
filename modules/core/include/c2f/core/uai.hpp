#pragma once
// Import and export of PairwiseEnergy in the UAI format of the UAI inference competitions
// (a MARKOV network: variables with cardinalities, factor scopes, then factor tables of
// non-negative potentials, the last scope variable changing fastest), as read by toulbar2 and
// other MAP solvers. Costs and potentials are related by cost = -ln(potential).

#include <cstddef>
#include <cstdint>
#include <functional>
#include <iosfwd>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>

#include "c2f/core/labeling.hpp"
#include "c2f/core/memory_budget.hpp"
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
/// read_uai on a file read through the input layer (a regular file, refused by name before it
/// could block), within `budget`: the file may take half of it, and
/// the memory its declarations imply (the unary costs of every variable and label, the largest
/// table, the factors) must fit it and the machine (MemoryBudget::require) before the costs
/// are allocated. Throws std::invalid_argument naming the path otherwise.
PairwiseEnergy read_uai_file(const std::string& path, const MemoryBudget& budget);
/// read_uai_file within the default budget (default_memory_budget).
PairwiseEnergy read_uai_file(const std::string& path);

/// Thrown by a long write that its caller asked to stop (an interrupt): what was written is
/// incomplete and must not be used.
struct WriteStopped : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Writes one unary factor per variable and one pairwise factor per edge (table
/// weight * cost(a, b)) as potentials exp(-(cost - the factor's lowest cost)) with 17
/// significant digits, all in (0, 1]. Reading the file back gives the energy minus the sum of
/// the factors' lowest costs: every energy difference is kept (to rounding), whatever the
/// costs' magnitude. Throws std::invalid_argument when two costs of one factor lie more than
/// about 708 apart (their potentials' ratio leaves the normal double range).
/// `stop`, when given, is asked between tables; when it says so the write ends with WriteStopped.
void write_uai(const PairwiseEnergy& energy, std::ostream& out,
               const std::function<bool()>& stop = {});
/// An upper estimate of the bytes write_uai writes for `energy` (its tables dominate:
/// num_variables * L + num_edges * L^2 potentials).
std::uintmax_t uai_bytes_estimate(const PairwiseEnergy& energy);
/// write_uai to a file; throws std::runtime_error naming the path on failure, and before
/// writing anything when uai_bytes_estimate exceeds the space free on the file's disk.
void write_uai_file(const PairwiseEnergy& energy, const std::string& path,
                    const std::function<bool()>& stop = {});

/// Writes a labeling in the UAI competitions' MPE result format: the line "MPE", then one line
/// with the number of variables followed by each variable's label.
void write_uai_mpe(std::span<const Label> labeling, std::ostream& out);
/// write_uai_mpe to a file; throws std::runtime_error naming the path on failure.
void write_uai_mpe_file(std::span<const Label> labeling, const std::string& path);

/// Reads an MPE result (as write_uai_mpe writes it; the "MPE" line is optional, and with
/// "-BEGIN-" blocks the last solution counts) for a model of num_variables variables and
/// num_labels labels. Throws std::invalid_argument naming `source` for a
/// malformed file, another variable count, a label out of range or trailing data.
Labeling read_uai_mpe(std::istream& in, std::string_view source, std::size_t num_variables,
                      int num_labels);

}  // namespace c2f
