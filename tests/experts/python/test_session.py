"""The protocol of an external expert, against a stand-in for the bridge
that speaks the server side of it (modules/python/README.md)."""

import asyncio
import json
import struct
import types
import unittest

import websockets

from beft_expert import foxglove
from beft_expert.live import LiveCore
from beft_expert.session import _connect_and_run
from geometry_expert import GeometryExpert

SERVER_TOPICS = ["FIRE", "RUN_STATUS", "GT_OBJECTS", "GT_VERSION", "ROBOT_STATE", "GEOMETRY"]


def robot(tick):
    return {"utime": tick * 100000, "tick": tick, "x": 0.0, "y": 0.0, "yaw": 0.0, "head_yaw": 0.0,
            "head_pitch": 0.0, "camera_height": 1.2}


def scene(tick):
    return {"utime": tick * 100000, "tick": tick, "objects": [
        {"id": "siren", "x": 3.0, "y": 4.0, "z": 0.0, "shape": 0, "size_x": 0.0, "size_y": 0.0, "size_z": 0.0,
         "has_acoustic": True, "sound_active": True}]}


def fire(firing_id, tick):
    return {"utime": tick * 100000, "expert": "geometry", "transition": "t_geometry", "tick": tick,
            "firing_id": firing_id, "after_sender": 0, "after_frontier": 0}


class FakeBridge:
    """Accepts one expert, sends it inputs and FIREs, keeps what it publishes."""

    def __init__(self, refuse=False):
        self.refuse = refuse
        self.published = []  # (topic, message)
        self.hello = None
        self.subscribed = {}

    async def handler(self, ws, path=None):
        await ws.send(json.dumps({"op": "serverInfo", "name": "fake", "capabilities": ["clientPublish"],
                                  "supportedEncodings": ["json"]}))
        await ws.send(json.dumps({"op": "advertise", "channels": [
            {"id": 100 + i, "topic": t, "encoding": "json", "schemaName": "x", "schema": "{}",
             "schemaEncoding": "jsonschema"} for i, t in enumerate(SERVER_TOPICS)]}))
        client_topics = {}
        async for frame in ws:
            if isinstance(frame, str):
                message = json.loads(frame)
                if message["op"] == "advertise":
                    client_topics = {c["id"]: c["topic"] for c in message["channels"]}
                elif message["op"] == "subscribe":
                    for s in message["subscriptions"]:
                        self.subscribed[SERVER_TOPICS[s["channelId"] - 100]] = s["id"]
                    await self.drive(ws)
                continue
            topic = client_topics[struct.unpack_from("<I", frame, 1)[0]]
            payload = json.loads(frame[5:].decode())
            if topic == "/beft/expert":
                self.hello = payload
                level = 2 if self.refuse else 0
                await ws.send(json.dumps({"op": "status", "level": level, "message": "expert geometry: answered",
                                          "id": "beft.expert.geometry"}))
            elif topic != "HEARTBEAT":
                self.published.append((topic, payload))

    async def send(self, ws, topic, message):
        await ws.send(struct.pack("<BIQ", 1, self.subscribed[topic], 0) + json.dumps(message).encode())

    async def drive(self, ws):
        await self.send(ws, "GT_OBJECTS", scene(0))
        await self.send(ws, "FIRE", fire(7, 0))  # before its ROBOT_STATE: the expert waits for it
        await self.send(ws, "ROBOT_STATE", robot(0))
        await self.until(lambda: any(t == "DONE" for t, _ in self.published))
        await self.send(ws, "FIRE", fire(7, 0))  # the arbiter did not hear the DONE: sent again
        await self.until(lambda: sum(t == "DONE" for t, _ in self.published) == 2)
        await self.send(ws, "RUN_STATUS", {"utime": 0, "state": 2, "message": "finished"})

    async def until(self, condition):
        for _ in range(500):
            if condition():
                return
            await asyncio.sleep(0.01)


def options(port):
    return types.SimpleNamespace(url="ws://127.0.0.1:%d" % port, resume_log="", heartbeat_period=0.05,
                                 connect_timeout=5.0)


async def run_against(bridge):
    async with websockets.serve(bridge.handler, "127.0.0.1", 0, subprotocols=[foxglove.SUBPROTOCOL]) as server:
        port = server.sockets[0].getsockname()[1]
        expert = GeometryExpert()
        expert.start_up()
        return await asyncio.wait_for(
            _connect_and_run(expert, LiveCore(expert, "geometry", log=lambda *a: None), options(port)), 30)


class SessionTest(unittest.TestCase):
    def test_an_expert_announces_itself_fires_once_and_answers_a_repeated_fire(self):
        bridge = FakeBridge()
        self.assertEqual(asyncio.run(run_against(bridge)), 0)
        self.assertEqual(bridge.hello["name"], "geometry")
        self.assertEqual(bridge.hello["writes"], [{"channel": "GEOMETRY", "type": "beft.geometry_percepts_t"}])
        self.assertEqual([r["channel"] for r in bridge.hello["reads"]], ["GT_OBJECTS", "GT_VERSION", "ROBOT_STATE"])
        self.assertEqual(set(bridge.subscribed), {"FIRE", "RUN_STATUS", "GT_OBJECTS", "GT_VERSION", "ROBOT_STATE"})
        topics = [t for t, _ in bridge.published]
        self.assertEqual(topics, ["GEOMETRY", "DONE", "DONE"])  # outputs before the DONE, once
        geometry, done = bridge.published[0][1], bridge.published[1][1]
        self.assertEqual(geometry["percepts"][0]["distance"], 5.0)
        self.assertEqual((done["firing_id"], done["outcome"]), (7, 0))
        self.assertEqual(bridge.published[2][1], done)

    def test_a_refused_expert_exits_with_2(self):
        self.assertEqual(asyncio.run(run_against(FakeBridge(refuse=True))), 2)


if __name__ == "__main__":
    unittest.main()
