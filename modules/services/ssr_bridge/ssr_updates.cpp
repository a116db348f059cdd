#include "services/ssr_bridge/ssr_updates.hpp"

#include <tinyxml2.h>

#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <cstring>

namespace beft::ssr_bridge {

void MessageSplitter::feed(const char* data, std::size_t size, std::vector<std::string>& messages) {
  const char* end = data + size;
  while (data < end) {
    const char* zero = static_cast<const char*>(std::memchr(data, '\0', static_cast<std::size_t>(end - data)));
    const char* stop = zero ? zero : end;
    if (!skipping_) {
      pending_.append(data, static_cast<std::size_t>(stop - data));
      if (pending_.size() > max_bytes_) {
        pending_.clear();
        skipping_ = true;
        ++dropped_;
      }
    }
    if (!zero) break;
    if (!skipping_) messages.push_back(std::move(pending_));
    pending_.clear();
    skipping_ = false;
    data = zero + 1;
  }
}

namespace {

// Attribute readers: nothing when absent; false when present but unreadable.
bool readNumber(const tinyxml2::XMLElement* e, const char* name, std::optional<double>& out) {
  const char* text = e->Attribute(name);
  if (!text) return true;
  errno = 0;
  char* end = nullptr;
  const double value = std::strtod(text, &end);
  if (end == text || *end != '\0' || errno == ERANGE || !std::isfinite(value)) return false;
  out = value;
  return true;
}

bool readBool(const tinyxml2::XMLElement* e, const char* name, std::optional<bool>& out) {
  const char* text = e->Attribute(name);
  if (!text) return true;
  if (!std::strcmp(text, "true") || !std::strcmp(text, "1")) out = true;
  else if (!std::strcmp(text, "false") || !std::strcmp(text, "0")) out = false;
  else return false;
  return true;
}

std::optional<int> sourceNumber(const tinyxml2::XMLElement* e) {
  const char* text = e->Attribute("id");
  if (!text) return std::nullopt;
  errno = 0;
  char* end = nullptr;
  const long value = std::strtol(text, &end, 10);
  if (end == text || *end != '\0' || errno == ERANGE || value <= 0 || value > INT_MAX) return std::nullopt;
  return static_cast<int>(value);
}

// A position element's x and y, both or neither.
bool readPosition(const tinyxml2::XMLElement* parent, std::optional<double>& x, std::optional<double>& y) {
  const auto* position = parent->FirstChildElement("position");
  if (!position) return true;
  std::optional<double> px, py;
  if (!readNumber(position, "x", px) || !readNumber(position, "y", py) || px.has_value() != py.has_value())
    return false;
  if (px) x = px, y = py;
  return true;
}

bool readSource(const tinyxml2::XMLElement* e, SsrScene& scene, UpdateNews& news) {
  const auto number = sourceNumber(e);
  if (!number) return false;
  SsrSource source = scene.sources.count(*number) ? scene.sources.at(*number) : SsrSource{};
  if (!readNumber(e, "volume", source.volume_db) || !readBool(e, "mute", source.mute) ||
      !readPosition(e, source.x, source.y))
    return false;
  if (const char* name = e->Attribute("name")) {
    source.name = name;
    news.names.emplace_back(*number, source.name);
  }
  scene.sources[*number] = std::move(source);
  return true;
}

bool readReference(const tinyxml2::XMLElement* e, SsrScene& scene) {
  if (!readPosition(e, scene.reference_x, scene.reference_y)) return false;
  if (const auto* orientation = e->FirstChildElement("orientation"))
    if (!readNumber(orientation, "azimuth", scene.reference_azimuth)) return false;
  return true;
}

// SSR numbers its sources by their place in its list: those after a deleted one move up.
bool readDelete(const tinyxml2::XMLElement* e, SsrScene& scene) {
  for (const auto* s = e->FirstChildElement("source"); s; s = s->NextSiblingElement("source")) {
    const auto number = sourceNumber(s);
    if (!number) return false;
    if (!scene.sources.erase(*number)) continue;
    std::map<int, SsrSource> renumbered;
    for (auto& [n, source] : scene.sources) renumbered.emplace(n > *number ? n - 1 : n, std::move(source));
    scene.sources = std::move(renumbered);
  }
  return true;
}

}  // namespace

bool applyUpdate(const std::string& message, SsrScene& scene, UpdateNews* news) {
  tinyxml2::XMLDocument doc;
  if (doc.Parse(message.data(), message.size()) != tinyxml2::XML_SUCCESS) return false;
  const auto* root = doc.RootElement();
  if (!root || std::strcmp(root->Name(), "update") != 0) return false;
  const bool summary = root->FirstChildElement("volume") != nullptr;
  SsrScene changed = scene;
  UpdateNews heard;
  for (const auto* e = root->FirstChildElement(); e; e = e->NextSiblingElement()) {
    const std::string element = e->Name();
    bool ok = true;
    if (element == "source") ok = summary || readSource(e, changed, heard);
    else if (element == "reference") ok = readReference(e, changed);
    else if (element == "delete") ok = readDelete(e, changed);
    else if (element == "reference_offset" && e->FirstChildElement("orientation")) heard.end_of_state = true;
    // Anything else (master volume, transport, CPU load, ...) is not mirrored.
    if (!ok) return false;
  }
  if (heard.end_of_state) changed.state_received = true;
  scene = std::move(changed);
  if (news) *news = std::move(heard);
  return true;
}

}  // namespace beft::ssr_bridge
