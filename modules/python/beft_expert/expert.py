"""One way to write an expert, the shape of the C++ framework
(lib/expert/expert.hpp): a class that declares its inputs and outputs as
port attributes and its parameters in declare_parameters, stores messages
through its ports in on_message, computes and publishes only in fire(), and
is driven by the arbiter's FIRE tokens. The same class runs live through the
bridge (runner.py) or offline against a run's messages (replay.py)."""

import collections

from beft_expert.parameters import DeclaredParameters
from beft_expert.ports import InputPort, OutputPort

# One FIRE token from the arbiter.
Firing = collections.namedtuple("Firing", "expert transition tick utime firing_id")

ChannelSpec = collections.namedtuple("ChannelSpec", "channel type")


class Outcome:
    def __init__(self, ok=True, message=""):
        self.ok, self.message = ok, message

    @staticmethod
    def success():
        return Outcome()

    @staticmethod
    def failure(why):
        return Outcome(False, why)


class UndeclaredChannel(Exception):
    pass


class Output:
    """Where fire() writes its outputs: live, to the bridge; offline, a list.
    Only the channels the expert declared an OutputPort for are accepted."""

    def __init__(self, declared=None):
        self._declared = set(declared or ())

    def publish(self, channel, message):
        if self._declared and channel not in self._declared:
            raise UndeclaredChannel("publish on %s, which the expert does not declare" % channel)
        self.send(channel, message)

    def send(self, channel, message):
        raise NotImplementedError


class CapturingOutput(Output):
    def __init__(self, declared=None):
        super().__init__(declared)
        self.captured = []  # (channel, message)

    def send(self, channel, message):
        self.captured.append((channel, message))


class Expert:
    """Subclass it: set `name` and `description`, declare ports as attributes
    in __init__ (after calling super().__init__()), override
    declare_parameters, on_start_up, inputs_ready (only to add conditions)
    and fire."""

    name = "expert"
    description = ""

    def __init__(self):
        self._parameters = None

    # --- what it reads and writes, from its ports, in the order declared ---
    def _input_ports(self):
        ports = []
        for value in vars(self).values():
            if isinstance(value, InputPort):
                ports.extend(value.ports())
        return ports

    def reads(self):
        return [ChannelSpec(port.channel, port.type) for port in self._input_ports()]

    def writes(self):
        return [ChannelSpec(v.channel, v.type) for v in vars(self).values() if isinstance(v, OutputPort)]

    # --- parameters ---
    def parameters(self):
        if self._parameters is None:
            self._parameters = DeclaredParameters()
            self.declare_parameters(self._parameters)
        return self._parameters

    def start_up(self, given=None):
        """Sets the parameters given (every other one back to its default) and
        calls on_start_up; ValueError for an unknown name, a value out of range
        or what on_start_up refuses."""
        parameters = self.parameters()
        parameters.reset_to_defaults()
        for name, value in (given or {}).items():
            parameters.set(name, value)
        self.on_start_up()

    def declare_parameters(self, parameters):
        pass

    def on_start_up(self):
        pass

    # --- messages and firings ---
    def on_message(self, channel, message):
        """Hands a message to the port that reads its channel (store only).
        False if no port reads the channel."""
        for port in self._input_ports():
            if port.channel == channel:
                port.receive(message)
                return True
        return False

    def inputs_lacking(self, firing):
        return [port.channel for port in self._input_ports() if port.lacks_tick(firing.tick)]

    def inputs_ready(self, firing):
        return not self.inputs_lacking(firing)

    def fire(self, firing, out):
        raise NotImplementedError
