#include "services/bridge/foxglove_hub.hpp"

#include <type_traits>
#include <utility>

#include "lib/common/channels.hpp"
#include "lib/foxglove/json_text.hpp"
#include "lib/foxglove/lcm_json.hpp"
#include "lib/foxglove/scene_messages.hpp"
#include "lib/service/firing_trace.hpp"

namespace beft::bridge {

namespace {

constexpr uint32_t kTimeKey = 0;  // the latest-wins key of Time frames (channel ids start at 1)

// The channels whose newest message is all a slow viewer needs.
bool bulky(const std::string& channel) {
  namespace c = channels;
  return channel == c::kCameraColor || channel == c::kCameraDepth || channel == c::kCameraInstance ||
         channel == c::kObstacleMap || channel == c::kGroundTruth || channel == c::kHypotheses ||
         channel == c::kEars || channel == c::kObstacleMapChanges;
}

struct DerivedSpec {
  DerivedTopic topic;
  const char* name;
  const char* schema;
};
const DerivedSpec kDerivedSpecs[] = {
    {DerivedTopic::kScene, "/scene", foxglove::kSceneUpdateSchema},
    {DerivedTopic::kTransforms, "/tf", foxglove::kFrameTransformsSchema},
    {DerivedTopic::kObstacleMap, "/obstacle_map", foxglove::kGridSchema},
    {DerivedTopic::kCameraColor, "/camera/color", foxglove::kRawImageSchema},
    {DerivedTopic::kCameraDepth, "/camera/depth", foxglove::kRawImageSchema}};

}  // namespace

log::Level levelOfLine(const std::string& text) {
  if (text.find("] ERROR:") != std::string::npos) return log::Level::Error;
  if (text.find("] WARN:") != std::string::npos) return log::Level::Warn;
  if (text.find("] debug:") != std::string::npos) return log::Level::Debug;
  return log::Level::Info;
}

FoxgloveHub::FoxgloveHub(HubOptions options, ControlSink& controls)
    : options_(std::move(options)), controls_(controls) {
  addTopics();
}

void FoxgloveHub::addTopics() {
  const auto& types = foxglove::beftTypeSet();
  uint32_t id = 1;
  const auto add = [&](Topic topic) {
    topic.channel.id = id++;
    topic.channel.encoding = "json";
    topic.channel.schema_encoding = "jsonschema";
    channels_.push_back(topic.channel);
    topics_.emplace(topic.channel.id, std::move(topic));
  };
  for (const auto& entry : channels::allChannels()) {
    const wire::LcmStruct* type = types.find(entry.type);
    if (entry.plane == channels::Plane::kTransport || type == nullptr) continue;
    Topic topic;
    topic.channel.topic = entry.name;
    topic.channel.schema_name = entry.type;
    topic.channel.schema = foxglove::dumpJson(foxglove::jsonSchemaOf(types, *type));
    topic.beft_channel = entry.name;
    topic.type = type;
    topic.latest_wins = bulky(entry.name);
    by_beft_channel_[entry.name] = id;
    add(std::move(topic));
  }
  for (const auto& spec : kDerivedSpecs) {
    Topic topic;
    topic.channel.topic = spec.name;
    topic.channel.schema_name = spec.schema;
    topic.channel.schema = foxglove::dumpJson(foxglove::foxgloveSchema(spec.schema));
    topic.source = Source::kDerived;
    topic.derived = spec.topic;
    topic.latest_wins = true;
    by_derived_[spec.topic] = id;
    add(std::move(topic));
  }
  for (const char* name : {kLogTopic, kFiringsTopic}) {
    Topic log_topic;
    log_topic.channel.topic = name;
    log_topic.channel.schema_name = foxglove::kLogSchema;
    log_topic.channel.schema = foxglove::dumpJson(foxglove::foxgloveSchema(foxglove::kLogSchema));
    log_topic.source = Source::kLog;
    (name == kLogTopic ? log_topic_ : firings_topic_) = id;
    add(std::move(log_topic));
  }
}

void FoxgloveHub::onRunMessage(const std::string& channel, const uint8_t* data, std::size_t size,
                               uint64_t receive_ns) {
  scene_.take(channel, data, size);
  last_receive_ns_ = receive_ns;
  const auto found = by_beft_channel_.find(channel);
  if (found == by_beft_channel_.end()) return;
  Topic& topic = topics_.at(found->second);
  Kept& kept = kept_[topic.channel.id];
  kept.bytes.assign(data, data + size);
  kept.receive_ns = receive_ns;
  if (topic.subscribers.empty()) return;
  try {
    // Converted only if some subscriber is sent it now (not held by its throttle).
    const auto as_json = [&] {
      return foxglove::dumpJson(foxglove::lcmToJson(foxglove::beftTypeSet(), *topic.type, data, size));
    };
    sendData(topic, as_json, receive_ns);
  } catch (const std::exception&) {
    // A message that does not decode as its channel's type: the guard counts such refusals for the run.
  }
}

void FoxgloveHub::publishDerived() {
  for (const auto& spec : kDerivedSpecs) {
    if (!scene_.changed(spec.topic)) continue;
    Topic& topic = topics_.at(by_derived_.at(spec.topic));
    if (topic.subscribers.empty()) continue;  // built when someone subscribes
    scene_.clearChanged(spec.topic);
    if (const auto message = scene_.build(spec.topic))
      sendData(topic, [&] { return foxglove::dumpJson(*message); }, last_receive_ns_);
  }
}

void FoxgloveHub::publishLogLines(const std::vector<std::string>& lines, uint64_t receive_ns) {
  for (const auto& line : lines) {
    const ProcessLine split = splitProcessLine(line);
    // At full speed nearly every line is the arbiter's trace, ten a tick: apart, /log stays readable and a
    // viewer can take the trace at the pace it shows it (throttleMs). A firing that went wrong is on both.
    const service::FiringTraceLine trace =
        split.process == "arbiter" ? service::readFiringTraceLine(split.text) : service::FiringTraceLine{};
    const bool firing = trace.is_firing, routine = trace.routine;
    const auto message = foxglove::logLine(static_cast<int64_t>(receive_ns / 1000), levelOfLine(split.text),
                                           split.process, split.text);
    const std::string payload = foxglove::dumpJson(message);
    for (const uint32_t topic_id : {firing ? firings_topic_ : 0u, routine ? 0u : log_topic_}) {
      if (topic_id == 0) continue;
      // Kept for viewers that come later: a log's processes.log is written before any of them connects.
      auto& recent = recent_lines_[topic_id];
      recent.push_back({payload, receive_ns});
      if (recent.size() > kRecentLogLines) recent.pop_front();
      Topic& topic = topics_.at(topic_id);
      if (!topic.subscribers.empty()) sendData(topic, [&] { return payload; }, receive_ns);
    }
  }
}

void FoxgloveHub::sendTime(uint64_t time_ns) {
  const std::string frame = foxglove::timeFrame(time_ns);
  for (auto& [id, client] : clients_) {
    client->queue.push({frame, true, kTimeKey});
    wake(id);
  }
}

void FoxgloveHub::broadcastStatus(int level, const std::string& message, const std::string& id) {
  for (auto& [client_id, client] : clients_) sendStatus(*client, level, message, id);
}

void FoxgloveHub::reportDrops() {
  for (auto& [id, client] : clients_) {
    // Frames dropped for room and frames a newer one of their bulky topic replaced: both never reach the viewer.
    const uint64_t dropped = client->queue.takeDropped() + client->queue.takeReplaced();
    client->dropped += dropped;
    frames_dropped_ += dropped;
    if (client->dropped == 0 || client->queued_text > 0) continue;  // one notice at a time
    sendStatus(*client, foxglove::kStatusWarning,
               std::to_string(client->dropped) +
                   " message(s) not sent: this viewer reads slower than the run sends (the bulky topics keep "
                   "only their newest message)",
               "beft.dropped");
    client->dropped = 0;
  }
}

void FoxgloveHub::sendData(Topic& topic, const std::function<std::string()>& make_payload, uint64_t receive_ns) {
  std::optional<std::string> payload;
  for (const auto& [client_id, subscription] : topic.subscribers) {
    const auto found = clients_.find(client_id);
    if (found == clients_.end()) continue;
    if (holdForThrottle(*found->second, topic.channel.id)) continue;
    if (!payload) payload = make_payload();
    foxglove::Frame frame{foxglove::messageDataFrame(subscription, receive_ns, *payload), true, std::nullopt};
    if (topic.latest_wins) frame.latest_wins_key = topic.channel.id;
    found->second->queue.push(std::move(frame));
    wakeForData(*found->second);
  }
}

// A viewer's data frames wait for the next flush(), so that what the run
// sent meanwhile leaves in one burst: at full speed the run gives the page a
// message every millisecond or so, and each frame written alone wakes the
// browser's network, IPC and page threads on the cores the run's lockstep
// chain needs. Nothing is dropped for it but what the queue's bound drops
// anyway. An external expert takes part in the lockstep loop: its frames
// leave at once.
void FoxgloveHub::wakeForData(Client& client) {
  if (experts_ != nullptr && experts_->isExpert(client.info.id)) return wake(client.info.id);
  client.unflushed = true;
}

void FoxgloveHub::flush() {
  for (auto& [id, client] : clients_) {
    if (!client->unflushed) continue;
    client->unflushed = false;
    wake(id);
  }
}

// True when the client's subscription to the channel is throttled and was
// sent too recently: it is marked to be sent the channel's newest message
// when its time is up (sendThrottled), and nothing is converted now.
bool FoxgloveHub::holdForThrottle(Client& client, uint32_t channel_id) {
  const auto found = client.throttles.find(channel_id);
  if (found == client.throttles.end()) return false;
  Throttle& throttle = found->second;
  const auto now = std::chrono::steady_clock::now();
  if (now < throttle.next_send) {
    throttle.pending = true;
    return true;
  }
  throttle.next_send = now + throttle.interval;
  throttle.pending = false;
  return false;
}

void FoxgloveHub::sendThrottled(std::chrono::steady_clock::time_point now) {
  for (auto& [client_id, client] : clients_) {
    for (auto& [channel_id, throttle] : client->throttles) {
      if (!throttle.pending || now < throttle.next_send) continue;
      throttle.pending = false;
      throttle.next_send = now + throttle.interval;
      Topic& topic = topics_.at(channel_id);
      const auto subscription = topic.subscribers.find(client_id);
      if (subscription != topic.subscribers.end()) sendKept(*client, topic, subscription->second, true);
    }
  }
}

void FoxgloveHub::sendText(Client& client, const std::string& text) {
  if (client.dropping) return;
  client.queue.push({text, false, std::nullopt});
  ++client.queued_text;
  wake(client.info.id);
  // Answers pile up only for a client that never reads them: it goes, the bridge's memory stays bounded.
  if (client.queued_text > options_.max_queued_text && server_) {
    client.dropping = true;
    server_->drop(client.info.id);
  }
}

void FoxgloveHub::sendStatus(Client& client, int level, const std::string& message, const std::string& id) {
  sendText(client, foxglove::status(level, message, id.empty() ? std::nullopt : std::optional<std::string>(id)));
}

void FoxgloveHub::wake(uint32_t client) {
  if (server_) server_->wake(client);
}

void FoxgloveHub::onOpen(const ClientInfo& info) {
  auto client = std::make_unique<Client>(options_.queue_bytes);
  client->info = info;
  Client& added = *client;
  clients_[info.id] = std::move(client);
  std::vector<std::string> capabilities = {foxglove::kCapabilityClientPublish};
  if (options_.time_capability) capabilities.push_back(foxglove::kCapabilityTime);
  sendText(added, foxglove::serverInfo(options_.name, capabilities, options_.session_id, options_.metadata));
  sendText(added, foxglove::advertise(channels_));
}

void FoxgloveHub::onClose(uint32_t client) {
  for (auto& [id, topic] : topics_) topic.subscribers.erase(client);
  clients_.erase(client);
  if (experts_ != nullptr) experts_->forget(client);
}

bool FoxgloveHub::nextFrame(uint32_t client_id, OutgoingFrame& frame) {
  const auto found = clients_.find(client_id);
  if (found == clients_.end() || found->second->queue.empty()) return false;
  Client& client = *found->second;
  foxglove::Frame next = client.queue.pop();
  if (!next.binary && client.queued_text > 0) --client.queued_text;
  frame.text = !next.binary;
  frame.bytes = std::move(next.bytes);
  return true;
}

void FoxgloveHub::onText(uint32_t client, const std::string& text) {
  const auto found = clients_.find(client);
  if (found != clients_.end()) handle(*found->second, foxglove::parseClientText(text));
}

void FoxgloveHub::onBinary(uint32_t client, const std::string& bytes) {
  const auto found = clients_.find(client);
  if (found != clients_.end()) handle(*found->second, foxglove::parseClientBinary(bytes));
}

void FoxgloveHub::handle(Client& client, const foxglove::ClientMessage& message) {
  std::visit(
      [&](const auto& m) {
        using T = std::decay_t<decltype(m)>;
        if constexpr (std::is_same_v<T, foxglove::Subscribe>) subscribe(client, m);
        else if constexpr (std::is_same_v<T, foxglove::Unsubscribe>) unsubscribe(client, m);
        else if constexpr (std::is_same_v<T, foxglove::ClientAdvertise>) advertiseFromClient(client, m);
        else if constexpr (std::is_same_v<T, foxglove::ClientUnadvertise>) {
          for (const uint32_t id : m.channel_ids) client.published.erase(id);
        } else if constexpr (std::is_same_v<T, foxglove::ClientPublish>) publishFromClient(client, m);
        else sendStatus(client, foxglove::kStatusError, "invalid message: " + m.reason);
      },
      message);
}

void FoxgloveHub::subscribe(Client& client, const foxglove::Subscribe& request) {
  for (const auto& wanted : request.subscriptions) {
    const auto topic = topics_.find(wanted.channel_id);
    if (topic == topics_.end()) {
      sendStatus(client, foxglove::kStatusError,
                 "subscribe: no channel " + std::to_string(wanted.channel_id) + " is advertised");
      continue;
    }
    if (client.subscriptions.count(wanted.id)) {
      sendStatus(client, foxglove::kStatusError,
                 "subscribe: subscription id " + std::to_string(wanted.id) + " is already in use");
      continue;
    }
    if (topic->second.subscribers.count(client.info.id)) {
      sendStatus(client, foxglove::kStatusWarning,
                 "subscribe: already subscribed to " + topic->second.channel.topic + " (one subscription a channel)");
      continue;
    }
    client.subscriptions[wanted.id] = wanted.channel_id;
    topic->second.subscribers[client.info.id] = wanted.id;
    if (wanted.throttle_ms > 0)
      client.throttles[wanted.channel_id].interval = std::chrono::milliseconds(wanted.throttle_ms);
    sendKept(client, topic->second, wanted.id);
  }
}

// What a new subscriber sees at once: the newest message of the channel, or the topic as it is now.
void FoxgloveHub::sendKept(Client& client, Topic& topic, uint32_t subscription, bool newest_only) {
  std::string payload;
  uint64_t receive_ns = 0;
  try {
    if (topic.source == Source::kBeftChannel) {
      const auto kept = kept_.find(topic.channel.id);
      if (kept == kept_.end()) return;
      payload = foxglove::dumpJson(
          foxglove::lcmToJson(foxglove::beftTypeSet(), *topic.type, kept->second.bytes.data(), kept->second.bytes.size()));
      receive_ns = kept->second.receive_ns;
    } else if (topic.source == Source::kDerived) {
      const auto message = scene_.build(topic.derived);
      if (!message) return;
      payload = foxglove::dumpJson(*message);
      receive_ns = last_receive_ns_;
    } else {
      const auto& recent = recent_lines_[topic.channel.id];
      const std::size_t first = newest_only && !recent.empty() ? recent.size() - 1 : 0;
      for (std::size_t i = first; i < recent.size(); ++i)
        client.queue.push({foxglove::messageDataFrame(subscription, recent[i].receive_ns, recent[i].payload), true,
                           std::nullopt});
      wake(client.info.id);
      return;
    }
  } catch (const std::exception&) {
    return;  // a kept message that does not convert: the next one will
  }
  foxglove::Frame frame{foxglove::messageDataFrame(subscription, receive_ns, payload), true, std::nullopt};
  if (topic.latest_wins) frame.latest_wins_key = topic.channel.id;
  client.queue.push(std::move(frame));
  wake(client.info.id);
}

void FoxgloveHub::unsubscribe(Client& client, const foxglove::Unsubscribe& request) {
  for (const uint32_t id : request.subscription_ids) {
    const auto found = client.subscriptions.find(id);
    if (found == client.subscriptions.end()) {
      sendStatus(client, foxglove::kStatusWarning, "unsubscribe: no subscription " + std::to_string(id));
      continue;
    }
    topics_.at(found->second).subscribers.erase(client.info.id);
    client.throttles.erase(found->second);
    client.subscriptions.erase(found);
  }
}

void FoxgloveHub::advertiseFromClient(Client& client, const foxglove::ClientAdvertise& request) {
  for (const auto& channel : request.channels) {
    if (experts_ != nullptr && !isControlTopic(channel.topic) &&
        ExternalExperts::advertisable(channel.topic, channel.schema_name).empty() && channel.encoding == "json") {
      client.published[channel.id] = channel.topic;  // an external expert's channel
      continue;
    }
    if (!isControlTopic(channel.topic)) {
      sendStatus(client, foxglove::kStatusError,
                 "advertise: \"" + channel.topic + "\" is no control topic of this bridge (" + kRunControlTopic +
                     ", " + kTaskTopic + ", " + kPlaybackTopic + ")");
      continue;
    }
    if (channel.encoding != "json") {
      sendStatus(client, foxglove::kStatusError,
                 "advertise: " + channel.topic + " takes encoding \"json\", not \"" + channel.encoding + "\"");
      continue;
    }
    client.published[channel.id] = channel.topic;
  }
}

void FoxgloveHub::publishFromClient(Client& client, const foxglove::ClientPublish& message) {
  const auto channel = client.published.find(message.channel_id);
  if (channel == client.published.end()) {
    sendStatus(client, foxglove::kStatusError,
               "publish: channel " + std::to_string(message.channel_id) + " was not advertised by this client");
    return;
  }
  if (!client.info.loopback && !client.info.token_ok) {
    sendStatus(client, foxglove::kStatusError,
               channel->second + ": refused: controls from another host need the bridge's token (connect to "
                                 "ws://HOST:PORT/?token=TOKEN; beft-bridge --token)");
    return;
  }
  if (experts_ != nullptr && !isControlTopic(channel->second)) {
    publishFromExpert(client, channel->second, message.payload);
    return;
  }
  const ControlRequest request = parseControlRequest(channel->second, message.payload);
  const std::string error = request.error.empty() ? carryOut(request) : request.error;
  if (!error.empty()) sendStatus(client, foxglove::kStatusError, error);
}

// An external expert's announcement (the run's history first when it
// resumes: text frames, never dropped) or message; a refusal names the field.
void FoxgloveHub::publishFromExpert(Client& client, const std::string& topic, const std::string& payload) {
  const bool announcing = ExternalExperts::isExpertTopic(topic);
  const ExpertStatus status =
      announcing ? experts_->announce(client.info.id, payload) : experts_->publish(client.info.id, topic, payload);
  if (announcing) {
    for (auto& text : experts_->takeHistory(client.info.id)) client.queue.push({std::move(text), false, std::nullopt});
    wake(client.info.id);
  }
  if (!status.message.empty()) sendStatus(client, status.level, status.message, status.id);
}

std::string FoxgloveHub::carryOut(const ControlRequest& request) {
  return std::visit(
      [&](const auto& r) -> std::string {
        using T = std::decay_t<decltype(r)>;
        if constexpr (std::is_same_v<T, RunControlRequest>) return controls_.runControl(r);
        else if constexpr (std::is_same_v<T, TaskRequest>) return controls_.task(r);
        else if constexpr (std::is_same_v<T, PlaybackRequest>) return controls_.playback(r);
        else return "no request";
      },
      request.request);
}

}  // namespace beft::bridge
