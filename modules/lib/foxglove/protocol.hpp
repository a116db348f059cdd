// The server side of the Foxglove WebSocket protocol v1 (foxglove/ws-protocol,
// docs/spec.md) without the socket: the JSON text of the server's messages,
// its binary frames, and what a client sends, checked. Client bytes are
// untrusted: the parsers never throw and never read out of bounds; whatever
// is not a well-formed, supported message within the limits below comes back
// as Invalid with a reason a person can read (the bridge may send it back in
// a status message).
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace beft::foxglove {

// WebSocket subprotocols a server may select (Sec-WebSocket-Protocol).
inline constexpr const char* kSubprotocolV1 = "foxglove.websocket.v1";
inline constexpr const char* kSubprotocolSdkV1 = "foxglove.sdk.v1";

// Opcodes: the first byte of a binary message.
inline constexpr uint8_t kServerOpMessageData = 1;  // server -> client: a message of a subscription
inline constexpr uint8_t kServerOpTime = 2;         // server -> client: the server's clock
inline constexpr uint8_t kClientOpMessagePublish = 1;  // client -> server: a message on a client channel

// Server capabilities (serverInfo) this project uses.
inline constexpr const char* kCapabilityClientPublish = "clientPublish";
inline constexpr const char* kCapabilityTime = "time";

// Status levels.
inline constexpr int kStatusInfo = 0;
inline constexpr int kStatusWarning = 1;
inline constexpr int kStatusError = 2;

// Limits on what a client sends.
inline constexpr std::size_t kMaxClientTextBytes = std::size_t{1} << 20;    // one text message
inline constexpr std::size_t kMaxClientBinaryBytes = std::size_t{1} << 20;  // one binary message
inline constexpr std::size_t kMaxClientListEntries = 1000;  // subscriptions, ids or channels of one message
inline constexpr std::size_t kMaxTopicChars = 256;          // a client channel's topic (bytes of UTF-8)
inline constexpr std::size_t kMaxNameChars = 256;           // its encoding and schema name

// A channel the server advertises.
struct ServerChannel {
  uint32_t id = 0;
  std::string topic;
  std::string encoding;         // "json"
  std::string schema_name;      // "beft.robot_state_t", "foxglove.SceneUpdate"
  std::string schema;           // the schema's text (a JSON Schema for "jsonschema")
  std::string schema_encoding;  // "jsonschema"; left out of the message when empty
};

// --- server messages: JSON text ---

// serverInfo; supportedEncodings is ["json"]; metadata and sessionId are left
// out when empty.
std::string serverInfo(const std::string& name, const std::vector<std::string>& capabilities,
                       const std::string& session_id, const std::map<std::string, std::string>& metadata = {});
std::string advertise(const std::vector<ServerChannel>& channels);
std::string unadvertise(const std::vector<uint32_t>& channel_ids);
// level kStatusInfo, kStatusWarning or kStatusError (others are sent as
// error); id lets a later removeStatus take it back.
std::string status(int level, const std::string& message, const std::optional<std::string>& id = std::nullopt);
std::string removeStatus(const std::vector<std::string>& status_ids);

// --- server messages: binary frames, little-endian ---

// opcode 1, uint32 subscription id, uint64 receive time [ns], the payload.
std::string messageDataFrame(uint32_t subscription_id, uint64_t receive_time_ns, std::string_view payload);
// opcode 2, uint64 time [ns].
std::string timeFrame(uint64_t time_ns);

// --- client messages ---

// At most this long a subscription may ask its messages to be held [ms].
constexpr uint32_t kMaxThrottleMs = 10000;

struct SubscriptionRequest {
  uint32_t id = 0;          // chosen by the client
  uint32_t channel_id = 0;  // a channel the server advertised
  // BEFT's extension, after rosbridge's throttle_rate: the shortest time
  // between two messages sent on this subscription [ms], the newest held
  // meanwhile and sent when the time is up; 0 (or absent, as from any other
  // Foxglove client): every message. Meant for channels whose message holds
  // the whole state (a viewer drawing at 10 Hz needs no more).
  uint32_t throttle_ms = 0;
};
struct Subscribe {
  std::vector<SubscriptionRequest> subscriptions;
};
struct Unsubscribe {
  std::vector<uint32_t> subscription_ids;
};
struct ClientChannel {
  uint32_t id = 0;  // chosen by the client
  std::string topic;
  std::string encoding;
  std::string schema_name;
  std::optional<std::string> schema;
  std::optional<std::string> schema_encoding;
};
struct ClientAdvertise {
  std::vector<ClientChannel> channels;
};
struct ClientUnadvertise {
  std::vector<uint32_t> channel_ids;
};
struct ClientPublish {
  uint32_t channel_id = 0;  // a channel the client advertised
  std::string payload;      // the message, in that channel's encoding
};
struct Invalid {
  std::string reason;
};

using ClientMessage =
    std::variant<Subscribe, Unsubscribe, ClientAdvertise, ClientUnadvertise, ClientPublish, Invalid>;

// A text message: a JSON object whose "op" is subscribe, unsubscribe,
// advertise or unadvertise. Checked: at most kMaxClientTextBytes; every
// field the spec requires present with its JSON type; ids integers in
// 0..2^32-1; at most kMaxClientListEntries entries per list; an id not
// repeated within one list; topics of 1..kMaxTopicChars bytes, encoding and
// schemaName of at most kMaxNameChars. Other ops of the protocol
// (parameters, services, ...) are Invalid as unsupported. Never throws.
ClientMessage parseClientText(std::string_view text);

// A binary message: opcode kClientOpMessagePublish, uint32 channel id
// (little-endian), the payload; at most kMaxClientBinaryBytes. Never throws.
ClientMessage parseClientBinary(std::string_view bytes);

}  // namespace beft::foxglove
