"""An expert live through the bridge (modules/python/README.md, "The
protocol"): connects over the Foxglove WebSocket protocol, announces itself,
subscribes to FIRE, RUN_STATUS and its inputs, and publishes its outputs,
DONE and HEARTBEAT as JSON, which the bridge checks and publishes on the
run's channels. Crash-only: when the bridge goes away the process exits (1),
and its supervisor restarts it with --resume-log."""

import asyncio
import os
import signal
import socket
import sys
import time

from beft_expert import foxglove
from beft_expert.jsonvalues import dumps, from_json_value as _from_json, loads
from beft_expert.replay import resume

ANNOUNCE_TOPIC = "/beft/expert"
ANNOUNCE_SCHEMA = "beft.external_expert"
CONTROL_TYPES = {"FIRE": "beft.fire_t", "RUN_STATUS": "beft.run_status_t"}
ANSWER_TYPES = {"DONE": "beft.done_t", "HEARTBEAT": "beft.heartbeat_t"}


def log(*parts):
    print("[%s] %s" % (log.process, " ".join(str(p) for p in parts)), file=sys.stderr, flush=True)


log.process = "expert"


def announcement(expert, process_name, resume_log):
    """The first message: who the expert is (the fields --interface prints)."""
    return {"protocol": 1, "name": process_name, "pid": os.getpid(), "host": socket.gethostname(),
            "reads": [{"channel": s.channel, "type": s.type} for s in expert.reads()],
            "writes": [{"channel": s.channel, "type": s.type} for s in expert.writes()],
            "parameters": [p.as_json() for p in expert.parameters().list()],
            "resume_log": resume_log or ""}


