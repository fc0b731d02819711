#pragma once
// The process's peak resident size over one stretch of a benchmark (Linux): reset_peak_resident()
// before it, peak_resident_mib() after. The kernel keeps one high-water mark per process
// (VmHWM in /proc/self/status); writing "5" to /proc/self/clear_refs sets it back to the current
// resident size, so each stretch's peak includes what is already resident (the scene, the energy)
// and nothing freed before it.

#include <cmath>
#include <fstream>
#include <limits>
#include <string>

namespace c2f::bench {

/// Sets the process's peak resident size back to its current size. false where the kernel does
/// not allow it (not Linux, no /proc): peak_resident_mib() then measures since the process began.
inline bool reset_peak_resident() {
  std::ofstream clear("/proc/self/clear_refs");
  clear << "5";
  clear.close();
  return static_cast<bool>(clear);
}

/// The process's peak resident size in MiB since the last reset, NaN where /proc gives none.
inline double peak_resident_mib() {
  std::ifstream status("/proc/self/status");
  std::string key;
  while (status >> key) {
    if (key == "VmHWM:") {
      double kib = 0.0;
      if (status >> kib) return kib / 1024.0;
      break;
    }
    status.ignore(std::numeric_limits<std::streamsize>::max(), '\n');
  }
  return std::nan("");
}

}  // namespace c2f::bench
