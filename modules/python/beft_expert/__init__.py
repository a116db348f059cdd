"""Experts written in Python, taking part in a BEFT run through the bridge
(modules/python/README.md)."""

from beft_expert.expert import ChannelSpec, Expert, Firing, Outcome, Output
from beft_expert.main import run_expert_main
from beft_expert.parameters import NO_LIMIT
from beft_expert.ports import HandledInput, OutputPort, SceneInput, TickInput

__all__ = ["ChannelSpec", "Expert", "Firing", "Outcome", "Output", "run_expert_main", "NO_LIMIT",
           "HandledInput", "OutputPort", "SceneInput", "TickInput"]
