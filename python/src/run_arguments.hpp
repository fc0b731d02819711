#pragma once
// Keyword arguments of c2f.solve and c2f.segment turned into the run layer's configuration, in
// numpy's idiom: None for "no limit" and "the default", the solver's own options in one dict
// (method= plus options=, as scipy.optimize.minimize). Only the conversion of Python values
// happens here; the ranges are checked once, by the run layer's validators, and their refusals
// (RunConfigError) are raised as ValueError naming the Python argument (raise_run_error).

#include <pybind11/pybind11.h>

#include <cstddef>
#include <optional>
#include <string>

#include "c2f/adapters/coop/coop_solver.hpp"
#include "c2f/driver/options.hpp"
#include "c2f/run/defaults.hpp"
#include "c2f/run/run_error.hpp"
#include "c2f/run/segmentation_run.hpp"
#include "c2f/run/solver_spec.hpp"

namespace c2f::python {

/// The solver `method` names ('expansion', 'swap', 'lbp', 'icm') with `options` (None or a dict
/// of that solver's option names: order, seed, tolerance, near_radius, near_seeds,
/// near_sweep_gain, shift_moves, near_levels, maxflow, regions, threads and flow_parts for
/// expansion; order, seed, tolerance and maxflow for swap; schedule and damping for lbp; order,
/// seed and tolerance for icm); expansion's near_radius, near_seeds and shift_moves not named are
/// `defaults`' (near_seeds: RunDefaults::near_seeds_on(on_grid)). ValueError naming
/// `method` or `options['name']` for an unknown name or value, TypeError for a value of the
/// wrong type.
SolverSpec solver_spec_from(const std::string& method, const pybind11::handle& options,
                            const RunDefaults& defaults, bool on_grid);

/// A text argument or option (`name`: TypeError for anything but a str).
std::string text_option(const pybind11::handle& value, const std::string& name);

/// The cooperative cut's solver options from `options` (None or a dict: aux, start,
/// expansion_cycles, near_radius), as solver_spec_from; what is not named is `defaults`'
/// (near_radius: defaults.near_radius_for the strategy in use).
CoopSolverOptions coop_options_from(const pybind11::handle& options,
                                    const vision::SegmentationDefaults& defaults);

/// A limit that is None (none) or a number > 0 (`name`: ValueError for 0 or less, which would
/// mean no limit in C++; TypeError for what is no number).
double optional_positive_real(const pybind11::handle& value, const std::string& name);
/// The same for an integer count of at least 1.
long optional_positive_count(const pybind11::handle& value, const std::string& name);

/// A byte count given in GiB: None (std::nullopt) or a number >= 0.
std::optional<std::size_t> optional_gib_bytes(const pybind11::handle& value,
                                              const std::string& name);

/// Raises `error` as a ValueError whose message names the Python argument its field stands
/// for: solver fields as `options`, a run's limits by their keywords (time_limit, max_steps,
/// plateau, plateau_tolerance), the budget as `memory`.
[[noreturn]] void raise_run_error(const RunConfigError& error);

}  // namespace c2f::python
