"""What the C++ live runner (lib/expert/live_runner.cpp) decides, without the
socket: which FIRE tokens to take, when a firing's inputs are ready, the DONE
it answers (and answers again to a repeated FIRE), the heartbeat's state and
the end of the run. session.py carries it over the bridge."""

import time

from beft_expert.expert import CapturingOutput, Outcome
from beft_expert.replay import firing_of

OUTCOME_OK, OUTCOME_FAILED = 0, 1
RUN_WAITING, RUN_RUNNING, RUN_FINISHED, RUN_FAILED = 0, 1, 2, 3


class LiveCore:
    def __init__(self, expert, process_name, ready_timeout_s=0.0, log=print):
        self.expert, self.process_name = expert, process_name
        self.ready_timeout_s = ready_timeout_s
        self.log = log
        self.pending = None          # the firing taken last (a Firing)
        self.pending_fired = False
        self.pending_since = 0.0
        self.last_fired_id = -1
        self.last_done = None        # the DONE of the last firing run
        self.firing = self.waiting = False
        self.run_ended, self.run_end_reason = False, ""
        self.firings_run = 0
        self.writes = [spec.channel for spec in expert.writes()]

    def adopt_resumed(self, state):
        """After resume(): the last firing replayed counts as done, its logged
        DONE is sent again if the arbiter asks."""
        if state.last_fired is not None and state.last_done is not None:
            self.pending, self.pending_fired = state.last_fired, True
            self.last_fired_id = state.last_fired.firing_id
            self.last_done = dict(state.last_done)

    def on_fire(self, fire, now=None):
        """Returns the DONE to send again at once (a repeated FIRE), or None."""
        if fire["expert"] != self.process_name:
            return None
        firing_id = fire["firing_id"]
        if self.pending is not None and self.pending.firing_id >= firing_id:
            if self.pending.firing_id == firing_id and self.pending_fired:
                return self.last_done
            if firing_id < self.pending.firing_id:
                self.log("dropped stale FIRE %d (already at %d)" % (firing_id, self.pending.firing_id))
            return None
        if self._repeats_the_firing_done(fire):
            # A restarted arbiter whose log lacked the first FIRE fires it
            # again under a new id: its DONE answers, no outputs twice.
            self.pending = self.pending._replace(firing_id=firing_id)
            self.last_fired_id = self.last_done["firing_id"] = firing_id
            return self.last_done
        if self.pending is not None and not self.pending_fired:
            self.log("FIRE %d superseded by %d before it ran" % (self.pending.firing_id, firing_id))
        self.pending = firing_of(fire)
        self.pending_fired, self.firing = False, True
        self.pending_since = time.monotonic() if now is None else now
        return None

    def _repeats_the_firing_done(self, fire):
        return (self.pending is not None and self.pending_fired and self.last_done is not None and
                self.last_done["outcome"] == OUTCOME_OK and self.last_done["firing_id"] == self.pending.firing_id
                and self.pending.tick == fire["tick"] and self.pending.transition == fire["transition"])

    def on_run_status(self, status):
        """True when a heartbeat should go now (an arbiter waiting for them)."""
        if status["state"] in (RUN_FINISHED, RUN_FAILED):
            self.run_ended, self.run_end_reason = True, status.get("message", "")
        return status["state"] == RUN_WAITING

    def firing_due(self, now=None):
        """Whether the taken firing should run now: its inputs are ready, or
        ready_timeout_s (> 0) has passed."""
        if self.pending is None or self.pending_fired:
            return False
        try:
            ready = self.expert.inputs_ready(self.pending)
        except Exception as error:
            self.log("inputs_ready raised: %s" % error)
            ready = True
        self.waiting = not ready
        if ready:
            return True
        waited = (time.monotonic() if now is None else now) - self.pending_since
        if self.ready_timeout_s > 0 and waited >= self.ready_timeout_s:
            self.log("firing %d (tick %d): inputs incomplete after %g s; firing anyway (--ready-timeout)"
                     % (self.pending.firing_id, self.pending.tick, self.ready_timeout_s))
            return True
        return False

    def fire_now(self):
        """Runs the firing: its outputs [(channel, message)] and its DONE."""
        out = CapturingOutput(self.writes)
        start = time.monotonic()
        try:
            outcome = self.expert.fire(self.pending, out)
            if outcome is None:
                outcome = Outcome.success()
        except Exception as error:
            outcome = Outcome.failure("exception: %s" % error)
        self.firings_run += 1
        self.pending_fired, self.firing, self.waiting = True, False, False
        self.last_fired_id = self.pending.firing_id
        if not outcome.ok:
            self.log("firing %d (tick %d) failed: %s" % (self.pending.firing_id, self.pending.tick, outcome.message))
        self.last_done = done_message(self.process_name, self.pending, outcome, time.monotonic() - start)
        return out.captured, self.last_done

    def heartbeat(self, pid, host, wall_us):
        state = "idle" if not self.firing else "waiting" if self.waiting else "firing"
        return {"utime": wall_us, "process": self.process_name, "pid": pid, "host": host,
                "last_firing_id": self.last_fired_id, "state": state}


def done_message(process_name, firing, outcome, duration_s):
    # sender and the published lists are the bridge's to fill: it published
    # the outputs, under its own sender id and sequence numbers.
    return {"utime": firing.utime, "expert": process_name, "tick": firing.tick, "firing_id": firing.firing_id,
            "outcome": OUTCOME_OK if outcome.ok else OUTCOME_FAILED, "message": outcome.message,
            "duration": float(duration_s), "sender": 0, "num_published": 0,
            "published_channels": [], "published_sequences": []}
