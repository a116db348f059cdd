#!/usr/bin/env python3
"""The dynamic-weighting expert in Python: a faithful port of the C++ one
(modules/experts/dw), with the same parameters and, fed the same inputs,
the same DYNAMIC_WEIGHTS and TASK_COMMAND messages bit for bit.

    python3 modules/python/examples/dw_expert.py --interface
    ./beft run scenarios/yard.xml --external dw="python3 modules/python/examples/dw_expert.py"
"""

import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))  # beft_expert from a checkout

from beft_expert import NO_LIMIT, Expert, Outcome, OutputPort, SceneInput, TickInput, run_expert_main  # noqa: E402
from beft_expert import model  # noqa: E402
from dynamic_weighting import CongruencyTable, DwParameters, DynamicWeighting, Stimulus, step_index  # noqa: E402

DESCRIPTION = (
    "High-level dynamic-weighting expert (paper section 3, eq. 4), in Python: keeps a weight in [0, 1] for every "
    "acoustic object heard (0 congruent, 1 incongruent or dangerous), stepped every dw_step_s of simulated time. "
    "Its congruency c comes from the estimated label (LABELS_ACOUSTIC) and activity (AUDIO) through the "
    "scenario's congruency table (GT_OBJECTS). Turn-to reflex: when a weight crosses reflex_threshold upward, a "
    "look_at task for that object is pushed on TASK_COMMAND with priority reflex_priority. Publishes "
    "DYNAMIC_WEIGHTS every tick.")


def _number(value):
    """A task's number as lib/task describes it: NaN is "any", else %g."""
    return "any" if math.isnan(value) else "%g" % value


def describe_task(task):
    """lib/task's describe(): "goto(12, 8, 90)", "look_at(victim1)", ..."""
    k = task["kind"]
    if k == "goto":
        return "%s(%s, %s, %s)" % (k, _number(task["x"]), _number(task["y"]), _number(task["yaw"]))
    if k in ("turn_head", "turn"):
        return "%s(%s)" % (k, _number(task["yaw"]))
    if k == "wait":
        return "%s(%s s)" % (k, _number(task["x"]))
    if k == "look_at":
        return "%s(%s)" % (k, task["object_id"] or _number(task["x"]) + ", " + _number(task["y"]))
    return "%s(%s)" % (k, task["object_id"])


def _llround(value):
    whole = math.floor(value)
    return int(whole) + (1 if value - whole >= 0.5 else 0)


def best_label(estimate):
    """The category with the highest L_j (eq. 3); None on a tie."""
    best, tie = -1, False
    confidence = estimate["confidence"]
    for j in range(min(len(estimate["categories"]), len(confidence))):
        if best < 0 or confidence[j] > confidence[best] + 1e-12:
            best, tie = j, False
        elif abs(confidence[j] - confidence[best]) <= 1e-12:
            tie = True
    return estimate["categories"][best] if best >= 0 and not tie else None


