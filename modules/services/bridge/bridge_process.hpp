// beft-bridge as a service: a run (live) or a run's log for web viewers, over
// the Foxglove WebSocket protocol, and the viewer's page over plain HTTP on
// the same port (web_server.hpp, foxglove_hub.hpp). Live, it only listens:
// the run never waits for it, and the only messages it sends are the
// controls a viewer asks for (RUN_CONTROL until the arbiter answers,
// TASK_COMMAND). Crash-only: killed and started again it serves again, and
// viewers reconnect.
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include <beft/run_control_t.hpp>
#include <beft/task_command_t.hpp>

#include "lib/service/run_control_client.hpp"
#include "lib/service/service.hpp"
#include "services/bridge/foxglove_hub.hpp"
#include "services/bridge/log_index.hpp"
#include "services/bridge/log_player.hpp"
#include "services/bridge/log_tail.hpp"

namespace boost::asio {
class io_context;
}

namespace beft::bridge {

struct BridgeOptions {
  int port = 8765;
  std::string bind = "127.0.0.1";
  std::string web_dir;
  std::string token;
  std::string log;        // log mode: the run's log
  double speed = 1.0;     // log mode
  bool paused = false;    // log mode: start paused
  std::string log_file;   // the processes' log to tail on /log
  std::string run_id;     // live mode: the run (default: BEFT_RUN_ID, else the one heard)
  std::string scenario;   // for the viewer's metadata
  std::string net;        // the run's Petri net (PNML), drawn for the page at /net.svg
  int max_clients = 32;
  int batch_ms = 10;      // live: how long the run's messages gather between reads (0: read each as it comes)
};

// Where the page finds the run's net drawn (serverInfo's metadata "net" says so).
inline constexpr const char* kNetDrawingPath = "/net.svg";

class BridgeProcess : public service::Service, public ControlSink, public ExpertBus {
 public:
  BridgeProcess();
  ~BridgeProcess() override;
  std::string name() const override { return "bridge"; }
  std::string description() const override;
  void addOptions(CLI::App& app) override;
  void onStartUp() override;
  int serve(service::Context& context) override;

 private:
  // ControlSink: what a viewer asks.
  std::string runControl(const RunControlRequest& request) override;
  std::string task(const TaskRequest& request) override;
  std::string playback(const PlaybackRequest& request) override;
  // ExpertBus: what an external expert publishes, on the run's channels.
  std::string publish(const std::string& channel, const std::vector<uint8_t>& bytes) override;
  void listPublished(beft::done_t& done) override;

  HubOptions hubOptions(bool log_mode) const;
  void onRunMessage(const transport::Message& message);
  // Every 50 ms: playback, controls to resend, the processes' log, the scene's topics.
  void onTimer(service::Context& context);
  void advancePlayback();
  int serveLive(service::Context& context, boost::asio::io_context& io);
  int serveLog(service::Context& context, boost::asio::io_context& io);
  void runLoop(service::Context& context, boost::asio::io_context& io);

  BridgeOptions options_;
  std::unique_ptr<FoxgloveHub> hub_;
  std::unique_ptr<ExternalExperts> experts_;
  std::unique_ptr<LogIndex> index_;
  std::unique_ptr<LogPlayer> player_;
  std::unique_ptr<LogTail> tail_;
  std::string net_svg_;  // the run's net drawn (--net), served at kNetDrawingPath
  service::RunControlClient run_control_{"viewer"};
  std::optional<beft::run_control_t> last_state_told_;
  lcm::LCM* lcm_ = nullptr;
  std::chrono::steady_clock::time_point next_drop_report_{}, next_tail_{};
  int64_t last_time_sent_ = -1;
  bool told_end_ = false;

  service::EveryChannelPort everything_in_{
      *this, "every channel of the run: shown to viewers as topics of their own, converted while subscribed",
      [this](const transport::Message& m) { onRunMessage(m); }};
  service::WritePort<beft::run_control_t> control_out_{
      *this, channels::kRunControl, "pause, step, run: what a viewer asks, sent again until the arbiter answers"};
  service::WritePort<beft::task_command_t> tasks_out_{*this, channels::kTaskCommand,
                                                      "a viewer's goto, look_at or clear (origin \"viewer\")"};
};

}  // namespace beft::bridge
