"""An expert fed a run's messages as it heard them live (the C++
log_replay.cpp): offline against a recorded run, comparing its outputs with
the recorded ones, and on a restart, rebuilding its state from the run's
history (crash-only). Events are (channel, message) pairs in log order, the
messages as JSON objects (plain channel names, no run id)."""

import collections
import json

from beft_expert.expert import CapturingOutput, Firing
from beft_expert.jsonvalues import dumps, loads, to_json_value


def firing_of(fire):
    return Firing(fire["expert"], fire["transition"], fire["tick"], fire["utime"], fire["firing_id"])


class LogFeeder:
    """Its inputs in log order; its FIREs fired once their inputs are ready,
    or when a newer FIRE for it comes (as live after the time-out). may_fire
    decides which FIREs run at all."""

    def __init__(self, expert, process_name, output, may_fire=lambda firing_id: True, before_fire=None):
        self.expert, self.process_name, self.output = expert, process_name, output
        self.may_fire, self.before_fire = may_fire, before_fire
        self.reads = {spec.channel for spec in expert.reads()}
        self.pending = self.last_fired = self.in_flight = None
        self.last_firing_id = -1
        self.firings = 0
        self.firings_lacking_inputs = 0
        self.lacking_inputs = collections.Counter()

    def feed(self, channel, message):
        """True if the event was an input delivered to the expert."""
        if channel == "FIRE":
            if message["expert"] != self.process_name or message["firing_id"] <= self.last_firing_id:
                return False
            self.fire_pending()
            self.last_firing_id = message["firing_id"]
            self.pending = firing_of(message)
            if not self.may_fire(message["firing_id"]):
                self.in_flight, self.pending = self.pending, None
                return False
            if self.expert.inputs_ready(self.pending):
                self.fire_pending()
            return False
        if channel not in self.reads:
            return False
        self.expert.on_message(channel, message)
        if self.pending is not None and self.expert.inputs_ready(self.pending):
            self.fire_pending()
        return True

    def fire_pending(self):
        if self.pending is None:
            return
        if not self.expert.inputs_ready(self.pending):
            self.firings_lacking_inputs += 1
            self.lacking_inputs.update(self.expert.inputs_lacking(self.pending))
        if self.before_fire:
            self.before_fire(self.pending)
        try:
            self.expert.fire(self.pending, self.output)
        except Exception as error:  # a replayed firing that raises is reported, as live
            print("replayed firing %d raised: %s" % (self.pending.firing_id, error))
        self.firings += 1
        self.last_fired, self.pending = self.pending, None


class ReplayResult:
    def __init__(self):
        self.firings = self.outputs_compared = self.outputs_matching = 0
        self.recorded_only = self.replayed_only = 0
        self.first_mismatches = []  # (channel, firing id, recorded, replayed)

    def exact_match(self):
        return (self.firings > 0 and self.outputs_compared > 0 and
                self.outputs_compared == self.outputs_matching and self.recorded_only == 0)


class _FiringOutput(CapturingOutput):
    def __init__(self, declared):
        super().__init__(declared)
        self.firing_id = -1
        self.by_firing = collections.defaultdict(lambda: collections.defaultdict(list))

    def send(self, channel, message):
        # As the bridge would carry it: through JSON text and back.
        self.by_firing[self.firing_id][channel].append(canonical(loads(dumps(message))))


def replay(expert, process_name, events):
    """Replays the events and compares each firing's outputs with those
    recorded between its FIRE and its DONE."""
    writes = {spec.channel for spec in expert.writes()}
    output = _FiringOutput(writes)
    recorded = collections.defaultdict(lambda: collections.defaultdict(list))
    in_recorded_firing = False

    def before_fire(firing):
        output.firing_id = firing.firing_id

    feeder = LogFeeder(expert, process_name, output, before_fire=before_fire)
    for channel, message in events:
        before = feeder.last_firing_id
        feeder.feed(channel, message)
        if feeder.last_firing_id != before:
            in_recorded_firing = True
            continue
        if channel == "DONE":
            if message["expert"] == process_name and message["firing_id"] == feeder.last_firing_id:
                in_recorded_firing = False
            continue
        if channel in writes and in_recorded_firing:
            recorded[feeder.last_firing_id][channel].append(canonical(message))
    feeder.fire_pending()
    result = ReplayResult()
    result.firings = feeder.firings
    _compare(recorded, output.by_firing, result)
    return result


def canonical(message):
    """A message as comparable text: keys sorted, NaN as null, every double
    in its shortest round-trip form (so -0.0 and 0.0 differ, as their bits do)."""
    return json.dumps(to_json_value(message), sort_keys=True, allow_nan=False)


def _compare(recorded, replayed, result):
    for firing_id in sorted(set(recorded) | set(replayed)):
        for channel in sorted(set(recorded[firing_id]) | set(replayed[firing_id])):
            was, now = recorded[firing_id][channel], replayed[firing_id][channel]
            common = min(len(was), len(now))
            for i in range(common):
                result.outputs_compared += 1
                if was[i] == now[i]:
                    result.outputs_matching += 1
                elif len(result.first_mismatches) < 3:
                    result.first_mismatches.append((channel, firing_id, was[i], now[i]))
            result.recorded_only += len(was) - common
            result.replayed_only += len(now) - common


class ResumeState:
    def __init__(self):
        self.firings = self.inputs = 0
        self.last_fired = self.last_done = self.in_flight = None


def resume(expert, process_name, events):
    """Rebuilds the state of a restarted expert from the run's history: every
    input it had heard and every firing it had finished (those whose DONE the
    history holds) replayed, their outputs dropped (the run already has them)."""
    events = list(events)
    dones = {m["firing_id"]: m for c, m in events if c == "DONE" and m["expert"] == process_name}
    feeder = LogFeeder(expert, process_name, CapturingOutput(), may_fire=lambda firing_id: firing_id in dones)
    state = ResumeState()
    for channel, message in events:
        if feeder.feed(channel, message):
            state.inputs += 1
    feeder.fire_pending()
    state.firings = feeder.firings
    state.last_fired = feeder.last_fired
    if state.last_fired is not None:
        state.last_done = dones.get(state.last_fired.firing_id)
    state.in_flight = feeder.in_flight
    if state.in_flight and state.last_fired and state.in_flight.firing_id < state.last_fired.firing_id:
        state.in_flight = None
    return state


def read_json_lines(path):
    """Events of a run as JSON lines: {"channel": ..., "message": {...}}."""
    with open(path, encoding="utf-8") as lines:
        for line in lines:
            if line.strip():
                event = loads(line)
                yield event["channel"], event["message"]
