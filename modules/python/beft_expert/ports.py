"""An expert's inputs and outputs, declared once as attributes (the C++
ports.hpp): what it reads and writes (--interface, the subscriptions, the
announcement to the bridge) is derived from them. Messages are the JSON
objects of the .lcm definitions (the bridge's lcmToJson), NaN as None."""

import collections


class InputPort:
    def __init__(self, channel, type_name):
        self.channel = channel
        self.type = type_name

    def receive(self, message):
        raise NotImplementedError

    def lacks_tick(self, tick):
        """Whether the port keeps inputs by tick and has none of this one."""
        return False

    def ports(self):
        """The channels this input reads, each as a port (a scene reads two)."""
        return [self]


class _History:
    """The newest `capacity` messages of a channel in arrival order (the C++
    ChannelHistory), each with a sequence number and its utime."""

    Entry = collections.namedtuple("Entry", "sequence utime message")

    def __init__(self, capacity):
        self._entries = collections.deque(maxlen=max(1, capacity))
        self._last_sequence = 0

    def store(self, message):
        self._last_sequence += 1
        self._entries.append(self.Entry(self._last_sequence, message["utime"], message))

    def latest(self):
        return self._entries[-1] if self._entries else None

    def at_or_before(self, utime):
        for entry in reversed(self._entries):
            if entry.utime <= utime:
                return entry
        return None

    def of_tick(self, tick):
        """The newest entry of tick k; walks back one simulated time at a time."""
        entry = self.latest()
        while entry is not None:
            if entry.message["tick"] == tick:
                return entry
            entry = self.at_or_before(entry.utime - 1)
        return None

    def empty(self):
        return not self._entries


class TickInput(InputPort):
    """Messages kept by the tick they belong to (every such type carries utime
    and tick), looked up by the firing's tick."""

    def __init__(self, channel, type_name, capacity=16, optional_until_heard=False):
        super().__init__(channel, type_name)
        self._history = _History(capacity)
        self._optional_until_heard = optional_until_heard

    def receive(self, message):
        self._history.store(message)

    def of_tick(self, tick):
        entry = self._history.of_tick(tick)
        return None if entry is None else entry.message

    def latest(self):
        entry = self._history.latest()
        return None if entry is None else entry.message

    def has(self, tick):
        return self._history.of_tick(tick) is not None

    def empty(self):
        return self._history.empty()

    def lacks_tick(self, tick):
        return not (self._optional_until_heard and self.empty()) and not self.has(tick)


class HandledInput(InputPort):
    """Each message handed to a function of the expert's (a queue of commands)."""

    def __init__(self, channel, type_name, handler):
        super().__init__(channel, type_name)
        self._handler = handler

    def receive(self, message):
        self._handler(message)


class SceneInput(InputPort):
    """The ground truth of a tick (the C++ SceneInput): GT_OBJECTS comes when
    the scene changed and at keyframes, GT_VERSION every tick naming the
    GT_OBJECTS message in force; without any GT_VERSION heard (older logs)
    tick k's ground truth is the GT_OBJECTS message of tick k."""

    def __init__(self, capacity=4):
        super().__init__("GT_OBJECTS", "beft.scene_objects_t")
        self._keyframes = _History(capacity)
        self.versions = TickInput("GT_VERSION", "beft.scene_version_t", 16, optional_until_heard=True)

    def receive(self, message):
        self._keyframes.store(message)

    def of_tick(self, tick):
        """Tick k's ground truth stamped with tick k's utime and tick, or None."""
        version = self.versions.of_tick(tick)
        keyframe = self._keyframes.of_tick(version["scene_tick"] if version is not None else tick)
        if keyframe is None:
            return None
        if keyframe.message["tick"] == tick:
            return keyframe.message
        restamped = dict(keyframe.message)
        restamped["utime"] = version["utime"]
        restamped["tick"] = tick
        return restamped

    def has(self, tick):
        return self.of_tick(tick) is not None

    def latest(self):
        entry = self._keyframes.latest()
        return None if entry is None else entry.message

    def lacks_tick(self, tick):
        return not self.has(tick)

    def ports(self):
        return [self, self.versions]


class OutputPort:
    def __init__(self, channel, type_name):
        self.channel = channel
        self.type = type_name

    def publish(self, out, message):
        out.publish(self.channel, message)
