#pragma once
// --export-uai for the tools: the model they solve written as UAI, sized first and stopped by
// an interrupt.

#include <string>

#include "c2f/core/pairwise_energy.hpp"
#include "interrupt_watch.hpp"
#include "run_record.hpp"

namespace c2f::examples {

/// --export-uai: the model written to `path`, staged with the run's other outputs in `record`
/// (it lands only if the run does; write_uai_file refuses it first when the disk cannot hold
/// it); nothing to do for an empty path. An interrupt while it is written stops the write:
/// "TOOL: interrupted by SIG... while writing the UAI model; nothing was written" on stderr,
/// and false (the caller returns interrupts.exit_code() without committing: no output lands).
bool export_uai(const PairwiseEnergy& energy, const std::string& path, RunRecord& record,
                const InterruptWatch& interrupts);

}  // namespace c2f::examples
