#include "tool_options.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <stdexcept>

#include "c2f/support/input_file.hpp"
#include "c2f/support/number_text.hpp"
#include "staged_paths.hpp"

namespace po = boost::program_options;

namespace c2f::examples {

namespace {

/// "--labels" for the declaration "labels", "--out" for "out,o".
std::string option_text(const char* name) {
  const std::string declared(name);
  return "--" + declared.substr(0, declared.find(','));
}

std::string with_range(const char* help, const std::string& range) {
  return std::string(help) + " (" + range + ")";
}

/// Stands in for '%' while Boost writes a message (an ASCII control character, never typed).
constexpr char kPercentStandIn = '\x1a';

/// The message of the error Boost.ProgramOptions raised for this command line. Boost 1.74 fills
/// its message templates by replacing each placeholder (%option%, %value%, ...) until none is
/// left, so an argument that itself contains a placeholder ("--%option%") never finishes: the
/// message grows until memory runs out. The message is therefore taken from a second parse of
/// the same command line with every '%' stood in for, and the '%' put back in the text.
std::string command_line_error(int argc, const char* const* argv,
                               const po::options_description& options,
                               const po::positional_options_description& positional, int style) {
  std::vector<std::string> escaped(argv, argv + argc);
  for (std::string& argument : escaped)
    std::replace(argument.begin(), argument.end(), '%', kPercentStandIn);
  std::vector<const char*> escaped_argv;
  for (const std::string& argument : escaped) escaped_argv.push_back(argument.c_str());
  escaped_argv.push_back(nullptr);
  try {
    po::variables_map values;
    po::store(po::command_line_parser(argc, escaped_argv.data())
                  .options(options)
                  .positional(positional)
                  .style(style)
                  .run(),
              values);
  } catch (const po::error& error) {
    std::string message = error.what();
    std::replace(message.begin(), message.end(), kPercentStandIn, '%');
    return message;
  }
  return "the command line could not be read";  // unreachable: both parses see the same words
}

}  // namespace

std::string option_message(const std::string& option, const std::string& message) {
  const std::string name = option.substr(option.find_first_not_of('-')) + ": ";
  return option + ": " + (message.rfind(name, 0) == 0 ? message.substr(name.size()) : message);
}

void guard_process() {
  // A closed standard descriptor would be handed to the next file opened (a trace would then
  // receive the progress lines meant for stderr): open it to /dev/null first.
  for (int fd = 0; fd <= 2; ++fd) {
    if (fcntl(fd, F_GETFD) == -1 && errno == EBADF) {
      const int opened = open("/dev/null", fd == 0 ? O_RDONLY : O_WRONLY);
      if (opened != fd && opened >= 0) {
        dup2(opened, fd);
        close(opened);
      }
    }
  }
  // Past a file-size limit (ulimit -f) a write fails with EFBIG, which the checked writes
  // report naming the file, instead of SIGXFSZ ending the process without a word.
  std::signal(SIGXFSZ, SIG_IGN);
  // A reader that went away (`--trace /dev/stdout | head`) makes a write fail with EPIPE, which
  // the checked writes report as an error (exit 1; the unfinished output folder is removed),
  // instead of SIGPIPE ending the process without a word and leaving it half made.
  std::signal(SIGPIPE, SIG_IGN);
}

int run_tool(const char* tool, const std::function<int()>& body) {
  guard_process();
  try {
    const int code = body();
    // What a tool prints on stdout is an output too: a failed write is an error.
    errno = 0;
    std::cout.flush();
    const bool written = std::cout.good() && std::fflush(stdout) == 0 && !std::ferror(stdout);
    if (!written) {
      std::cerr << tool << ": error: writing standard output failed"
                << (errno != 0 ? std::string(" (") + std::strerror(errno) + ")" : std::string())
                << "\n";
      return 1;
    }
    return code;
  } catch (const std::invalid_argument& error) {
    std::cerr << tool << ": error: " << with_target_paths(error.what()) << "\n";
    return 2;
  } catch (const std::exception& error) {
    std::cerr << tool << ": error: " << with_target_paths(error.what()) << "\n";
    return 1;
  }
}

void require_file(const std::string& path, const char* argument) {
  if (const std::string why = why_not_a_file(path); !why.empty())
    throw std::invalid_argument(std::string(argument) + ": file '" + path + "' " + why);
}

std::string describe(IntegerRange range) {
  return "an integer in [" + std::to_string(range.min) + ", " + std::to_string(range.max) + "]";
}

std::string describe(RealRange range) {
  return std::string("a finite number in ") + (range.exclusive_min ? "(" : "[") +
         format_real(range.min) + ", " + format_real(range.max) + (range.exclusive_max ? ")" : "]");
}

long long parse_integer_option(const std::string& option, const std::string& text,
                               IntegerRange range) {
  const std::optional<long long> value = parse_integer(text);
  if (!value || *value < range.min || *value > range.max)
    throw std::invalid_argument(option + ": expected " + describe(range) + ", got '" + text + "'");
  return *value;
}

double parse_real_option(const std::string& option, const std::string& text, RealRange range) {
  const std::optional<double> value = parse_real(text);
  const bool inside = value && (range.exclusive_min ? *value > range.min : *value >= range.min) &&
                      (range.exclusive_max ? *value < range.max : *value <= range.max);
  if (!inside)
    throw std::invalid_argument(option + ": expected " + describe(range) + ", got '" + text + "'");
  return *value;
}

ToolOptions::ToolOptions(const std::string& caption) : visible_(caption) {
  visible_.add_options()("help,h", "show this help");
}

ToolOptions& ToolOptions::flag(const char* name, bool* target, const char* help) {
  visible_.add_options()(name, po::bool_switch(target), help);
  return *this;
}

ToolOptions& ToolOptions::on_off_auto(const char* name, std::string* target, const char* help) {
  const std::string option = option_text(name);
  auto* value = po::value<std::string>()->implicit_value("on")->default_value(*target)->notifier(
      [option, target](const std::string& text) {
        if (text != "on" && text != "off" && text != "auto")
          throw std::invalid_argument(option + ": expected on, off or auto (as " + option +
                                      "=off), got '" + text + "'");
        *target = text;
      });
  visible_.add_options()(name, value, help);
  return *this;
}

ToolOptions& ToolOptions::text(const char* name, std::string* target, const char* help) {
  auto* value = po::value(target);
  if (!target->empty()) value->default_value(*target);
  visible_.add_options()(name, value, help);
  return *this;
}

ToolOptions& ToolOptions::file(const char* name, std::string* target, const char* help) {
  const std::string option = option_text(name);
  visible_.add_options()(name, po::value(target)->notifier([option](const std::string& path) {
    if (const std::string why = why_not_a_file(path); !why.empty())
      throw std::invalid_argument(option + ": file '" + path + "' " + why);
  }),
                         help);
  return *this;
}

ToolOptions& ToolOptions::path(const char* name, std::string* target, const char* help) {
  const std::string option = option_text(name);
  auto* value = po::value(target)->notifier([option](const std::string& path) {
    if (path.empty()) throw std::invalid_argument(option + ": expected a path, got ''");
  });
  if (!target->empty()) value->default_value(*target);
  visible_.add_options()(name, value, help);
  return *this;
}

ToolOptions& ToolOptions::add_integer(const char* name, std::function<void(long long)> store,
                                      long long default_value, IntegerRange range,
                                      const char* help) {
  const std::string option = option_text(name);
  visible_.add_options()(name,
                         po::value<std::string>()
                             ->default_value(std::to_string(default_value))
                             ->notifier([option, store, range](const std::string& text) {
                               store(parse_integer_option(option, text, range));
                             }),
                         with_range(help, describe(range)).c_str());
  return *this;
}

ToolOptions& ToolOptions::real(const char* name, double* target, RealRange range,
                               const char* help) {
  const std::string option = option_text(name);
  // The default goes through the notifier as text: all 17 digits, so it parses back to the
  // same double; --help shows the short form.
  char exact[32];
  std::snprintf(exact, sizeof exact, "%.17g", *target);
  visible_.add_options()(name,
                         po::value<std::string>()
                             ->default_value(exact, format_real(*target))
                             ->notifier([option, target, range](const std::string& text) {
                               *target = parse_real_option(option, text, range);
                             }),
                         with_range(help, describe(range)).c_str());
  return *this;
}

std::optional<std::vector<std::string>> ToolOptions::parse(int argc, const char* const* argv,
                                                           const Positionals& positionals) const {
  po::options_description hidden;
  hidden.add_options()("positional", po::value<std::vector<std::string>>(), "");
  po::options_description all;
  all.add(visible_).add(hidden);
  po::positional_options_description positional;
  positional.add("positional", -1);
  // No abbreviations: "--lab 3" is an unknown option, not --labels.
  const int style = po::command_line_style::default_style & ~po::command_line_style::allow_guessing;
  po::variables_map values;
  try {
    po::store(
        po::command_line_parser(argc, argv).options(all).positional(positional).style(style).run(),
        values);
  } catch (const po::error&) {
    throw std::invalid_argument(command_line_error(argc, argv, all, positional, style));
  }
  if (values.count("help")) {
    std::cout << visible_ << "\n";
    return std::nullopt;
  }
  try {
    po::notify(values);  // the notifiers parse and check every value
  } catch (const po::error& error) {
    throw std::invalid_argument(error.what());
  }
  std::vector<std::string> arguments = values.count("positional")
                                           ? values["positional"].as<std::vector<std::string>>()
                                           : std::vector<std::string>{};
  if (arguments.size() > positionals.max_count) {
    const std::string expected = positionals.max_count == 0
                                     ? "takes no positional arguments"
                                     : "takes at most " + std::to_string(positionals.max_count) +
                                           " (" + positionals.names + ")";
    throw std::invalid_argument("unexpected argument '" + arguments[positionals.max_count] +
                                "': the tool " + expected + "; see --help");
  }
  return arguments;
}

}  // namespace c2f::examples
