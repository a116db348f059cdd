#include "services/bridge/net_drawing.hpp"

#include <optional>

#include "lib/petri/graphviz.hpp"
#include "lib/petri/net_dot.hpp"
#include "lib/petri/pnml_reader.hpp"

namespace beft::bridge {

std::string drawNetAsSvg(const std::string& pnml_path, std::string& why) {
  arbiter::Net net;
  try {
    arbiter::PnmlReadOptions options;
    options.schedule = false;  // any net the arbiter ran is drawn; it has checked it already
    net = arbiter::readPnmlFile(pnml_path, options);
  } catch (const arbiter::NetError& e) {
    why = e.problems().empty() ? std::string(e.what()) : e.problems().front();
    return "";
  }
  // Drawn empty: the page fills in each MARKING as it comes.
  arbiter::ShownMarking empty;
  empty.caption = "the marking as the run's arbiter publishes it";
  return arbiter::drawWithGraphviz(arbiter::netToDot(net, empty), "svg", why);
}

}  // namespace beft::bridge
