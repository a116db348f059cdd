#include "lib/scenario/element_reader.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace beft::scenario {

namespace {

std::string trimmed(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) return "";
  const auto last = text.find_last_not_of(" \t\r\n");
  return text.substr(first, last - first + 1);
}

std::string formatNumber(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

bool parseInteger(const std::string& text, int64_t* value) {
  const std::string clean = trimmed(text);
  if (clean.empty()) return false;
  errno = 0;
  char* end = nullptr;
  const long long parsed = std::strtoll(clean.c_str(), &end, 10);
  if (errno != 0 || end != clean.c_str() + clean.size()) return false;
  *value = parsed;
  return true;
}

}  // namespace

void emitWarning(const std::string& file, int line, const std::string& message,
                 std::ostream* warnings, std::vector<std::string>* collected) {
  const std::string text = file + ":" + std::to_string(line) + ": warning: " + message;
  if (warnings != nullptr) *warnings << text << '\n';
  if (collected != nullptr) collected->push_back(text);
}

ElementReader::ElementReader(const tinyxml2::XMLElement& element, const std::string& file)
    : element_(element), file_(file), line_(element.GetLineNum()) {}

void ElementReader::fail(const std::string& message) const {
  throw ScenarioError(file_, line_, message);
}

std::string ElementReader::describe(const char* attribute) const {
  return std::string("attribute '") + attribute + "' of <" + element_.Name() + ">";
}

bool ElementReader::has(const char* attribute) const {
  return element_.Attribute(attribute) != nullptr;
}

const char* ElementReader::raw(const char* attribute) {
  read_.insert(attribute);
  return element_.Attribute(attribute);
}

std::string ElementReader::requiredString(const char* attribute) {
  const char* value = raw(attribute);
  if (value == nullptr) {
    fail(std::string("<") + element_.Name() + "> is missing required attribute '" + attribute + "'");
  }
  if (trimmed(value).empty()) fail(describe(attribute) + " is empty");
  return value;
}

std::optional<std::string> ElementReader::optionalString(const char* attribute) {
  const char* value = raw(attribute);
  if (value == nullptr) return std::nullopt;
  return std::string(value);
}

bool ElementReader::parseNumber(const std::string& text, double* value) {
  const std::string clean = trimmed(text);
  if (clean.empty()) return false;
  errno = 0;
  char* end = nullptr;
  const double parsed = std::strtod(clean.c_str(), &end);
  if (end != clean.c_str() + clean.size()) return false;
  *value = parsed;
  return true;
}

std::optional<double> ElementReader::optionalNumber(const char* attribute) {
  const char* text = raw(attribute);
  if (text == nullptr) return std::nullopt;
  if (trimmed(text).empty()) fail(describe(attribute) + " is empty");
  double value = 0;
  if (!parseNumber(text, &value)) {
    fail(describe(attribute) + " is not a number: '" + text + "'");
  }
  if (!std::isfinite(value)) {
    fail(describe(attribute) + " must be a finite number, got '" + text + "'");
  }
  return value;
}

double ElementReader::requiredNumber(const char* attribute) {
  if (!has(attribute)) requiredString(attribute);  // fails with "missing"
  return *optionalNumber(attribute);
}

double ElementReader::number(const char* attribute, double default_value) {
  return optionalNumber(attribute).value_or(default_value);
}

double ElementReader::requiredPositive(const char* attribute) {
  const double value = requiredNumber(attribute);
  if (value <= 0) fail(describe(attribute) + " must be > 0, got " + formatNumber(value));
  return value;
}

double ElementReader::positive(const char* attribute, double default_value) {
  if (!has(attribute)) {
    read_.insert(attribute);
    return default_value;
  }
  return requiredPositive(attribute);
}

double ElementReader::nonNegative(const char* attribute, double default_value) {
  const double value = number(attribute, default_value);
  if (value < 0) fail(describe(attribute) + " must be >= 0, got " + formatNumber(value));
  return value;
}

int64_t ElementReader::integer(const char* attribute, int64_t default_value) {
  const char* text = raw(attribute);
  if (text == nullptr) return default_value;
  int64_t value = 0;
  if (!parseInteger(text, &value)) {
    fail(describe(attribute) + " is not an integer: '" + text + "'");
  }
  return value;
}

int ElementReader::positiveInteger(const char* attribute, int default_value) {
  const int64_t value = integer(attribute, default_value);
  if (value <= 0 || value > 1000000) {
    fail(describe(attribute) + " must be a whole number in [1, 1000000], got " +
         std::to_string(value));
  }
  return static_cast<int>(value);
}

uint64_t ElementReader::unsignedInteger(const char* attribute, uint64_t default_value) {
  const char* text = raw(attribute);
  if (text == nullptr) return default_value;
  const std::string clean = trimmed(text);
  errno = 0;
  char* end = nullptr;
  const unsigned long long value = std::strtoull(clean.c_str(), &end, 10);
  if (clean.empty() || clean[0] == '-' || errno != 0 || end != clean.c_str() + clean.size()) {
    fail(describe(attribute) + " is not a non-negative integer: '" + text + "'");
  }
  return value;
}

std::optional<bool> ElementReader::optionalFlag(const char* attribute) {
  const char* text = raw(attribute);
  if (text == nullptr) return std::nullopt;
  const std::string clean = trimmed(text);
  if (clean == "0") return false;
  if (clean == "1") return true;
  fail(describe(attribute) + " must be 0 or 1, got '" + text + "'");
}

bool ElementReader::flag(const char* attribute, bool default_value) {
  return optionalFlag(attribute).value_or(default_value);
}

void ElementReader::warnUnread(std::ostream* warnings, std::vector<std::string>* collected) const {
  for (const tinyxml2::XMLAttribute* attribute = element_.FirstAttribute(); attribute != nullptr;
       attribute = attribute->Next()) {
    if (read_.count(attribute->Name()) == 0) {
      emitWarning(file_, line_,
                  std::string("unknown attribute '") + attribute->Name() + "' on <" +
                      element_.Name() + ">",
                  warnings, collected);
    }
  }
}

}  // namespace beft::scenario
