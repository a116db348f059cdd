"""Messages as JSON, as the bridge's lcmToJson writes them: a double that is
NaN or infinite is null. Received, every null is a non-finite double (no
other member is ever null) and becomes NaN; sent, NaN becomes null again.
Python's json reads and writes doubles exactly (shortest round trip), as the
bridge does, so a number crosses the bridge bit for bit."""

import json
import math


def from_json_value(value):
    if value is None:
        return math.nan
    if isinstance(value, dict):
        return {key: from_json_value(item) for key, item in value.items()}
    if isinstance(value, list):
        return [from_json_value(item) for item in value]
    return value


def to_json_value(value):
    if isinstance(value, float) and not math.isfinite(value):
        return None
    if isinstance(value, dict):
        return {key: to_json_value(item) for key, item in value.items()}
    if isinstance(value, (list, tuple)):
        return [to_json_value(item) for item in value]
    return value


def dumps(message):
    return json.dumps(to_json_value(message), allow_nan=False, separators=(",", ":"))


def loads(text):
    return from_json_value(json.loads(text))
