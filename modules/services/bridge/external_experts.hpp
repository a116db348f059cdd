// Experts outside the run's processes: clients of the bridge that take part
// in the run as experts (modules/python/README.md, "The protocol"). A client
// announces itself on /beft/expert with its name, reads, writes and
// parameters; from then on what it publishes on its declared channels, on
// DONE and on HEARTBEAT is checked against the .lcm definitions (jsonToLcm)
// and the message guard, and published on the run's channel like a C++
// expert's message. Anything else is refused with a status naming the
// channel and the field, and nothing reaches the bus. An expert killed
// between an output and its DONE runs that firing again when restarted: the
// outputs it sends again, identical to those already on the bus, are taken
// and not published twice, so the run's messages do not change. No socket
// and no LCM here: the bridge gives it a Bus.
#pragma once

#include <cstdint>
#include <deque>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <beft/done_t.hpp>

namespace beft::bridge {

inline constexpr const char* kExpertTopic = "/beft/expert";
inline constexpr const char* kExpertSchema = "beft.external_expert";

// What an external expert's messages become on the LCM side.
class ExpertBus {
 public:
  virtual ~ExpertBus() = default;
  // Publishes an encoded message on the run's channel (plain name given);
  // "" when sent, else why not.
  virtual std::string publish(const std::string& channel, const std::vector<uint8_t>& bytes) = 0;
  // Fills a DONE's sender and published lists with what the bridge has
  // published (lib/expert/frontier.hpp listPublished).
  virtual void listPublished(beft::done_t& done) = 0;
};

// A status for the client: level foxglove::kStatus*, empty message: none.
struct ExpertStatus {
  int level = 0;
  std::string message;
  std::string id;
};

class ExternalExperts {
 public:
  explicit ExternalExperts(ExpertBus& bus) : bus_(bus) {}

  // Whether a client may advertise this topic as an external expert's:
  // /beft/expert, or a channel of the channel table with its type as schema
  // name. "" when it may, else why not.
  static std::string advertisable(const std::string& topic, const std::string& schema_name);
  static bool isExpertTopic(const std::string& topic);

  // The announcement (JSON text) of a client: accepted (info) or refused (error).
  ExpertStatus announce(uint32_t client, const std::string& payload);
  // An expert restarted mid-run names the run's log (resume_log): what to
  // send it before the acceptance, the run's FIRE, DONE and the channels it
  // reads in log order as {"op": "beftHistory", "channel", "message"} texts,
  // from which it rebuilds its state (lib/expert/log_replay.hpp). Taken once.
  std::vector<std::string> takeHistory(uint32_t client);
  // A message the client published on a channel topic: nothing to say when
  // published, else an error naming the channel and the field.
  ExpertStatus publish(uint32_t client, const std::string& topic, const std::string& payload);
  // The client left: its name is free again.
  void forget(uint32_t client) {
    sessions_.erase(client);
    histories_.erase(client);
  }

  // Whether any client, or this one, takes part in the run as an expert now.
  bool any() const { return !sessions_.empty(); }
  bool isExpert(uint32_t client) const { return sessions_.count(client) > 0; }
  // The name of the expert a client is, or "" (not announced).
  std::string nameOf(uint32_t client) const;
  std::size_t published() const { return published_; }
  // Outputs a restarted expert sent again that were on the bus already.
  std::size_t resentTaken() const { return resent_taken_; }
  std::size_t refused() const { return refused_; }

 private:
  struct Session {
    std::string name;
    std::set<std::string> writes;
  };
  ExpertStatus refuse(const std::string& name, const std::string& why);
  std::string checkAnswer(const Session& session, const std::string& channel, std::vector<uint8_t>& bytes);

  using Sent = std::pair<std::string, std::vector<uint8_t>>;  // channel, encoded bytes
  // True when `sent` is the next output a restarted expert owes again (on the bus already).
  bool alreadyOnTheBus(const std::string& name, const Sent& sent);

  ExpertBus& bus_;
  std::map<uint32_t, Session> sessions_;
  // By expert name (outliving its clients): outputs published since its last
  // DONE, and, for an expert restarted since, those it has yet to send again.
  std::map<std::string, std::vector<Sent>> since_done_;
  std::map<std::string, std::deque<Sent>> owed_again_;
  std::size_t resent_taken_ = 0;
  std::map<uint32_t, std::vector<std::string>> histories_;
  std::size_t published_ = 0, refused_ = 0;
};

}  // namespace beft::bridge
