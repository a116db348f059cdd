// beft-bridge: a run, or a run's log, for web viewers (see --help).
#include "services/bridge/bridge_process.hpp"

int main(int argc, char** argv) {
  beft::bridge::BridgeProcess bridge;
  return beft::service::runServiceMain(argc, argv, bridge);
}
