// A Slurm cluster of one node for a test: munged with its own key and
// socket, slurmctld and slurmd with a slurm.conf of their own, everything in
// a temporary folder, SLURM_CONF set for the test's process and its children.
// It needs root (the daemons run as root) and Debian's munge, slurmctld,
// slurmd and slurm-client.
#pragma once

#include <sys/types.h>

#include <filesystem>
#include <string>
#include <vector>

namespace beft::test {

class SlurmCluster {
 public:
  inline static const char* const kPartition = "beft";

  // "" once the node is idle in the partition kPartition, else why it is not
  // (the cluster is stopped again then).
  std::string start(const std::filesystem::path& dir);
  // Cancels what is left in the queue, ends the daemons, removes the folder.
  void stop();
  ~SlurmCluster() { stop(); }

 private:
  std::string startMunge();
  std::string startSlurm();
  std::string logTail(const std::string& log) const;
  void writeConfig(int controller_port, int node_port) const;

  std::filesystem::path dir_;
  std::vector<pid_t> daemons_;  // children of the test, in the foreground
  bool up_ = false;             // the node was idle: jobs may be left to cancel
};

}  // namespace beft::test
