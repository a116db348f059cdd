import unittest

from beft_expert import Expert, Outcome, OutputPort, TickInput
from beft_expert.replay import replay, resume


class Summer(Expert):
    """Publishes the running sum of the x it fired on: state that a resume must rebuild."""
    name = "summer"

    def __init__(self):
        super().__init__()
        self.robot = TickInput("ROBOT_STATE", "beft.robot_state_t")
        self.out = OutputPort("GEOMETRY", "beft.geometry_percepts_t")
        self.total = 0.0

    def fire(self, firing, out):
        self.total += self.robot.of_tick(firing.tick)["x"]
        self.out.publish(out, {"tick": firing.tick, "total": self.total})
        return Outcome.success()


def run_events(ticks, with_done=True):
    events, total = [], 0.0
    for tick in range(ticks):
        x = 0.5 * tick
        total += x
        events.append(("ROBOT_STATE", {"utime": tick, "tick": tick, "x": x}))
        events.append(("FIRE", {"expert": "summer", "transition": "t", "tick": tick, "utime": tick,
                                "firing_id": 10 + tick}))
        events.append(("GEOMETRY", {"tick": tick, "total": total}))
        if with_done or tick < ticks - 1:
            events.append(("DONE", {"expert": "summer", "firing_id": 10 + tick, "outcome": 0, "tick": tick}))
    return events


class ReplayTest(unittest.TestCase):
    def test_replaying_a_run_gives_its_outputs(self):
        result = replay(Summer(), "summer", run_events(5))
        self.assertTrue(result.exact_match())
        self.assertEqual((result.firings, result.outputs_compared), (5, 5))

    def test_a_different_output_is_reported(self):
        events = run_events(3)
        events[2] = ("GEOMETRY", {"tick": 0, "total": 1.0})
        result = replay(Summer(), "summer", events)
        self.assertFalse(result.exact_match())
        self.assertEqual(result.first_mismatches[0][:2], ("GEOMETRY", 10))

    def test_resume_rebuilds_the_state_and_leaves_the_firing_in_flight_to_the_arbiter(self):
        expert = Summer()
        state = resume(expert, "summer", run_events(4, with_done=False))
        self.assertEqual(state.firings, 3)  # the last FIRE has no DONE: the arbiter sends it again
        self.assertEqual(state.in_flight.firing_id, 13)
        self.assertEqual(state.last_done["firing_id"], 12)
        self.assertEqual(expert.total, 0.0 + 0.5 + 1.0)


if __name__ == "__main__":
    unittest.main()
