#include "tools/generate/district_xml.hpp"

#include <tinyxml2.h>

#include <cstdio>

namespace beft::generate {

namespace {

std::string number(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.2f", value);
  std::string text = buffer;
  while (text.size() > 1 && text.back() == '0') text.pop_back();
  if (text.back() == '.') text.pop_back();
  if (text == "-0") text = "0";
  return text;
}

std::string colour(uint32_t rgb) {
  char buffer[8];
  std::snprintf(buffer, sizeof(buffer), "#%06x", rgb & 0xffffff);
  return buffer;
}

void writeObject(tinyxml2::XMLPrinter& out, const PlacedObject& object) {
  out.OpenElement("object");
  out.PushAttribute("id", object.id.c_str());
  out.PushAttribute("label", object.label.c_str());
  out.PushAttribute("x", number(object.x).c_str());
  out.PushAttribute("y", number(object.y).c_str());
  if (object.z != 0) out.PushAttribute("z", number(object.z).c_str());
  if (object.yaw != 0) out.PushAttribute("yaw", number(object.yaw).c_str());
  if (object.activity != "idle") out.PushAttribute("activity", object.activity.c_str());
  out.OpenElement("visual");
  if (object.cylinder) {
    out.PushAttribute("shape", "cylinder");
    out.PushAttribute("radius", number(object.radius).c_str());
    out.PushAttribute("height", number(object.height).c_str());
  } else {
    out.PushAttribute("shape", "box");
    out.PushAttribute("size", (number(object.size_x) + " " + number(object.size_y) + " " + number(object.size_z)).c_str());
  }
  out.PushAttribute("color", colour(object.color).c_str());
  out.CloseElement();
  if (object.sound) {
    out.OpenElement("acoustic");
    out.PushAttribute("sound", object.sound->file.c_str());
    out.PushAttribute("active", object.sound->active ? "1" : "0");
    out.PushAttribute("level", number(object.sound->level).c_str());
    if (!object.sound->label.empty()) out.PushAttribute("label", object.sound->label.c_str());
    out.CloseElement();
  }
  out.CloseElement();
}

// An XML comment may not hold "--" (XML 1.0, section 2.5).
std::string withoutDoubleDashes(std::string text) {
  for (auto at = text.find("--"); at != std::string::npos; at = text.find("--", at)) text.replace(at, 2, "-");
  return text;
}

}  // namespace

std::string districtXml(const District& district, const std::string& name, const std::string& how_made) {
  const DistrictParameters& p = district.parameters;
  tinyxml2::XMLPrinter out;
  out.PushHeader(false, true);
  const std::string comment =
      "\n  " + name + ": a generated district, " + number(p.width) + " x " + number(p.height) + " m, " +
      std::to_string(district.objects.size()) + " objects: " + std::to_string(district.buildings) +
      " ruined houses open on one side, " + std::to_string(district.persons) + " persons (" +
      std::to_string(district.calling_persons) + " calling for help), " + std::to_string(district.radios) +
      " radios that sound like a voice, rubble, cars, sirens and fires.\n"
      "  Streets 6 m wide run between the blocks; every person can be reached by\n"
      "  the robot's footprint, and every object but the walls seen from a place\n"
      "  it reaches (checked when the file was written).\n"
      "  Made by: " + withoutDoubleDashes(how_made) + "\n";
  out.PushComment(comment.c_str());
  out.OpenElement("scenario");
  out.PushAttribute("name", name.c_str());
  out.PushAttribute("version", "1");
  out.PushAttribute("dt", "0.1");
  out.PushAttribute("duration", number(district.duration).c_str());
  out.PushAttribute("seed", std::to_string(p.seed).c_str());
  out.OpenElement("world");
  out.PushAttribute("width", number(p.width).c_str());
  out.PushAttribute("height", number(p.height).c_str());
  out.PushAttribute("resolution", "0.1");
  out.CloseElement();
  out.OpenElement("robot");
  out.PushAttribute("x", number(district.robot_x).c_str());
  out.PushAttribute("y", number(district.robot_y).c_str());
  out.PushAttribute("yaw", number(district.robot_yaw).c_str());
  out.CloseElement();
  for (const PlacedObject& object : district.objects) writeObject(out, object);
  if (!district.events.empty()) {
    out.OpenElement("events");
    for (const PlacedEvent& event : district.events) {
      out.OpenElement("event");
      out.PushAttribute("t", number(event.t).c_str());
      out.PushAttribute("object", event.object.c_str());
      out.PushAttribute("activity", event.activity.c_str());
      if (event.active) out.PushAttribute("active", *event.active ? "1" : "0");
      out.CloseElement();
    }
    out.CloseElement();
  }
  out.OpenElement("congruency");
  out.OpenElement("c");
  out.PushAttribute("label", "person");
  out.PushAttribute("activity", "talking");
  out.PushAttribute("value", "0.5");
  out.CloseElement();
  out.CloseElement();
  out.CloseElement();
  return out.CStr();
}

}  // namespace beft::generate
