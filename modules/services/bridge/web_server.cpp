#include "services/bridge/web_server.hpp"

#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>

#include <map>
#include <stdexcept>
#include <utility>

#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>

#include "services/bridge/static_files.hpp"

namespace beft::bridge {

namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
namespace net = boost::asio;
using tcp = net::ip::tcp;

class WsSession;

struct WebServer::State {
  State(net::io_context& io, const WebServerOptions& o, SessionHandler& h) : io(io), acceptor(io), options(o), handler(h) {}
  net::io_context& io;
  tcp::acceptor acceptor;
  WebServerOptions options;
  SessionHandler& handler;
  std::map<uint32_t, std::weak_ptr<WsSession>> sessions;
  uint32_t next_id = 1;
  bool stopped = false;
};

namespace {

std::string queryValue(beast::string_view target, const std::string& name) {
  const std::size_t query = target.find('?');
  if (query == beast::string_view::npos) return "";
  std::size_t start = query + 1;
  while (start < target.size()) {
    std::size_t end = target.find('&', start);
    if (end == beast::string_view::npos) end = target.size();
    const beast::string_view pair = target.substr(start, end - start);
    if (pair.substr(0, name.size() + 1) == name + "=") return std::string(pair.substr(name.size() + 1));
    start = end + 1;
  }
  return "";
}

bool offersSubprotocol(beast::string_view offered, beast::string_view wanted) {
  std::size_t start = 0;
  while (start <= offered.size()) {
    std::size_t end = offered.find(',', start);
    if (end == beast::string_view::npos) end = offered.size();
    beast::string_view item = offered.substr(start, end - start);
    while (!item.empty() && item.front() == ' ') item.remove_prefix(1);
    while (!item.empty() && item.back() == ' ') item.remove_suffix(1);
    if (item == wanted) return true;
    start = end + 1;
  }
  return false;
}

// The subprotocol to answer with: foxglove.websocket.v1 when offered, else
// foxglove.sdk.v1 (what newer Foxglove clients offer: the same messages);
// "" when the client offers neither (it is served all the same).
std::string chosenSubprotocol(beast::string_view offered) {
  for (const char* known : {kSubprotocol, kSubprotocolSdk})
    if (offersSubprotocol(offered, known)) return known;
  return "";
}

}  // namespace

// One WebSocket client: reads frames to the handler, writes what the handler gives.
class WsSession : public std::enable_shared_from_this<WsSession> {
 public:
  WsSession(tcp::socket&& socket, std::shared_ptr<WebServer::State> state, ClientInfo info)
      : ws_(std::move(socket)), state_(std::move(state)), info_(std::move(info)) {}

  void start(http::request<http::string_body> request) {
    const std::string subprotocol = chosenSubprotocol(request[http::field::sec_websocket_protocol]);
    ws_.set_option(websocket::stream_base::timeout::suggested(beast::role_type::server));
    ws_.set_option(websocket::stream_base::decorator([subprotocol](websocket::response_type& response) {
      response.set(http::field::server, "beft-bridge");
      if (!subprotocol.empty()) response.set(http::field::sec_websocket_protocol, subprotocol);
    }));
    ws_.read_message_max(state_->options.max_frame_bytes);
    // A message is one frame, written at once, rather than fragments of 4 KiB written one by one.
    ws_.auto_fragment(false);
    ws_.async_accept(request, [self = shared_from_this()](beast::error_code error) { self->onAccepted(error); });
  }

  // Writes what the handler has queued, frame after frame, corked: the
  // frames of one burst leave in as few segments as they fill, and the
  // client is woken once for them rather than once a frame.
  void wake() {
    if (writing_ || !open_) return;
    if (!state_->handler.nextFrame(info_.id, frame_)) return setCorked(false);
    setCorked(true);
    writing_ = true;
    ws_.text(frame_.text);
    ws_.async_write(net::buffer(frame_.bytes), [self = shared_from_this()](beast::error_code error, std::size_t) {
      self->writing_ = false;
      if (error) return self->finish();
      self->wake();
    });
  }

  void close(const std::string& reason) {
    if (!open_ || closing_) return;
    closing_ = true;
    setCorked(false);
    ws_.async_close(websocket::close_reason(websocket::close_code::normal, reason),
                    [self = shared_from_this()](beast::error_code) { self->finish(); });
  }

