#include "model_export.hpp"

#include <cstdio>

#include "c2f/core/uai.hpp"
#include "c2f/support/output_file.hpp"

namespace c2f::examples {

bool export_uai(const PairwiseEnergy& energy, const std::string& path, RunRecord& record,
                const InterruptWatch& interrupts) {
  if (path.empty()) return true;
  try {
    write_uai_file(energy, record.stage(path, "--export-uai").string(),
                   [&] { return interrupts.interrupted(); });
    return true;
  } catch (const WriteStopped&) {
    std::fprintf(stderr, "%s: interrupted by %s while writing the UAI model; nothing was written\n",
                 record.tool().c_str(), interrupts.signal_name().c_str());
    return false;
  }
}

}  // namespace c2f::examples
