// beft-dw: the dynamic-weighting expert process (see --help).
#include "experts/dw/dw_expert.hpp"
#include "lib/expert/run_expert.hpp"

int main(int argc, char** argv) {
  beft::dw::DwExpert expert;
  return beft::expert::runExpertMain(argc, argv, expert);
}
