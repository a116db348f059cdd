// The run's Petri net drawn for the page (GET /net.svg): the layout of
// `beft net draw`, with every place and transition named so that the page
// lights the marking and the firing experts as MARKING messages come.
#pragma once

#include <string>

namespace beft::bridge {

// The SVG of the net in `pnml_path`; "" with `why` set when the file cannot
// be read or Graphviz cannot draw it (the page then lists the marking).
std::string drawNetAsSvg(const std::string& pnml_path, std::string& why);

}  // namespace beft::bridge
