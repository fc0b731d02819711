#pragma once
// The input-validation layer every command-line tool goes through before it reads or writes
// anything: each option is declared with its type and its range, every value is parsed
// strictly (the whole text is the number, reals are finite, integers fit), files must exist,
// options are never abbreviated, and arguments beyond the positional ones a tool takes are
// refused. Every error is an std::invalid_argument that names the option, what was expected
// and what was given:
//   --labels: expected an integer in [2, 256], got '1e3'
//   --time-limit: expected a finite number in [0, 1e+07], got 'nan'

#include <boost/program_options.hpp>
#include <concepts>
#include <cstddef>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace c2f::examples {

/// The integers an option accepts: min <= value <= max.
struct IntegerRange {
  long long min, max;
};

/// The reals an option accepts: finite, min <= value <= max (min < value with exclusive_min,
/// value < max with exclusive_max).
struct RealRange {
  double min, max;
  bool exclusive_min = false;
  bool exclusive_max = false;
};

/// The positional arguments a tool takes: their names for messages ("LEFT RIGHT") and how many
/// may be given at most.
struct Positionals {
  std::string names;
  std::size_t max_count = 0;
};

/// A tool's options. Each declaration stores the parsed value into `target` (whose value on
/// entry is the default shown in --help; text and file options without a value keep it).
class ToolOptions {
 public:
  /// `caption` starts --help (tool name, purpose, usage); the options follow it.
  explicit ToolOptions(const std::string& caption);

  /// A switch without a value.
  ToolOptions& flag(const char* name, bool* target, const char* help);
  /// A three-way switch with a default of its own: `--name` or `--name=on`, `--name=off`,
  /// `--name=auto` (--help shows the default).
  ToolOptions& on_off_auto(const char* name, std::string* target, const char* help);
  /// Free text (a schedule, a name the tool checks itself).
  ToolOptions& text(const char* name, std::string* target, const char* help);
  /// A path that must name an existing regular file when given.
  ToolOptions& file(const char* name, std::string* target, const char* help);
  /// A path the tool writes (a folder or file); it must not be empty when given.
  ToolOptions& path(const char* name, std::string* target, const char* help);
  /// An integer of any integral type (the range must fit the type).
  template <std::integral Integer>
  ToolOptions& integer(const char* name, Integer* target, IntegerRange range, const char* help) {
    return add_integer(
        name, [target](long long value) { *target = static_cast<Integer>(value); },
        static_cast<long long>(*target), range, help);
  }
  ToolOptions& real(const char* name, double* target, RealRange range, const char* help);

  /// Parses argv and stores every value. Returns std::nullopt after printing --help to stdout;
  /// otherwise the positional arguments (at most positionals.max_count). Throws
  /// std::invalid_argument naming the option or argument for anything invalid.
  std::optional<std::vector<std::string>> parse(int argc, const char* const* argv,
                                                const Positionals& positionals) const;

  /// The --help text.
  const boost::program_options::options_description& description() const { return visible_; }

 private:
  ToolOptions& add_integer(const char* name, std::function<void(long long)> store,
                           long long default_value, IntegerRange range, const char* help);

  boost::program_options::options_description visible_;
};

/// Limits shared by the tools: a run's --time-limit (seconds, 0 = none) and step counts.
inline constexpr RealRange kTimeLimitRange{0.0, 1e7};
inline constexpr long long kMaxSteps = 1'000'000'000;

/// Throws std::invalid_argument "<argument>: file '<path>' <why_not_a_file>" (does not exist,
/// is a folder, ...) unless `path` names a regular file (for positional arguments; options use
/// ToolOptions::file).
void require_file(const std::string& path, const char* argument);

/// "<option>: <message>", without repeating the option's name when the message already
/// starts with it ("--schedule: schedule: level ..." becomes "--schedule: level ...").
std::string option_message(const std::string& option, const std::string& message);

/// parse(), with "<option>: " put before the message of an std::invalid_argument it throws
/// (for options whose text a library function parses: schedules, solver names).
template <class Parse>
auto with_flag(const char* option, Parse parse) {
  try {
    return parse();
  } catch (const std::invalid_argument& error) {
    throw std::invalid_argument(option_message(option, error.what()));
  }
}

/// Makes the process safe to write from: standard descriptors that are closed are opened to
/// /dev/null (so no file the tool opens becomes stdout or stderr), and SIGXFSZ is ignored (a
/// write past a file-size limit fails and is reported naming the file).
void guard_process();

/// Runs a tool's main body after guard_process() and returns its exit code: the body's own (0,
/// or 128 + a signal's number after an interrupt), 2 for std::invalid_argument (bad input or
/// arguments), 1 for any other exception and for a failed write to stdout (a full disk), each
/// printed as "TOOL: error: MESSAGE" on stderr.
int run_tool(const char* tool, const std::function<int()>& body);

/// Strict parsing of one option value, for tools and formats that read values themselves.
/// Throws std::invalid_argument "<option>: expected ..., got '<text>'".
long long parse_integer_option(const std::string& option, const std::string& text,
                               IntegerRange range);
double parse_real_option(const std::string& option, const std::string& text, RealRange range);

/// "an integer in [2, 256]", "a finite number in (0, 1e+06]": what a range accepts, for
/// messages and --help.
std::string describe(IntegerRange range);
std::string describe(RealRange range);

}  // namespace c2f::examples
