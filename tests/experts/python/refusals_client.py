"""A client that announces itself as expert dw to a running bridge, then
publishes a message with a wrong field type, one with a missing field and
one on a channel it did not declare; prints every status the bridge sends.
    refusals_client.py ws://127.0.0.1:PORT"""

import asyncio
import json
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "modules", "python"))

import websockets  # noqa: E402
from beft_expert import foxglove  # noqa: E402

async def main(url):
    async with websockets.connect(url, subprotocols=[foxglove.SUBPROTOCOL], max_size=None) as ws:
        await ws.send(foxglove.advertise([(1, "/beft/expert", "beft.external_expert"),
                                          (2, "DYNAMIC_WEIGHTS", "beft.dynamic_weights_t"), (3, "TASK_COMMAND", "beft.task_command_t")]))
        hello = {"name": "dw", "reads": [], "writes": [{"channel": "DYNAMIC_WEIGHTS", "type": "beft.dynamic_weights_t"}]}
        await ws.send(foxglove.publish_frame(1, json.dumps(hello)))
        bad = {"utime": 0, "tick": 0, "viewing_direction": None, "current_task": "", "attended_object": "",
               "num_weights": 1, "weights": [{"object_id": "a", "weight": "heavy", "congruency": 0.5, "rising": False,
               "step": 0, "label": "", "activity": "", "sounding": False}]}
        await ws.send(foxglove.publish_frame(2, json.dumps(bad)))
        del bad["tick"]
        await ws.send(foxglove.publish_frame(2, json.dumps(bad)))
        await ws.send(foxglove.publish_frame(3, json.dumps({})))
        end = asyncio.get_running_loop().time() + 3
        while asyncio.get_running_loop().time() < end:
            try:
                m = await asyncio.wait_for(ws.recv(), 0.5)
            except asyncio.TimeoutError:
                continue
            if isinstance(m, str) and '"status"' in m:
                print(json.loads(m)["message"])

asyncio.run(main(sys.argv[1]))
