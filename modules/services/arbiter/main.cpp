// beft-arbiter: the Petri-net arbiter process (see --help, --interface).
#include "arbiter_process.hpp"

int main(int argc, char** argv) {
  beft::arbiter::ArbiterProcess arbiter;
  return beft::service::runServiceMain(argc, argv, arbiter);
}
