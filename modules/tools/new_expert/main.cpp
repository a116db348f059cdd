// beft-new-expert: writes a new expert and its tests, prints the steps left
// (./beft new expert NAME ...; see --help).
#include <iostream>

#include "tools/new_expert/expert_command_line.hpp"
#include "tools/new_expert/expert_files.hpp"
#include "tools/new_expert/manual_steps.hpp"

int main(int argc, char** argv) {
  using namespace beft::new_expert;
  ExpertRequest request;
  if (const auto code = parseCommandLine(argc, argv, request)) return *code;
  try {
    if (const auto steps = finishInterruptedWrite(request.root)) {
      std::cerr << "beft-new-expert: an earlier run was stopped while putting its files in place; they are all "
                   "there now (run again for anything else)\n";
      std::cout << *steps;
      return 0;
    }
    const ExpertSpec spec = checkRequest(request);
    const auto files = expertFiles(spec);
    const std::string steps = manualSteps(spec, files);  // reads the nets before anything is written
    writeFiles(spec.root, files, steps);
    std::cout << steps;
    return 0;
  } catch (const SpecError& error) {
    std::cerr << "beft-new-expert: " << error.what() << "\n";
    return 2;
  } catch (const std::exception& error) {
    std::cerr << "beft-new-expert: " << error.what() << "\n";
    return 1;
  }
}
