// The XML requests the bridge sends to SSR's network interface (SSR 0.6,
// src/legacy_network/commandparser.cpp), each one message without the binary
// zero that ends it on the wire (SsrLink adds it).
//
// Sources are addressed by SSR's number for them: their one-based place in
// SSR's list of sources, in the order they were made (scene.h: get_source_id).
// One request per source, because SSR abandons the rest of a request at the
// first unknown source number.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace beft::ssr_bridge {

// Whether text can stand in an XML attribute: valid UTF-8 without control
// characters other than tab, line feed and carriage return (XML 1.0 has no
// way to write the others, and a binary zero would end the message early).
bool representable(std::string_view text);

// text with & < > " ' (and tab, line feed, carriage return, which a parser
// would turn into spaces) written as references. text must be representable.
std::string escapeAttribute(std::string_view text);

struct NewSource {
  std::string name;  // shown by SSR, and how the bridge recognises SSR's reports of it
  std::string file;  // absolute path of the WAV file, opened by SSR itself
  double x = 0, y = 0;
  double volume_db = 0;
  bool mute = false;
};
std::string newSourceRequest(const NewSource& source);

// What changed of one source: only the fields given are sent.
struct SourceChange {
  std::optional<double> x, y;  // both or neither
  std::optional<double> volume_db;
  std::optional<bool> mute;
  bool empty() const { return !x && !volume_db && !mute; }
};
std::string sourceChangeRequest(int number, const SourceChange& change);

// The listener: position and/or azimuth (degrees counter-clockwise from +x).
struct ReferenceChange {
  std::optional<double> x, y;  // both or neither
  std::optional<double> azimuth;
  bool empty() const { return !x && !azimuth; }
};
std::string referenceRequest(const ReferenceChange& change);

// Removes every source from SSR's scene.
std::string clearSceneRequest();

// How values are written: metres to the millimetre, degrees and decibels to
// the hundredth. The bridge compares values at this resolution, so a change
// too small to be written is not sent.
std::string metres(double value);
std::string hundredths(double value);

}  // namespace beft::ssr_bridge
