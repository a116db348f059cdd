#include "lib/launch/tcp_port.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <thread>

namespace beft::launch {

namespace {

bool addressOf(const std::string& address, int port, sockaddr_in& out) {
  out = {};
  out.sin_family = AF_INET;
  out.sin_port = htons(static_cast<uint16_t>(port));
  return inet_pton(AF_INET, address.c_str(), &out.sin_addr) == 1;
}

// A bound TCP socket on address:port, or -1.
int boundSocket(const std::string& address, int port) {
  sockaddr_in where{};
  if (!addressOf(address, port, where)) return -1;
  const int fd = socket(AF_INET, SOCK_STREAM, 0);
  if (fd < 0) return -1;
  const int yes = 1;
  setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);  // as the server binds: TIME_WAIT does not count
  if (bind(fd, reinterpret_cast<const sockaddr*>(&where), sizeof where) != 0) {
    close(fd);
    return -1;
  }
  return fd;
}

}  // namespace

bool tcpPortFree(int port, const std::string& address) {
  const int fd = boundSocket(address, port);
  if (fd < 0) return false;
  close(fd);
  return true;
}

int findFreeTcpPort(const std::string& address) {
  const int fd = boundSocket(address, 0);
  if (fd < 0) return -1;
  sockaddr_in bound{};
  socklen_t length = sizeof bound;
  const int port = getsockname(fd, reinterpret_cast<sockaddr*>(&bound), &length) == 0 ? ntohs(bound.sin_port) : -1;
  close(fd);
  return port;
}

bool waitForTcpListener(const std::string& address, int port, double timeout_s) {
  sockaddr_in where{};
  if (!addressOf(address, port, where)) return false;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  while (true) {
    const int fd = socket(AF_INET, SOCK_STREAM, 0);
    if (fd < 0) return false;
    const bool connected = connect(fd, reinterpret_cast<const sockaddr*>(&where), sizeof where) == 0;
    close(fd);
    if (connected) return true;
    if (std::chrono::steady_clock::now() >= deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
}

}  // namespace beft::launch
