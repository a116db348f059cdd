// The server's messages (protocol.hpp): JSON text and binary frames.
#include "lib/foxglove/protocol.hpp"

#include <nlohmann/json.hpp>

#include "lib/foxglove/json_text.hpp"

namespace beft::foxglove {

std::string serverInfo(const std::string& name, const std::vector<std::string>& capabilities,
                       const std::string& session_id, const std::map<std::string, std::string>& metadata) {
  nlohmann::json message = {{"op", "serverInfo"},
                            {"name", name},
                            {"capabilities", capabilities},
                            {"supportedEncodings", {"json"}}};
  if (!metadata.empty()) message["metadata"] = metadata;
  if (!session_id.empty()) message["sessionId"] = session_id;
  return dumpJson(message);
}

std::string advertise(const std::vector<ServerChannel>& channels) {
  nlohmann::json list = nlohmann::json::array();
  for (const ServerChannel& channel : channels) {
    nlohmann::json entry = {{"id", channel.id},
                            {"topic", channel.topic},
                            {"encoding", channel.encoding},
                            {"schemaName", channel.schema_name},
                            {"schema", channel.schema}};
    if (!channel.schema_encoding.empty()) entry["schemaEncoding"] = channel.schema_encoding;
    list.push_back(std::move(entry));
  }
  return dumpJson({{"op", "advertise"}, {"channels", list}});
}

std::string unadvertise(const std::vector<uint32_t>& channel_ids) {
  return dumpJson({{"op", "unadvertise"}, {"channelIds", channel_ids}});
}

std::string status(int level, const std::string& message, const std::optional<std::string>& id) {
  const int sent_level = level == kStatusInfo || level == kStatusWarning ? level : kStatusError;
  nlohmann::json json = {{"op", "status"}, {"level", sent_level}, {"message", message}};
  if (id) json["id"] = *id;
  return dumpJson(json);
}

std::string removeStatus(const std::vector<std::string>& status_ids) {
  return dumpJson({{"op", "removeStatus"}, {"statusIds", status_ids}});
}

namespace {

void appendLittleEndian(std::string& out, uint64_t value, int bytes) {
  for (int i = 0; i < bytes; ++i) out += static_cast<char>((value >> (8 * i)) & 0xff);
}

}  // namespace

std::string messageDataFrame(uint32_t subscription_id, uint64_t receive_time_ns, std::string_view payload) {
  std::string frame;
  frame.reserve(1 + 4 + 8 + payload.size());
  frame += static_cast<char>(kServerOpMessageData);
  appendLittleEndian(frame, subscription_id, 4);
  appendLittleEndian(frame, receive_time_ns, 8);
  frame.append(payload);
  return frame;
}

std::string timeFrame(uint64_t time_ns) {
  std::string frame(1, static_cast<char>(kServerOpTime));
  appendLittleEndian(frame, time_ns, 8);
  return frame;
}

}  // namespace beft::foxglove
