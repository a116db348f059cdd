#include "services/ssr_bridge/scene_mirror.hpp"

#include <cmath>
#include <filesystem>
#include <set>

#include "services/ssr_bridge/ssr_conventions.hpp"
#include "services/ssr_bridge/ssr_requests.hpp"

namespace beft::ssr_bridge {

namespace {

// Each source is a player process in SSR (ecasound): a scene that asks for
// more is refused beyond this, with a warning.
constexpr std::size_t kMostSources = 256;

int64_t millimetres(double metres) { return std::llround(metres * 1000.0); }
int64_t hundredthsOf(double value) { return std::llround(value * 100.0); }

}  // namespace

SceneMirror::SceneMirror(std::string scenario_dir) : scenario_dir_(std::move(scenario_dir)) {}

std::string SceneMirror::absoluteSoundPath(const std::string& sound) const {
  namespace fs = std::filesystem;
  fs::path path(sound);
  if (path.is_relative()) path = scenario_dir_.empty() ? fs::current_path() / path : fs::path(scenario_dir_) / path;
  return fs::absolute(path).lexically_normal().string();
}

void SceneMirror::warnOnce(const std::string& warning) {
  if (warned_.emplace(warning, true).second) warnings_.push_back(warning);
}

std::vector<std::string> SceneMirror::takeWarnings() {
  std::vector<std::string> out;
  out.swap(warnings_);
  return out;
}

SceneMirror::Source& SceneMirror::sourceFor(const beft::scene_object_t& object, const std::string& file) {
  const std::string key = object.id + '\n' + file;
  if (const auto it = by_object_file_.find(key); it != by_object_file_.end()) return sources_[it->second];
  Source source;
  source.file = file;
  // The first sound of an object is named by the object; a later one also by its file.
  const int sounds_before = files_per_object_[object.id]++;
  source.name = sounds_before == 0 ? object.id
                                   : object.id + " [" + std::filesystem::path(file).filename().string() + "]";
  for (int n = 2; by_name_.count(source.name); ++n) source.name = object.id + " #" + std::to_string(n);
  by_object_file_[key] = sources_.size();
  by_name_[source.name] = sources_.size();
  sources_.push_back(std::move(source));
  return sources_.back();
}

void SceneMirror::setObjects(const beft::scene_objects_t& objects) {
  std::set<std::size_t> sounding;  // the sources of the objects' current sounds
  for (const auto& object : objects.objects) {
    if (!object.has_acoustic) continue;
    if (object.sound.empty()) {
      warnOnce("object '" + object.id + "' is acoustic but names no sound file: not played");
      continue;
    }
    if (!representable(object.id) || !representable(object.sound)) {
      warnOnce("an object's id or sound path is not printable UTF-8: not played");
      continue;
    }
    const std::string file = absoluteSoundPath(object.sound);
    if (!by_object_file_.count(object.id + '\n' + file) && sources_.size() >= kMostSources) {
      warnOnce("more than " + std::to_string(kMostSources) + " sounds in the scene: the rest are not played");
      continue;
    }
    Source& source = sourceFor(object, file);
    source.x = object.x;
    source.y = object.y;
    source.volume_db = volumeDecibels(object.level);
    source.mute = !object.sound_active;
    sounding.insert(static_cast<std::size_t>(&source - sources_.data()));
  }
  for (std::size_t i = 0; i < sources_.size(); ++i)
    if (!sounding.count(i)) sources_[i].mute = true;
}

void SceneMirror::setRobot(const beft::robot_state_t& robot) {
  const ListenerPose pose = listenerPose(robot);
  listener_x_ = pose.x;
  listener_y_ = pose.y;
  listener_azimuth_ = pose.azimuth;
  has_robot_ = true;
}

void SceneMirror::restart() {
  clear_pending_ = true;
  made_since_clear_ = 0;
  for (auto& source : sources_) source.told = Told{};
  listener_known_ = false;
}

std::vector<std::string> SceneMirror::requests() {
  std::vector<std::string> out;
  if (clear_pending_) {
    out.push_back(clearSceneRequest());
    clear_pending_ = false;
  }
  // The listener first: SSR answers it at once, while making a source (starting its player) takes a while.
  if (has_robot_) {
    const int64_t x = millimetres(listener_x_), y = millimetres(listener_y_);
    const int64_t azimuth = hundredthsOf(listener_azimuth_);
    ReferenceChange change;
    if (!listener_known_ || x != told_x_mm_ || y != told_y_mm_) change.x = listener_x_, change.y = listener_y_;
    if (!listener_known_ || azimuth != told_azimuth_cdeg_) change.azimuth = listener_azimuth_;
    if (!change.empty()) out.push_back(referenceRequest(change));
    told_x_mm_ = x, told_y_mm_ = y, told_azimuth_cdeg_ = azimuth;
    listener_known_ = true;
  }
  for (auto& source : sources_) {
    Told now;
    now.x_mm = millimetres(source.x);
    now.y_mm = millimetres(source.y);
    now.volume_cdb = hundredthsOf(source.volume_db);
    now.mute = source.mute;
    now.made = now.known = true;
    Told& told = source.told;
    if (!told.made) {
      out.push_back(newSourceRequest({source.name, source.file, source.x, source.y, source.volume_db, source.mute}));
      now.number = ++made_since_clear_;
      told = now;
      continue;
    }
    if (!told.number) continue;  // SSR's number for it is not known: nothing can reach it
    SourceChange change;
    if (!told.known || now.x_mm != told.x_mm || now.y_mm != told.y_mm) change.x = source.x, change.y = source.y;
    if (!told.known || now.volume_cdb != told.volume_cdb) change.volume_db = source.volume_db;
    if (!told.known || now.mute != told.mute) change.mute = source.mute;
    if (!change.empty()) out.push_back(sourceChangeRequest(*told.number, change));
    now.number = told.number;
    told = now;
  }
  return out;
}

std::string SceneMirror::sourceNamed(int number, const std::string& name) {
  const auto it = by_name_.find(name);
  if (it == by_name_.end()) return "";
  Source& source = sources_[it->second];
  if (!source.told.made || source.told.number == number) return "";
  const std::string expected = source.told.number ? std::to_string(*source.told.number) : "unknown";
  for (auto& other : sources_)
    if (other.told.number == number) {
      other.told.number.reset();
      other.told.known = false;
    }
  source.told.number = number;
  source.told.known = false;
  return "SSR numbered source '" + name + "' " + std::to_string(number) + ", not " + expected +
         " (another client changing SSR's scene, or a source SSR refused): telling it its state again";
}

}  // namespace beft::ssr_bridge
