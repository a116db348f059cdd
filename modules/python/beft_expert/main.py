"""The command line of an expert written in Python, as the C++ experts'
(lib/expert/run_expert.cpp): --help, --interface, --param NAME=VALUE,
--name, --replay, and live through the bridge."""

import argparse
import os
import sys

from beft_expert.live import LiveCore
from beft_expert.replay import read_json_lines, replay


def interface_text(expert, process_name):
    lines = ["process: " + process_name, "reads:"]
    lines += ["  %s  (%s)" % (s.channel, s.type) for s in expert.reads()]
    lines.append("  FIRE  (beft.fire_t, tokens addressed to %s)" % process_name)
    lines.append("  RUN_STATUS  (beft.run_status_t, stops at the end of the run)")
    lines.append("writes:")
    lines += ["  %s  (%s)" % (s.channel, s.type) for s in expert.writes()]
    lines += ["  DONE  (beft.done_t)", "  HEARTBEAT  (beft.heartbeat_t)"]
    text = "\n".join(lines) + "\n"
    parameters = expert.parameters().describe()
    if parameters:
        text += "parameters (--param NAME=VALUE):\n" + parameters
    return text


def _parser(expert):
    parser = argparse.ArgumentParser(
        prog=expert.name,
        description=expert.description + "\n\nRuns through the run's bridge (beft-bridge): it connects to --url, "
        "announces itself, and fires when the arbiter sends FIRE tokens addressed to its --name. Offline: "
        "--replay EVENTS compares it with a recorded run (the run's messages as JSON lines).")
    parser.add_argument("--url", default=os.environ.get("BEFT_BRIDGE_URL", "ws://127.0.0.1:8765"),
                        help="the bridge's WebSocket URL (env BEFT_BRIDGE_URL; default %(default)s)")
    parser.add_argument("--lcm-url", help="accepted and unused: the bridge publishes on the run's LCM")
    parser.add_argument("--name", default=expert.name, help="process name the arbiter fires (default %(default)s)")
    parser.add_argument("--param", action="append", default=[], metavar="NAME=VALUE",
                        help="parameter NAME=VALUE (repeatable; see --interface)")
    parser.add_argument("--heartbeat-period", type=float, default=0.5, help="seconds between heartbeats")
    parser.add_argument("--ready-timeout", type=float, default=0.0,
                        help="longest wait for a firing's inputs before firing without them [s]; 0: never")
    parser.add_argument("--connect-timeout", type=float, default=30.0,
                        help="how long to try to reach the bridge at start [s]")
    parser.add_argument("--resume-log", default="",
                        help="restarted after a crash: the run's LCM log, from which the bridge sends the run's "
                        "history to rebuild this expert's state; the launcher passes it")
    parser.add_argument("--replay", metavar="EVENTS", help="run offline against a run's messages (JSON lines)")
    parser.add_argument("--interface", action="store_true", help="print the channels read and written, and the "
                        "parameters")
    return parser


def _parameters(arguments):
    given = {}
    for argument in arguments:
        name, eq, value = argument.partition("=")
        if not eq or not name:
            raise ValueError("--param '%s' is not NAME=VALUE" % argument)
        given[name] = value
    return given


def run_expert_main(expert, argv=None):
    """Returns the process exit code, as the C++ runExpertMain."""
    options = _parser(expert).parse_args(argv)
    if options.interface:
        sys.stdout.write(interface_text(expert, options.name))
        return 0
    try:
        expert.start_up(_parameters(options.param))
    except ValueError as error:
        print("start-up failed: %s" % error, file=sys.stderr)
        return 2
    if options.replay:
        result = replay(expert, options.name, read_json_lines(options.replay))
        print("%s: %d firings, %d of %d outputs identical, %d recorded only, %d replayed only"
              % (options.name, result.firings, result.outputs_matching, result.outputs_compared,
                 result.recorded_only, result.replayed_only))
        for channel, firing_id, was, now in result.first_mismatches:
            print("  firing %d, %s:\n    recorded %s\n    replayed %s" % (firing_id, channel, was, now))
        return 0 if result.exact_match() else 3
    try:
        import websockets  # noqa: F401 - Debian's python3-websockets, needed live only
    except ImportError:
        print("%s needs python3-websockets to run live (apt-get install python3-websockets); %s does not have it"
              % (options.name, sys.executable), file=sys.stderr)
        return 2
    from beft_expert.session import run_live
    return run_live(expert, LiveCore(expert, options.name, options.ready_timeout), options)
