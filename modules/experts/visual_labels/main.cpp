// beft-visual-labels: the mid-level visual labelling expert process (see --help).
#include "lib/expert/run_expert.hpp"
#include "experts/visual_labels/visual_labels_expert.hpp"

int main(int argc, char** argv) {
  beft::visual_labels::VisualLabelsExpert expert;
  return beft::expert::runExpertMain(argc, argv, expert);
}
