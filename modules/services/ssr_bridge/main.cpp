// beft-ssr-bridge: mirrors a run into the SoundScape Renderer (see --help, README.md).
#include "services/ssr_bridge/ssr_bridge_process.hpp"

int main(int argc, char** argv) {
  beft::ssr_bridge::SsrBridgeProcess bridge;
  return beft::service::runServiceMain(argc, argv, bridge);
}
