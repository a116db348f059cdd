"""The Python ports fed a recorded run's inputs give the run's outputs, bit
for bit: BEFT_PORT_EVENTS names the run's messages as JSON lines
(log_to_json, as the bridge converts them), several separated by the path
separator; the test is skipped without them."""

import os
import unittest

from beft_expert.replay import read_json_lines, replay
from dw_expert import DwExpert
from geometry_expert import GeometryExpert

EVENT_FILES = [f for f in os.environ.get("BEFT_PORT_EVENTS", "").split(os.pathsep) if f]


class PortsAgainstCppTest(unittest.TestCase):
    def check(self, expert_class):
        if not EVENT_FILES:
            self.skipTest("BEFT_PORT_EVENTS names no recorded run")
        for path in EVENT_FILES:
            with self.subTest(run=os.path.basename(path)):
                fresh = expert_class()
                fresh.start_up()
                result = replay(fresh, fresh.name, read_json_lines(path))
                self.assertGreater(result.firings, 0)
                self.assertEqual(result.first_mismatches, [])
                self.assertEqual(result.recorded_only, 0)
                self.assertTrue(result.exact_match())

    def test_geometry(self):
        self.check(GeometryExpert)

    def test_dynamic_weighting(self):
        self.check(DwExpert)


if __name__ == "__main__":
    unittest.main()
