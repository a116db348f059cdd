#include "services/ssr_bridge/ssr_requests.hpp"

#include <cstdint>
#include <cstdio>

namespace beft::ssr_bridge {

namespace {

// The length of the UTF-8 sequence starting at text[i], 0 if it is not one.
std::size_t utf8SequenceLength(std::string_view text, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char lead = byte(i);
  std::size_t length;
  uint32_t code;
  if (lead < 0x80) return 1;
  if ((lead & 0xE0) == 0xC0) length = 2, code = lead & 0x1F;
  else if ((lead & 0xF0) == 0xE0) length = 3, code = lead & 0x0F;
  else if ((lead & 0xF8) == 0xF0) length = 4, code = lead & 0x07;
  else return 0;
  if (i + length > text.size()) return 0;
  for (std::size_t k = 1; k < length; ++k) {
    if ((byte(i + k) & 0xC0) != 0x80) return 0;
    code = (code << 6) | (byte(i + k) & 0x3F);
  }
  static const uint32_t kSmallest[] = {0, 0, 0x80, 0x800, 0x10000};
  if (code < kSmallest[length] || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF)) return 0;
  return length;
}

std::string formatted(const char* format, double value) {
  char text[64];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

std::string positionElement(double x, double y) {
  return "<position x=\"" + metres(x) + "\" y=\"" + metres(y) + "\"/>";
}

}  // namespace

bool representable(std::string_view text) {
  for (std::size_t i = 0; i < text.size();) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (c < 0x20 && c != '\t' && c != '\n' && c != '\r') return false;
    if (c == 0x7F) return false;
    const std::size_t length = utf8SequenceLength(text, i);
    if (length == 0) return false;
    i += length;
  }
  return true;
}

std::string escapeAttribute(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      case '\t': out += "&#9;"; break;
      case '\n': out += "&#10;"; break;
      case '\r': out += "&#13;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string metres(double value) { return formatted("%.3f", value); }
std::string hundredths(double value) { return formatted("%.2f", value); }

std::string newSourceRequest(const NewSource& source) {
  return "<request><source new=\"true\" name=\"" + escapeAttribute(source.name) + "\" file=\"" +
         escapeAttribute(source.file) + "\" volume=\"" + hundredths(source.volume_db) + "\" mute=\"" +
         (source.mute ? "true" : "false") + "\">" + positionElement(source.x, source.y) + "</source></request>";
}

std::string sourceChangeRequest(int number, const SourceChange& change) {
  std::string request = "<request><source id=\"" + std::to_string(number) + "\"";
  if (change.volume_db) request += " volume=\"" + hundredths(*change.volume_db) + "\"";
  if (change.mute) request += std::string(" mute=\"") + (*change.mute ? "true" : "false") + "\"";
  if (change.x && change.y) return request + ">" + positionElement(*change.x, *change.y) + "</source></request>";
  return request + "/></request>";
}

std::string referenceRequest(const ReferenceChange& change) {
  std::string request = "<request><reference>";
  if (change.x && change.y) request += positionElement(*change.x, *change.y);
  if (change.azimuth) request += "<orientation azimuth=\"" + hundredths(*change.azimuth) + "\"/>";
  return request + "</reference></request>";
}

std::string clearSceneRequest() { return "<request><scene clear=\"true\"/></request>"; }

}  // namespace beft::ssr_bridge
