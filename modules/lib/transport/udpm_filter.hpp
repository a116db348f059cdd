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

namespace lcm {
class LCM;
}

namespace beft::udpm_filter {

// A datagram matches when its channel is `channel` and, when `field` is not
// empty, the encoded message (after its 8-byte fingerprint) holds exactly the
// bytes `field` at `field_offset`.
struct Rule {
  std::string channel;
  std::size_t field_offset = 0;  // [bytes] from the first byte after the fingerprint
  std::string field;             // encoded bytes that must be there
  std::string what;              // what the field selects, for the log ("own firings")
};

struct Spec {
  enum class Mode { AcceptListed, RejectListed };
  Mode mode = Mode::AcceptListed;
  std::vector<Rule> rules;
};

// Every message on one channel.
Rule channelRule(const std::string& channel);

// FIRE messages for one expert only: fire_t encodes utime (8 bytes) and then
// the expert's name as an LCM string (big-endian length with the NUL, bytes, NUL).
Rule fireFor(const std::string& channel, const std::string& expert);

// RUN_STATUS messages in one state only: run_status_t encodes utime and tick
// (8 bytes each) and then its state byte. `what` names it for the log.
Rule runStatusIn(const std::string& channel, int8_t state, const std::string& what);

// True when an LCM subscription pattern is a plain channel name (no regex).
bool isPlainChannel(const std::string& pattern);

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

// The port of a udpm:// URL, or -1 for any other provider.
int udpmPort(const std::string& url);

}  // namespace beft::udpm_filter
