import unittest

from beft_expert import Expert, Outcome, OutputPort, TickInput
from beft_expert.live import OUTCOME_FAILED, OUTCOME_OK, LiveCore
from beft_expert.replay import ResumeState
from beft_expert.expert import Firing


class Counter(Expert):
    name = "counter"

    def __init__(self):
        super().__init__()
        self.robot = TickInput("ROBOT_STATE", "beft.robot_state_t")
        self.out = OutputPort("GEOMETRY", "beft.geometry_percepts_t")
        self.fired = 0
        self.fail = False

    def fire(self, firing, out):
        self.fired += 1
        if self.fail:
            raise RuntimeError("broken")
        self.out.publish(out, {"tick": firing.tick})
        return Outcome.success()


def fire(firing_id, tick, expert="counter", transition="t_counter"):
    return {"utime": tick * 100000, "expert": expert, "transition": transition, "tick": tick,
            "firing_id": firing_id, "after_sender": 0, "after_frontier": 0}


class LiveCoreTest(unittest.TestCase):
    def setUp(self):
        self.expert = Counter()
        self.core = LiveCore(self.expert, "counter", log=lambda *a: None)

    def test_a_fire_for_another_expert_is_not_taken(self):
        self.core.on_fire(fire(1, 0, expert="dw"))
        self.assertFalse(self.core.firing_due(0.0))

    def test_a_firing_waits_for_its_inputs_and_says_so_in_the_heartbeat(self):
        self.core.on_fire(fire(1, 3), now=0.0)
        self.assertFalse(self.core.firing_due(10.0))  # ready timeout 0: waits for ever
        self.assertEqual(self.core.heartbeat(1, "h", 0)["state"], "waiting")
        self.expert.on_message("ROBOT_STATE", {"utime": 300000, "tick": 3})
        self.assertTrue(self.core.firing_due(10.0))
        outputs, done = self.core.fire_now()
        self.assertEqual(outputs, [("GEOMETRY", {"tick": 3})])
        self.assertEqual((done["firing_id"], done["tick"], done["outcome"], done["expert"]), (1, 3, OUTCOME_OK, "counter"))
        beat = self.core.heartbeat(1, "h", 0)
        self.assertEqual((beat["state"], beat["last_firing_id"]), ("idle", 1))

    def test_with_a_ready_timeout_it_fires_without_its_inputs(self):
        core = LiveCore(self.expert, "counter", ready_timeout_s=2.0, log=lambda *a: None)
        core.on_fire(fire(1, 3), now=0.0)
        self.assertFalse(core.firing_due(1.0))
        self.assertTrue(core.firing_due(2.5))

    def test_a_repeated_fire_gets_the_same_done_and_no_second_firing(self):
        self.expert.on_message("ROBOT_STATE", {"utime": 0, "tick": 0})
        self.core.on_fire(fire(5, 0))
        _, done = self.core.fire_now()
        self.assertIs(self.core.on_fire(fire(5, 0)), done)
        self.assertIsNone(self.core.on_fire(fire(4, 0)))  # stale
        self.assertFalse(self.core.firing_due())
        self.assertEqual(self.expert.fired, 1)

    def test_the_same_firing_under_a_new_id_is_answered_with_its_done(self):
        self.expert.on_message("ROBOT_STATE", {"utime": 0, "tick": 0})
        self.core.on_fire(fire(5, 0))
        self.core.fire_now()
        again = self.core.on_fire(fire(9, 0))  # a restarted arbiter's new id for it
        self.assertEqual(again["firing_id"], 9)
        self.assertEqual(self.expert.fired, 1)

    def test_an_exception_is_a_failed_outcome(self):
        self.expert.fail = True
        self.core.on_fire(fire(1, 0))
        _, done = self.core.fire_now()
        self.assertEqual(done["outcome"], OUTCOME_FAILED)
        self.assertIn("broken", done["message"])

    def test_the_end_of_the_run_stops_it_and_waiting_asks_for_a_heartbeat(self):
        self.assertTrue(self.core.on_run_status({"state": 0, "message": ""}))
        self.assertFalse(self.core.run_ended)
        self.core.on_run_status({"state": 2, "message": "done"})
        self.assertTrue(self.core.run_ended)

    def test_after_a_resume_the_logged_done_answers_its_fire(self):
        state = ResumeState()
        state.last_fired = Firing("counter", "t_counter", 7, 700000, 12)
        state.last_done = {"firing_id": 12, "outcome": 0, "tick": 7}
        self.core.adopt_resumed(state)
        self.assertEqual(self.core.on_fire(fire(12, 7))["firing_id"], 12)
        self.assertEqual(self.core.heartbeat(1, "h", 0)["last_firing_id"], 12)
        self.assertEqual(self.expert.fired, 0)


if __name__ == "__main__":
    unittest.main()