class DwExpert(Expert):
    name = "dw"
    description = DESCRIPTION

    def __init__(self):
        super().__init__()
        self.audio = TickInput("AUDIO", "beft.acoustic_percepts_t")
        self.labels = TickInput("LABELS_ACOUSTIC", "beft.labels_t")
        self.scene = SceneInput()
        self.robot = TickInput("ROBOT_STATE", "beft.robot_state_t")
        self.stack = TickInput("TASK_STACK", "beft.task_stack_t", 4)
        self.weights_out = OutputPort("DYNAMIC_WEIGHTS", "beft.dynamic_weights_t")
        self.task_command_out = OutputPort("TASK_COMMAND", "beft.task_command_t")
        self.dw = None
        self.last_step_index = -2 ** 63
        self.adopted_entries = None
        self.attended_object = ""
        self.next_command_id = 1

    def declare_parameters(self, p):
        p.number("dw_step_s", 0.5, 1e-6, NO_LIMIT, "simulated time between two DW steps [s]")
        p.whole("t_max", 10, 1, 1000000, "T_max of eq. 4: curve length and re-evaluation delay [steps]")
        p.number("n", 100, 1, NO_LIMIT, "n of eq. 4 (T_max^2: one curve spans 0.25)", low_open=True)
        p.number("reflex_threshold", 0.75, 0, 1, "an upward crossing of this weight triggers the turn-to reflex")
        p.whole("reflex_priority", 100, 0, 1000000, "priority of the reflex look_at task")
        p.flag("reflex", True, "push reflex tasks at all (0: weights only)")
        p.number("incongruent_c", 0.75, 0, 1, "a (label, activity) with c >= this rises, others fall")
        p.number("initial_weight", 0.5, 0, 1, "weight of a newly heard object")
        p.number("default_c", 0.5, 0, 1, "c of a (label, activity) pair not in the congruency table")
        p.flag("reevaluate", True, "re-evaluate c after more than T_max unchanged steps")
        p.number("min_perceptibility", 0.0, 0, 1, "an object counts as heard when its a_P is at least this")
        p.number("residual_floor", 0.5, 0, 1, "the lowest weight of an object that has been incongruent")
        p.number("danger_radius", 3.0, 0, NO_LIMIT, "a person this close to a hazard (centre to centre) is "
                 "endangered: c = incongruent_c; 0: off [m]")
        p.text("danger_labels", "fire", "labels of hazards, comma-separated (a hazard's pair has c >= incongruent_c)")

    def on_start_up(self):
        p = self.parameters()
        self.step_us = _llround(p["dw_step_s"] * 1e6)
        parameters = DwParameters()
        for name in ("t_max", "n", "reflex_threshold", "incongruent_c", "initial_weight", "reevaluate",
                     "residual_floor", "danger_radius"):
            setattr(parameters, name, p[name])
        parameters.danger_labels = [label for label in p["danger_labels"].split(",") if label]
        table = CongruencyTable()
        table.default_value = p["default_c"]
        self.dw = DynamicWeighting(parameters, table)

    def step_due(self, utime):
        return step_index(utime, self.step_us) > self.last_step_index

    def inputs_ready(self, firing):
        if not self.robot.has(firing.tick) or not self.scene.has(firing.tick):
            return False
        if self.step_due(firing.utime) and (not self.audio.has(firing.tick) or not self.labels.has(firing.tick)):
            return False
        stack = self.stack.latest()  # the stack of the previous tick (tasks fire last)
        return not (stack is not None and firing.tick - 2 <= stack["tick"] < firing.tick - 1)

    def adopt_table(self, scene):
        entries = [(e["label"], e["activity"], e["value"]) for e in scene["congruency"]]
        if entries == self.adopted_entries:
            return
        self.adopted_entries = entries
        table = CongruencyTable()  # the defaults, overridden and extended by the scenario
        table.default_value = self.parameters()["default_c"]
        for label, activity, value in entries:
            try:
                table.set(label, activity, value)
            except ValueError as error:
                print("GT_OBJECTS congruency entry ignored: %s" % error, file=sys.stderr)
        self.dw.table = table

    def stimuli_of(self, audio, labels):
        min_perceptibility = self.parameters()["min_perceptibility"]
        stimuli = []
        for percept in audio["percepts"]:
            label = percept["acoustic_label"]  # used when the labels cannot tell
            estimate = None
            for labelled in (labels["objects"] if labels is not None else []):
                if labelled["object_id"] == percept["object_id"]:
                    estimate = labelled
            if estimate is not None:
                if estimate["perceptibility"] < min_perceptibility:
                    continue
                label = best_label(estimate) or label
            elif min_perceptibility > 0:
                continue  # not labelled: not heard well enough
            stimuli.append(Stimulus(percept["object_id"], label, percept["activity"], percept["est_x"],
                                    percept["est_y"]))
        return stimuli

    def viewing_direction(self, robot):
        heaviest = None
        for o in self.dw.objects:
            if o.weight >= self.dw.parameters.reflex_threshold and (heaviest is None or o.weight > heaviest.weight):
                heaviest = o
        if heaviest is None or robot is None:
            return math.nan
        return model.wrap_degrees(math.atan2(heaviest.y - robot["y"], heaviest.x - robot["x"]) * 180.0 / math.pi)

    def reflex_command(self, trigger, utime):
        note = "turn-to reflex: %s weight %.2f" % (trigger.object_id, trigger.weight_after)
        task = {"task_id": 0, "parent_id": 0, "kind": "look_at", "priority": self.parameters()["reflex_priority"],
                "x": trigger.x, "y": trigger.y, "yaw": 0.0, "object_id": trigger.object_id, "status": 0,
                "origin": "dw", "note": note}
        command = {"utime": utime, "command_id": self.next_command_id, "command": 0, "task": task}
        self.next_command_id += 1
        return command

    def step(self, firing, out):
        self.last_step_index = step_index(firing.utime, self.step_us)
        audio = self.audio.of_tick(firing.tick)
        if audio is None:
            print("tick %d: no AUDIO of this tick, DW step with nothing heard" % firing.tick, file=sys.stderr)
            self.dw.step([])
            return
        for trigger in self.dw.step(self.stimuli_of(audio, self.labels.of_tick(firing.tick))):
            self.attended_object = trigger.object_id
            if self.parameters()["reflex"]:
                self.task_command_out.publish(out, self.reflex_command(trigger, firing.utime))

    def fire(self, firing, out):
        if self.dw is None:
            self.start_up()
        scene = self.scene.of_tick(firing.tick) or self.scene.latest()
        if scene is not None:
            self.adopt_table(scene)
        if self.step_due(firing.utime):
            self.step(firing, out)
        robot = self.robot.of_tick(firing.tick) or self.robot.latest()
        stack = self.stack.latest()
        if stack is not None and stack["tasks"]:
            current_task = describe_task(stack["tasks"][0])
        else:
            current_task = "idle" if stack is not None else ""
        weights = [{"object_id": o.object_id, "weight": o.weight, "congruency": o.congruency, "rising": o.rising,
                    "step": o.step, "label": o.label, "activity": o.activity, "sounding": o.sounding}
                   for o in self.dw.objects]
        self.weights_out.publish(out, {
            "utime": firing.utime, "tick": firing.tick, "viewing_direction": self.viewing_direction(robot),
            "current_task": current_task, "attended_object": self.attended_object,
            "num_weights": len(weights), "weights": weights})
        return Outcome.success()


if __name__ == "__main__":
    sys.exit(run_expert_main(DwExpert()))
