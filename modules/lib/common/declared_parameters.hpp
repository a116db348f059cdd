// Named parameters declared once, as OMPL's declareParam: the name, the
// member it sets, the range and the meaning. The default is the member's
// value when it is declared, so it is written once, in the member's
// initialiser. Used by experts, planners, the model's parameters and the
// world: --param NAME=VALUE, --help and --interface all read the same list.
#pragma once

#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <string>
#include <type_traits>
#include <vector>

namespace beft {

class DeclaredParameters {
 public:
  DeclaredParameters() = default;
  // Entries point at the members they set: never copied.
  DeclaredParameters(const DeclaredParameters&) = delete;
  DeclaredParameters& operator=(const DeclaredParameters&) = delete;

  struct Info {
    std::string name;
    std::string default_value;  // as text, the member's value at declaration
    std::string range;          // e.g. "[0, 1]", "> 0", "0/1", "euclidean|geodesic"
    std::string meaning;
  };

  static constexpr double kNoLimit = std::numeric_limits<double>::infinity();

  // A number within [min, max]; min_open / max_open exclude the bound.
  void declare(const std::string& name, double& member, double min, double max, const std::string& meaning,
               bool min_open = false, bool max_open = false);
  // A whole number within [min, max].
  template <typename Integer, typename = std::enable_if_t<std::is_integral_v<Integer> && !std::is_same_v<Integer, bool>>>
  void declare(const std::string& name, Integer& member, int64_t min, int64_t max, const std::string& meaning);
  void declare(const std::string& name, bool& member, const std::string& meaning);
  // One of a list of words, each with the value it stands for.
  template <typename Enum>
  void declareChoice(const std::string& name, Enum& member, const std::vector<std::pair<std::string, Enum>>& words,
                     const std::string& meaning);
  // Free text, checked by `check` (which throws std::invalid_argument).
  void declare(const std::string& name, std::string& member, const std::string& meaning,
               std::function<void(const std::string&)> check = {});

  // Sets one parameter from text; std::invalid_argument naming the
  // parameter and its range when the name is unknown or the value out of range.
  void set(const std::string& name, const std::string& value);
  void setAll(const std::map<std::string, std::string>& values);
  // Every parameter back to its default.
  void resetToDefaults();
  bool has(const std::string& name) const;
  const std::vector<Info>& list() const { return infos_; }
  // Current value as text (after set), for reports.
  std::string current(const std::string& name) const;
  // "name (default D, range R): meaning" lines, for --help and --interface.
  std::string describe(const std::string& indent = "  ") const;

 private:
  struct Entry {
    std::function<bool(const std::string&)> set;  // false: out of range
    std::function<std::string()> get;
    std::function<void()> reset;  // back to the value it had when declared
  };
  void add(Info info, Entry entry);
  static bool parseWholeNumber(const std::string& text, int64_t& value);

  std::vector<Info> infos_;
  std::map<std::string, Entry> entries_;
};

template <typename Integer, typename>
void DeclaredParameters::declare(const std::string& name, Integer& member, int64_t min, int64_t max,
                                 const std::string& meaning) {
  Entry entry;
  entry.set = [&member, min, max](const std::string& text) {
    int64_t value = 0;
    if (!parseWholeNumber(text, value) || value < min || value > max) return false;
    member = static_cast<Integer>(value);
    return true;
  };
  entry.get = [&member] { return std::to_string(member); };
  entry.reset = [&member, initial = member] { member = initial; };
  add({name, std::to_string(member), "whole number in [" + std::to_string(min) + ", " + std::to_string(max) + "]",
       meaning},
      std::move(entry));
}

template <typename Enum>
void DeclaredParameters::declareChoice(const std::string& name, Enum& member,
                                       const std::vector<std::pair<std::string, Enum>>& words,
                                       const std::string& meaning) {
  std::string range, default_word;
  for (const auto& [word, value] : words) {
    range += (range.empty() ? "" : "|") + word;
    if (value == member && default_word.empty()) default_word = word;
  }
  Entry entry;
  entry.set = [&member, words](const std::string& text) {
    for (const auto& [word, value] : words)
      if (word == text) {
        member = value;
        return true;
      }
    return false;
  };
  entry.reset = [&member, initial = member] { member = initial; };
  entry.get = [&member, words] {
    for (const auto& [word, value] : words)
      if (value == member) return word;
    return std::string("?");
  };
  add({name, default_word, range, meaning}, std::move(entry));
}

}  // namespace beft
