// beft-audio: the low-level audio expert process (see --help).
#include "experts/audio/audio_expert.hpp"
#include "lib/expert/run_expert.hpp"

int main(int argc, char** argv) {
  beft::audio::AudioExpert expert;
  return beft::expert::runExpertMain(argc, argv, expert);
}
