#include "lib/common/declared_parameters.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace beft {

namespace {

std::string numberText(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

std::string rangeText(double min, double max, bool min_open, bool max_open) {
  const bool has_min = std::isfinite(min), has_max = std::isfinite(max);
  if (has_min && has_max)
    return std::string(min_open ? "(" : "[") + numberText(min) + ", " + numberText(max) + (max_open ? ")" : "]");
  if (has_min) return (min_open ? "> " : ">= ") + numberText(min);
  if (has_max) return (max_open ? "< " : "<= ") + numberText(max);
  return "any finite number";
}

bool parseNumber(const std::string& text, double& value) {
  std::size_t used = 0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    return false;
  }
  return used == text.size() && std::isfinite(value);
}

bool within(double value, double min, double max, bool min_open, bool max_open) {
  if (min_open ? !(value > min) : !(value >= min)) return false;
  if (max_open ? !(value < max) : !(value <= max)) return false;
  return true;
}

}  // namespace

void DeclaredParameters::resetToDefaults() {
  for (auto& [name, entry] : entries_) entry.reset();
}

void DeclaredParameters::add(Info info, Entry entry) {
  if (entries_.count(info.name)) throw std::logic_error("parameter " + info.name + " declared twice");
  entries_.emplace(info.name, std::move(entry));
  infos_.push_back(std::move(info));
}

void DeclaredParameters::declare(const std::string& name, double& member, double min, double max,
                                 const std::string& meaning, bool min_open, bool max_open) {
  Entry entry;
  entry.set = [&member, min, max, min_open, max_open](const std::string& text) {
    double value = 0;
    if (!parseNumber(text, value) || !within(value, min, max, min_open, max_open)) return false;
    member = value;
    return true;
  };
  entry.get = [&member] { return numberText(member); };
  entry.reset = [&member, initial = member] { member = initial; };
  add({name, numberText(member), rangeText(min, max, min_open, max_open), meaning}, std::move(entry));
}

bool DeclaredParameters::parseWholeNumber(const std::string& text, int64_t& value) {
  std::size_t used = 0;
  try {
    value = std::stoll(text, &used);
  } catch (const std::exception&) {
    return false;
  }
  return used == text.size() && !text.empty();
}

void DeclaredParameters::declare(const std::string& name, bool& member, const std::string& meaning) {
  Entry entry;
  entry.set = [&member](const std::string& v) {
    if (v == "1" || v == "true" || v == "yes" || v == "on") member = true;
    else if (v == "0" || v == "false" || v == "no" || v == "off") member = false;
    else return false;
    return true;
  };
  entry.get = [&member] { return std::string(member ? "1" : "0"); };
  entry.reset = [&member, initial = member] { member = initial; };
  add({name, member ? "1" : "0", "0|1", meaning}, std::move(entry));
}

void DeclaredParameters::declare(const std::string& name, std::string& member, const std::string& meaning,
                                 std::function<void(const std::string&)> check) {
  Entry entry;
  entry.set = [&member, check](const std::string& text) {
    if (check) check(text);
    member = text;
    return true;
  };
  entry.get = [&member] { return member; };
  entry.reset = [&member, initial = member] { member = initial; };
  add({name, member, "text", meaning}, std::move(entry));
}

void DeclaredParameters::set(const std::string& name, const std::string& value) {
  const auto it = entries_.find(name);
  if (it == entries_.end()) {
    std::string known;
    for (const auto& info : infos_) known += (known.empty() ? "" : ", ") + info.name;
    throw std::invalid_argument("unknown parameter '" + name + "' (known: " + (known.empty() ? "none" : known) + ")");
  }
  if (it->second.set(value)) return;
  for (const auto& info : infos_)
    if (info.name == name)
      throw std::invalid_argument("parameter " + name + "='" + value + "' is not " + info.range);
}

void DeclaredParameters::setAll(const std::map<std::string, std::string>& values) {
  for (const auto& [name, value] : values) set(name, value);
}

bool DeclaredParameters::has(const std::string& name) const { return entries_.count(name) > 0; }

std::string DeclaredParameters::current(const std::string& name) const {
  const auto it = entries_.find(name);
  if (it == entries_.end()) throw std::invalid_argument("unknown parameter '" + name + "'");
  return it->second.get();
}

std::string DeclaredParameters::describe(const std::string& indent) const {
  std::ostringstream out;
  for (const auto& info : infos_)
    out << indent << info.name << " (default " << info.default_value << ", " << info.range << "): " << info.meaning
        << "\n";
  return out.str();
}

}  // namespace beft
