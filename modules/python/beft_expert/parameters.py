"""Named parameters declared once (the C++ DeclaredParameters): name,
default, range and meaning; --param NAME=VALUE, --help and --interface read
the same list, and the texts are the C++ ones."""

import math

NO_LIMIT = math.inf


def number_text(value):
    """A double as C++'s `ostream << value` writes it (6 significant digits)."""
    return "%g" % value


def _range_text(low, high, low_open, high_open):
    has_low, has_high = math.isfinite(low), math.isfinite(high)
    if has_low and has_high:
        return "%s%s, %s%s" % ("(" if low_open else "[", number_text(low), number_text(high),
                                ")" if high_open else "]")
    if has_low:
        return ("> " if low_open else ">= ") + number_text(low)
    if has_high:
        return ("< " if high_open else "<= ") + number_text(high)
    return "any finite number"


def _parse_number(text):
    try:
        value = float(text)
    except ValueError:
        return None
    return value if math.isfinite(value) else None


def _parse_whole(text):
    if "_" in text:
        return None
    try:
        return int(text, 10)
    except ValueError:
        return None


_TRUE = ("1", "true", "yes", "on")
_FALSE = ("0", "false", "no", "off")


class Parameter:
    """One declared parameter; `value` holds its current value."""

    def __init__(self, name, kind, default, range_text, meaning, accept):
        self.name, self.kind, self.default = name, kind, default
        self.range, self.meaning = range_text, meaning
        self.value = default
        self._accept = accept  # text -> value, or None when out of range

    def default_text(self):
        return self.text_of(self.default)

    def text_of(self, value):
        if self.kind == "number":
            return number_text(value)
        if self.kind == "bool":
            return "1" if value else "0"
        return str(value)

    def as_json(self):
        """What the expert's announcement lists (the fields --interface prints)."""
        return {"name": self.name, "kind": self.kind, "default": self.default_text(),
                "value": self.text_of(self.value), "range": self.range, "meaning": self.meaning}


class DeclaredParameters:
    def __init__(self):
        self._list = []
        self._by_name = {}

    def _add(self, parameter):
        if parameter.name in self._by_name:
            raise ValueError("parameter %s declared twice" % parameter.name)
        self._list.append(parameter)
        self._by_name[parameter.name] = parameter
        return parameter

    def number(self, name, default, low, high, meaning, low_open=False, high_open=False):
        def accept(text):
            value = _parse_number(text)
            if value is None:
                return None
            if (not value > low) if low_open else (not value >= low):
                return None
            if (not value < high) if high_open else (not value <= high):
                return None
            return value
        return self._add(Parameter(name, "number", float(default), _range_text(low, high, low_open, high_open),
                                   meaning, accept))

    def whole(self, name, default, low, high, meaning):
        def accept(text):
            value = _parse_whole(text)
            return value if value is not None and low <= value <= high else None
        return self._add(Parameter(name, "whole", int(default), "whole number in [%d, %d]" % (low, high),
                                   meaning, accept))

    def flag(self, name, default, meaning):
        def accept(text):
            return True if text in _TRUE else False if text in _FALSE else None
        return self._add(Parameter(name, "bool", bool(default), "0|1", meaning, accept))

    def text(self, name, default, meaning):
        return self._add(Parameter(name, "text", str(default), "text", meaning, lambda text: text))

    def set(self, name, text):
        """ValueError naming the parameter and its range, or the known names."""
        parameter = self._by_name.get(name)
        if parameter is None:
            known = ", ".join(p.name for p in self._list) or "none"
            raise ValueError("unknown parameter '%s' (known: %s)" % (name, known))
        value = parameter._accept(text)
        if value is None:
            raise ValueError("parameter %s='%s' is not %s" % (name, text, parameter.range))
        parameter.value = value

    def reset_to_defaults(self):
        for parameter in self._list:
            parameter.value = parameter.default

    def __getitem__(self, name):
        return self._by_name[name].value

    def __contains__(self, name):
        return name in self._by_name

    def list(self):
        return list(self._list)

    def describe(self, indent="  "):
        return "".join("%s%s (default %s, %s): %s\n" % (indent, p.name, p.default_text(), p.range, p.meaning)
                       for p in self._list)
