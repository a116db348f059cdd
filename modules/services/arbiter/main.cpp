// beft-arbiter: the Petri-net arbiter process (see --help, --interface).
#include "services/arbiter/arbiter_process.hpp"

int main(int argc, char** argv) {
  beft::arbiter::ArbiterProcess arbiter;
  return beft::service::runServiceMain(argc, argv, arbiter);
}
