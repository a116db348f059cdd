"""The paper's model as lib/model/model.cpp computes it, operation by
operation in the same order, so that a Python expert gives the same doubles
as a C++ one (the C++ is built without fused multiply-add; Python's float
arithmetic is the same IEEE double arithmetic). The functions the C library
provides are called in it: math.sin, cos, tan, atan2, exp, log and fmod are
the C library's; hypot is taken from it through ctypes, as Python's own
math.hypot is computed differently and may differ in the last bit."""

import ctypes
import ctypes.util
import math

_libm = ctypes.CDLL(ctypes.util.find_library("m"))
_libm.hypot.restype = ctypes.c_double
_libm.hypot.argtypes = (ctypes.c_double, ctypes.c_double)

RAD_TO_DEG = 180.0 / math.pi
DEG_TO_RAD = math.pi / 180.0


def hypot(x, y):
    """std::hypot."""
    return _libm.hypot(x, y)


def std_min(a, b):
    """std::min: b only when b < a."""
    return b if b < a else a


def std_max(a, b):
    """std::max: b only when a < b."""
    return b if a < b else a


def clamp(value, low, high):
    """std::clamp."""
    return low if value < low else high if high < value else value


def clamp01(value):
    return std_min(1.0, std_max(0.0, value))


def wrap_degrees(angle_deg):
    """Angle wrapped into (-180, 180] degrees."""
    a = math.fmod(angle_deg, 360.0)
    if a <= -180.0:
        a += 360.0
    if a > 180.0:
        a -= 360.0
    return a


def distance(px, py, pz, ox, oy, oz):
    return math.sqrt((ox - px) * (ox - px) + (oy - py) * (oy - py) + (oz - pz) * (oz - pz))


def azimuth(px, py, nose_heading_deg, ox, oy):
    bearing = math.atan2(oy - py, ox - px) * RAD_TO_DEG
    return wrap_degrees(bearing - nose_heading_deg)


def _curve_term(t, t_max, n):
    """The shared term of eq. 4: log(min(t, T_max)) / (2 log n), t >= 1."""
    steps = max(1, min(t, t_max))
    return math.log(float(steps)) / (2.0 * math.log(n))


def weight_rising(t, c, t_max, n):
    """Eq. 4, rising: log(min(t, T_max)) / (2 log n) + c, clamped to [0, 1]."""
    return clamp01(_curve_term(t, t_max, n) + c)


def weight_falling(t, c, t_max, n):
    """Eq. 4, falling: 2c - (log(min(t, T_max)) / (2 log n) + c), clamped."""
    return clamp01(2.0 * c - (_curve_term(t, t_max, n) + c))
