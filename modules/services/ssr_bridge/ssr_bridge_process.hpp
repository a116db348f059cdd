// beft-ssr-bridge as a service: listens to a run's ground truth and robot
// state and mirrors them into a running SoundScape Renderer over its XML
// network interface, so a person hears the scene from the robot's ears.
// It only listens: the arbiter does not fire it and the run never waits for
// it; SSR missing or going away is said once and tried again every second.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include "services/ssr_bridge/scene_mirror.hpp"
#include "lib/service/service.hpp"
#include "services/ssr_bridge/ssr_link.hpp"
#include "services/ssr_bridge/ssr_updates.hpp"
#include "lib/transport/transport.hpp"

namespace beft::ssr_bridge {

class SsrBridgeProcess : public service::Service {
 public:
  std::string name() const override { return "ssr_bridge"; }
  std::string description() const override;
  std::vector<service::Port> reads() const override;
  std::vector<service::Port> writes() const override;
  void addOptions(CLI::App& app) override;
  void onStartUp() override;
  int serve(service::Context& context) override;

 private:
  // Stores the newest bytes of each channel; decoded when SSR is to be told.
  void onMessage(const transport::Message& message);
  // Brings SSR to the newest state heard (when connected).
  void tellSsr(SsrLink& link, SceneMirror& mirror);
  void readSsr(const std::vector<std::string>& messages, SceneMirror& mirror);
  void logWarnings(SceneMirror& mirror);
  // Until the ground truth has been heard, asks the blackboard for it every
  // 0.2 s: GT_OBJECTS goes out only when the scene changes, so a bridge
  // that starts after it would otherwise wait for the next keyframe (and a
  // blackboard asked before it stored tick 0's has none yet).
  void askForTheScene(lcm::LCM& lcm);

  std::string ssr_host_ = "localhost";
  int ssr_port_ = 4711;
  std::string scenario_;
  int batch_ms_ = 20;
  std::vector<uint8_t> newest_objects_, newest_robot_;
  bool heard_news_ = false;
  bool heard_objects_ = false;
  std::string snapshot_channel_;  // BB_SNAPSHOT_<name>_<pid>: the blackboard's answers
  std::chrono::steady_clock::time_point next_query_{};
  int64_t queries_ = 0;
  SsrScene ssr_scene_;  // SSR's own reports on this connection
  uint64_t unreadable_ = 0;
};

}  // namespace beft::ssr_bridge
