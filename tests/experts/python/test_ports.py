import unittest

from beft_expert import Expert, Firing, OutputPort, SceneInput, TickInput
from beft_expert.expert import CapturingOutput, UndeclaredChannel


def robot(tick):
    return {"utime": tick * 100000, "tick": tick, "x": float(tick)}


class Probe(Expert):
    name = "probe"

    def __init__(self):
        super().__init__()
        self.robot = TickInput("ROBOT_STATE", "beft.robot_state_t", capacity=3)
        self.scene = SceneInput()
        self.out = OutputPort("GEOMETRY", "beft.geometry_percepts_t")


def firing(tick):
    return Firing("probe", "t", tick, tick * 100000, tick + 1)


class PortsTest(unittest.TestCase):
    def test_reads_and_writes_follow_the_declaration_order(self):
        expert = Probe()
        self.assertEqual([s.channel for s in expert.reads()], ["ROBOT_STATE", "GT_OBJECTS", "GT_VERSION"])
        self.assertEqual([s.type for s in expert.writes()], ["beft.geometry_percepts_t"])

    def test_a_tick_input_keeps_the_newest_messages_by_tick(self):
        port = TickInput("ROBOT_STATE", "beft.robot_state_t", capacity=3)
        for tick in range(5):
            port.receive(robot(tick))
        self.assertIsNone(port.of_tick(1))  # dropped: capacity 3
        self.assertEqual(port.of_tick(3)["x"], 3.0)
        self.assertEqual(port.latest()["tick"], 4)
        self.assertTrue(port.lacks_tick(7))

    def test_the_scene_of_a_tick_is_the_keyframe_its_version_names_restamped(self):
        scene = SceneInput()
        scene.receive({"utime": 0, "tick": 0, "objects": ["a"]})
        for tick in range(3):
            scene.versions.receive({"utime": tick * 100000, "tick": tick, "scene_tick": 0})
        got = scene.of_tick(2)
        self.assertEqual((got["tick"], got["utime"], got["objects"]), (2, 200000, ["a"]))
        self.assertIsNone(scene.of_tick(3))  # no GT_VERSION of tick 3 yet
        self.assertEqual(scene.latest()["tick"], 0)

    def test_without_versions_the_scene_of_a_tick_is_its_own_message(self):
        scene = SceneInput()
        scene.receive({"utime": 100000, "tick": 1, "objects": []})
        self.assertTrue(scene.has(1))
        self.assertFalse(scene.has(2))

    def test_inputs_lacking_names_the_channels_without_the_tick(self):
        expert = Probe()
        expert.on_message("ROBOT_STATE", robot(4))
        self.assertEqual(expert.inputs_lacking(firing(4)), ["GT_OBJECTS"])
        expert.on_message("GT_OBJECTS", {"utime": 400000, "tick": 4, "objects": []})
        self.assertTrue(expert.inputs_ready(firing(4)))
        self.assertFalse(expert.on_message("AUDIO", {}))

    def test_an_undeclared_channel_is_refused_on_publish(self):
        out = CapturingOutput(["GEOMETRY"])
        out.publish("GEOMETRY", {"a": 1})
        with self.assertRaises(UndeclaredChannel):
            out.publish("TASK_COMMAND", {})
        self.assertEqual(out.captured, [("GEOMETRY", {"a": 1})])


if __name__ == "__main__":
    unittest.main()
