// The Foxglove side of the bridge: what every client is told (serverInfo,
// the advertised topics), what each has subscribed, and what it is sent.
// Every BEFT channel of the run is a topic of its own (its name without the
// run id, encoding "json", its JSON Schema), converted only while a client
// subscribes; /scene, /tf, /obstacle_map, /camera/color, /camera/depth and
// /log are made in Foxglove's own schemas. Each client has a bounded send
// queue (latest-wins for the bulky topics): a client that reads slowly, or
// never, loses frames and is told so; one that floods the bridge with
// requests it never reads the answers to is closed. Client frames are
// untrusted: anything wrong is answered with a status message.
#pragma once

#include <chrono>
#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "lib/common/log.hpp"
#include "lib/foxglove/protocol.hpp"
#include "lib/foxglove/send_queue.hpp"
#include "lib/wire/lcm_schema.hpp"
#include "services/bridge/control_requests.hpp"
#include "services/bridge/external_experts.hpp"
#include "services/bridge/log_tail.hpp"
#include "services/bridge/scene_model.hpp"
#include "services/bridge/web_server.hpp"

namespace beft::bridge {

// The processes' log lines, and the arbiter's line per firing apart from them (foxglove.Log both).
inline constexpr const char* kLogTopic = "/log";
inline constexpr const char* kFiringsTopic = "/firings";

// Carries out a control a client published; returns "" when done, else
// what was wrong (sent back to the client as an error status).
class ControlSink {
 public:
  virtual ~ControlSink() = default;
  virtual std::string runControl(const RunControlRequest& request) = 0;
  virtual std::string task(const TaskRequest& request) = 0;
  virtual std::string playback(const PlaybackRequest& request) = 0;
};

struct HubOptions {
  std::string name = "beft-bridge";
  std::string session_id;
  std::map<std::string, std::string> metadata;
  bool time_capability = false;             // log mode: Time frames
  std::size_t queue_bytes = std::size_t{16} << 20;  // per client
  std::size_t max_queued_text = 256;        // answers a client has not read before it is closed
};

class FoxgloveHub : public SessionHandler {
 public:
  FoxgloveHub(HubOptions options, ControlSink& controls);
  void attach(ClientSockets& server) { server_ = &server; }
  // Live: clients may also be experts of the run (external_experts.hpp).
  void acceptExperts(ExternalExperts& experts) { experts_ = &experts; }

  // A message of the run (plain channel name) received at `receive_ns`.
  void onRunMessage(const std::string& channel, const uint8_t* data, std::size_t size, uint64_t receive_ns);
  // Sends what the scene's topics show now, where it changed and someone subscribes.
  void publishDerived();
  // Lines of the processes' log: the arbiter's routine firing lines on
  // /firings (lib/service/firing_trace.hpp), every other line on /log.
  void publishLogLines(const std::vector<std::string>& lines, uint64_t receive_ns);
  // The server's clock (log mode), to every client.
  void sendTime(uint64_t time_ns);
  // A status to every client (level foxglove::kStatus*).
  void broadcastStatus(int level, const std::string& message, const std::string& id = "");
  // Tells clients who lost frames since the last call; call about once a second.
  void reportDrops();
  // Sends each throttled subscription (throttleMs, protocol.hpp) that had a
  // message held back, and whose time is up at `now`, its channel's newest
  // message; call every few tens of milliseconds.
  void sendThrottled(std::chrono::steady_clock::time_point now = std::chrono::steady_clock::now());
  // Forgets the kept messages (a seek): what a new subscriber is sent first.
  void forgetKept() { kept_.clear(); }
  // Starts sending the data frames queued for viewers since the last call;
  // call every few tens of milliseconds (a viewer's data frames go out in
  // bursts, see sendData).
  void flush();

  const std::vector<foxglove::ServerChannel>& channels() const { return channels_; }
  std::size_t clientCount() const { return clients_.size(); }
  uint64_t framesDropped() const { return frames_dropped_; }

  // SessionHandler
  void onOpen(const ClientInfo& client) override;
  void onText(uint32_t client, const std::string& text) override;
  void onBinary(uint32_t client, const std::string& bytes) override;
  bool nextFrame(uint32_t client, OutgoingFrame& frame) override;
  void onClose(uint32_t client) override;

