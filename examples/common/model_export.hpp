#pragma once
// --export-uai for the tools: the model they solve written as UAI, sized first and stopped by
// an interrupt.

#include <filesystem>
#include <string>

#include "c2f/core/pairwise_energy.hpp"
#include "interrupt_watch.hpp"

namespace c2f::examples {

/// --export-uai: the model written to `staged` (write_uai_file: refused first when the disk
/// cannot hold it). An interrupt while it is written stops the write: "TOOL: interrupted by
/// SIG... while writing the UAI model; nothing was written" on stderr, and false (the caller
/// returns interrupts.exit_code() without committing, so no output lands).
bool export_uai(const PairwiseEnergy& energy, const std::filesystem::path& staged,
                const std::string& tool, const InterruptWatch& interrupts);

}  // namespace c2f::examples
