#include "c2f/lift/schedule.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "c2f/support/number_text.hpp"
#include "c2f/support/text_input.hpp"

namespace c2f {

namespace {

[[noreturn]] void bad(std::string_view token, const std::string& why) {
  throw std::invalid_argument("schedule: level '" + printable(token) + "': " + why);
}

std::vector<std::string> split(std::string_view text, char separator) {
  std::vector<std::string> parts;
  std::string part;
  std::istringstream stream{std::string(text)};
  while (std::getline(stream, part, separator)) parts.push_back(part);
  if (!text.empty() && text.back() == separator) parts.emplace_back();
  return parts;
}

double number(std::string_view token, const std::string& text) {
  const std::optional<double> value = parse_real(text);
  if (!value) bad(token, "'" + printable(text) + "' is not a number");
  return *value;
}

int whole_number(std::string_view token, const std::string& text, int min) {
  constexpr long long kMax = 1'000'000'000;
  const std::optional<long long> value = parse_integer(text);
  const double real = number(token, text);  // names text that is no number at all
  const bool too_large = value ? *value > kMax : real > static_cast<double>(kMax);
  if (too_large && real == std::floor(real)) {
    bad(token, "'" + printable(text) + "' is too large (at most " + std::to_string(kMax) + ")");
  }
  if (!value || *value < min || *value > kMax) {
    bad(token, "'" + printable(text) + "' must be a whole number >= " + std::to_string(min));
  }
  return static_cast<int>(*value);
}

/// One level token without presets, auto or flat: KIND:ARGS[/cc].
LevelSpec parse_level(const std::string& token) {
  LevelSpec spec;
  std::string body = token;
  if (body.size() > 3 && body.compare(body.size() - 3, 3, "/cc") == 0) {
    spec.connected = true;
    body.resize(body.size() - 3);
  }
  const auto colon = body.find(':');
  if (colon == std::string::npos) {
    bad(token,
        "expected KIND:ARGS (cp, local, threshold, slic, agg, blocks, auto), flat or a preset");
  }
  const std::string kind = body.substr(0, colon);
  const auto args = split(std::string_view(body).substr(colon + 1), ',');
  if (kind == "cp" || kind == "local") {
    if (args.size() != 2) bad(token, "expected " + kind + ":N_L,N_iter");
    const int labels = whole_number(token, args[0], 1);
    const int iterations = whole_number(token, args[1], kind == "cp" ? 0 : 1);
    if (kind == "cp") {
      spec.partition = ColourPassingLevel{labels, iterations};
    } else {
      spec.partition = LocalGroupingLevel{labels, iterations};
    }
  } else if (kind == "threshold") {
    if (args.empty() || args.size() > 2)
      bad(token, "expected threshold:TAU or threshold:TAU,RADIUS");
    ThresholdLevel level{number(token, args[0]), 1};
    if (level.tau < 0.0) bad(token, "TAU must be >= 0");
    if (args.size() == 2) level.radius = whole_number(token, args[1], 1);
    spec.partition = level;
  } else if (kind == "slic") {
    if (args.size() != 1) bad(token, "expected slic:SIZE");
    spec.partition = SlicLevel{whole_number(token, args[0], 2)};
  } else if (kind == "agg") {
    if (args.size() != 1 && args.size() != 3)
      bad(token, "expected agg:RADIUS or agg:RADIUS,MAX_RADIUS,SHARE");
    AggregatedLevel level{whole_number(token, args[0], 0)};
    if (args.size() == 3) {
      level.max_radius = whole_number(token, args[1], level.radius + 1);
      level.max_share = number(token, args[2]);
      if (!(level.max_share > 0.0 && level.max_share <= 1.0))
        bad(token, "SHARE must be in (0, 1], got '" + printable(args[2]) + "'");
    }
    spec.partition = level;
  } else if (kind == "blocks") {
    if (args.size() != 1) bad(token, "expected blocks:SIZE");
    spec.partition = BlockLevel{whole_number(token, args[0], 1)};
  } else {
    bad(token, "unknown level kind '" + kind + "'");
  }
  return spec;
}

std::vector<double> parse_auto_fractions(const std::string& token) {
  if (token.size() > 3 && token.compare(token.size() - 3, 3, "/cc") == 0)
    bad(token, "auto levels cannot take /cc");
  std::vector<double> fractions;
  for (const std::string& arg : split(std::string_view(token).substr(5), ',')) {
    const double fraction = number(token, arg);
    if (!(fraction > 0.0 && fraction < 1.0)) bad(token, "fractions must lie in (0, 1)");
    if (!fractions.empty() && fraction <= fractions.back())
      bad(token, "fractions must increase (coarsest first)");
    fractions.push_back(fraction);
  }
  if (fractions.empty()) bad(token, "auto needs at least one fraction (e.g. auto:0.002,0.02,0.2)");
  return fractions;
}

}  // namespace

Schedule Schedule::parse(std::string_view text, std::span<const SchedulePreset> presets) {
  std::istringstream stream{std::string(text)};
  std::vector<std::string> tokens;
  for (std::string token; stream >> token;) tokens.push_back(token);
  if (tokens.empty()) throw std::invalid_argument("schedule: empty (use 'flat' for the flat run)");

  const auto preset = std::find_if(presets.begin(), presets.end(),
                                   [&](const SchedulePreset& p) { return p.name == tokens[0]; });
  if (preset != presets.end()) {
    if (tokens.size() != 1) bad(tokens[0], "'" + tokens[0] + "' stands alone");
    return parse(preset->levels);
  }
  Schedule schedule;
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    const std::string& token = tokens[i];
    const bool last = i + 1 == tokens.size();
    if (token == "flat") {
      if (!last) bad(token, "'flat' (the original problem) can only be the last level");
    } else if (token.rfind("auto:", 0) == 0) {
      if (!(tokens.size() == 1 || (tokens.size() == 2 && tokens[1] == "flat")))
        bad(token, "auto:FRACTIONS stands alone (optionally followed by flat)");
      schedule.auto_fractions = parse_auto_fractions(token);
    } else if (token.find(':') == std::string::npos && !presets.empty() &&
               std::none_of(presets.begin(), presets.end(),
                            [&](const SchedulePreset& p) { return p.name == token; })) {
      std::string names;
      for (const SchedulePreset& p : presets) names += (names.empty() ? "" : ", ") + p.name;
      bad(token, "neither a level (KIND:ARGS), flat, nor a preset (" + names + ")");
    } else if (std::any_of(presets.begin(), presets.end(),
                           [&](const SchedulePreset& p) { return p.name == token; })) {
      bad(token, "'" + token + "' stands alone");
    } else {
      schedule.levels.push_back(parse_level(token));
    }
  }
  return schedule;
}

