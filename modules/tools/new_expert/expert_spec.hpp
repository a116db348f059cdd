// What `beft-new-expert` is asked for, checked: the expert's name (a fresh
// lowercase identifier), the channels it reads and writes (each in the
// channel table, or a new channel with its new message type), its level in
// the schedules and the expert it goes after. Every refusal is a SpecError,
// thrown before anything is written.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "tools/new_expert/channel_table.hpp"

namespace beft::new_expert {

class SpecError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// As given on the command line.
struct ExpertRequest {
  std::string name;
  std::vector<std::string> reads, writes;
  std::vector<std::string> new_channels;  // "CHANNEL:type_t"
  std::string level = "high";
  std::string after;        // the expert it follows in every net; "" = the level's usual one
  std::string root;         // where the files go (the repository, or --out)
  std::string source_root;  // the repository: nets, launch file, channel table, message types
};

struct ExpertSpec {
  std::string name;          // "threat_map"
  std::string class_name;    // "ThreatMapExpert"
  std::string program;       // "beft-threat-map"
  std::string level;         // "low", "mid" or "high"
  std::string after;         // "dw"
  std::vector<KnownChannel> reads;
  std::vector<KnownChannel> writes;        // also the new channels
  std::vector<KnownChannel> new_channels;  // not in the table yet: their .lcm is written
  std::string root, source_root;
};

// The expert a level's new expert follows unless --after says otherwise.
std::string usualExpertOfLevel(const std::string& level);

// Throws SpecError with what is wrong and how to put it right.
ExpertSpec checkRequest(const ExpertRequest& request);

// "threat_map" -> "ThreatMap".
std::string camelCase(const std::string& snake);

}  // namespace beft::new_expert
