#include "interrupt_watch.hpp"

#include <atomic>
#include <csignal>
#include <stdexcept>

namespace c2f::examples {

namespace {

volatile std::sig_atomic_t g_signal = 0;
std::atomic<bool> g_watching{false};
struct sigaction g_previous_int {
}, g_previous_term{};

extern "C" void record_signal(int number) {
  if (g_signal != 0) {  // the second one: end the process as the signal would have
    std::signal(number, SIG_DFL);
    std::raise(number);
    return;
  }
  g_signal = number;
}

}  // namespace

InterruptWatch::InterruptWatch() {
  if (g_watching.exchange(true))
    throw std::logic_error("InterruptWatch: only one may watch at a time");
  g_signal = 0;
  struct sigaction action {};
  action.sa_handler = record_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;
  sigaction(SIGINT, &action, &g_previous_int);
  sigaction(SIGTERM, &action, &g_previous_term);
}

InterruptWatch::~InterruptWatch() {
  sigaction(SIGINT, &g_previous_int, nullptr);
  sigaction(SIGTERM, &g_previous_term, nullptr);
  g_watching = false;
}

int InterruptWatch::signal() const noexcept {
  return g_signal;
}

std::string InterruptWatch::signal_name() const {
  switch (signal()) {
    case SIGINT:
      return "SIGINT";
    case SIGTERM:
      return "SIGTERM";
    default:
      return {};
  }
}

int InterruptWatch::exit_code() const noexcept {
  return interrupted() ? 128 + signal() : 0;
}

Observer InterruptWatch::observer() const {
  return [](const StepEvent&) {
    return g_signal != 0 ? ObserverDecision::stop : ObserverDecision::continue_run;
  };
}

}  // namespace c2f::examples
