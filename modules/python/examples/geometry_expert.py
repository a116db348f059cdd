#!/usr/bin/env python3
"""The low-level geometry expert in Python: a faithful port of the C++ one
(modules/experts/geometry, reference points of lib/scene/object_geometry),
with the same parameter and, fed the same inputs, the same GEOMETRY
messages bit for bit."""

import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))  # beft_expert from a checkout

from beft_expert import Expert, Outcome, OutputPort, SceneInput, TickInput, run_expert_main  # noqa: E402
from beft_expert import model  # noqa: E402

SHAPE_BOX, SHAPE_CYLINDER = 1, 2

DESCRIPTION = (
    "Low-level geometry expert, in Python: for every scene object that sounds now or may be in front of the "
    "camera (every_object: all of them), the 3-D distance d_i from the platform centre (on the ground) to the "
    "object centre (half its height), the azimuth alpha_i relative to the nose (platform yaw + head yaw; "
    "(-180, 180] deg, positive to the left) and the elevation relative to the head pitch; flags objects that "
    "sound now. Reads GT_OBJECTS and ROBOT_STATE of the fired tick, writes GEOMETRY.")


def has_visual(o):
    return o["shape"] in (SHAPE_BOX, SHAPE_CYLINDER)


def is_sounding(o):
    return bool(o["has_acoustic"] and o["sound_active"])


def nose_heading_deg(robot):
    return robot["yaw"] + robot["head_yaw"]


def object_centre_z(o):
    half_height = 0.5 * o["size_z"] if has_visual(o) else 0.0
    return o["z"] + half_height


def perceivable(robot, o):
    """Sounds now, or some part of it may be in front of the camera."""
    if is_sounding(o):
        return True
    if not has_visual(o):
        return False
    heading = nose_heading_deg(robot) * model.DEG_TO_RAD
    ahead = (o["x"] - robot["x"]) * math.cos(heading) + (o["y"] - robot["y"]) * math.sin(heading)
    extent = 0.5 * model.hypot(o["size_x"], o["size_y"])
    tilt = model.std_min(abs(robot["head_pitch"]), 80.0) * model.DEG_TO_RAD
    seen_behind = model.std_max(robot["camera_height"], o["z"] + o["size_z"]) * math.tan(tilt)
    return ahead > -(extent + seen_behind + 0.5)


def percept_of(robot, o):
    oz = object_centre_z(o)
    dx, dy, dz = o["x"] - robot["x"], o["y"] - robot["y"], oz - robot["camera_height"]
    elevation = math.atan2(dz, model.hypot(dx, dy)) / model.DEG_TO_RAD - robot["head_pitch"]
    return {"object_id": o["id"],
            "distance": model.distance(robot["x"], robot["y"], 0.0, o["x"], o["y"], oz),
            "azimuth": model.azimuth(robot["x"], robot["y"], nose_heading_deg(robot), o["x"], o["y"]),
            "elevation": elevation, "acoustic": is_sounding(o)}


def estimate_geometry(scene, robot, every_object=False):
    percepts = [percept_of(robot, o) for o in scene["objects"] if every_object or perceivable(robot, o)]
    return {"utime": scene["utime"], "tick": scene["tick"], "num_percepts": len(percepts), "percepts": percepts}


class GeometryExpert(Expert):
    name = "geometry"
    description = DESCRIPTION

    def __init__(self):
        super().__init__()
        self.scene = SceneInput()
        self.robot = TickInput("ROBOT_STATE", "beft.robot_state_t")
        self.geometry_out = OutputPort("GEOMETRY", "beft.geometry_percepts_t")

    def declare_parameters(self, p):
        p.flag("every_object", False, "a percept for every scene object, also the silent ones behind the camera, "
               "which no expert reads (off: only those that sound now or may be in front of the camera)")

    def fire(self, firing, out):
        scene, robot = self.scene.of_tick(firing.tick), self.robot.of_tick(firing.tick)
        if scene is None or robot is None:
            return Outcome.failure("no %s for tick %d" % ("GT_OBJECTS" if scene is None else "ROBOT_STATE",
                                                          firing.tick))
        self.geometry_out.publish(out, estimate_geometry(scene, robot, self.parameters()["every_object"]))
        return Outcome.success()


if __name__ == "__main__":
    sys.exit(run_expert_main(GeometryExpert()))
