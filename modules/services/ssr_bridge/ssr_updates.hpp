// What SSR reports over its network interface (SSR 0.6,
// src/legacy_network/networksubscriber.cpp), read into a picture of its
// scene. The bytes come from the network: anything that is not a well-formed
// update is refused, never trusted.
//
// On connecting, a client gets SSR's whole state: one summary <update>
// (server.cpp: get_scene_as_XML; it starts with the master <volume> and
// numbers its sources by SSR's internal ids, not by the numbers requests
// use, so its sources are skipped), then one update per property of the
// reference and of each source, ending with the reference offset's
// orientation (connection.cpp: Connection::start subscribes to the scene,
// then to the renderer, whose state ends with it).
// After that, an update for every change, from any client (the one that
// asked too), and the sources' signal levels several times a second.
#pragma once

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace beft::ssr_bridge {

// Cuts SSR's byte stream into messages at each binary zero. A message longer
// than the limit is dropped, up to its zero, and counted.
class MessageSplitter {
 public:
  explicit MessageSplitter(std::size_t max_message_bytes = 1 << 20) : max_bytes_(max_message_bytes) {}
  // Appends the messages completed by these bytes (without their zero).
  void feed(const char* data, std::size_t size, std::vector<std::string>& messages);
  std::size_t dropped() const { return dropped_; }
  std::size_t pendingBytes() const { return pending_.size(); }

 private:
  std::size_t max_bytes_;
  std::string pending_;
  bool skipping_ = false;  // inside a message that was too long
  std::size_t dropped_ = 0;
};

struct SsrSource {
  std::string name;
  std::optional<double> x, y;       // [m]
  std::optional<double> volume_db;  // [dB]
  std::optional<bool> mute;
};

struct SsrScene {
  std::map<int, SsrSource> sources;  // by SSR's number
  std::optional<double> reference_x, reference_y;  // [m]
  std::optional<double> reference_azimuth;         // [deg], as SSR reports it: within (-90, 270]
  // The reference offset's orientation was reported: on a fresh connection,
  // the end of SSR's state.
  bool state_received = false;
};

// What one update said that a client acts on.
struct UpdateNews {
  std::vector<std::pair<int, std::string>> names;  // (number, name) of sources named in it
  bool end_of_state = false;                       // it reported the reference offset's orientation
};

// Applies one message to the scene. False, with the scene unchanged, for a
// message that is not an <update> SSR could have sent (not XML, another root,
// a source without a number > 0, a number or boolean that does not read).
bool applyUpdate(const std::string& message, SsrScene& scene, UpdateNews* news = nullptr);

}  // namespace beft::ssr_bridge
