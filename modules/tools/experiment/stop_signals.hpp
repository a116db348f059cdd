// Ctrl-C and SIGTERM as a request to stop, for the local pool (it stops its
// running episodes and records nothing for them) and for the wait on a Slurm
// job (the job goes on). Installed without SA_RESTART, so that a signal
// wakes a blocking waitpid or sleep.
#pragma once

namespace beft::experiment {

void catchStopSignals();
bool stopRequested();

}  // namespace beft::experiment
