// What SSR's scene should be, and the requests that make it so: the pure
// part of the bridge, free of sockets and LCM.
//
// - One SSR source per sound of an acoustic object, made once with the WAV
//   file's absolute path (sounds are relative to the scenario file) and named
//   by the object's id. An object whose sound changes (a timed event) gets a
//   further source, named "ID [FILE]"; its earlier ones are muted, since SSR
//   cannot change the file a source plays.
// - A source is muted while its object does not sound, and also when the
//   object is no longer in the scene or no longer acoustic. Sources are never
//   deleted: SSR numbers its sources by their place in its list, and a
//   deletion would renumber those after it.
// - The reference (listener) follows the head: listenerPose.
// - Only what changed since SSR was told is sent, compared at the resolution
//   it is written with (ssr_requests.hpp).
//
// SSR numbers the sources of a cleared scene 1, 2, ... in the order they
// were made, also when a file cannot be opened, so a source's number is
// known when it is asked for. SSR's reports of the names it gave each number
// are checked against that (sourceNamed): a source numbered otherwise (made
// by another client meanwhile, or refused) is renumbered and told its whole
// state again.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <beft/robot_state_t.hpp>
#include <beft/scene_objects_t.hpp>

namespace beft::ssr_bridge {

class SceneMirror {
 public:
  // Relative sound paths are taken from scenario_dir (the current directory
  // when empty).
  explicit SceneMirror(std::string scenario_dir);

  // The newest state of the world; what SSR should be.
  void setObjects(const beft::scene_objects_t& objects);
  void setRobot(const beft::robot_state_t& robot);

  // A new connection: SSR's scene is cleared and every source made again
  // (the clear request is the first of the next requests()).
  void restart();

  // The requests that bring SSR to the newest state, in order; afterwards
  // SSR counts as told.
  std::vector<std::string> requests();

  // SSR reported that its source `number` is named `name`. A warning when
  // that contradicts the numbering, "" otherwise.
  std::string sourceNamed(int number, const std::string& name);

  // Problems with the scene's data met since the last call (an object's id or
  // sound path that cannot be written in a request), each said once.
  std::vector<std::string> takeWarnings();

  std::size_t sourceCount() const { return sources_.size(); }

 private:
  // Values at the resolution they are written with: mm, hundredths.
  struct Told {
    std::optional<int> number;
    int64_t x_mm = 0, y_mm = 0, volume_cdb = 0;
    bool mute = false;
    bool made = false;  // a creation request was sent since the last clear
    bool known = false;  // SSR was told every field below
  };
  struct Source {
    std::string name, file;  // file: absolute
    double x = 0, y = 0, volume_db = 0;
    bool mute = true;
    Told told;
  };
  std::string absoluteSoundPath(const std::string& sound) const;
  Source& sourceFor(const beft::scene_object_t& object, const std::string& file);
  void warnOnce(const std::string& warning);

  std::string scenario_dir_;
  std::vector<Source> sources_;                        // in the order they were made
  std::map<std::string, std::size_t> by_object_file_;  // "id\nfile" -> index
  std::map<std::string, std::size_t> by_name_;         // name -> index
  std::map<std::string, int> files_per_object_;
  bool clear_pending_ = true;
  int made_since_clear_ = 0;
  // The listener.
  bool has_robot_ = false;
  double listener_x_ = 0, listener_y_ = 0, listener_azimuth_ = 0;
  bool listener_known_ = false;
  int64_t told_x_mm_ = 0, told_y_mm_ = 0, told_azimuth_cdeg_ = 0;
  std::vector<std::string> warnings_;
  std::map<std::string, bool> warned_;
};

}  // namespace beft::ssr_bridge
