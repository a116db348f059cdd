// beft-blackboard: the blackboard process (see --help, --interface).
#include "blackboard/blackboard_process.hpp"

int main(int argc, char** argv) {
  beft::blackboard::BlackboardProcess blackboard;
  return beft::service::runServiceMain(argc, argv, blackboard);
}