 private:
  void onAccepted(beast::error_code error) {
    if (error) {  // not a WebSocket after all: the connection just ends
      state_->sessions.erase(info_.id);
      return;
    }
    open_ = true;
    state_->handler.onOpen(info_);
    read();
    wake();
  }

  void read() {
    ws_.async_read(buffer_, [self = shared_from_this()](beast::error_code error, std::size_t) {
      if (error) return self->finish();
      std::string bytes = beast::buffers_to_string(self->buffer_.data());
      self->buffer_.consume(self->buffer_.size());
      if (self->ws_.got_text())
        self->state_->handler.onText(self->info_.id, bytes);
      else
        self->state_->handler.onBinary(self->info_.id, bytes);
      self->read();
    });
  }

  // TCP_CORK: held while a burst is written, let go when the queue is empty
  // (which sends what is held at once).
  void setCorked(bool corked) {
    if (corked == corked_) return;
    corked_ = corked;
    const int value = corked ? 1 : 0;
    ::setsockopt(beast::get_lowest_layer(ws_).socket().native_handle(), IPPROTO_TCP, TCP_CORK, &value,
                 sizeof(value));
  }

  websocket::stream<beast::tcp_stream> ws_;
  std::shared_ptr<WebServer::State> state_;
  ClientInfo info_;
  beast::flat_buffer buffer_;
  OutgoingFrame frame_;
  bool writing_ = false;
  bool open_ = false;
  bool closing_ = false;
  bool corked_ = false;

 public:
  // Once, whichever side ended it: the handler forgets the client.
  void finish() {
    if (!open_) return;
    open_ = false;
    state_->sessions.erase(info_.id);
    state_->handler.onClose(info_.id);
    beast::error_code ignored;
    beast::get_lowest_layer(ws_).socket().close(ignored);
  }
};

namespace {

// One HTTP connection: files until it asks for a WebSocket.
class HttpSession : public std::enable_shared_from_this<HttpSession> {
 public:
  HttpSession(tcp::socket&& socket, std::shared_ptr<WebServer::State> state)
      : stream_(std::move(socket)), state_(std::move(state)) {}

  void read() {
    parser_.emplace();
    parser_->header_limit(16 * 1024);
    parser_->body_limit(64 * 1024);
    stream_.expires_after(std::chrono::seconds(30));
    http::async_read(stream_, buffer_, *parser_, [self = shared_from_this()](beast::error_code error, std::size_t) {
      if (error) return self->shutdown();
      self->onRequest(self->parser_->release());
    });
  }

 private:
  void onRequest(http::request<http::string_body> request) {
    if (websocket::is_upgrade(request)) return upgrade(std::move(request));
    if (request.method() != http::verb::get && request.method() != http::verb::head)
      return reply(simple(request, http::status::method_not_allowed, "only GET and HEAD\n"));
    if (const auto* document = documentFor(request.target())) return reply(served(request, *document));
    const auto file = resolveStaticFile(state_->options.web_dir, request.target());
    if (!file) return reply(simple(request, http::status::not_found, "not found\n"));
    http::file_body::value_type body;
    beast::error_code error;
    body.open(file->c_str(), beast::file_mode::scan, error);
    if (error) return reply(simple(request, http::status::not_found, "not found\n"));
    const auto size = body.size();
    if (request.method() == http::verb::head) {
      http::response<http::empty_body> head{http::status::ok, request.version()};
      head.set(http::field::content_type, contentTypeOf(*file));
      head.content_length(size);
      head.keep_alive(request.keep_alive());
      return reply(std::move(head));
    }
    http::response<http::file_body> response{std::piecewise_construct, std::make_tuple(std::move(body)),
                                             std::make_tuple(http::status::ok, request.version())};
    response.set(http::field::content_type, contentTypeOf(*file));
    response.set(http::field::cache_control, "no-cache");
    response.content_length(size);
    response.keep_alive(request.keep_alive());
    reply(std::move(response));
  }

  const ServedDocument* documentFor(std::string_view target) const {
    const auto path = target.substr(0, target.find('?'));
    const auto found = state_->options.documents.find(std::string(path));
    return found == state_->options.documents.end() ? nullptr : &found->second;
  }

  static http::response<http::string_body> served(const http::request<http::string_body>& request,
                                                  const ServedDocument& document) {
    http::response<http::string_body> response{http::status::ok, request.version()};
    response.set(http::field::content_type, document.content_type);
    response.set(http::field::cache_control, "no-cache");
    if (request.method() != http::verb::head) response.body() = document.body;
    response.content_length(document.body.size());
    response.keep_alive(request.keep_alive());
    return response;
  }

