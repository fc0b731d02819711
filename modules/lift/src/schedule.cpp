#include "c2f/lift/schedule.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "c2f/lift/block_hierarchy.hpp"
#include "c2f/lift/connected_components.hpp"
#include "c2f/lift/local_grouping.hpp"
#include "c2f/lift/threshold_partition.hpp"

namespace c2f {

namespace {

[[noreturn]] void bad(std::string_view token, const std::string& why) {
  throw std::invalid_argument("schedule: level '" + std::string(token) + "': " + why);
}

std::vector<std::string> split(std::string_view text, char separator) {
  std::vector<std::string> parts;
  std::string part;
  std::istringstream stream{std::string(text)};
  while (std::getline(stream, part, separator)) parts.push_back(part);
  if (!text.empty() && text.back() == separator) parts.emplace_back();
  return parts;
}

double parse_number(std::string_view token, const std::string& text) {
  std::size_t used = 0;
  double value = 0.0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || !std::isfinite(value))
    bad(token, "'" + text + "' is not a number");
  return value;
}

int parse_integer(std::string_view token, const std::string& text, int min) {
  const double value = parse_number(token, text);
  if (value != std::floor(value) || value < min || value > 1e9) {
    bad(token, "'" + text + "' must be a whole number >= " + std::to_string(min));
  }
  return static_cast<int>(value);
}

std::string format_number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

}  // namespace

std::string LevelSpec::to_string() const {
  return base_string() + (connected ? "/cc" : "");
}

std::string LevelSpec::base_string() const {
  switch (kind) {
    case LevelKind::colour_passing:
      return "cp:" + std::to_string(labels) + "," + std::to_string(iterations);
    case LevelKind::local_grouping:
      return "local:" + std::to_string(labels) + "," + std::to_string(iterations);
    case LevelKind::threshold:
      return "threshold:" + format_number(tau) + (radius != 1 ? "," + std::to_string(radius) : "");
    case LevelKind::slic:
      return "slic:" + std::to_string(size);
    case LevelKind::blocks:
      return "blocks:" + std::to_string(size);
  }
  return "?";
}

Schedule Schedule::parse(std::string_view text) {
  Schedule schedule;
  std::istringstream stream{std::string(text)};
  std::vector<std::string> tokens;
  for (std::string token; stream >> token;) tokens.push_back(token);
  if (tokens.empty()) throw std::invalid_argument("schedule: empty (use 'flat' for the flat run)");
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    const std::string& token = tokens[i];
    const bool last = i + 1 == tokens.size();
    if (token == "flat") {
      if (!last) bad(token, "'flat' (the original problem) can only be the last level");
      continue;
    }
    if (token == "paper" || token == "paper-cc" || token == "regions") {
      if (tokens.size() != 1) bad(token, "'" + token + "' stands alone");
      if (token == "paper") return parse("cp:1,1 cp:2,1 cp:3,1 flat");
      if (token == "paper-cc") return parse("cp:1,1/cc cp:2,1/cc cp:3,1/cc flat");
      return parse("local:1,1/cc local:2,1/cc local:3,1/cc flat");
    }
    LevelSpec spec;
    std::string body = token;
    if (body.size() > 3 && body.compare(body.size() - 3, 3, "/cc") == 0) {
      spec.connected = true;
      body.resize(body.size() - 3);
    }
    const auto colon = body.find(':');
    if (colon == std::string::npos) {
      bad(token, "expected KIND:ARGS (cp, local, threshold, slic, blocks, auto) or flat");
    }
    const std::string kind = body.substr(0, colon);
    const auto args = split(std::string_view(body).substr(colon + 1), ',');
    if (kind == "cp" || kind == "local") {
      if (args.size() != 2) bad(token, "expected " + kind + ":N_L,N_iter");
      spec.kind = kind == "cp" ? LevelKind::colour_passing : LevelKind::local_grouping;
      spec.labels = parse_integer(token, args[0], 1);
      spec.iterations = parse_integer(token, args[1], kind == "cp" ? 0 : 1);
    } else if (kind == "threshold") {
      if (args.empty() || args.size() > 2)
        bad(token, "expected threshold:TAU or threshold:TAU,RADIUS");
      spec.kind = LevelKind::threshold;
      spec.tau = parse_number(token, args[0]);
      if (spec.tau < 0.0) bad(token, "TAU must be >= 0");
      if (args.size() == 2) spec.radius = parse_integer(token, args[1], 1);
    } else if (kind == "slic" || kind == "blocks") {
      if (args.size() != 1) bad(token, "expected " + kind + ":SIZE");
      spec.kind = kind == "slic" ? LevelKind::slic : LevelKind::blocks;
      spec.size = parse_integer(token, args[0], kind == "slic" ? 2 : 1);
    } else if (kind == "auto") {
      if (spec.connected) bad(token, "auto levels cannot take /cc");
      if (!(tokens.size() == 1 || (tokens.size() == 2 && tokens[1] == "flat"))) {
        bad(token, "auto:FRACTIONS stands alone (optionally followed by flat)");
      }
      for (const std::string& arg : args) {
        const double fraction = parse_number(token, arg);
        if (!(fraction > 0.0 && fraction < 1.0)) bad(token, "fractions must lie in (0, 1)");
        if (!schedule.auto_fractions.empty() && fraction <= schedule.auto_fractions.back()) {
          bad(token, "fractions must increase (coarsest first)");
        }
        schedule.auto_fractions.push_back(fraction);
      }
      continue;
    } else {
      bad(token, "unknown level kind '" + kind + "'");
    }
    schedule.levels.push_back(spec);
  }
  return schedule;
}

