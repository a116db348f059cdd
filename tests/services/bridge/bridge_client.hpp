// For the bridge's tests: beft-bridge started as a program, a minimal
// WebSocket client (Boost.Beast, synchronous) speaking foxglove.websocket.v1,
// and a plain HTTP GET.
#pragma once

#include <sys/types.h>

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace beft::bridge_test {

// beft-bridge in the background on a free port of 127.0.0.1 (unless `args`
// say --port), stopped (SIGTERM, then SIGKILL) when this goes.
class BridgeProgram {
 public:
  BridgeProgram(std::vector<std::string> args, const std::map<std::string, std::string>& env = {});
  ~BridgeProgram();
  int port() const { return port_; }
  pid_t pid() const { return pid_; }
  // Waits until it listens; false if it exited first or did not within `timeout_s`.
  bool listening(double timeout_s = 30);
  long residentKilobytes() const;  // VmRSS of the program, -1 if unknown
  int stop();                      // SIGTERM; its exit code
  std::string output() const;      // what it printed

 private:
  int port_ = 0;
  pid_t pid_ = -1;
  std::string output_file_;
};

struct Frame {
  bool text = false;
  std::string bytes;
};

// A Message Data frame: opcode 1, subscription id, time, payload.
struct MessageData {
  uint32_t subscription = 0;
  uint64_t time_ns = 0;
  std::string payload;
};
bool parseMessageData(const Frame& frame, MessageData& data);

class WsClient {
 public:
  // Connects and shakes hands (offering `subprotocols`, by default
  // foxglove.websocket.v1), from `local_address` when given. Throws on failure.
  WsClient(const std::string& address, int port, const std::string& target = "/",
           const std::string& local_address = "", int receive_buffer_bytes = 0,
           const std::string& subprotocols = "foxglove.websocket.v1");
  ~WsClient();
  const std::string& subprotocol() const { return subprotocol_; }

  Frame read();
  // Frames until a text frame whose "op" is `op` (the others in `skipped`).
  nlohmann::json readOp(const std::string& op, std::vector<Frame>* skipped = nullptr);
  // Frames until a Message Data frame of `subscription`.
  MessageData readData(uint32_t subscription);
  void sendText(const std::string& text);
  void sendJson(const nlohmann::json& json) { sendText(json.dump()); }
  void sendBinary(const std::string& bytes);
  // Advertises a client channel (id) on a control topic and publishes JSON on it.
  void advertise(uint32_t id, const std::string& topic);
  void publish(uint32_t id, const nlohmann::json& body);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::string subprotocol_;
};

// GET `target` (sent as it is, "../" and all); the status, content type and body.
struct HttpReply {
  int status = 0;
  std::string content_type, body;
};
HttpReply httpGet(int port, const std::string& target);

// An IPv4 address of this host that is not a loopback one, "" if none.
std::string nonLoopbackAddress();

}  // namespace beft::bridge_test
