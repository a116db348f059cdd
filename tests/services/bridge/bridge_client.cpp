#include "tests/services/bridge/bridge_client.hpp"

#include <arpa/inet.h>
#include <fcntl.h>
#include <ifaddrs.h>
#include <netinet/in.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>

#include <boost/asio/connect.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>

#include "lib/launch/tcp_port.hpp"

namespace beft::bridge_test {

namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
namespace net = boost::asio;
using tcp = net::ip::tcp;

BridgeProgram::BridgeProgram(std::vector<std::string> args, const std::map<std::string, std::string>& env) {
  bool has_port = false;
  for (std::size_t i = 0; i + 1 < args.size(); ++i)
    if (args[i] == "--port") {
      has_port = true;
      port_ = std::stoi(args[i + 1]);
    }
  if (!has_port) {
    port_ = launch::findFreeTcpPort();
    args.insert(args.end(), {"--port", std::to_string(port_)});
  }
  output_file_ = (std::filesystem::temp_directory_path() /
                  ("beft_bridge_test_" + std::to_string(getpid()) + "_" + std::to_string(port_) + ".log"))
                     .string();
  pid_ = fork();
  if (pid_ == 0) {
    const int fd = open(output_file_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    dup2(fd, STDOUT_FILENO);
    dup2(fd, STDERR_FILENO);
    for (const auto& [name, value] : env) setenv(name.c_str(), value.c_str(), 1);
    std::vector<std::string> argv = {std::string(BEFT_BIN_DIR) + "/beft-bridge"};
    argv.insert(argv.end(), args.begin(), args.end());
    std::vector<char*> raw;
    for (auto& a : argv) raw.push_back(a.data());
    raw.push_back(nullptr);
    execv(raw[0], raw.data());
    _exit(127);
  }
}

BridgeProgram::~BridgeProgram() {
  stop();
  std::remove(output_file_.c_str());
}

bool BridgeProgram::listening(double timeout_s) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  while (std::chrono::steady_clock::now() < deadline) {
    int status = 0;
    if (pid_ <= 0 || waitpid(pid_, &status, WNOHANG) == pid_) {
      pid_ = -1;
      return false;
    }
    if (launch::waitForTcpListener("127.0.0.1", port_, 0.2)) return true;
  }
  return false;
}

long BridgeProgram::residentKilobytes() const {
  std::ifstream status("/proc/" + std::to_string(pid_) + "/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("VmRSS:", 0) == 0) return std::stol(line.substr(6));
  return -1;
}

int BridgeProgram::stop() {
  if (pid_ <= 0) return -1;
  kill(pid_, SIGTERM);
  int status = 0;
  for (int i = 0; i < 100; ++i) {
    if (waitpid(pid_, &status, WNOHANG) == pid_) {
      pid_ = -1;
      return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  kill(pid_, SIGKILL);
  waitpid(pid_, &status, 0);
  pid_ = -1;
  return 128 + SIGKILL;
}

std::string BridgeProgram::output() const {
  std::ifstream in(output_file_);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

bool parseMessageData(const Frame& frame, MessageData& data) {
  if (frame.text || frame.bytes.size() < 13 || frame.bytes[0] != 1) return false;
  const auto* b = reinterpret_cast<const uint8_t*>(frame.bytes.data());
  data.subscription = b[1] | (b[2] << 8) | (b[3] << 16) | (uint32_t(b[4]) << 24);
  data.time_ns = 0;
  for (int i = 0; i < 8; ++i) data.time_ns |= uint64_t(b[5 + i]) << (8 * i);
  data.payload = frame.bytes.substr(13);
  return true;
}

struct WsClient::Impl {
  net::io_context io;
  websocket::stream<tcp::socket> ws{io};
};

WsClient::WsClient(const std::string& address, int port, const std::string& target, const std::string& local_address,
                   int receive_buffer_bytes, const std::string& subprotocols)
    : impl_(std::make_unique<Impl>()) {
  auto& socket = impl_->ws.next_layer();
  socket.open(tcp::v4());
  if (receive_buffer_bytes > 0) socket.set_option(net::socket_base::receive_buffer_size(receive_buffer_bytes));
  if (!local_address.empty()) socket.bind(tcp::endpoint(net::ip::make_address(local_address), 0));
  socket.connect(tcp::endpoint(net::ip::make_address(address), static_cast<unsigned short>(port)));
  impl_->ws.set_option(websocket::stream_base::decorator(
      [subprotocols](websocket::request_type& request) { request.set(http::field::sec_websocket_protocol, subprotocols); }));
  websocket::response_type response;
  impl_->ws.handshake(response, address + ":" + std::to_string(port), target);
  subprotocol_ = std::string(response[http::field::sec_websocket_protocol]);
  impl_->ws.read_message_max(std::size_t{256} << 20);
}

WsClient::~WsClient() {
  beast::error_code ignored;
  impl_->ws.next_layer().close(ignored);
}

Frame WsClient::read() {
  beast::flat_buffer buffer;
  impl_->ws.read(buffer);
  return {impl_->ws.got_text(), beast::buffers_to_string(buffer.data())};
}

nlohmann::json WsClient::readOp(const std::string& op, std::vector<Frame>* skipped) {
  while (true) {
    Frame frame = read();
    if (frame.text) {
      auto json = nlohmann::json::parse(frame.bytes);
      if (json.value("op", "") == op) return json;
    }
    if (skipped) skipped->push_back(std::move(frame));
  }
}

MessageData WsClient::readData(uint32_t subscription) {
  while (true) {
    MessageData data;
    if (parseMessageData(read(), data) && data.subscription == subscription) return data;
  }
}

void WsClient::sendText(const std::string& text) {
  impl_->ws.text(true);
  impl_->ws.write(net::buffer(text));
}

void WsClient::sendBinary(const std::string& bytes) {
  impl_->ws.binary(true);
  impl_->ws.write(net::buffer(bytes));
}

void WsClient::advertise(uint32_t id, const std::string& topic) {
  sendJson(nlohmann::json{{"op", "advertise"},
                          {"channels", {{{"id", id}, {"topic", topic}, {"encoding", "json"}, {"schemaName", topic}}}}});
}

void WsClient::publish(uint32_t id, const nlohmann::json& body) {
  std::string frame(5, '\0');
  frame[0] = 1;
  for (int i = 0; i < 4; ++i) frame[1 + i] = static_cast<char>((id >> (8 * i)) & 0xff);
  sendBinary(frame + body.dump());
}

HttpReply httpGet(int port, const std::string& target) {
  net::io_context io;
  beast::tcp_stream stream(io);
  stream.connect(tcp::endpoint(net::ip::make_address("127.0.0.1"), static_cast<unsigned short>(port)));
  http::request<http::empty_body> request{http::verb::get, target, 11};
  request.set(http::field::host, "127.0.0.1");
  http::write(stream, request);
  beast::flat_buffer buffer;
  http::response<http::string_body> response;
  http::read(stream, buffer, response);
  return {static_cast<int>(response.result_int()), std::string(response[http::field::content_type]), response.body()};
}

std::string nonLoopbackAddress() {
  ifaddrs* list = nullptr;
  if (getifaddrs(&list) != 0) return "";
  std::string found;
  for (ifaddrs* a = list; a && found.empty(); a = a->ifa_next) {
    if (!a->ifa_addr || a->ifa_addr->sa_family != AF_INET) continue;
    const auto* in = reinterpret_cast<const sockaddr_in*>(a->ifa_addr);
    char text[INET_ADDRSTRLEN] = {0};
    inet_ntop(AF_INET, &in->sin_addr, text, sizeof text);
    if (std::string(text).rfind("127.", 0) != 0) found = text;
  }
  freeifaddrs(list);
  return found;
}

}  // namespace beft::bridge_test
