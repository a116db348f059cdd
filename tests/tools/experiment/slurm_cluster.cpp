#include "slurm_cluster.hpp"

#include <fcntl.h>
#include <netinet/in.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <functional>
#include <fstream>
#include <random>
#include <sstream>
#include <thread>

namespace beft::test {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// The program on PATH or in /usr/sbin (root's daemons), else "".
std::string program(const std::string& name) {
  const char* path = std::getenv("PATH");
  std::stringstream folders(std::string(path ? path : "") + ":/usr/sbin:/sbin");
  for (std::string folder; std::getline(folders, folder, ':');)
    if (!folder.empty() && access((fs::path(folder) / name).c_str(), X_OK) == 0) return (fs::path(folder) / name);
  return "";
}

// Started with its output into `log`; it dies with the test if the test dies.
pid_t startDaemon(const std::vector<std::string>& argv, const fs::path& log) {
  const pid_t pid = fork();
  if (pid != 0) return pid;
  prctl(PR_SET_PDEATHSIG, SIGKILL);
  const int out = open(log.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
  dup2(out, STDOUT_FILENO);
  dup2(out, STDERR_FILENO);
  std::vector<char*> args;
  for (const auto& arg : argv) args.push_back(const_cast<char*>(arg.c_str()));
  args.push_back(nullptr);
  execv(args[0], args.data());
  _exit(127);
}

// Its output's first line ("" if it failed).
std::string outputOf(const std::vector<std::string>& argv, const fs::path& file) {
  const pid_t pid = startDaemon(argv, file);
  int status = 0;
  waitpid(pid, &status, 0);
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  fs::remove(file);
  return WIFEXITED(status) && WEXITSTATUS(status) == 0 ? line : "";
}

bool waitFor(const std::function<bool()>& condition, int seconds) {
  const auto deadline = Clock::now() + std::chrono::seconds(seconds);
  while (!condition()) {
    if (Clock::now() > deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
  }
  return true;
}

// Two TCP ports free now (held together, so that they differ).
std::pair<int, int> freePorts() {
  int ports[2] = {0, 0}, sockets[2];
  for (int i = 0; i < 2; ++i) {
    sockets[i] = socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in address = {};
    address.sin_family = AF_INET;
    socklen_t length = sizeof(address);
    bind(sockets[i], reinterpret_cast<sockaddr*>(&address), sizeof(address));
    getsockname(sockets[i], reinterpret_cast<sockaddr*>(&address), &length);
    ports[i] = ntohs(address.sin_port);
  }
  for (const int s : sockets) close(s);
  return {ports[0], ports[1]};
}

}  // namespace

std::string SlurmCluster::logTail(const std::string& log) const {
  std::ifstream in(dir_ / log);
  std::string line, last;
  while (std::getline(in, line))
    if (line.find("error") != std::string::npos) last = line;
  return last.empty() ? "" : " (" + log + ": " + last + ")";
}

std::string SlurmCluster::startMunge() {
  const std::string munged = program("munged");
  if (munged.empty()) return "munged is not installed (Debian's munge)";
  fs::create_directories(dir_ / "munge");
  std::random_device random;
  std::ofstream key(dir_ / "munge" / "munge.key", std::ios::binary);
  for (int i = 0; i < 1024; ++i) key.put(static_cast<char>(random()));
  key.close();
  chmod((dir_ / "munge" / "munge.key").c_str(), 0400);
  const std::string d = dir_.string();
  // --force: as root, in a folder munged would not choose.
  daemons_.push_back(startDaemon({munged, "--foreground", "--force", "--socket=" + d + "/munge/munge.socket",
                                  "--key-file=" + d + "/munge/munge.key", "--pid-file=" + d + "/munge/munged.pid",
                                  "--seed-file=" + d + "/munge/munged.seed", "--log-file=" + d + "/munged.log"},
                                 dir_ / "munged.out"));
  if (!waitFor([&] { return fs::exists(dir_ / "munge" / "munge.socket"); }, 10))
    return "munged did not come up within 10 s" + logTail("munged.log");
  return "";
}

void SlurmCluster::writeConfig(int controller_port, int node_port) const {
  const std::string d = dir_.string();
  const long cpus = sysconf(_SC_NPROCESSORS_ONLN);
  // Half the memory: a node configured with more than it has is drained.
  const long memory_mb = sysconf(_SC_PHYS_PAGES) / 2 / (1024 * 1024 / sysconf(_SC_PAGESIZE));
  std::ofstream(dir_ / "slurm.conf")
      << "ClusterName=beft\nSlurmctldHost=localhost\nSlurmctldPort=" << controller_port
      << "\nSlurmdPort=" << node_port << "\nSlurmUser=root\nSlurmdUser=root\nAuthType=auth/munge\n"
      << "CredType=cred/munge\nAuthInfo=socket=" << d << "/munge/munge.socket\nStateSaveLocation=" << d
      << "/state\nSlurmdSpoolDir=" << d << "/spool\nSlurmctldPidFile=" << d << "/slurmctld.pid\nSlurmdPidFile=" << d
      << "/slurmd.pid\nSlurmctldLogFile=" << d << "/slurmctld.log\nSlurmdLogFile=" << d << "/slurmd.log\n"
      << "ProctrackType=proctrack/linuxproc\nTaskPlugin=task/none\nSelectType=select/cons_tres\n"
      << "SelectTypeParameters=CR_CPU\nJobAcctGatherType=jobacct_gather/none\n"
      << "AccountingStorageType=accounting_storage/none\nMpiDefault=none\nReturnToService=2\n"
      << "NodeName=localhost CPUs=" << cpus << " RealMemory=" << memory_mb << " State=UNKNOWN\n"
      << "PartitionName=" << kPartition << " Nodes=localhost Default=YES MaxTime=INFINITE State=UP\n";
}

std::string SlurmCluster::startSlurm() {
  const std::string slurmctld = program("slurmctld"), slurmd = program("slurmd"), sinfo = program("sinfo");
  if (slurmctld.empty() || slurmd.empty()) return "slurmctld or slurmd is not installed (Debian's slurmctld, slurmd)";
  if (sinfo.empty() || program("sbatch").empty()) return "sinfo or sbatch is not installed (Debian's slurm-client)";
  fs::create_directories(dir_ / "state");
  fs::create_directories(dir_ / "spool");
  const auto [controller_port, node_port] = freePorts();
  writeConfig(controller_port, node_port);
  setenv("SLURM_CONF", (dir_ / "slurm.conf").c_str(), 1);
  daemons_.push_back(startDaemon({slurmctld, "-D", "-c"}, dir_ / "slurmctld.out"));
  daemons_.push_back(startDaemon({slurmd, "-D", "-N", "localhost"}, dir_ / "slurmd.out"));
  const std::vector<std::string> state = {sinfo, "--noheader", "--nodes=localhost", "--format=%t"};
  if (!waitFor([&] { return outputOf(state, dir_ / "sinfo.txt") == "idle"; }, 30))
    return "the node was not idle within 30 s" + logTail("slurmctld.log") + logTail("slurmd.log");
  up_ = true;
  return "";
}

std::string SlurmCluster::start(const fs::path& dir) {
  if (geteuid() != 0) return "needs root (the daemons run as root)";
  dir_ = dir;
  fs::remove_all(dir_);
  fs::create_directories(dir_);
  std::string why = startMunge();
  if (why.empty()) why = startSlurm();
  if (!why.empty()) stop();
  return why;
}

void SlurmCluster::stop() {
  const std::string scancel = program("scancel");
  if (up_ && !scancel.empty()) outputOf({scancel, "--partition", kPartition}, dir_ / "scancel.txt");
  up_ = false;
  // The last started first: slurmd, slurmctld, then munged.
  for (auto pid = daemons_.rbegin(); pid != daemons_.rend(); ++pid) {
    kill(*pid, SIGTERM);
    if (!waitFor([&] { return waitpid(*pid, nullptr, WNOHANG) == *pid; }, 5)) {
      kill(*pid, SIGKILL);
      waitpid(*pid, nullptr, 0);
    }
  }
  daemons_.clear();
  unsetenv("SLURM_CONF");
  if (!dir_.empty()) fs::remove_all(dir_);
  dir_.clear();
}

}  // namespace beft::test
