#include "tools/experiment/stop_signals.hpp"

#include <signal.h>

namespace beft::experiment {
namespace {

volatile sig_atomic_t stop_requested = 0;
void requestStop(int) { stop_requested = 1; }

}  // namespace

void catchStopSignals() {
  struct sigaction action = {};
  action.sa_handler = requestStop;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

bool stopRequested() { return stop_requested != 0; }

}  // namespace beft::experiment
