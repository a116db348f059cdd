// Kernel-side channel filter for LCM's UDP multicast provider.
//
// With udpm every process on a port receives every datagram: the kernel copies
// it to each socket, LCM's receive thread wakes, queues it, wakes the main
// thread, and only then is it dropped for want of a subscriber. With a dozen
// processes and ~45 messages a tick that fan-out, not the experts' work, was
// most of a lockstep run's CPU time. A classic BPF program attached to the
// process's receive socket (SO_ATTACH_FILTER) drops a datagram whose channel the
// process does not read before anything wakes up. Nothing else changes: other
// processes, lcm-logger, lcm-spy and other machines see every message.
//
// The program reads LCM's short-message header (magic "LC02", sequence number,
// channel name and its NUL); fragments of large messages ("LC03") carry their
// channel only in the first fragment, so they always pass. BEFT_UDPM_FILTER=0 in
// the environment turns filtering off.
#pragma once

#include <linux/filter.h>

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "lib/transport/transport.hpp"

namespace lcm {
class LCM;
}

namespace beft::udpm_filter {

using Rule = transport::Rule;
using Spec = transport::Selection;
using transport::channelRule;
using transport::isPlainChannel;
using transport::udpmPort;

// The BPF program for a spec. Throws std::invalid_argument for a rule too long
// to jump over (a channel or field of hundreds of bytes).
std::vector<sock_filter> compile(const Spec& spec);

// What the program decides, for a whole message (channel and encoded bytes):
// used for fragmented messages, which the program lets through unseen.
bool accepts(const Spec& spec, std::string_view channel, const void* data, std::size_t size);

// Attaches the program to a socket; false (errno set) if the kernel refuses.
bool attach(int fd, const Spec& spec);

// Attaches the program to `lcm`'s receive socket when `url` is udpm. Returns
// false, with the reason in `why`, when it did not (another provider, filtering
// turned off, the socket not found); LCM then works unfiltered as before.
bool install(lcm::LCM& lcm, const std::string& url, const Spec& spec, std::string* why = nullptr);

// "receiving only A, B (own firings)" or "dropping A, B": what a spec lets through.
std::string describe(const Spec& spec);

// install(), with one line in the process's log saying what it did.
bool installAndReport(lcm::LCM& lcm, const std::string& url, const Spec& spec);

// Finds the UDP socket bound to `port` in this process (-1 if none or several).
int findReceiveSocket(int port);

}  // namespace beft::udpm_filter
