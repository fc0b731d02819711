#pragma once
// Moving labelings between levels without changing their energy.

#include <span>

#include "c2f/core/labeling.hpp"
#include "c2f/lift/dense_partition.hpp"

namespace c2f {

/// The labeling of the original variables in which every member of group g gets
/// labeling_on_groups[g]. Throws std::invalid_argument when the size is not num_groups.
Labeling expand(std::span<const Label> labeling_on_groups, const DensePartition& partition);

/// The labeling of the groups of `to` that stands for the same original labeling as
/// `labeling` on the groups of `from`, so its energy on reduce(e, to) equals the energy of
/// `labeling` on reduce(e, from). Requires `to` to refine `from`; otherwise (or on size
/// mismatch) throws std::invalid_argument.
Labeling transfer_labels(std::span<const Label> labeling, const DensePartition& from,
                         const DensePartition& to);

}  // namespace c2f

namespace c2f {

/// For level sequences that do not refine each other (allowed only on request): every group of
/// `to` takes the label most of its variables had under `labeling` on `from` (ties: the lower
/// label). Equals transfer_labels when `to` refines `from`; otherwise the energy of the
/// result can differ from the energy of `labeling`. Throws std::invalid_argument on size
/// mismatch.
Labeling transfer_labels_by_majority(std::span<const Label> labeling, const DensePartition& from,
                                     const DensePartition& to);

}  // namespace c2f