 private:
  enum class Source { kBeftChannel, kDerived, kLog };
  struct Topic {
    foxglove::ServerChannel channel;
    Source source = Source::kBeftChannel;
    std::string beft_channel;             // kBeftChannel
    const wire::LcmStruct* type = nullptr;  // kBeftChannel
    DerivedTopic derived = DerivedTopic::kScene;
    bool latest_wins = false;
    std::map<uint32_t, uint32_t> subscribers;  // client -> its subscription id
  };
  // A subscription's throttleMs: nothing sent before next_send; pending when
  // a message came meanwhile (the channel's newest is sent then).
  struct Throttle {
    std::chrono::milliseconds interval{0};
    std::chrono::steady_clock::time_point next_send{};
    bool pending = false;
  };
  struct Client {
    ClientInfo info;
    foxglove::SendQueue queue;
    std::map<uint32_t, uint32_t> subscriptions;      // subscription id -> channel id
    std::map<uint32_t, std::string> published;       // client channel id -> control topic
    std::map<uint32_t, Throttle> throttles;          // channel id -> its subscription's throttle
    std::size_t queued_text = 0;
    uint64_t dropped = 0;                            // not yet told
    bool dropping = false;                           // closed for not reading: nothing more is queued
    bool unflushed = false;                          // data frames queued since the last flush()
    explicit Client(std::size_t bytes) : queue(bytes) {}
  };

  void addTopics();
  void handle(Client& client, const foxglove::ClientMessage& message);
  void subscribe(Client& client, const foxglove::Subscribe& request);
  void unsubscribe(Client& client, const foxglove::Unsubscribe& request);
  void advertiseFromClient(Client& client, const foxglove::ClientAdvertise& request);
  void publishFromClient(Client& client, const foxglove::ClientPublish& message);
  void publishFromExpert(Client& client, const std::string& topic, const std::string& payload);
  std::string carryOut(const ControlRequest& request);
  void sendText(Client& client, const std::string& text);
  void sendStatus(Client& client, int level, const std::string& message, const std::string& id = "");
  // make_payload: the message as JSON, made at most once and only if a subscriber is sent it now.
  void sendData(Topic& topic, const std::function<std::string()>& make_payload, uint64_t receive_ns);
  bool holdForThrottle(Client& client, uint32_t channel_id);
  // newest_only: of a log topic, only its newest line (a throttled subscription's turn).
  void sendKept(Client& client, Topic& topic, uint32_t subscription, bool newest_only = false);
  void wake(uint32_t client);
  void wakeForData(Client& client);

  HubOptions options_;
  ControlSink& controls_;
  ClientSockets* server_ = nullptr;
  ExternalExperts* experts_ = nullptr;
  SceneModel scene_;
  std::vector<foxglove::ServerChannel> channels_;
  std::map<uint32_t, Topic> topics_;                 // by channel id
  std::map<std::string, uint32_t> by_beft_channel_;  // plain channel name -> channel id
  std::map<DerivedTopic, uint32_t> by_derived_;
  uint32_t log_topic_ = 0;
  uint32_t firings_topic_ = 0;
  struct Kept {
    std::vector<uint8_t> bytes;
    uint64_t receive_ns = 0;
  };
  std::map<uint32_t, Kept> kept_;  // the newest message of each BEFT channel, for a new subscriber
  struct LogLine {
    std::string payload;  // foxglove.Log as JSON
    uint64_t receive_ns = 0;
  };
  static constexpr std::size_t kRecentLogLines = 200;
  // By topic: the newest lines of /log and of /firings, for a new subscriber.
  std::map<uint32_t, std::deque<LogLine>> recent_lines_;
  std::map<uint32_t, std::unique_ptr<Client>> clients_;
  uint64_t frames_dropped_ = 0;
  uint64_t last_receive_ns_ = 0;  // of the newest run message
};

// The level of a processes.log line ("[vision] [vision] WARN: ...").
log::Level levelOfLine(const std::string& text);

}  // namespace beft::bridge