  static http::response<http::string_body> simple(const http::request<http::string_body>& request,
                                                  http::status status, const std::string& text) {
    http::response<http::string_body> response{status, request.version()};
    response.set(http::field::content_type, "text/plain; charset=utf-8");
    response.keep_alive(request.keep_alive());
    response.body() = text;
    response.prepare_payload();
    return response;
  }

  template <typename Response>
  void reply(Response&& response) {
    auto held = std::make_shared<std::decay_t<Response>>(std::forward<Response>(response));
    http::async_write(stream_, *held, [self = shared_from_this(), held](beast::error_code error, std::size_t) {
      if (error || !held->keep_alive()) return self->shutdown();
      self->read();
    });
  }

  void upgrade(http::request<http::string_body> request) {
    if (state_->sessions.size() >= state_->options.max_clients)
      return reply(simple(request, http::status::service_unavailable,
                          "too many clients (" + std::to_string(state_->options.max_clients) + ")\n"));
    ClientInfo info;
    info.id = state_->next_id++;
    beast::error_code error;
    const tcp::endpoint peer = stream_.socket().remote_endpoint(error);
    info.peer = error ? "?" : peer.address().to_string() + ":" + std::to_string(peer.port());
    info.loopback = !error && peer.address().is_loopback();
    info.token_ok = !state_->options.token.empty() && queryValue(request.target(), "token") == state_->options.token;
    stream_.expires_never();
    auto session = std::make_shared<WsSession>(stream_.release_socket(), state_, info);
    state_->sessions[info.id] = session;
    session->start(std::move(request));
  }

  void shutdown() {
    beast::error_code ignored;
    stream_.socket().shutdown(tcp::socket::shutdown_send, ignored);
  }

  beast::tcp_stream stream_;
  std::shared_ptr<WebServer::State> state_;
  beast::flat_buffer buffer_;
  std::optional<http::request_parser<http::string_body>> parser_;
};

void acceptNext(const std::shared_ptr<WebServer::State>& state) {
  state->acceptor.async_accept([state](beast::error_code error, tcp::socket socket) {
    if (state->stopped) return;
    if (!error) std::make_shared<HttpSession>(std::move(socket), state)->read();
    acceptNext(state);
  });
}

}  // namespace

WebServer::WebServer(net::io_context& io, const WebServerOptions& options, SessionHandler& handler)
    : state_(std::make_shared<State>(io, options, handler)) {
  beast::error_code error;
  const auto address = net::ip::make_address(options.bind_address, error);
  if (error) throw std::runtime_error("--bind " + options.bind_address + ": not an IP address");
  const tcp::endpoint endpoint(address, static_cast<unsigned short>(options.port));
  auto& acceptor = state_->acceptor;
  acceptor.open(endpoint.protocol(), error);
  if (!error) acceptor.set_option(net::socket_base::reuse_address(true), error);
  if (!error) acceptor.bind(endpoint, error);
  if (!error) acceptor.listen(net::socket_base::max_listen_connections, error);
  if (error)
    throw std::runtime_error("cannot listen on " + options.bind_address + ":" + std::to_string(options.port) + ": " +
                             error.message());
  acceptNext(state_);
}

WebServer::~WebServer() {
  state_->stopped = true;
  beast::error_code ignored;
  state_->acceptor.close(ignored);
  for (auto& [id, weak] : state_->sessions)
    if (auto session = weak.lock()) session->close("the bridge stops");
}

int WebServer::port() const {
  beast::error_code error;
  return state_->acceptor.local_endpoint(error).port();
}

void WebServer::wake(uint32_t client) {
  const auto found = state_->sessions.find(client);
  if (found == state_->sessions.end()) return;
  if (auto session = found->second.lock()) session->wake();
}

void WebServer::close(uint32_t client, const std::string& reason) {
  const auto found = state_->sessions.find(client);
  if (found == state_->sessions.end()) return;
  if (auto session = found->second.lock()) session->close(reason);
}

void WebServer::drop(uint32_t client) {
  const auto found = state_->sessions.find(client);
  if (found == state_->sessions.end()) return;
  if (auto session = found->second.lock()) net::post(state_->io, [session] { session->finish(); });
}

std::size_t WebServer::clients() const { return state_->sessions.size(); }

}  // namespace beft::bridge
