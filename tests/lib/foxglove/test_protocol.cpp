// The server's messages of the Foxglove WebSocket protocol and the checking
// of what clients send: every reason a client message is refused.
#include <gtest/gtest.h>

#include <string>

#include <nlohmann/json.hpp>

#include "lib/foxglove/protocol.hpp"

using namespace beft::foxglove;
using nlohmann::json;

namespace {

// The reason of an Invalid, or "" when the message was accepted.
std::string reasonOf(const ClientMessage& message) {
  if (const auto* invalid = std::get_if<Invalid>(&message)) return invalid->reason;
  return "";
}

std::string refusal(const std::string& text) { return reasonOf(parseClientText(text)); }

void expectRefused(const std::string& text, const std::string& part) {
  const std::string reason = refusal(text);
  EXPECT_NE(reason.find(part), std::string::npos) << "text: " << text << "\nreason: " << reason;
}

std::string bytes(std::initializer_list<int> values) {
  std::string out;
  for (int value : values) out += static_cast<char>(value);
  return out;
}

}  // namespace

TEST(FoxgloveServerMessages, ServerInfoNamesCapabilitiesEncodingsAndSession) {
  const json info =
      json::parse(serverInfo("beft", {kCapabilityClientPublish, kCapabilityTime}, "run-7", {{"run", "yard"}}));
  EXPECT_EQ(info.at("op"), "serverInfo");
  EXPECT_EQ(info.at("name"), "beft");
  EXPECT_EQ(info.at("capabilities"), json({"clientPublish", "time"}));
  EXPECT_EQ(info.at("supportedEncodings"), json({"json"}));
  EXPECT_EQ(info.at("sessionId"), "run-7");
  EXPECT_EQ(info.at("metadata").at("run"), "yard");
  EXPECT_FALSE(json::parse(serverInfo("beft", {}, "")).contains("sessionId"));
  EXPECT_STREQ(kSubprotocolV1, "foxglove.websocket.v1");
  EXPECT_STREQ(kSubprotocolSdkV1, "foxglove.sdk.v1");
}

TEST(FoxgloveServerMessages, AdvertiseUnadvertiseStatus) {
  ServerChannel channel{3, "ROBOT_STATE", "json", "beft.robot_state_t", "{\"type\":\"object\"}", "jsonschema"};
  ServerChannel bare{4, "X", "json", "x", "", ""};
  const json advertised = json::parse(advertise({channel, bare}));
  EXPECT_EQ(advertised.at("op"), "advertise");
  const json& first = advertised.at("channels").at(0);
  EXPECT_EQ(first.at("id"), 3);
  EXPECT_EQ(first.at("topic"), "ROBOT_STATE");
  EXPECT_EQ(first.at("encoding"), "json");
  EXPECT_EQ(first.at("schemaName"), "beft.robot_state_t");
  EXPECT_EQ(first.at("schema"), "{\"type\":\"object\"}");
  EXPECT_EQ(first.at("schemaEncoding"), "jsonschema");
  EXPECT_FALSE(advertised.at("channels").at(1).contains("schemaEncoding"));

  EXPECT_EQ(json::parse(unadvertise({1, 2})), json::parse(R"({"op":"unadvertise","channelIds":[1,2]})"));
  EXPECT_EQ(json::parse(status(kStatusWarning, "slow client", std::string("drops"))),
            json::parse(R"({"op":"status","level":1,"message":"slow client","id":"drops"})"));
  EXPECT_EQ(json::parse(status(7, "x")).at("level"), 2);
  EXPECT_FALSE(json::parse(status(kStatusInfo, "x")).contains("id"));
  EXPECT_EQ(json::parse(removeStatus({"drops"})), json::parse(R"({"op":"removeStatus","statusIds":["drops"]})"));
  // Invalid UTF-8 in a message is replaced, not thrown.
  EXPECT_NO_THROW(json::parse(status(kStatusError, "bad \xff")));
}

TEST(FoxgloveServerMessages, BinaryFramesAreLittleEndian) {
  EXPECT_EQ(messageDataFrame(0x04030201u, 0x0c0b0a0908070605ull, "xy"),
            bytes({1, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 'x', 'y'}));
  EXPECT_EQ(messageDataFrame(0, 0, ""), std::string(13, '\0').replace(0, 1, 1, '\x01'));
  EXPECT_EQ(timeFrame(0x0807060504030201ull), bytes({2, 1, 2, 3, 4, 5, 6, 7, 8}));
  EXPECT_EQ(kServerOpMessageData, 1);
  EXPECT_EQ(kServerOpTime, 2);
}

