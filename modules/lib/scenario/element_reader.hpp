// Reads one XML element's attributes with the checks the scenario format asks
// for (numbers that parse and are finite, 0/1 flags, required attributes) and
// turns every problem into a ScenarioError at the element's line. Attributes
// never read are reported as warnings by warnUnread(): extensions are welcome,
// but a typo must not pass silently.
#pragma once

#include <cstdint>
#include <optional>
#include <ostream>
#include <set>
#include <string>

#include <tinyxml2.h>

#include "lib/scenario/scenario.hpp"

namespace beft::scenario {

class ElementReader {
 public:
  ElementReader(const tinyxml2::XMLElement& element, const std::string& file);

  int line() const { return line_; }
  const char* name() const { return element_.Name(); }
  [[noreturn]] void fail(const std::string& message) const;

  bool has(const char* attribute) const;
  std::string requiredString(const char* attribute);
  std::optional<std::string> optionalString(const char* attribute);

  // Finite numbers; "1.5x", "nan" and "inf" are refused.
  double requiredNumber(const char* attribute);
  std::optional<double> optionalNumber(const char* attribute);
  double number(const char* attribute, double default_value);
  // The same, also refused unless > 0.
  double requiredPositive(const char* attribute);
  double positive(const char* attribute, double default_value);
  double nonNegative(const char* attribute, double default_value);

  int positiveInteger(const char* attribute, int default_value);
  int64_t integer(const char* attribute, int64_t default_value);
  uint64_t unsignedInteger(const char* attribute, uint64_t default_value);

  // Exactly "0" or "1".
  std::optional<bool> optionalFlag(const char* attribute);
  bool flag(const char* attribute, bool default_value);

  // One "FILE:LINE: warning: unknown attribute 'x' on <name>" per attribute
  // this reader was never asked about.
  void warnUnread(std::ostream* warnings, std::vector<std::string>* collected) const;

  // Strict parse helpers, exposed for values inside text (e.g. box size).
  static bool parseNumber(const std::string& text, double* value);

 private:
  const char* raw(const char* attribute);
  std::string describe(const char* attribute) const;

  const tinyxml2::XMLElement& element_;
  const std::string& file_;
  int line_;
  std::set<std::string> read_;
};

// Emits "FILE:LINE: warning: MESSAGE" to the stream (if any) and the list.
void emitWarning(const std::string& file, int line, const std::string& message,
                 std::ostream* warnings, std::vector<std::string>* collected);

}  // namespace beft::scenario
