#include "services/bridge/external_experts.hpp"

#include <algorithm>
#include <chrono>

#include <nlohmann/json.hpp>

#include <beft/heartbeat_t.hpp>

#include "lib/common/channels.hpp"
#include "lib/foxglove/lcm_json.hpp"
#include "lib/foxglove/protocol.hpp"
#include "lib/wire/log_reader.hpp"
#include "lib/wire/message_check.hpp"
#include "lib/wire/run_identity.hpp"

namespace beft::bridge {

namespace {

const channels::ChannelEntry* entryOf(const std::string& channel) {
  for (const auto& entry : channels::allChannels())
    if (channel == entry.name) return &entry;
  return nullptr;
}

bool isAnswerChannel(const std::string& channel) {
  return channel == channels::kDone.name || channel == channels::kHeartbeat.name;
}

bool validName(const std::string& name) {
  return !name.empty() && name.size() <= 64 && std::all_of(name.begin(), name.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
  });
}

// The channels of "reads" or "writes": each a channel of the table with its
// type. "" when right, else what is wrong, naming the entry.
std::string channelList(const nlohmann::json& announcement, const char* key, bool writes,
                        std::vector<std::string>& out) {
  const auto list = announcement.find(key);
  if (list == announcement.end() || !list->is_array()) return std::string(key) + ": missing, or not a list";
  for (std::size_t i = 0; i < list->size(); ++i) {
    const auto& spec = (*list)[i];
    const std::string where = std::string(key) + "[" + std::to_string(i) + "]";
    if (!spec.is_object() || !spec.contains("channel") || !spec["channel"].is_string() || !spec.contains("type") ||
        !spec["type"].is_string())
      return where + ": not {\"channel\": ..., \"type\": ...}";
    const std::string channel = spec["channel"], type = spec["type"];
    const auto* entry = entryOf(channel);
    if (entry == nullptr) return where + ": " + channel + " is no channel of the run";
    if (entry->type != type) return where + ": " + channel + " carries " + entry->type + ", not " + type;
    if (writes && entry->plane != channels::Plane::kData && entry->plane != channels::Plane::kReport)
      return where + ": " + channel + " is not a data channel (an expert answers on DONE and HEARTBEAT)";
    out.push_back(channel);
  }
  return "";
}

std::string joined(const std::vector<std::string>& names) {
  std::string text;
  for (const auto& name : names) text += (text.empty() ? "" : ", ") + name;
  return text.empty() ? "none" : text;
}

// The run's events an expert restarted mid-run had heard, as history texts:
// its FIREs and DONEs and what it reads. The log is first given up to 5 s to
// hold what was published before now, as a restarted C++ expert does.
std::vector<std::string> historyOf(const std::string& log_path, const std::string& name,
                                   const std::vector<std::string>& reads) {
  const int64_t now_us = std::chrono::duration_cast<std::chrono::microseconds>(
                             std::chrono::system_clock::now().time_since_epoch())
                             .count();
  wire::waitForLogPast(log_path, now_us, 5.0);
  std::set<std::string> wanted(reads.begin(), reads.end());
  wanted.insert(channels::kFire.name);
  wanted.insert(channels::kDone.name);
  const auto& types = foxglove::beftTypeSet();
  const int64_t run = wire::runId() != 0 ? wire::runId() : wire::runOfLog(log_path);
  std::vector<std::string> history;
  wire::LogReader log(log_path);
  wire::LogEvent event;
  while (log.nextOfRun(event, run)) {
    if (!wanted.count(event.channel)) continue;
    const auto* type = types.find(channels::typeOfChannel(event.channel));
    if (type == nullptr) continue;
    try {
      nlohmann::json text = {{"op", "beftHistory"}, {"channel", event.channel}};
      text["message"] = foxglove::lcmToJson(types, *type, event.data.data(), event.data.size());
      const bool token = event.channel == channels::kFire.name || event.channel == channels::kDone.name;
      if (token && text["message"]["expert"] != name) continue;  // another expert's
      history.push_back(text.dump());
    } catch (const std::exception&) {
      // a damaged message in the log: the expert did not get it either
    }
  }
  return history;
}

}  // namespace

std::vector<std::string> ExternalExperts::takeHistory(uint32_t client) {
  std::vector<std::string> history;
  const auto found = histories_.find(client);
  if (found != histories_.end()) {
    history = std::move(found->second);
    histories_.erase(found);
  }
  return history;
}

bool ExternalExperts::isExpertTopic(const std::string& topic) { return topic == kExpertTopic; }

std::string ExternalExperts::advertisable(const std::string& topic, const std::string& schema_name) {
  if (isExpertTopic(topic)) return "";
  const auto* entry = entryOf(topic);
  if (entry == nullptr) return "\"" + topic + "\" is no channel of the run";
  if (entry->type != schema_name)
    return topic + " carries " + entry->type + ": advertise it with that schemaName, not \"" + schema_name + "\"";
  return "";
}

std::string ExternalExperts::nameOf(uint32_t client) const {
  const auto found = sessions_.find(client);
  return found == sessions_.end() ? std::string() : found->second.name;
}

ExpertStatus ExternalExperts::refuse(const std::string& name, const std::string& why) {
  ++refused_;
  return {foxglove::kStatusError, why, name.empty() ? std::string("beft.expert") : "beft.expert." + name + ".refused"};
}

