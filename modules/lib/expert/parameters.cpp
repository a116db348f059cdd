#include <cmath>
#include <stdexcept>

#include "expert.hpp"

namespace beft::expert {

namespace {
std::invalid_argument badValue(const std::string& key, const std::string& value,
                               const char* expected) {
  return std::invalid_argument("parameter " + key + "='" + value + "' is not " + expected);
}
}  // namespace

double Parameters::getDouble(const std::string& key, double fallback) const {
  auto it = values_.find(key);
  if (it == values_.end()) return fallback;
  std::size_t used = 0;
  double value = 0;
  try {
    value = std::stod(it->second, &used);
  } catch (const std::exception&) {
    throw badValue(key, it->second, "a number");
  }
  if (used != it->second.size() || !std::isfinite(value))
    throw badValue(key, it->second, "a finite number");
  return value;
}

int64_t Parameters::getInt(const std::string& key, int64_t fallback) const {
  auto it = values_.find(key);
  if (it == values_.end()) return fallback;
  std::size_t used = 0;
  int64_t value = 0;
  try {
    value = std::stoll(it->second, &used);
  } catch (const std::exception&) {
    throw badValue(key, it->second, "an integer");
  }
  if (used != it->second.size()) throw badValue(key, it->second, "an integer");
  return value;
}

bool Parameters::getBool(const std::string& key, bool fallback) const {
  auto it = values_.find(key);
  if (it == values_.end()) return fallback;
  const std::string& v = it->second;
  if (v == "1" || v == "true" || v == "yes" || v == "on") return true;
  if (v == "0" || v == "false" || v == "no" || v == "off") return false;
  throw badValue(key, v, "a boolean (1/0, true/false)");
}

std::string Parameters::getString(const std::string& key, const std::string& fallback) const {
  auto it = values_.find(key);
  return it == values_.end() ? fallback : it->second;
}

}  // namespace beft::expert
