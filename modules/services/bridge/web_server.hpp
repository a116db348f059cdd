// The bridge's one port: plain HTTP for the web page's files, and WebSocket
// upgrades (subprotocol foxglove.websocket.v1 or foxglove.sdk.v1) handed to a
// SessionHandler.
// Everything runs on one io_context thread: no locks, and a slow client only
// ever waits on its own socket. What is sent is pulled from the handler when
// the socket has taken the previous frame, so what waits for a client that
// does not read stays in the handler's bounded queue.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <string>

#include <boost/asio/io_context.hpp>

namespace beft::bridge {

inline constexpr const char* kSubprotocol = "foxglove.websocket.v1";
inline constexpr const char* kSubprotocolSdk = "foxglove.sdk.v1";

struct OutgoingFrame {
  bool text = true;
  std::string bytes;
};

// One WebSocket client as the server knows it.
struct ClientInfo {
  uint32_t id = 0;
  std::string peer;        // "127.0.0.1:51234"
  bool loopback = false;   // the peer is this host
  bool token_ok = false;   // presented the server's token (?token=... in the WebSocket URL)
};

class SessionHandler {
 public:
  virtual ~SessionHandler() = default;
  virtual void onOpen(const ClientInfo& client) = 0;
  virtual void onText(uint32_t client, const std::string& text) = 0;
  virtual void onBinary(uint32_t client, const std::string& bytes) = 0;
  // The next frame to send to the client, if any.
  virtual bool nextFrame(uint32_t client, OutgoingFrame& frame) = 0;
  virtual void onClose(uint32_t client) = 0;
};

// What a SessionHandler asks of the server that holds its clients' sockets.
class ClientSockets {
 public:
  virtual ~ClientSockets() = default;
  // Frames are waiting for `client`: start sending if its socket is idle.
  virtual void wake(uint32_t client) = 0;
  // Ends a client's connection at once, without a close handshake (one that
  // does not read cannot take one); the handler hears onClose afterwards,
  // never from within this call.
  virtual void drop(uint32_t client) = 0;
};

// A document the server makes itself rather than reads from web_dir.
struct ServedDocument {
  std::string content_type;
  std::string body;
};

struct WebServerOptions {
  std::string bind_address = "127.0.0.1";
  int port = 8765;                      // 0: any free port
  std::filesystem::path web_dir;        // the page's files
  std::map<std::string, ServedDocument> documents;  // by request path ("/net.svg"), before web_dir
  std::string token;                    // "" : none; controls from other hosts are then refused
  std::size_t max_clients = 32;         // WebSocket clients at once; more are refused (503)
  std::size_t max_frame_bytes = 1 << 20;  // a bigger frame from a client closes its connection
};

class WebServer : public ClientSockets {
 public:
  // Binds and listens at once; throws std::runtime_error (with the address) when it cannot.
  WebServer(boost::asio::io_context& io, const WebServerOptions& options, SessionHandler& handler);
  ~WebServer() override;
  WebServer(const WebServer&) = delete;
  WebServer& operator=(const WebServer&) = delete;

  int port() const;  // the port bound (options.port, or the one chosen for 0)
  void wake(uint32_t client) override;
  // Closes a client's connection (a normal close, with the reason).
  void close(uint32_t client, const std::string& reason);
  void drop(uint32_t client) override;
  std::size_t clients() const;

  struct State;

 private:
  std::shared_ptr<State> state_;
};

}  // namespace beft::bridge
