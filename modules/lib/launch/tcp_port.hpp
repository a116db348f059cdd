// TCP ports of a viewer's server (beft-bridge): one that is free before a
// run starts it, and whether it listens yet, so the URL is printed when it
// can be opened.
#pragma once

#include <string>

namespace beft::launch {

// Whether nothing on this host listens on `port` at `address` (IPv4).
bool tcpPortFree(int port, const std::string& address = "127.0.0.1");

// A port the kernel picks as free now; -1 if none.
int findFreeTcpPort(const std::string& address = "127.0.0.1");

// Waits until a TCP connection to address:port succeeds, or `timeout_s` passes.
bool waitForTcpListener(const std::string& address, int port, double timeout_s);

}  // namespace beft::launch
