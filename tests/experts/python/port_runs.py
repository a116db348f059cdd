"""The Python ports against the C++ experts of this build: runs yard, peek
and decoy with the C++ experts (beft-run), turns each run's log into JSON
lines as the bridge would give them (log_to_json), and runs
test_ports_against_cpp on them: fed each run's inputs, the Python geometry
and dw experts must give the run's outputs exactly. Their --interface must
be the C++ experts' too.
    port_runs.py BIN_DIR WORK_DIR"""

import os
import subprocess
import sys
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", "..", ".."))
CHANNELS = ["FIRE", "DONE", "AUDIO", "LABELS_ACOUSTIC", "GT_OBJECTS", "GT_VERSION", "ROBOT_STATE", "TASK_STACK",
            "DYNAMIC_WEIGHTS", "TASK_COMMAND", "GEOMETRY"]


def run_events(bin_dir, work_dir, scenario):
    out = os.path.join(work_dir, scenario)
    run = subprocess.run([os.path.join(bin_dir, "beft-run"), os.path.join(ROOT, "scenarios", scenario + ".xml"),
                          "--out", out, "--no-report"], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if run.returncode != 0:
        print(run.stdout)
        raise RuntimeError("the %s run failed (%d)" % (scenario, run.returncode))
    events = os.path.join(work_dir, scenario + ".jsonl")
    subprocess.run([os.path.join(bin_dir, "log_to_json"), os.path.join(out, "run.lcmlog"), events] + CHANNELS,
                   check=True)
    return events


def same_interfaces(bin_dir):
    """Each port's --interface is the C++ expert's: channels, types, parameters."""
    same = True
    for name in ("geometry", "dw"):
        cpp = subprocess.run([os.path.join(bin_dir, "beft-" + name), "--interface"], stdout=subprocess.PIPE,
                             text=True, check=True).stdout
        python = subprocess.run([sys.executable, os.path.join(ROOT, "modules", "python", "examples", name +
                                 "_expert.py"), "--interface"], stdout=subprocess.PIPE, text=True, check=True).stdout
        if cpp != python:
            print("--interface of the Python %s differs:\n%s\n---\n%s" % (name, cpp, python))
            same = False
    return same


def main(bin_dir, work_dir):
    os.makedirs(work_dir, exist_ok=True)
    if not same_interfaces(bin_dir):
        return 1
    events = [run_events(bin_dir, work_dir, scenario) for scenario in ("yard", "peek", "decoy")]
    os.environ["BEFT_PORT_EVENTS"] = os.pathsep.join(events)
    python_dir = os.path.join(ROOT, "modules", "python")
    sys.path[:0] = [python_dir, os.path.join(python_dir, "examples"), HERE]
    suite = unittest.defaultTestLoader.loadTestsFromName("test_ports_against_cpp")
    return 0 if unittest.TextTestRunner(verbosity=2).run(suite).wasSuccessful() else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2]))
