#include "run_arguments.hpp"

#include <climits>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string_view>
#include <utility>
#include <vector>

#include "c2f/support/text_input.hpp"
#include "numpy_input.hpp"

namespace c2f::python {

namespace py = pybind11;

namespace {

/// The entries of `options` (None: none) after checking that each key is one of `allowed`.
std::vector<std::pair<std::string, py::handle>> option_items(
    const py::handle& options, const std::string& owner,
    const std::vector<std::string_view>& allowed) {
  std::vector<std::pair<std::string, py::handle>> items;
  if (options.is_none()) return items;
  if (!py::isinstance<py::dict>(options)) {
    throw py::type_error("options: expected a dict of " + owner + "'s options or None, got " +
                         std::string(py::str(py::type::handle_of(options).attr("__name__"))));
  }
  std::string names;
  for (const std::string_view name : allowed)
    names += (names.empty() ? "" : ", ") + std::string(name);
  for (const auto& [key, value] : py::reinterpret_borrow<py::dict>(options)) {
    if (!py::isinstance<py::str>(key)) throw py::type_error("options: keys are option names (str)");
    const std::string name = key.cast<std::string>();
    bool known = false;
    for (const std::string_view candidate : allowed) known = known || candidate == name;
    if (!known) {
      throw py::value_error("options: '" + printable(name, 40) + "' is not an option of " + owner +
                            " (its options: " + names + ")");
    }
    items.emplace_back(name, value);
  }
  return items;
}

/// options['shift_moves']: True, False, or 'auto' (shift moves where some expansion move on the
/// energy is not submodular, ExpansionOptions::shift_moves_unless_submodular).
void set_shift_moves(ExpansionOptions& expansion, const py::handle& value,
                     const std::string& name) {
  const bool automatic = py::isinstance<py::str>(value) && value.cast<std::string>() == "auto";
  if (!automatic && !py::isinstance<py::bool_>(value)) {
    throw py::type_error(name + ": expected True, False or 'auto', got " +
                         std::string(py::repr(value)));
  }
  expansion.shift_moves = !automatic && value.cast<bool>();
  expansion.shift_moves_unless_submodular = automatic;
}

/// Parses a name with `parse`, a std::invalid_argument becoming a ValueError naming `name`.
template <class Parse>
auto named_value(const py::handle& value, const std::string& name, Parse parse) {
  const std::string text = text_option(value, name);
  try {
    return parse(text);
  } catch (const std::invalid_argument& error) {
    throw py::value_error(name + ": " + error.what());
  }
}

/// Sets the options every move-making solver has: order, seed, tolerance.
template <class Options>
bool set_move_option(Options& options, const std::string& key, const py::handle& value,
                     const std::string& name) {
  if (key == "order") {
    options.order = named_value(value, name, visit_order_from_string);
  } else if (key == "seed") {
    options.seed = static_cast<std::uint64_t>(integer_argument(value, name, 0, INT64_MAX));
  } else if (key == "tolerance") {
    options.tolerance = real_argument(value, name);
  } else {
    return false;
  }
  return true;
}

std::string option_name(const std::string& key) {
  return "options['" + key + "']";
}

}  // namespace

std::string text_option(const py::handle& value, const std::string& name) {
  if (!py::isinstance<py::str>(value))
    throw py::type_error(name + ": expected a str, got " +
                         std::string(py::str(py::type::handle_of(value).attr("__name__"))));
  return value.cast<std::string>();
}

SolverSpec solver_spec_from(const std::string& method, const py::handle& options,
                            const RunDefaults& defaults, bool on_grid) {
  SolverKind kind;
  try {
    kind = solver_kind_from_string(method);
  } catch (const std::invalid_argument& error) {
    throw py::value_error(std::string("method: ") + error.what());
  }
  const std::string owner = "method '" + method + "'";
  SolverSpec spec;
  switch (kind) {
    case SolverKind::expansion: {
      ExpansionOptions expansion;  // the defaults' moves unless options name others
      expansion.near_radius = defaults.near_radius;
      expansion.near_seeds = defaults.near_seeds_on(on_grid);
      expansion.near_moves_only_if_local = defaults.near_moves_only_if_local;
      expansion.near_moves_min_variables = defaults.near_moves_min_variables;
      expansion.shift_moves = defaults.shift_moves;
      expansion.shift_moves_unless_submodular = defaults.shift_moves_unless_submodular;
      NearLevels levels = NearLevels::original;
      bool near_radius_named = false, min_variables_named = false;
      for (const auto& [key, value] :
           option_items(options, owner,
                        {"order", "seed", "tolerance", "near_radius", "near_seeds", "near_graphs",
                         "near_min_variables", "near_sweep_gain", "shift_moves", "near_levels",
                         "maxflow", "regions", "threads", "flow_parts"})) {
        const std::string name = option_name(key);
        if (set_move_option(expansion, key, value, name)) continue;
        if (key == "near_radius") {
          expansion.near_radius = static_cast<int>(integer_argument(value, name, 0, INT32_MAX));
          near_radius_named = true;
        } else if (key == "near_seeds") {
          expansion.near_seeds = named_value(value, name, near_seeds_from_string);
        } else if (key == "near_graphs") {
          expansion.near_moves_only_if_local =
              named_value(value, name, near_only_if_local_from_string);
        } else if (key == "near_min_variables") {
          expansion.near_moves_min_variables =
              static_cast<std::size_t>(integer_argument(value, name, 0, INT64_MAX));
          min_variables_named = true;
        } else if (key == "near_sweep_gain") {
          expansion.near_sweep_gain = real_argument(value, name);
        } else if (key == "shift_moves") {
          set_shift_moves(expansion, value, name);
        } else if (key == "regions") {
          expansion.regions = static_cast<int>(integer_argument(value, name, 1, 65535));
        } else if (key == "threads") {
          expansion.threads = static_cast<int>(integer_argument(value, name, 0, 1024));
        } else if (key == "flow_parts") {
          expansion.flow_parts = static_cast<int>(integer_argument(value, name, 0, 255));
        } else if (key == "near_levels") {
          levels = named_value(value, name, near_levels_from_string);
        } else {
          spec.maxflow = named_value(value, name, maxflow_kind_from_string);
        }
      }
      // The defaults' size floor belongs to the defaults' near moves: near_radius named alone
      // makes near moves on an energy of any size.
      if (near_radius_named && !min_variables_named) expansion.near_moves_min_variables = 0;
      if (min_variables_named && expansion.near_radius == 0)
        throw py::value_error("options['near_min_variables']: has no effect without near_radius");
      if (expansion.regions > 1 && expansion.near_radius == 0)
        throw py::value_error("options['regions']: has no effect without near_radius");
      if (expansion.flow_parts > 1 && spec.maxflow != MaxFlowKind::dynamic) {
        throw py::value_error(
            "options['flow_parts']: only our max-flow ('dynamic') solves in parts");
      }
      return expansion_spec(expansion, levels, spec.maxflow);
    }
    case SolverKind::swap: {
      SwapOptions swap;
      for (const auto& [key, value] :
           option_items(options, owner, {"order", "seed", "tolerance", "maxflow"})) {
        const std::string name = option_name(key);
        if (!set_move_option(swap, key, value, name))
          spec.maxflow = named_value(value, name, maxflow_kind_from_string);
      }
      spec.original = swap;
      return spec;
    }
    case SolverKind::lbp: {
      LbpOptions lbp;
      for (const auto& [key, value] :
           option_items(options, owner, {"schedule", "damping", "threads", "band_variables"})) {
        const std::string name = option_name(key);
        if (key == "schedule") {
          lbp.schedule = named_value(value, name, bp_schedule_from_string);
        } else if (key == "threads") {
          lbp.threads = static_cast<int>(integer_argument(value, name, 0, 1024));
        } else if (key == "band_variables") {
          lbp.band_variables =
              static_cast<std::size_t>(integer_argument(value, name, 1, INT64_MAX));
        } else {
          lbp.damping = real_argument(value, name);
        }
      }
      spec.original = lbp;
      return spec;
    }
    case SolverKind::icm: {
      IcmOptions icm;
      for (const auto& [key, value] : option_items(options, owner, {"order", "seed", "tolerance"}))
        set_move_option(icm, key, value, option_name(key));
      spec.original = icm;
      return spec;
    }
  }
  throw py::value_error("method: unknown solver '" + method + "'");
}

CoopSolverOptions coop_options_from(const py::handle& options,
                                    const vision::SegmentationDefaults& defaults) {
  CoopSolverOptions coop;
  coop.strategy = defaults.strategy;
  std::optional<int> near_radius;
  for (const auto& [key, value] : option_items(
           options, "method 'coop'", {"aux", "start", "expansion_cycles", "near_radius"})) {
    const std::string name = option_name(key);
    if (key == "aux") {
      coop.strategy = named_value(value, name, aux_strategy_from_string);
    } else if (key == "start") {
      coop.start = named_value(value, name, expansion_start_from_string);
    } else if (key == "near_radius") {
      near_radius = static_cast<int>(integer_argument(value, name, 0, INT32_MAX));
    } else {
      coop.expansion_cycles = static_cast<int>(integer_argument(value, name, 1, INT32_MAX));
    }
  }
  coop.near_radius = near_radius.value_or(defaults.near_radius_for(coop.strategy));
  return coop;
}

double optional_positive_real(const py::handle& value, const std::string& name) {
  if (value.is_none()) return 0.0;
  const double real = real_argument(value, name);
  if (real <= 0.0) throw py::value_error(name + ": expected a number > 0, or None for no limit");
  return real;
}

long optional_positive_count(const py::handle& value, const std::string& name) {
  if (value.is_none()) return 0;
  return static_cast<long>(integer_argument(value, name, 1, LONG_MAX));
}

std::optional<std::size_t> optional_gib_bytes(const py::handle& value, const std::string& name) {
  if (value.is_none()) return std::nullopt;
  const double gib = real_argument(value, name);
  if (gib < 0.0 || gib > 65536.0)
    throw py::value_error(name + ": expected a number of GiB in [0, 65536], or None");
  return static_cast<std::size_t>(gib * static_cast<double>(std::size_t{1} << 30));
}

void raise_run_error(const RunConfigError& error) {
  const std::string& field = error.field();
  std::string problem = error.problem();
  if (field.rfind("solver", 0) == 0 || field == "coop")
    throw py::value_error("options: " + problem);
  if (field == "limits") {
    // The driver's field names, as the keywords that set them.
    constexpr std::pair<std::string_view, std::string_view> kKeywords[] = {
        {"time_limit_seconds", "time_limit"},
        {"max_total_steps", "max_steps"},
        {"plateau_steps[0]", "plateau"},
        {"plateau_tolerance", "plateau_tolerance"}};
    for (const auto& [cpp, keyword] : kKeywords) {
      if (problem.rfind(cpp, 0) == 0) {
        throw py::value_error(std::string(keyword) + ": " + problem.substr(cpp.size() + 1));
      }
    }
  }
  throw py::value_error(field + ": " + problem);
}

}  // namespace c2f::python
