"""Dynamic weighting of acoustic objects (paper section 3, eq. 4), a faithful
port of modules/experts/dw/dynamic_weighting.cpp: one weight per object
heard, stepped at a fixed interval of simulated time, and the turn-to
reflex when a weight crosses the reflex threshold upward. Plain logic."""

import math

from beft_expert import model

UNCHANGED_EPSILON = 1e-9  # weights equal to this precision count as unchanged


class CongruencyTable:
    """c for (label, activity) pairs; pairs not in the table give the default."""

    def __init__(self):
        self.values = {}
        self.default_value = 0.5
        # The default pairs of the scenario format; a scenario may override them.
        for label, activity, c in (("person", "walking", 0.25), ("person", "idle", 0.25),
                                   ("person", "yelling", 0.75), ("fire", "burning", 0.5),
                                   ("fire", "spreading", 0.75), ("siren", "ringing", 0.5), ("car", "idle", 0.25)):
            self.set(label, activity, c)

    def set(self, label, activity, c):
        if not math.isfinite(c) or c < 0 or c > 1:
            raise ValueError("congruency of (%s, %s) must be in [0, 1], not %f" % (label, activity, c))
        self.values[(label, activity)] = c

    def of(self, label, activity):
        return self.values.get((label, activity), self.default_value)


class DwParameters:
    def __init__(self):
        self.t_max = 10
        self.n = 100.0
        self.initial_weight = 0.5
        self.incongruent_c = 0.75
        self.reflex_threshold = 0.75
        self.reevaluate = True
        self.residual_floor = 0.5
        self.danger_radius = 3.0
        self.danger_labels = ["fire"]
        self.endangered_label = "person"


class Stimulus:
    def __init__(self, object_id, label, activity, x, y):
        self.object_id, self.label, self.activity, self.x, self.y = object_id, label, activity, x, y


class ObjectWeight:
    def __init__(self, object_id):
        self.object_id = object_id
        self.weight = 0.5
        self.congruency = 0.5
        self.rising = False
        self.step = 0
        self.unchanged_steps = 0
        self.label = self.activity = ""
        self.x = self.y = 0.0
        self.sounding = False
        self.first_step = 0
        self.was_incongruent = False
        self.endangered = False


class ReflexTrigger:
    def __init__(self, object_id, weight_before, weight_after, x, y):
        self.object_id, self.weight_before, self.weight_after = object_id, weight_before, weight_after
        self.x, self.y = x, y


class DynamicWeighting:
    def __init__(self, parameters, table):
        if parameters.t_max < 1:
            raise ValueError("t_max must be >= 1")
        if not parameters.n > 1:
            raise ValueError("n must be > 1")
        self.parameters, self.table = parameters, table
        self.objects = []  # every object ever heard, in the order first heard
        self.steps_taken = 0

    def _curve(self, o):
        p = self.parameters
        return (model.weight_rising if o.rising else model.weight_falling)(o.step, o.congruency, p.t_max, p.n)

    def _start_curve(self, o, c):
        o.congruency = c
        o.rising = c >= self.parameters.incongruent_c
        o.step = 1

    def _advance(self, o, c):
        """One step of a known object heard with congruency c, or silent (None)."""
        p = self.parameters
        incongruent = p.incongruent_c
        on_incongruent_curve = o.congruency >= incongruent
        weight = o.weight
        if c is not None and c >= incongruent:
            if o.rising and on_incongruent_curve:
                o.step += 1
            else:
                self._start_curve(o, c)
            o.was_incongruent = True
            weight = self._curve(o)
        elif o.rising:
            o.rising = False
            o.step = 1
            weight = self._curve(o)
        elif on_incongruent_curve:
            o.step += 1
            weight = self._curve(o)
        elif c is None:
            return weight
        else:
            if c != o.congruency:
                self._start_curve(o, c)
            else:
                o.step += 1
            weight = model.std_min(weight, self._curve(o))
        if o.was_incongruent:
            weight = model.std_max(weight, p.residual_floor)
        if c is None:
            return weight
        o.unchanged_steps = o.unchanged_steps + 1 if abs(weight - o.weight) < UNCHANGED_EPSILON else 0
        if p.reevaluate and o.unchanged_steps > p.t_max:
            o.unchanged_steps = 0
            rises = c >= incongruent
            if c != o.congruency or rises != o.rising:
                self._start_curve(o, c)
                weight = self._curve(o) if rises else model.std_min(weight, self._curve(o))
                if o.was_incongruent:
                    weight = model.std_max(weight, p.residual_floor)
        return weight

    def _mark_endangered(self):
        p = self.parameters
        for o in self.objects:
            o.endangered = False
        if p.danger_radius <= 0:
            return
        radius2 = p.danger_radius * p.danger_radius
        for hazard in self.objects:
            if hazard.label not in p.danger_labels or self.table.of(hazard.label, hazard.activity) < p.incongruent_c:
                continue
            for o in self.objects:
                if o is hazard or o.label != p.endangered_label:
                    continue
                dx, dy = o.x - hazard.x, o.y - hazard.y
                if dx * dx + dy * dy <= radius2:
                    o.endangered = True

    def step(self, sounding):
        """One DW step with every object that sounds now; the reflex triggers."""
        p = self.parameters
        step_index = self.steps_taken
        self.steps_taken += 1
        for o in self.objects:
            o.sounding = False
        is_new = set()
        for stimulus in sounding:
            o = next((known for known in self.objects if known.object_id == stimulus.object_id), None)
            if o is None:
                o = ObjectWeight(stimulus.object_id)
                o.weight = model.clamp(p.initial_weight, 0.0, 1.0)
                o.congruency = self.table.of(stimulus.label, stimulus.activity)
                o.rising = o.congruency >= p.incongruent_c
                o.first_step = step_index
                self.objects.append(o)
                is_new.add(id(o))
            elif o.sounding:
                continue  # listed twice in one step: the first counts
            o.sounding = True
            o.label, o.activity, o.x, o.y = stimulus.label, stimulus.activity, stimulus.x, stimulus.y
        self._mark_endangered()
        triggers = []
        for o in self.objects:
            if id(o) in is_new:
                continue
            c = self.table.of(o.label, o.activity) if o.sounding else None
            if o.endangered:
                c = model.std_max(0.0 if c is None else c, p.incongruent_c)
            before = o.weight
            o.weight = model.clamp(self._advance(o, c), 0.0, 1.0)
            if before < p.reflex_threshold and o.weight >= p.reflex_threshold:
                triggers.append(ReflexTrigger(o.object_id, before, o.weight, o.x, o.y))
        return triggers


def step_index(utime, step_us):
    """floor(utime / step_us), also for negative times."""
    if step_us <= 0:
        raise ValueError("DW step must be > 0")
    return utime // step_us if utime >= 0 else -((-utime + step_us - 1) // step_us)
