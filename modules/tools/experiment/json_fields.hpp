// Fields of the experiment's JSON files (report.json, episode.json), which
// are files on disk, damaged or from another version: a field missing or of
// another type reads as the fallback (nlohmann's json::value would throw and
// end the experiment).
#pragma once

#include <string>
#include <type_traits>
#include <vector>

#include <nlohmann/json.hpp>

namespace beft::experiment {

template <typename T>
T valueOr(const nlohmann::json& object, const char* key, T fallback) {
  if (!object.is_object()) return fallback;
  const auto it = object.find(key);
  if (it == object.end()) return fallback;
  if constexpr (std::is_same_v<T, bool>) {
    return it->is_boolean() ? it->get<bool>() : fallback;
  } else if constexpr (std::is_arithmetic_v<T>) {
    return it->is_number() ? it->get<T>() : fallback;
  } else {
    return it->is_string() ? it->get<std::string>() : fallback;
  }
}

// The array under key, or an empty one.
inline nlohmann::json listOr(const nlohmann::json& object, const char* key) {
  if (!object.is_object()) return nlohmann::json::array();
  const auto it = object.find(key);
  return it != object.end() && it->is_array() ? *it : nlohmann::json::array();
}

// The strings of the array under key (entries of another type left out).
inline std::vector<std::string> stringsOr(const nlohmann::json& object, const char* key) {
  std::vector<std::string> strings;
  for (const auto& entry : listOr(object, key))
    if (entry.is_string()) strings.push_back(entry.get<std::string>());
  return strings;
}

}  // namespace beft::experiment
