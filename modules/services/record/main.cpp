// beft-record: records a run's LCM traffic into an LCM log (see --help);
// ./beft run and ./beft launch --record start it.
#include "services/record/record_process.hpp"

int main(int argc, char** argv) {
  beft::record::RecordProcess recorder;
  return beft::service::runServiceMain(argc, argv, recorder);
}
