// beft-acoustic-labels: the mid-level acoustic labelling expert process (see --help).
#include "experts/acoustic_labels/acoustic_labels_expert.hpp"
#include "lib/expert/run_expert.hpp"

int main(int argc, char** argv) {
  beft::acoustic_labels::AcousticLabelsExpert expert;
  return beft::expert::runExpertMain(argc, argv, expert);
}