TEST(FoxgloveClientMessages, ValidMessagesOfEveryKind) {
  const ClientMessage subscribe = parseClientText(
      R"({"op":"subscribe","subscriptions":[{"id":0,"channelId":3},{"id":4294967295,"channelId":5}]})");
  ASSERT_TRUE(std::holds_alternative<Subscribe>(subscribe)) << reasonOf(subscribe);
  const auto& requests = std::get<Subscribe>(subscribe).subscriptions;
  ASSERT_EQ(requests.size(), 2u);
  EXPECT_EQ(requests[1].id, 4294967295u);
  EXPECT_EQ(requests[1].channel_id, 5u);
  EXPECT_EQ(requests[1].throttle_ms, 0u);  // every message, as any Foxglove client expects

  const ClientMessage throttled = parseClientText(
      R"({"op":"subscribe","subscriptions":[{"id":1,"channelId":3,"throttleMs":50},{"id":2,"channelId":4,"throttleMs":10000}]})");
  ASSERT_TRUE(std::holds_alternative<Subscribe>(throttled)) << reasonOf(throttled);
  EXPECT_EQ(std::get<Subscribe>(throttled).subscriptions[0].throttle_ms, 50u);
  EXPECT_EQ(std::get<Subscribe>(throttled).subscriptions[1].throttle_ms, 10000u);

  const ClientMessage unsubscribe = parseClientText(R"({"op":"unsubscribe","subscriptionIds":[0,1]})");
  ASSERT_TRUE(std::holds_alternative<Unsubscribe>(unsubscribe));
  EXPECT_EQ(std::get<Unsubscribe>(unsubscribe).subscription_ids, (std::vector<uint32_t>{0, 1}));

  const ClientMessage advertised = parseClientText(
      R"({"op":"advertise","channels":[)"
      R"({"id":2,"topic":"TASK_COMMAND","encoding":"json","schemaName":"beft.task_command_t"},)"
      R"({"id":3,"topic":"B","encoding":"json","schemaName":"s","schema":"{}","schemaEncoding":"jsonschema"}]})");
  ASSERT_TRUE(std::holds_alternative<ClientAdvertise>(advertised)) << reasonOf(advertised);
  const auto& channels = std::get<ClientAdvertise>(advertised).channels;
  ASSERT_EQ(channels.size(), 2u);
  EXPECT_EQ(channels[0].topic, "TASK_COMMAND");
  EXPECT_EQ(channels[0].schema_name, "beft.task_command_t");
  EXPECT_FALSE(channels[0].schema.has_value());
  EXPECT_EQ(channels[1].schema_encoding.value_or(""), "jsonschema");

  const ClientMessage unadvertised = parseClientText(R"({"op":"unadvertise","channelIds":[2]})");
  ASSERT_TRUE(std::holds_alternative<ClientUnadvertise>(unadvertised));
  EXPECT_EQ(std::get<ClientUnadvertise>(unadvertised).channel_ids, std::vector<uint32_t>{2});

  const ClientMessage published = parseClientBinary(bytes({1, 2, 1, 0, 0, '{', '}'}));
  ASSERT_TRUE(std::holds_alternative<ClientPublish>(published)) << reasonOf(published);
  EXPECT_EQ(std::get<ClientPublish>(published).channel_id, 258u);
  EXPECT_EQ(std::get<ClientPublish>(published).payload, "{}");
  EXPECT_TRUE(std::holds_alternative<ClientPublish>(parseClientBinary(bytes({1, 0, 0, 0, 0}))));
}

TEST(FoxgloveClientMessages, EveryTextRefusalSaysWhy) {
  EXPECT_NE(refusal(std::string(kMaxClientTextBytes + 1, ' ')).find("longer than the 1048576 allowed"),
            std::string::npos);
  expectRefused("{\"op\":", "not JSON: ");
  expectRefused("", "not JSON: ");
  expectRefused("[1,2]", "must be a JSON object, this is array");
  expectRefused("{}", "no \"op\" string");
  expectRefused("{\"op\":3}", "no \"op\" string");
  expectRefused(R"({"op":"getParameters","parameterNames":[]})", "op \"getParameters\" is not supported");
  expectRefused(R"({"op":"fetchAsset"})", "is not supported");
  expectRefused(R"({"op":"explode"})", "unknown op \"explode\"");
  expectRefused(R"({"op":"subscribe"})", "subscribe.subscriptions is missing");
  expectRefused(R"({"op":"subscribe","subscriptions":{}})", "subscribe.subscriptions is not an array");
  expectRefused(R"({"op":"subscribe","subscriptions":[1]})", "subscribe.subscriptions[0] is not an object");
  expectRefused(R"({"op":"subscribe","subscriptions":[{"channelId":1}]})", "subscribe.subscriptions[0].id is missing");
  expectRefused(R"({"op":"subscribe","subscriptions":[{"id":"1","channelId":1}]})", ".id is not an integer");
  expectRefused(R"({"op":"subscribe","subscriptions":[{"id":1.5,"channelId":1}]})", ".id is not an integer");
  expectRefused(R"({"op":"subscribe","subscriptions":[{"id":-1,"channelId":1}]})", ".id = -1 is outside 0..4294967295");
  expectRefused(R"({"op":"subscribe","subscriptions":[{"id":1,"channelId":4294967296}]})",
                ".channelId = 4294967296 is outside");
  expectRefused(R"({"op":"subscribe","subscriptions":[{"id":1,"channelId":1},{"id":1,"channelId":2}]})",
                "subscriptions[1].id = 1 repeats an earlier entry");
  expectRefused(R"({"op":"subscribe","subscriptions":[{"id":1,"channelId":1},{"id":2,"channelId":1}]})",
                "subscriptions[1].channelId = 1 repeats");
  expectRefused(R"({"op":"subscribe","subscriptions":[{"id":1,"channelId":1,"throttleMs":10001}]})",
                "subscriptions[0].throttleMs = 10001 is more than the 10000 allowed");
  expectRefused(R"({"op":"subscribe","subscriptions":[{"id":1,"channelId":1,"throttleMs":-5}]})",
                "subscriptions[0].throttleMs = -5 is outside");
  expectRefused(R"({"op":"subscribe","subscriptions":[{"id":1,"channelId":1,"throttleMs":"50"}]})",
                "subscriptions[0].throttleMs is not an integer");
  expectRefused(R"({"op":"unsubscribe","subscriptionIds":[1,true]})",
                "unsubscribe.subscriptionIds[1] is not an integer");
  expectRefused(R"({"op":"unadvertise","channelIds":[3,3]})", "unadvertise.channelIds[1] = 3 repeats");
  expectRefused(R"({"op":"unadvertise"})", "unadvertise.channelIds is missing");
}

