// What a client sends (protocol.hpp: parseClientText, parseClientBinary),
// checked field by field.
#include <limits>
#include <set>

#include <nlohmann/json.hpp>

#include "lib/foxglove/protocol.hpp"

namespace beft::foxglove {

namespace {

using nlohmann::json;

// Why a message is refused; thrown only inside this file, caught below.
struct Refusal {
  std::string reason;
};

[[noreturn]] void refuse(std::string reason) { throw Refusal{std::move(reason)}; }

const json& fieldOf(const json& object, const char* key, const std::string& where) {
  const auto it = object.find(key);
  if (it == object.end()) refuse(where + "." + key + " is missing");
  return *it;
}

// An id: a JSON integer in 0..2^32-1; name says where it is.
uint32_t idValue(const json& value, const std::string& name) {
  if (!value.is_number_integer()) refuse(name + " is not an integer");
  constexpr uint64_t kMax = std::numeric_limits<uint32_t>::max();
  const bool fits = value.is_number_unsigned() ? value.get<uint64_t>() <= kMax
                                               : value.get<int64_t>() >= 0 && value.get<int64_t>() <= int64_t{kMax};
  if (!fits) refuse(name + " = " + value.dump() + " is outside 0..4294967295");
  return static_cast<uint32_t>(value.get<uint64_t>());
}

uint32_t idOf(const json& object, const char* key, const std::string& where) {
  return idValue(fieldOf(object, key, where), where + "." + key);
}

std::string textOf(const json& object, const char* key, const std::string& where, std::size_t max_bytes) {
  const json& value = fieldOf(object, key, where);
  if (!value.is_string()) refuse(where + "." + key + " is not a string");
  const std::string& text = value.get_ref<const std::string&>();
  if (text.size() > max_bytes)
    refuse(where + "." + key + " has " + std::to_string(text.size()) + " bytes, more than the " +
           std::to_string(max_bytes) + " allowed");
  return text;
}

std::optional<std::string> optionalTextOf(const json& object, const char* key, const std::string& where) {
  if (!object.contains(key) || object.at(key).is_null()) return std::nullopt;
  return textOf(object, key, where, kMaxClientTextBytes);
}

// The list under key, with at most kMaxClientListEntries entries.
const json& listOf(const json& message, const char* key, const std::string& op) {
  const json& list = fieldOf(message, key, op);
  if (!list.is_array()) refuse(op + "." + key + " is not an array");
  if (list.size() > kMaxClientListEntries)
    refuse(op + "." + key + " has " + std::to_string(list.size()) + " entries, more than the " +
           std::to_string(kMaxClientListEntries) + " allowed");
  return list;
}

const json& entryOf(const json& list, std::size_t index, const std::string& where) {
  const json& entry = list[index];
  if (!entry.is_object()) refuse(where + " is not an object");
  return entry;
}

// Refuses an id that an earlier entry of the same list already named.
void checkUnique(std::set<uint32_t>& seen, uint32_t id, const std::string& where) {
  if (!seen.insert(id).second) refuse(where + " = " + std::to_string(id) + " repeats an earlier entry");
}

std::string at(const std::string& list, std::size_t index) { return list + "[" + std::to_string(index) + "]"; }

// The optional throttleMs of a subscription (protocol.hpp), 0..kMaxThrottleMs.
uint32_t throttleOf(const json& entry, const std::string& where) {
  if (!entry.contains("throttleMs")) return 0;
  const uint32_t ms = idValue(entry.at("throttleMs"), where + ".throttleMs");
  if (ms > kMaxThrottleMs)
    refuse(where + ".throttleMs = " + std::to_string(ms) + " is more than the " + std::to_string(kMaxThrottleMs) +
           " allowed");
  return ms;
}

Subscribe parseSubscribe(const json& message) {
  const json& list = listOf(message, "subscriptions", "subscribe");
  Subscribe subscribe;
  std::set<uint32_t> ids, channels;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string where = at("subscribe.subscriptions", i);
    const json& entry = entryOf(list, i, where);
    SubscriptionRequest request{idOf(entry, "id", where), idOf(entry, "channelId", where)};
    request.throttle_ms = throttleOf(entry, where);
    checkUnique(ids, request.id, where + ".id");
    checkUnique(channels, request.channel_id, where + ".channelId");
    subscribe.subscriptions.push_back(request);
  }
  return subscribe;
}

std::vector<uint32_t> parseIds(const json& message, const char* key, const std::string& op) {
  const json& list = listOf(message, key, op);
  std::vector<uint32_t> ids;
  std::set<uint32_t> seen;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string where = at(op + "." + key, i);
    const uint32_t id = idValue(list[i], where);
    checkUnique(seen, id, where);
    ids.push_back(id);
  }
  return ids;
}

