#include "lib/launch/free_port.hpp"

#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

namespace beft::launch {

namespace {
// Binding without SO_REUSEADDR fails while any other socket holds the port.
bool udpPortIsFree(int port) {
  const int fd = socket(AF_INET, SOCK_DGRAM, 0);
  if (fd < 0) return false;
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_ANY);
  address.sin_port = htons(static_cast<uint16_t>(port));
  const bool free = bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof(address)) == 0;
  close(fd);
  return free;
}
}  // namespace

int findFreeUdpPort(int first, int last) {
  const int span = last - first + 1;
  const int offset = static_cast<int>(getpid() * 37) % span;
  for (int i = 0; i < span; ++i) {
    const int port = first + (offset + i) % span;
    if (udpPortIsFree(port)) return port;
  }
  return -1;
}

}  // namespace beft::launch