ExpertStatus ExternalExperts::announce(uint32_t client, const std::string& payload) {
  const nlohmann::json announcement = nlohmann::json::parse(payload, nullptr, false);
  if (!announcement.is_object()) return refuse("", std::string(kExpertTopic) + ": not a JSON object");
  const auto name_field = announcement.find("name");
  if (name_field == announcement.end() || !name_field->is_string() || !validName(*name_field))
    return refuse("", std::string(kExpertTopic) + ": name: missing, or not a lowercase process name");
  const std::string name = *name_field;
  const ExpertStatus refused = {foxglove::kStatusError, "", "beft.expert." + name};
  for (const auto& [other, session] : sessions_)
    if (other != client && session.name == name) {
      ++refused_;
      return {refused.level, "expert " + name + " refused: another client is expert " + name, refused.id};
    }
  std::vector<std::string> reads, writes;
  for (const std::string& problem :
       {channelList(announcement, "reads", false, reads), channelList(announcement, "writes", true, writes)})
    if (!problem.empty()) {
      ++refused_;
      return {refused.level, "expert " + name + " refused: " + problem, refused.id};
    }
  std::string resumed;
  const auto resume_log = announcement.find("resume_log");
  if (resume_log != announcement.end() && resume_log->is_string() && !resume_log->get<std::string>().empty()) {
    try {
      histories_[client] = historyOf(*resume_log, name, reads);
      resumed = " (resumes from " + std::to_string(histories_[client].size()) + " events of the run's log)";
    } catch (const std::exception& e) {
      ++refused_;
      return {refused.level, "expert " + name + " refused: resume_log: " + e.what(), refused.id};
    }
  }
  sessions_[client] = Session{name, std::set<std::string>(writes.begin(), writes.end())};
  // A restarted expert runs its unanswered firing again: what it published then is on the bus already.
  const auto& unanswered = since_done_[name];
  owed_again_[name] = std::deque<Sent>(unanswered.begin(), unanswered.end());
  return {foxglove::kStatusInfo,
          "expert " + name + " accepted: reads " + joined(reads) + "; writes " + joined(writes) +
              ", DONE, HEARTBEAT" + resumed,
          "beft.expert." + name};
}

// DONE and HEARTBEAT speak for the expert that sent them, and a DONE lists
// what the bridge published for it.
std::string ExternalExperts::checkAnswer(const Session& session, const std::string& channel,
                                         std::vector<uint8_t>& bytes) {
  const int size = static_cast<int>(bytes.size());
  if (channel == channels::kHeartbeat.name) {
    beft::heartbeat_t beat{};
    if (beat.decode(bytes.data(), 0, size) != size) return "undecodable";
    return beat.process == session.name ? "" : "process: \"" + beat.process + "\" is not " + session.name;
  }
  beft::done_t done{};
  if (done.decode(bytes.data(), 0, size) != size) return "undecodable";
  if (done.expert != session.name) return "expert: \"" + done.expert + "\" is not " + session.name;
  bus_.listPublished(done);
  bytes.resize(done.getEncodedSize());
  done.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return "";
}

ExpertStatus ExternalExperts::publish(uint32_t client, const std::string& topic, const std::string& payload) {
  const auto found = sessions_.find(client);
  if (found == sessions_.end())
    return refuse("", topic + " refused: announce the expert on " + kExpertTopic + " first");
  const Session& session = found->second;
  if (!isAnswerChannel(topic) && !session.writes.count(topic))
    return refuse(session.name, topic + " refused: expert " + session.name + " does not declare it (writes: " +
                                    joined({session.writes.begin(), session.writes.end()}) + ")");
  const nlohmann::json value = nlohmann::json::parse(payload, nullptr, false);
  if (value.is_discarded()) return refuse(session.name, topic + " refused: not JSON");
  const auto& types = foxglove::beftTypeSet();
  const auto* type = types.find(channels::typeOfChannel(topic));
  if (type == nullptr) return refuse(session.name, topic + " refused: no type known for it");
  std::vector<uint8_t> bytes;
  try {
    bytes = foxglove::jsonToLcm(types, *type, value);
  } catch (const std::exception& e) {  // JsonToLcmError names the member
    return refuse(session.name, topic + " refused: " + e.what());
  }
  const wire::Verdict verdict = wire::MessageRules::beftTypes().checkForChannel(topic, bytes.data(), bytes.size());
  if (!verdict.ok()) return refuse(session.name, topic + " refused: " + verdict.text());
  if (isAnswerChannel(topic))
    if (const std::string problem = checkAnswer(session, topic, bytes); !problem.empty())
      return refuse(session.name, topic + " refused: " + problem);
  Sent sent{topic, std::move(bytes)};
  if (alreadyOnTheBus(session.name, sent)) {
    ++resent_taken_;
    return {};
  }
  if (const std::string problem = bus_.publish(topic, sent.second); !problem.empty())
    return {foxglove::kStatusError, topic + ": " + problem, "beft.expert." + session.name + ".refused"};
  ++published_;
  if (topic == channels::kDone.name) {
    since_done_[session.name].clear();
    owed_again_[session.name].clear();
  } else if (!isAnswerChannel(topic)) {
    since_done_[session.name].push_back(std::move(sent));
  }
  return {};
}

bool ExternalExperts::alreadyOnTheBus(const std::string& name, const Sent& sent) {
  auto owed = owed_again_.find(name);
  if (owed == owed_again_.end() || owed->second.empty() || isAnswerChannel(sent.first)) return false;
  if (owed->second.front() == sent) {
    owed->second.pop_front();
    return true;
  }
  owed->second.clear();  // it computed something else this time: from here on, everything is new
  return false;
}

}  // namespace beft::bridge