std::string Schedule::to_string() const {
  std::string text;
  if (!auto_fractions.empty()) {
    text = "auto:";
    for (std::size_t i = 0; i < auto_fractions.size(); ++i)
      text += (i ? "," : "") + format_real(auto_fractions[i]);
    return text + " flat";
  }
  for (const LevelSpec& level : levels) text += level.to_string() + " ";
  return text + "flat";
}

std::string Schedule::validate(int num_labels) const {
  for (const LevelSpec& level : levels) {
    if (level.labels_needed() > num_labels) {
      return "level " + level.to_string() + " has N_L " + std::to_string(level.labels_needed()) +
             " above the " + std::to_string(num_labels) + " labels";
    }
  }
  return {};
}

std::string Schedule::validate_without_grid() const {
  for (const LevelSpec& level : levels) {
    if (!std::holds_alternative<ColourPassingLevel>(level.partition) &&
        !std::holds_alternative<AggregatedLevel>(level.partition))
      return "level " + level.to_string() + " needs a pixel grid";
  }
  return {};
}

std::string Schedule::validate_image(GridShape image) const {
  const std::size_t shorter = std::min(image.width, image.height);
  for (const LevelSpec& level : levels) {
    if (const auto* slic = std::get_if<SlicLevel>(&level.partition);
        slic && static_cast<std::size_t>(slic->region_size) > shorter) {
      return "level " + level.to_string() + " needs an image whose shorter side is at least " +
             std::to_string(slic->region_size) + " pixels, and the image is " +
             std::to_string(image.width) + "x" + std::to_string(image.height) +
             " (choose smaller regions, or --schedule flat)";
    }
  }
  return {};
}

std::span<const SchedulePreset> pairwise_schedule_presets() {
  static const std::array<SchedulePreset, 1> presets{
      SchedulePreset{"paper", "cp:1,1 cp:2,1 cp:3,1 flat"}};
  return presets;
}

}  // namespace c2f
