// beft-record as a service: writes every message heard into an LCM log file
// (lcm-logplayer plays it), and on SIGINT or SIGTERM what is still arriving.
#pragma once

#include <string>
#include <vector>

#include "services/record/recorded_ports.hpp"
#include "services/record/recorder.hpp"
#include "lib/service/service.hpp"

namespace beft::record {

class RecordProcess : public service::Service {
 public:
  RecordProcess() { include(recorded_); }
  std::string name() const override { return "record"; }
  std::string description() const override;
  void addOptions(CLI::App& app) override;
  void onStartUp() override;
  int serve(service::Context& context) override;
  bool resumable() const override { return false; }  // its log is what the others resume from
  bool belongsToARun() const override { return false; }  // it records every run heard

 private:
  void recordUntilStopped(Recorder& recorder, const service::StopSignals& stop);
  void reportEnd(const Recorder& recorder) const;

  RecordOptions options_;
  std::string camera_ = "all";  // --camera, parsed into options_ at start-up
  bool quiet_ = false;
  int batch_ms_ = 5;
  RecordedPorts recorded_;
};

}  // namespace beft::record