std::string Schedule::to_string() const {
  std::string text;
  if (!auto_fractions.empty()) {
    text = "auto:";
    for (std::size_t i = 0; i < auto_fractions.size(); ++i)
      text += (i ? "," : "") + format_number(auto_fractions[i]);
    return text + " flat";
  }
  for (const LevelSpec& level : levels) text += level.to_string() + " ";
  return text + "flat";
}

ScheduleProvider::ScheduleProvider(Schedule schedule, GridShape shape, SuperpixelSource superpixels,
                                   bool allow_non_refining)
    : schedule_(std::move(schedule)),
      shape_(shape),
      superpixels_(std::move(superpixels)),
      allow_non_refining_(allow_non_refining) {
  if (shape_.size() == 0) throw std::invalid_argument("ScheduleProvider: the grid is empty");
  for (const LevelSpec& level : schedule_.levels) {
    if (level.kind == LevelKind::slic && !superpixels_) {
      throw std::invalid_argument(
          "ScheduleProvider: level " + level.to_string() +
          " needs superpixels of an image, and no superpixel source was given");
    }
  }
}

void ScheduleProvider::resolve_auto(const PairwiseEnergy& energy) {
  resolved_ = true;
  if (schedule_.auto_fractions.empty()) return;
  // Candidates along one refining chain: CP(1,1), then alternately raise N_L and iterate.
  struct Candidate {
    LevelSpec spec;
    std::size_t groups;
  };
  std::vector<Candidate> chain;
  ColourPassing cp(energy, 1);
  cp.iterate();
  chain.push_back({LevelSpec{LevelKind::colour_passing, 1, 1}, cp.num_groups()});
  const double n = static_cast<double>(energy.num_variables());
  const double largest = schedule_.auto_fractions.back() * n;
  for (int step = 0; step < 16 && static_cast<double>(chain.back().groups) < largest; ++step) {
    if (step % 2 == 0 && cp.labels() < energy.num_labels()) {
      cp.increase_labels();
    } else if (!cp.iterate()) {
      break;
    }
    chain.push_back(
        {LevelSpec{LevelKind::colour_passing, cp.labels(), cp.iterations()}, cp.num_groups()});
  }
  std::size_t first_free = 0;
  for (const double fraction : schedule_.auto_fractions) {
    if (first_free >= chain.size()) break;
    std::size_t best = first_free;
    for (std::size_t c = first_free; c < chain.size(); ++c) {
      const auto misfit = [&](std::size_t k) {
        return std::abs(std::log(static_cast<double>(chain[k].groups) / (fraction * n)));
      };
      if (misfit(c) < misfit(best)) best = c;
    }
    schedule_.levels.push_back(chain[best].spec);
    first_free = best + 1;
  }
}

DensePartition ScheduleProvider::build(const LevelSpec& spec, const PairwiseEnergy& energy) {
  switch (spec.kind) {
    case LevelKind::colour_passing: {
      if (spec.labels > energy.num_labels()) {
        throw std::invalid_argument("schedule: level " + spec.to_string() + ": N_L exceeds the " +
                                    std::to_string(energy.num_labels()) + " labels");
      }
      if (!colour_passing_ || colour_passing_->labels() > spec.labels ||
          colour_passing_->iterations() > spec.iterations) {
        colour_passing_.emplace(energy, spec.labels);
      }
      while (colour_passing_->labels() < spec.labels) colour_passing_->increase_labels();
      while (colour_passing_->iterations() < spec.iterations) colour_passing_->iterate();
      return colour_passing_->partition();
    }
    case LevelKind::local_grouping:
      return local_grouping(energy, shape_, spec.labels, spec.iterations);
    case LevelKind::threshold:
      return threshold_partition(energy, shape_, spec.tau, spec.radius);
    case LevelKind::blocks:
      return block_partition(shape_, static_cast<std::size_t>(spec.size));
    case LevelKind::slic: {
      DensePartition superpixels = superpixels_(spec.size);
      if (superpixels.num_variables() != shape_.size()) {
        throw std::invalid_argument("schedule: level " + spec.to_string() +
                                    ": the superpixels cover " +
                                    std::to_string(superpixels.num_variables()) +
                                    " pixels, the grid has " + std::to_string(shape_.size()));
      }
      if (!previous_) return superpixels;
      return intersect(*previous_, superpixels);
    }
  }
  throw std::logic_error("schedule: unknown level kind");
}

std::optional<DensePartition> ScheduleProvider::next(const PairwiseEnergy& energy) {
  if (energy.num_variables() != shape_.size()) {
    throw std::invalid_argument("ScheduleProvider: the energy has " +
                                std::to_string(energy.num_variables()) + " variables, the " +
                                std::to_string(shape_.width) + "x" + std::to_string(shape_.height) +
                                " grid has " + std::to_string(shape_.size()));
  }
  const auto start = std::chrono::steady_clock::now();
  if (!resolved_) resolve_auto(energy);
  if (position_ >= schedule_.levels.size()) return std::nullopt;
  const LevelSpec& spec = schedule_.levels[position_];
  DensePartition partition = build(spec, energy);
  if (spec.connected) partition = connected_components(partition, shape_);
  if (previous_ && !allow_non_refining_ && !partition.is_refinement_of(*previous_)) {
    throw std::invalid_argument(
        "schedule: level " + std::to_string(position_) + " (" + spec.to_string() +
        ") does not refine level " + std::to_string(position_ - 1) + " (" +
        schedule_.levels[position_ - 1].to_string() +
        "), so labels cannot be handed down with the same energy; reorder the "
        "levels or allow non-refining schedules explicitly");
  }
  ++position_;
  reports_.push_back(
      {spec.to_string(), partition.num_groups(),
       std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()});
  previous_ = partition;
  return partition;
}

}  // namespace c2f