class Session:
    def __init__(self, expert, core, options):
        self.expert, self.core, self.options = expert, core, options
        self.name = core.process_name
        self.server_channels = {}   # topic -> server channel id
        self.subscriptions = {}     # subscription id -> topic
        self.client_ids = {}        # topic -> client channel id
        self.wanted = ["FIRE", "RUN_STATUS"] + [s.channel for s in expert.reads()]
        self.accepted = None        # None: no answer yet; True / False
        self.history = []
        self.stop = asyncio.Event()
        self.last_waiting_answer = 0.0

    async def run(self, ws):
        self.ws = ws
        await self._advertise()
        await self._publish(ANNOUNCE_TOPIC, announcement(self.expert, self.name, self.options.resume_log))
        while self.accepted is None:
            self._on_frame(await ws.recv())
        if not self.accepted:
            return 2
        if self.options.resume_log:
            self._resume()
        await self._subscribe()
        beats = asyncio.ensure_future(self._heartbeats())
        try:
            return await self._serve()
        finally:
            beats.cancel()

    async def _serve(self):
        while not self.stop.is_set() and not self.core.run_ended:
            try:
                frame = await asyncio.wait_for(self.ws.recv(), 0.1)
                answer = self._on_frame(frame)
                if answer is not None:
                    await self._publish("DONE", answer)
            except asyncio.TimeoutError:
                pass
            if self.core.firing_due():
                outputs, done = await asyncio.get_running_loop().run_in_executor(None, self.core.fire_now)
                for channel, message in outputs:  # before the DONE, on one ordered socket
                    await self._publish(channel, message)
                await self._publish("DONE", done)
        log("run ended: " + self.core.run_end_reason if self.core.run_ended else "stopped by signal",
            "(%d firings)" % self.core.firings_run)
        return 0

    def _resume(self):
        state = resume(self.expert, self.name, self.history)
        self.core.adopt_resumed(state)
        log("resumed from the run's history: %d firings and %d inputs replayed" % (state.firings, state.inputs))
        self.history = []

    async def _advertise(self):
        channels = [(1, ANNOUNCE_TOPIC, ANNOUNCE_SCHEMA)]
        for spec in self.expert.writes():
            channels.append((len(channels) + 1, spec.channel, spec.type))
        for topic, schema in ANSWER_TYPES.items():
            channels.append((len(channels) + 1, topic, schema))
        self.client_ids = {topic: cid for cid, topic, _ in channels}
        await self.ws.send(foxglove.advertise(channels))

    async def _subscribe(self):
        requests = []
        for topic in self.wanted:
            if topic in self.server_channels and topic not in self.subscriptions.values():
                sid = len(self.subscriptions) + 1
                self.subscriptions[sid] = topic
                requests.append((sid, self.server_channels[topic]))
        if requests:
            await self.ws.send(foxglove.subscribe(requests))

    async def _publish(self, topic, message):
        await self.ws.send(foxglove.publish_frame(self.client_ids[topic], dumps(message)))

    async def _heartbeats(self):
        while True:
            await self._beat()
            await asyncio.sleep(self.options.heartbeat_period)

    async def _beat(self):
        await self._publish("HEARTBEAT", self.core.heartbeat(os.getpid(), socket.gethostname(),
                                                             int(time.time() * 1e6)))

    def _on_frame(self, frame):
        """Handles one server frame; returns a DONE to send again, if any."""
        if isinstance(frame, (bytes, bytearray)):
            data = foxglove.parse_message_data(frame)
            if data is not None and data[0] in self.subscriptions:
                return self._on_message(self.subscriptions[data[0]], loads(data[2]))
            return None
        message = foxglove.parse_text(frame)
        if message is None:
            return None
        op = message["op"]
        if op == "advertise":
            for channel in message.get("channels", []):
                self.server_channels[channel["topic"]] = channel["id"]
            if self.accepted:
                asyncio.ensure_future(self._subscribe())  # channels advertised late
        elif op == "beftHistory":
            self.history.append((message["channel"], _from_json(message["message"])))
        elif op == "status":
            self._on_status(message)
        return None

    def _on_status(self, status):
        sid = status.get("id", "")
        text = status.get("message", "")
        if sid == "beft.expert." + self.name:
            self.accepted = status.get("level") != foxglove.STATUS_ERROR
            log("bridge:", text)
        elif sid.startswith("beft.expert." + self.name + "."):
            log("bridge refused:", text)
            if self.accepted is None and status.get("level") == foxglove.STATUS_ERROR:
                self.accepted = False

    def _on_message(self, topic, message):
        if topic == "FIRE":
            return self.core.on_fire(message)
        if topic == "RUN_STATUS":
            if self.core.on_run_status(message) and time.monotonic() - self.last_waiting_answer > 0.05:
                self.last_waiting_answer = time.monotonic()
                asyncio.ensure_future(self._beat())
            return None
        try:
            self.expert.on_message(topic, message)  # store only
        except Exception as error:
            log("message on %s raised: %s" % (topic, error))
        return None


async def _connect_and_run(expert, core, options):
    import websockets  # Debian: python3-websockets
    deadline = time.monotonic() + options.connect_timeout
    while True:
        try:
            ws = await websockets.connect(options.url, subprotocols=[foxglove.SUBPROTOCOL], max_size=None,
                                          close_timeout=1)
            break
        except (OSError, websockets.exceptions.InvalidHandshake) as error:
            if time.monotonic() >= deadline:
                log("cannot connect to the bridge at %s: %s" % (options.url, error))
                return 1
            await asyncio.sleep(0.2)  # the bridge may start after this process
    session = Session(expert, core, options)
    loop = asyncio.get_running_loop()
    for signum in (signal.SIGINT, signal.SIGTERM):
        loop.add_signal_handler(signum, session.stop.set)
    log("connected to", options.url)
    try:
        return await session.run(ws)
    except websockets.exceptions.ConnectionClosed:
        log("the bridge closed the connection; exiting (restarted, this process resumes)")
        return 1
    finally:
        await ws.close()


def run_live(expert, core, options):
    log.process = core.process_name
    return asyncio.run(_connect_and_run(expert, core, options))