ClientAdvertise parseAdvertise(const json& message) {
  const json& list = listOf(message, "channels", "advertise");
  ClientAdvertise advertise;
  std::set<uint32_t> ids;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string where = at("advertise.channels", i);
    const json& entry = entryOf(list, i, where);
    ClientChannel channel;
    channel.id = idOf(entry, "id", where);
    checkUnique(ids, channel.id, where + ".id");
    channel.topic = textOf(entry, "topic", where, kMaxTopicChars);
    if (channel.topic.empty()) refuse(where + ".topic is empty");
    channel.encoding = textOf(entry, "encoding", where, kMaxNameChars);
    channel.schema_name = textOf(entry, "schemaName", where, kMaxNameChars);
    channel.schema = optionalTextOf(entry, "schema", where);
    channel.schema_encoding = optionalTextOf(entry, "schemaEncoding", where);
    advertise.channels.push_back(std::move(channel));
  }
  return advertise;
}

bool isUnsupportedOp(const std::string& op) {
  static const std::set<std::string> kOps = {"getParameters", "setParameters", "subscribeParameterUpdates",
                                             "unsubscribeParameterUpdates", "subscribeConnectionGraph",
                                             "unsubscribeConnectionGraph", "fetchAsset"};
  return kOps.count(op) > 0;
}

ClientMessage parseMessage(const json& message) {
  if (!message.is_object()) refuse("a text message must be a JSON object, this is " + std::string(message.type_name()));
  const auto op_field = message.find("op");
  if (op_field == message.end() || !op_field->is_string()) refuse("the message has no \"op\" string");
  const std::string& op = op_field->get_ref<const std::string&>();
  if (op == "subscribe") return parseSubscribe(message);
  if (op == "unsubscribe") return Unsubscribe{parseIds(message, "subscriptionIds", op)};
  if (op == "advertise") return parseAdvertise(message);
  if (op == "unadvertise") return ClientUnadvertise{parseIds(message, "channelIds", op)};
  const std::string shown = op.size() > 64 ? op.substr(0, 64) + "..." : op;
  if (isUnsupportedOp(op)) refuse("op \"" + shown + "\" is not supported by this server");
  refuse("unknown op \"" + shown + "\"");
}

// nlohmann's parse error without its "[json.exception.parse_error.101] " tag.
std::string parseErrorText(const std::exception& error) {
  std::string text = error.what();
  const std::size_t tag_end = text.find("] ");
  if (!text.empty() && text[0] == '[' && tag_end != std::string::npos) text.erase(0, tag_end + 2);
  return text;
}

}  // namespace

ClientMessage parseClientText(std::string_view text) {
  if (text.size() > kMaxClientTextBytes)
    return Invalid{"a text message of " + std::to_string(text.size()) + " bytes is longer than the " +
                   std::to_string(kMaxClientTextBytes) + " allowed"};
  try {
    json message;
    try {
      message = json::parse(text.begin(), text.end());
    } catch (const json::parse_error& error) {
      return Invalid{"not JSON: " + parseErrorText(error)};
    }
    return parseMessage(message);
  } catch (const Refusal& refusal) {
    return Invalid{refusal.reason};
  } catch (const std::exception& error) {
    return Invalid{std::string("cannot read the message: ") + error.what()};
  } catch (...) {
    return Invalid{"cannot read the message"};
  }
}

ClientMessage parseClientBinary(std::string_view bytes) {
  if (bytes.empty()) return Invalid{"an empty binary message"};
  if (bytes.size() > kMaxClientBinaryBytes)
    return Invalid{"a binary message of " + std::to_string(bytes.size()) + " bytes is longer than the " +
                   std::to_string(kMaxClientBinaryBytes) + " allowed"};
  const auto opcode = static_cast<uint8_t>(bytes[0]);
  if (opcode != kClientOpMessagePublish)
    return Invalid{"binary opcode " + std::to_string(opcode) + " is not supported by this server (only " +
                   std::to_string(kClientOpMessagePublish) + ", message data)"};
  if (bytes.size() < 5)
    return Invalid{"a message data frame of " + std::to_string(bytes.size()) +
                   " bytes is shorter than its 5-byte header (opcode, channel id)"};
  uint32_t channel_id = 0;
  for (int i = 0; i < 4; ++i) channel_id |= uint32_t{static_cast<uint8_t>(bytes[1 + i])} << (8 * i);
  try {
    return ClientPublish{channel_id, std::string(bytes.substr(5))};
  } catch (...) {
    return Invalid{"cannot hold the message"};
  }
}

}  // namespace beft::foxglove