TEST(FoxgloveClientMessages, AdvertiseRefusals) {
  const std::string head = R"({"op":"advertise","channels":[)";
  expectRefused(head + R"({"id":1,"encoding":"json","schemaName":"s"}]})", "advertise.channels[0].topic is missing");
  expectRefused(head + R"({"id":1,"topic":7,"encoding":"json","schemaName":"s"}]})", ".topic is not a string");
  expectRefused(head + R"({"id":1,"topic":"","encoding":"json","schemaName":"s"}]})", ".topic is empty");
  expectRefused(head + R"({"id":1,"topic":")" + std::string(kMaxTopicChars + 1, 't') +
                    R"(","encoding":"json","schemaName":"s"}]})",
                ".topic has 257 bytes, more than the 256 allowed");
  expectRefused(head + R"({"id":1,"topic":"T","schemaName":"s"}]})", ".encoding is missing");
  expectRefused(head + R"({"id":1,"topic":"T","encoding":"json"}]})", ".schemaName is missing");
  expectRefused(head + R"({"id":1,"topic":"T","encoding":"json","schemaName":"s","schema":5}]})",
                ".schema is not a string");
  expectRefused(head + R"({"id":1,"topic":"T","encoding":"json","schemaName":"s"},)" +
                    R"({"id":1,"topic":"U","encoding":"json","schemaName":"s"}]})",
                "advertise.channels[1].id = 1 repeats");
}

TEST(FoxgloveClientMessages, ListsLongerThanTheLimitAreRefused) {
  std::string ids;
  for (std::size_t i = 0; i <= kMaxClientListEntries; ++i) ids += (i ? "," : "") + std::to_string(i);
  expectRefused(R"({"op":"unsubscribe","subscriptionIds":[)" + ids + "]}",
                "unsubscribe.subscriptionIds has 1001 entries, more than the 1000 allowed");
  ids = ids.substr(0, ids.rfind(','));
  const std::string at_limit = R"({"op":"unsubscribe","subscriptionIds":[)" + ids + "]}";
  EXPECT_TRUE(std::holds_alternative<Unsubscribe>(parseClientText(at_limit)));
}

TEST(FoxgloveClientMessages, DeepNestingAndGarbageNeverThrow) {
  const std::string deep = std::string(200000, '[') + std::string(200000, ']');
  EXPECT_NE(refusal(deep), "");
  const std::string deep_op = R"({"op":"subscribe","subscriptions":)" + deep + "}";
  EXPECT_NE(refusal(deep_op), "");
  uint32_t state = 7;
  for (int round = 0; round < 3000; ++round) {
    std::string text = R"({"op":"advertise","channels":[{"id":1,"topic":"T","encoding":"json","schemaName":"s"}]})";
    for (int flips = 0; flips < 3; ++flips) {
      state = state * 1664525u + 1013904223u;
      text[state % text.size()] = static_cast<char>(state >> 24);
    }
    EXPECT_NO_THROW(parseClientText(text));
    EXPECT_NO_THROW(parseClientBinary(text));
  }
}

TEST(FoxgloveClientMessages, EveryBinaryRefusalSaysWhy) {
  EXPECT_EQ(reasonOf(parseClientBinary("")), "an empty binary message");
  EXPECT_NE(reasonOf(parseClientBinary(bytes({2, 0, 0, 0, 0}))).find("binary opcode 2 is not supported"),
            std::string::npos);
  EXPECT_NE(reasonOf(parseClientBinary(bytes({1, 0, 0, 0}))).find("of 4 bytes is shorter than its 5-byte header"),
            std::string::npos);
  std::string huge(kMaxClientBinaryBytes + 1, '\0');
  huge[0] = 1;
  EXPECT_NE(reasonOf(parseClientBinary(huge)).find("longer than the 1048576 allowed"), std::string::npos);
}
