// The programs beft-bench-view runs (beft-run, beft-control, node), each a
// shell command in a process group of its own with its output in a file.
#pragma once

#include <sys/types.h>

#include <string>

namespace beft::bench {

// Starts `command` through sh in a process group of its own; it gets SIGTERM
// when this process ends (give "exec PROGRAM" for that to reach the program).
pid_t startShell(const std::string& command);
// Whether the process startShell started has ended (then it is reaped).
bool hasEnded(pid_t pid);
// Sends `signal` to the group, waits up to `grace_s`, then SIGKILLs it.
void stopGroup(pid_t pid, int signal, double grace_s);
// Runs `command` through sh to its end; its exit code (-1 when it did not run).
int runShell(const std::string& command);

std::string readFile(const std::string& path);
// What follows `prefix` on the first line of `text` that starts with it, "" if none.
std::string lineAfter(const std::string& text, const std::string& prefix);
// `text` in single quotes for sh.
std::string shellQuoted(const std::string& text);

}  // namespace beft::bench
