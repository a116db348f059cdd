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

#include <beft/bb_query_t.hpp>
#include <beft/bb_snapshot_t.hpp>
#include <beft/robot_state_t.hpp>
#include <beft/scene_objects_t.hpp>

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
  void addOptions(CLI::App& app) override;
  void onStartUp() override;
  int serve(service::Context& context) override;

 private:
  // The ports' handlers: the newest bytes of each channel, decoded when SSR
  // is to be told; the scene in force from the blackboard's answer.
  void keepObjects(const uint8_t* data, std::size_t size);
  void onSceneAnswer(const beft::bb_snapshot_t& snapshot);
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
  std::chrono::steady_clock::time_point next_query_{};
  int64_t queries_ = 0;
  SsrScene ssr_scene_;  // SSR's own reports on this connection
  uint64_t unreadable_ = 0;

  service::CheckedBytesPort<beft::scene_objects_t> objects_in_{
      *this, channels::kGroundTruth, "the acoustic objects: sound file, position, sounding, level",
      [this](const transport::Message& m) { keepObjects(m.data, m.size); }};
  service::CheckedBytesPort<beft::robot_state_t> robot_in_{
      *this, channels::kRobotState, "the head's position and heading: SSR's listener",
      [this](const transport::Message& m) {
        newest_robot_.assign(m.data, m.data + m.size);
        heard_news_ = true;
      }};
  service::AnswerPort<beft::bb_snapshot_t> scene_answer_in_{
      *this, channels::kBlackboardSnapshotPrefix, "the blackboard's answer: the ground truth in force",
      [this](beft::bb_snapshot_t&& snapshot) { onSceneAnswer(snapshot); }};
  service::WritePort<beft::bb_query_t> query_out_{
      *this, channels::kBlackboardQuery, "until GT_OBJECTS is heard, every 0.2 s: the scene in force"};
};

}  // namespace beft::ssr_bridge
