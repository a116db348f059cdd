// The PNML reader on any text, as the arbiter reads it and as any P/T net,
// and the analysis of whatever it reads (a small budget): a NetError for
// what is not a net, never a crash.
#include <stdexcept>
#include <string>

#include "lib/petri/net_analysis.hpp"
#include "lib/petri/pnml_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    beft::arbiter::readPnmlString(text, "fuzz.pnml");
  } catch (const std::exception&) {
  }
  try {
    beft::arbiter::PnmlReadOptions any_net;
    any_net.schedule = false;
    const beft::arbiter::Net net = beft::arbiter::readPnmlString(text, "fuzz.pnml", any_net);
    beft::arbiter::NetAnalysisOptions options;
    options.max_markings = 2000;
    beft::arbiter::analyseNet(net, options);
  } catch (const std::exception&) {
  }
  return 0;
}
