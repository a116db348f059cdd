// What beft-record takes, declared once as a port: every channel of every
// run heard, under the names heard (the log keeps the runs apart).
#pragma once

#include "lib/service/ports.hpp"

namespace beft::record {

struct RecordedPorts : service::PortSet {
  // The Recorder reads its receiver itself: no handler here.
  service::EveryChannelPort everything_in{
      *this, "every channel but --exclude, in the order the messages entered the host", nullptr,
      service::Receiving().everyRun()};
  transport::Selection taken() const { return selection(service::Delivery::kWakes); }
};

}  // namespace beft::record
