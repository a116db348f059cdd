import math
import random
import struct
import unittest

from beft_expert import foxglove
from beft_expert.jsonvalues import dumps, loads


class JsonValuesTest(unittest.TestCase):
    def test_nan_is_null_on_the_wire_and_nan_again_when_read(self):
        text = dumps({"viewing_direction": math.nan, "weights": [{"w": 0.25}]})
        self.assertEqual(text, '{"viewing_direction":null,"weights":[{"w":0.25}]}')
        self.assertTrue(math.isnan(loads(text)["viewing_direction"]))

    def test_doubles_cross_json_bit_for_bit(self):
        rng = random.Random(7)
        for _ in range(10000):
            value = struct.unpack("<d", struct.pack("<Q", rng.getrandbits(64)))[0]
            if math.isfinite(value):
                self.assertEqual(struct.pack("<d", loads(dumps({"v": value}))["v"]), struct.pack("<d", value))


class FoxgloveFramesTest(unittest.TestCase):
    def test_publish_frame_is_opcode_channel_and_payload(self):
        frame = foxglove.publish_frame(3, '{"a":1}')
        self.assertEqual(frame[:5], b"\x01\x03\x00\x00\x00")
        self.assertEqual(frame[5:], b'{"a":1}')

    def test_message_data_is_read_and_other_frames_are_not(self):
        frame = struct.pack("<BIQ", 1, 7, 123) + b'{"tick":1}'
        self.assertEqual(foxglove.parse_message_data(frame), (7, 123, '{"tick":1}'))
        self.assertIsNone(foxglove.parse_message_data(struct.pack("<BQ", 2, 5)))
        self.assertIsNone(foxglove.parse_text("not json"))
        self.assertEqual(foxglove.parse_text('{"op":"status"}')["op"], "status")


if __name__ == "__main__":
    unittest.main()
