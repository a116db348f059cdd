#include "lib/scenario/load_scenario.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <set>
#include <sstream>

#include <tinyxml2.h>

#include "lib/scenario/element_reader.hpp"
#include "lib/scenario/footprint.hpp"
#include "lib/scenario/wav_info.hpp"

namespace beft::scenario {

namespace fs = std::filesystem;
using tinyxml2::XMLElement;

std::map<std::pair<std::string, std::string>, double> defaultCongruency() {
  return {
      {{"person", "walking"}, 0.25}, {{"person", "idle"}, 0.25},
      {{"person", "yelling"}, 0.75}, {{"fire", "burning"}, 0.5},
      {{"fire", "spreading"}, 0.75}, {{"siren", "ringing"}, 0.5},
      {{"car", "idle"}, 0.25},
  };
}

std::vector<std::string> defaultCategories() { return {"person", "car", "siren", "wall", "fire"}; }

namespace {

std::string formatNumber(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

std::string joined(const std::vector<std::string>& words) {
  std::string text;
  for (const std::string& word : words) text += (text.empty() ? "" : " ") + word;
  return text;
}

std::vector<std::string> splitWords(const char* text) {
  std::vector<std::string> words;
  std::istringstream in(text == nullptr ? "" : text);
  for (std::string word; in >> word;) words.push_back(word);
  return words;
}

std::string describeXmlError(tinyxml2::XMLError error) {
  switch (error) {
    case tinyxml2::XML_ERROR_EMPTY_DOCUMENT: return "the file is empty";
    case tinyxml2::XML_ERROR_MISMATCHED_ELEMENT: return "an element is not closed, or closed by the wrong tag";
    case tinyxml2::XML_ERROR_PARSING_ATTRIBUTE: return "an attribute is badly written (values need quotes)";
    case tinyxml2::XML_ERROR_PARSING_ELEMENT: return "an element is badly written";
    case tinyxml2::XML_ERROR_PARSING_TEXT: return "bad text content";
    case tinyxml2::XML_ERROR_PARSING_COMMENT: return "a comment is not closed";
    case tinyxml2::XML_ERROR_PARSING_DECLARATION: return "bad <?xml ...?> declaration";
    case tinyxml2::XML_ERROR_PARSING: return "the document ends early or has stray content";
    default: return tinyxml2::XMLDocument::ErrorIDToName(error);
  }
}

// Walks the document once; every check names the element it is about.
class Loader {
 public:
  Loader(const std::string& path, std::ostream* warnings) : file_(path), warnings_(warnings) {
    scenario_.file = path;
    scenario_.categories = defaultCategories();
    scenario_.congruency = defaultCongruency();
    directory_ = fs::path(path).parent_path();
  }

  Scenario load() {
    openDocument();
    const XMLElement& root = *document_.RootElement();
    if (std::string(root.Name()) != "scenario") {
      throw ScenarioError(file_, root.GetLineNum(),
                          std::string("the root element must be <scenario>, got <") + root.Name() + ">");
    }
    readHeader(root);

    // Elements may come in any order; read those others depend on first.
    const XMLElement* world = single(root, "world", true);
    const XMLElement* categories = single(root, "categories", false);
    const XMLElement* robot = single(root, "robot", true);
    readWorld(*world);
    if (categories != nullptr) readCategories(*categories);
    readRobot(*robot);
    for (const XMLElement* e = root.FirstChildElement("object"); e; e = e->NextSiblingElement("object")) {
      readObject(*e);
    }
    for (const XMLElement* e = root.FirstChildElement("path"); e; e = e->NextSiblingElement("path")) {
      readPath(*e);
    }
    for (const XMLElement* e = root.FirstChildElement("events"); e; e = e->NextSiblingElement("events")) {
      readEvents(*e);
    }
    for (const XMLElement* e = root.FirstChildElement("congruency"); e;
         e = e->NextSiblingElement("congruency")) {
      readCongruency(*e);
    }
    if (const XMLElement* acoustics = single(root, "acoustics", false)) readAcoustics(*acoustics);
    warnUnknownChildren(root, {"world", "categories", "robot", "object", "path", "events", "congruency",
                               "acoustics"});

    checkRobotStart(*robot);
    checkCongruencyCoverage();
    std::stable_sort(scenario_.events.begin(), scenario_.events.end(),
                     [](const Event& a, const Event& b) { return a.t < b.t; });
    return std::move(scenario_);
  }

 private:
  void openDocument() {
    std::error_code error;
    if (!fs::is_regular_file(file_, error)) {
      throw ScenarioError(file_, 0, "cannot open scenario file (no such file)");
    }
    if (document_.LoadFile(file_.c_str()) != tinyxml2::XML_SUCCESS) {
      // tinyxml2's ErrorStr() is "Error=NAME ErrorID=N (0xN) Line number=N[: detail]".
      const std::string error_text = document_.ErrorStr();
      const auto detail_start = error_text.find(": ");
      std::string message = "malformed XML: " + describeXmlError(document_.ErrorID());
      if (detail_start != std::string::npos) message += " (" + error_text.substr(detail_start + 2) + ")";
      throw ScenarioError(file_, document_.ErrorLineNum(), message);
    }
    if (document_.RootElement() == nullptr) {
      throw ScenarioError(file_, 0, "malformed XML: the file has no root element");
    }
  }

  // The element `name` under `parent`, refused if repeated (or missing when required).
  const XMLElement* single(const XMLElement& parent, const char* name, bool required) {
    const XMLElement* first = parent.FirstChildElement(name);
    if (first == nullptr) {
      if (!required) return nullptr;
      throw ScenarioError(file_, parent.GetLineNum(),
                          std::string("<") + parent.Name() + "> is missing required element <" + name + ">");
    }
    if (const XMLElement* second = first->NextSiblingElement(name)) {
      throw ScenarioError(file_, second->GetLineNum(),
                          std::string("<") + name + "> may appear only once in <" + parent.Name() +
                              "> (first at line " + std::to_string(first->GetLineNum()) + ")");
    }
    return first;
  }

  void warn(int line, const std::string& message) {
    emitWarning(file_, line, message, warnings_, &scenario_.warnings);
  }

  void finish(const ElementReader& reader) { reader.warnUnread(warnings_, &scenario_.warnings); }

  void warnUnknownChildren(const XMLElement& parent, const std::set<std::string>& known) {
    for (const XMLElement* child = parent.FirstChildElement(); child; child = child->NextSiblingElement()) {
      if (known.count(child->Name()) == 0) {
        warn(child->GetLineNum(),
             std::string("unknown element <") + child->Name() + "> in <" + parent.Name() + ">");
      }
    }
  }

  bool insideWorld(double x, double y) const {
    return x >= 0 && x <= scenario_.world.width && y >= 0 && y <= scenario_.world.height;
  }

  std::string worldBounds() const {
    return "[0, " + formatNumber(scenario_.world.width) + "] x [0, " +
           formatNumber(scenario_.world.height) + "]";
  }

  std::string requireCategory(const ElementReader& reader, const std::string& label) const {
    const auto& categories = scenario_.categories;
    if (std::find(categories.begin(), categories.end(), label) == categories.end()) {
      reader.fail("label '" + label + "' is not a category (categories: " + joined(categories) + ")");
    }
    return label;
  }

  // Resolves a sound path against the scenario's folder and checks it is a WAV.
  std::string resolveSound(const ElementReader& reader, const std::string& sound) const {
    fs::path resolved(sound);
    if (resolved.is_relative()) resolved = directory_ / resolved;
    std::error_code error;
    resolved = fs::absolute(resolved, error).lexically_normal();
    if (!fs::exists(resolved, error)) {
      reader.fail("sound file '" + sound + "' does not exist (looked for '" + resolved.string() + "')");
    }
    if (!fs::is_regular_file(resolved, error)) {
      reader.fail("sound file '" + sound + "' is not a regular file");
    }
    try {
      readWavInfo(resolved.string());
    } catch (const WavError& wav_error) {
      reader.fail("sound file '" + sound + "' is not a readable WAV file: " + wav_error.what());
    }
    return resolved.string();
  }

  void readHeader(const XMLElement& root) {
    ElementReader reader(root, file_);
    scenario_.name = reader.requiredString("name");
    const int64_t version = reader.integer("version", 1);
    if (version != 1) warn(reader.line(), "version " + std::to_string(version) + " is not 1; reading it as version 1");
    scenario_.version = static_cast<int>(version);
    scenario_.dt = reader.positive("dt", scenario_.dt);
    scenario_.duration = reader.positive("duration", scenario_.duration);
    if (scenario_.dt > scenario_.duration) {
      reader.fail("dt (" + formatNumber(scenario_.dt) + " s) is longer than the duration (" +
                  formatNumber(scenario_.duration) + " s)");
    }
    scenario_.seed = reader.unsignedInteger("seed", 0);
    finish(reader);
  }

  void readWorld(const XMLElement& element) {
    ElementReader reader(element, file_);
    scenario_.world.width = reader.requiredPositive("width");
    scenario_.world.height = reader.requiredPositive("height");
    scenario_.world.resolution = reader.positive("resolution", scenario_.world.resolution);
    if (scenario_.world.resolution > std::min(scenario_.world.width, scenario_.world.height)) {
      reader.fail("resolution " + formatNumber(scenario_.world.resolution) +
                  " m is coarser than the world itself");
    }
    finish(reader);
    warnUnknownChildren(element, {});
  }

  void readCategories(const XMLElement& element) {
    ElementReader reader(element, file_);
    const std::vector<std::string> words = splitWords(element.GetText());
    if (words.empty()) reader.fail("<categories> lists no labels");
    std::set<std::string> seen;
    for (const std::string& word : words) {
      if (!seen.insert(word).second) reader.fail("category '" + word + "' is listed twice");
    }
    scenario_.categories = words;
    finish(reader);
    warnUnknownChildren(element, {});
  }

  void readRobot(const XMLElement& element) {
    ElementReader reader(element, file_);
    Robot& robot = scenario_.robot;
    robot.line = reader.line();
    robot.x = reader.requiredNumber("x");
    robot.y = reader.requiredNumber("y");
    robot.yaw = reader.number("yaw", robot.yaw);
    robot.head_yaw = reader.number("head_yaw", robot.head_yaw);
    robot.head_pitch = reader.number("head_pitch", robot.head_pitch);
    robot.radius = reader.positive("radius", robot.radius);
    finish(reader);

    if (const XMLElement* limits = single(element, "limits", false)) readLimits(*limits);
    if (const XMLElement* camera = single(element, "camera", false)) readCamera(*camera);
    warnUnknownChildren(element, {"limits", "camera"});

    if (std::abs(robot.head_yaw) > robot.limits.head_yaw_range / 2) {
      reader.fail("head_yaw " + formatNumber(robot.head_yaw) + " is outside the head's pan range +/-" +
                  formatNumber(robot.limits.head_yaw_range / 2));
    }
    if (std::abs(robot.head_pitch) > robot.limits.head_pitch_range / 2) {
      reader.fail("head_pitch " + formatNumber(robot.head_pitch) + " is outside the head's tilt range +/-" +
                  formatNumber(robot.limits.head_pitch_range / 2));
    }
  }

  void readLimits(const XMLElement& element) {
    ElementReader reader(element, file_);
    RobotLimits& limits = scenario_.robot.limits;
    limits.max_speed = reader.positive("max_speed", limits.max_speed);
    limits.max_turn_rate = reader.positive("max_turn_rate", limits.max_turn_rate);
    limits.head_yaw_range = reader.nonNegative("head_yaw_range", limits.head_yaw_range);
    limits.head_pitch_range = reader.nonNegative("head_pitch_range", limits.head_pitch_range);
    limits.head_turn_rate = reader.positive("head_turn_rate", limits.head_turn_rate);
    if (limits.head_yaw_range > 360) reader.fail("head_yaw_range must be <= 360 degrees");
    if (limits.head_pitch_range > 180) reader.fail("head_pitch_range must be <= 180 degrees");
    finish(reader);
    warnUnknownChildren(element, {});
  }

  void readCamera(const XMLElement& element) {
    ElementReader reader(element, file_);
    Camera& camera = scenario_.robot.camera;
    camera.fov = reader.positive("fov", camera.fov);
    if (camera.fov >= 180) reader.fail("fov must be below 180 degrees, got " + formatNumber(camera.fov));
    camera.width = reader.positiveInteger("width", camera.width);
    camera.height = reader.positiveInteger("height", camera.height);
    camera.range = reader.positive("range", camera.range);
    camera.height_above_ground = reader.positive("height_above_ground", camera.height_above_ground);
    finish(reader);
    warnUnknownChildren(element, {});
  }

  void readObject(const XMLElement& element) {
    ElementReader reader(element, file_);
    Object object;
    object.line = reader.line();
    object.id = reader.requiredString("id");
    object.label = requireCategory(reader, reader.requiredString("label"));
    object.x = reader.requiredNumber("x");
    object.y = reader.requiredNumber("y");
    object.z = reader.number("z", object.z);
    object.yaw = reader.number("yaw", object.yaw);
    if (auto activity = reader.optionalString("activity")) {
      if (activity->empty()) reader.fail("attribute 'activity' of <object> is empty");
      object.activity = *activity;
    }
    finish(reader);

    if (const Object* earlier = scenario_.findObject(object.id)) {
      reader.fail("duplicate object id '" + object.id + "' (first defined at line " +
                  std::to_string(earlier->line) + ")");
    }
    if (!insideWorld(object.x, object.y)) {
      reader.fail("object '" + object.id + "' at (" + formatNumber(object.x) + ", " + formatNumber(object.y) +
                  ") is outside the world " + worldBounds());
    }
    if (const XMLElement* visual = single(element, "visual", false)) object.visual = readVisual(*visual);
    if (const XMLElement* acoustic = single(element, "acoustic", false)) object.acoustic = readAcoustic(*acoustic);
    warnUnknownChildren(element, {"visual", "acoustic"});
    scenario_.objects.push_back(std::move(object));
  }

  Visual readVisual(const XMLElement& element) {
    ElementReader reader(element, file_);
    Visual visual;
    visual.line = reader.line();
    const std::string shape = reader.requiredString("shape");
    if (shape == "box") {
      visual.shape = Visual::Shape::Box;
      const std::string size = reader.requiredString("size");
      std::vector<double> extents;
      for (const std::string& word : splitWords(size.c_str())) {
        double value = 0;
        if (!ElementReader::parseNumber(word, &value) || !std::isfinite(value)) {
          reader.fail("attribute 'size' of <visual> has '" + word + "', which is not a finite number");
        }
        extents.push_back(value);
      }
      if (extents.size() != 3) {
        reader.fail("attribute 'size' of <visual> must be three numbers \"sx sy sz\", got '" + size + "'");
      }
      for (double extent : extents) {
        if (extent <= 0) reader.fail("every box size must be > 0, got '" + size + "'");
      }
      visual.size_x = extents[0];
      visual.size_y = extents[1];
      visual.size_z = extents[2];
    } else if (shape == "cylinder") {
      visual.shape = Visual::Shape::Cylinder;
      visual.radius = reader.requiredPositive("radius");
      visual.height = reader.requiredPositive("height");
    } else {
      reader.fail("attribute 'shape' of <visual> must be 'box' or 'cylinder', got '" + shape + "'");
    }
    if (auto color = reader.optionalString("color")) visual.color_rgb = parseColor(reader, *color);
    if (auto absorption = reader.optionalNumber("absorption")) visual.absorption = requireShare(reader, "absorption", *absorption);
    finish(reader);
    warnUnknownChildren(element, {});
    return visual;
  }

  static uint32_t parseColor(const ElementReader& reader, const std::string& text) {
    const bool well_formed = text.size() == 7 && text[0] == '#' &&
                             std::all_of(text.begin() + 1, text.end(), [](char c) { return std::isxdigit(static_cast<unsigned char>(c)) != 0; });
    if (!well_formed) reader.fail("attribute 'color' of <visual> must be '#rrggbb', got '" + text + "'");
    return static_cast<uint32_t>(std::stoul(text.substr(1), nullptr, 16));
  }

  Acoustic readAcoustic(const XMLElement& element) {
    ElementReader reader(element, file_);
    Acoustic acoustic;
    acoustic.line = reader.line();
    acoustic.sound = reader.requiredString("sound");
    acoustic.active = reader.flag("active", acoustic.active);
    acoustic.level = reader.nonNegative("level", acoustic.level);
    if (auto label = reader.optionalString("label")) acoustic.label = requireCategory(reader, *label);
    finish(reader);
    acoustic.sound_path = resolveSound(reader, acoustic.sound);
    warnUnknownChildren(element, {});
    return acoustic;
  }

  // A share in [0, 1] (absorption).
  static double requireShare(const ElementReader& reader, const char* attribute, double value) {
    if (!(value >= 0 && value <= 1)) {
      reader.fail(std::string("attribute '") + attribute + "' of <" + reader.name() + "> must be in [0, 1], got " +
                  formatNumber(value));
    }
    return value;
  }

  // <acoustics>: every attribute optional; refused outside the ranges the format gives.
  void readAcoustics(const XMLElement& element) {
    ElementReader reader(element, file_);
    Acoustics acoustics;
    acoustics.line = reader.line();
    acoustics.reverberation = reader.number("reverberation", acoustics.reverberation);
    if (acoustics.reverberation < 0 || acoustics.reverberation > 10) {
      reader.fail("attribute 'reverberation' of <acoustics> must be 0 (no tail) or a T60 in (0, 10] s, got " +
                  formatNumber(acoustics.reverberation));
    }
    if (auto text = reader.optionalString("reflection_order")) {
      const auto digit = std::find_if(text->begin(), text->end(), [](char c) { return c != ' '; });
      const bool one_digit = digit != text->end() && *digit >= '0' && *digit <= '4' &&
                             std::all_of(digit + 1, text->end(), [](char c) { return c == ' '; });
      if (!one_digit) {
        reader.fail("attribute 'reflection_order' of <acoustics> must be an integer in 0..4, got '" + *text + "'");
      }
      acoustics.reflection_order = *digit - '0';
    }
    acoustics.absorption = requireShare(reader, "absorption", reader.number("absorption", acoustics.absorption));
    acoustics.ground = reader.flag("ground", acoustics.ground);
    finish(reader);
    warnUnknownChildren(element, {});
    scenario_.acoustics = acoustics;
  }

  const Object& requireObject(const ElementReader& reader, const std::string& id) const {
    const Object* object = scenario_.findObject(id);
    if (object == nullptr) reader.fail(std::string("<") + reader.name() + "> names unknown object '" + id + "'");
    return *object;
  }

  void readPath(const XMLElement& element) {
    ElementReader reader(element, file_);
    Path path;
    path.line = reader.line();
    path.object = reader.requiredString("object");
    path.speed = reader.requiredPositive("speed");
    path.loop = reader.flag("loop", false);
    finish(reader);
    requireObject(reader, path.object);
    for (const Path& earlier : scenario_.paths) {
      if (earlier.object == path.object) {
        reader.fail("object '" + path.object + "' already has a path (line " + std::to_string(earlier.line) + ")");
      }
    }
    for (const XMLElement* e = element.FirstChildElement("waypoint"); e; e = e->NextSiblingElement("waypoint")) {
      ElementReader waypoint_reader(*e, file_);
      Waypoint waypoint;
      waypoint.line = waypoint_reader.line();
      waypoint.x = waypoint_reader.requiredNumber("x");
      waypoint.y = waypoint_reader.requiredNumber("y");
      finish(waypoint_reader);
      if (!insideWorld(waypoint.x, waypoint.y)) {
        waypoint_reader.fail("waypoint (" + formatNumber(waypoint.x) + ", " + formatNumber(waypoint.y) +
                             ") is outside the world " + worldBounds());
      }
      path.waypoints.push_back(waypoint);
    }
    if (path.waypoints.size() < 2) {
      reader.fail("a path needs at least two <waypoint>s, got " + std::to_string(path.waypoints.size()));
    }
    warnUnknownChildren(element, {"waypoint"});
    scenario_.paths.push_back(std::move(path));
  }

  void readEvents(const XMLElement& element) {
    ElementReader container(element, file_);
    finish(container);
    for (const XMLElement* e = element.FirstChildElement("event"); e; e = e->NextSiblingElement("event")) {
      readEvent(*e);
    }
    warnUnknownChildren(element, {"event"});
  }

  void readEvent(const XMLElement& element) {
    ElementReader reader(element, file_);
    Event event;
    event.line = reader.line();
    event.t = reader.requiredNumber("t");
    if (event.t < 0) reader.fail("event time t must be >= 0, got " + formatNumber(event.t));
    event.object = reader.requiredString("object");
    const Object& object = requireObject(reader, event.object);
    event.activity = reader.optionalString("activity");
    if (event.activity && event.activity->empty()) reader.fail("attribute 'activity' of <event> is empty");
    event.active = reader.optionalFlag("active");
    event.sound = reader.optionalString("sound");
    event.x = reader.optionalNumber("x");
    event.y = reader.optionalNumber("y");
    event.yaw = reader.optionalNumber("yaw");
    if (auto label = reader.optionalString("label")) event.label = requireCategory(reader, *label);
    finish(reader);

    if (event.sound && event.sound->empty()) reader.fail("attribute 'sound' of <event> is empty");
    if (event.sound) event.sound_path = resolveSound(reader, *event.sound);
    const double x = event.x.value_or(object.x);
    const double y = event.y.value_or(object.y);
    if ((event.x || event.y) && !insideWorld(x, y)) {
      reader.fail("event moves object '" + event.object + "' to (" + formatNumber(x) + ", " + formatNumber(y) +
                  "), outside the world " + worldBounds());
    }
    if (!event.activity && !event.active && !event.sound && !event.x && !event.y && !event.yaw && !event.label) {
      warn(event.line, "event changes nothing on object '" + event.object + "'");
    }
    if (event.t > scenario_.duration) {
      warn(event.line, "event at t=" + formatNumber(event.t) + " s comes after the end of the scenario (" +
                           formatNumber(scenario_.duration) + " s) and never applies");
    }
    if (!object.acoustic && !event.sound && event.active.value_or(false)) {
      warn(event.line, "event turns on object '" + event.object + "', which has no <acoustic> and no sound");
    }
    warnUnknownChildren(element, {});
    scenario_.events.push_back(std::move(event));
  }

  void readCongruency(const XMLElement& element) {
    ElementReader container(element, file_);
    finish(container);
    for (const XMLElement* e = element.FirstChildElement("c"); e; e = e->NextSiblingElement("c")) {
      ElementReader reader(*e, file_);
      const std::string label = requireCategory(reader, reader.requiredString("label"));
      const std::string activity = reader.requiredString("activity");
      const double value = reader.requiredNumber("value");
      if (value < 0 || value > 1) reader.fail("congruency value must be in [0, 1], got " + formatNumber(value));
      finish(reader);
      scenario_.congruency[{label, activity}] = value;
    }
    warnUnknownChildren(element, {"c"});
  }

  // The robot's disc must lie inside the world and clear of every visual footprint.
  void checkRobotStart(const XMLElement& element) const {
    const Robot& robot = scenario_.robot;
    const ElementReader reader(element, file_);
    const std::string where = "robot start (" + formatNumber(robot.x) + ", " + formatNumber(robot.y) + ")";
    if (robot.x - robot.radius < 0 || robot.x + robot.radius > scenario_.world.width ||
        robot.y - robot.radius < 0 || robot.y + robot.radius > scenario_.world.height) {
      reader.fail(where + " with radius " + formatNumber(robot.radius) + " m does not fit inside the world " +
                  worldBounds());
    }
    for (const Object& object : scenario_.objects) {
      if (distanceToFootprint(object, robot.x, robot.y) < robot.radius) {
        reader.fail(where + " with radius " + formatNumber(robot.radius) + " m overlaps object '" + object.id +
                    "' (line " + std::to_string(object.line) + ")");
      }
    }
  }

  // An audible object whose (acoustic label, activity) has no congruency gets
  // the default c; usually that is a typo in the activity.
  void checkCongruencyCoverage() {
    for (const Object& object : scenario_.objects) {
      if (!object.acoustic || !object.acoustic->active) continue;
      if (scenario_.congruency.count({object.acousticLabel(), object.activity}) == 0) {
        warn(object.line, "no congruency for (" + object.acousticLabel() + ", " + object.activity +
                              ") of audible object '" + object.id + "'; c defaults to 0.5");
      }
    }
  }

  std::string file_;
  std::ostream* warnings_;
  fs::path directory_;
  tinyxml2::XMLDocument document_;
  Scenario scenario_;
};

}  // namespace

Scenario loadScenario(const std::string& path, std::ostream* warnings) {
  return Loader(path, warnings).load();
}

Scenario loadScenario(const std::string& path) { return loadScenario(path, &std::cerr); }

}  // namespace beft::scenario
