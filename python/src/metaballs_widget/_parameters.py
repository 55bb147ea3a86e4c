"""The figure's parameter table (written from the Rust table by the build, never typed here) and the
checks its parser makes, with the messages the figure gives: a bad value set from Python is refused with
the words the figure would use for the same attribute."""

from __future__ import annotations

import json
import math
import pathlib
import struct

STATIC = pathlib.Path(__file__).parent / "static"

TABLE: list[dict] = json.loads((STATIC / "parameters.json").read_text(encoding="utf-8"))
# The 2D figure's settings: the rows it shares with the 3D figure, then its own.
PLANE_TABLE: list[dict] = json.loads((STATIC / "plane-parameters.json").read_text(encoding="utf-8"))


def trait_name(name: str) -> str:
    """The Python name of a parameter (``max-pixel-ratio`` → ``max_pixel_ratio``)."""
    return name.replace("-", "_")


def older_names() -> dict:
    """The older Python spellings still accepted (``balls`` → ``sphere_list``), from the table's aliases."""
    names = {}
    for row in TABLE:
        for alias in row["aliases"]:
            old = trait_name(alias)
            if old.isidentifier() and old != row["python"] and not any(old == r["python"] for r in TABLE):
                names[old] = row["python"]
    return names


def _f32(value: float) -> float:
    """`value` rounded to single precision, as the figure holds it (infinite beyond its range)."""
    try:
        return struct.unpack("f", struct.pack("f", value))[0]
    except OverflowError:
        return math.copysign(math.inf, value)


def _f32_text(value: float) -> str:
    """A single-precision number as the figure prints it: the shortest text that reads back the same."""
    single = _f32(value)
    if single == int(single) and abs(single) < 1e16:
        return str(int(single))
    for digits in range(1, 10):
        text = f"{single:.{digits}g}"
        if _f32(float(text)) == single:
            return text
    return repr(single)


def _number_text(value: float) -> str:
    """A number as an attribute holds it (``30``, ``0.7``)."""
    return str(int(value)) if float(value).is_integer() and abs(value) < 1e16 else repr(float(value))


def attribute_text(value) -> str:
    """A Python value as its attribute's text."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, (int, float)):
        return _number_text(value)
    return str(value)


def shown(value) -> str:
    """A value as the figure quotes the one it keeps (strings in quotes)."""
    return f'"{value}"' if isinstance(value, str) else attribute_text(value)


class Refused(ValueError):
    """A value the figure would not take; the message is the figure's."""


def _invalid(row: dict, text: str) -> Refused:
    return Refused(f"{row['noun']} must be {row['expected']}, got {json.dumps(text)}")


def _range(row: dict, value: str) -> Refused:
    return Refused(f"{row['noun']} must be between {row['min_text']} and {row['max_text']}, got {value}")


def check(row: dict, value):
    """Reads ``value`` as parameter ``row`` does in the figure: returns it as the figure holds it, or
    raises ``Refused`` with the figure's message. Slices, sphere lists and free text are checked by the
    figure itself."""
    kind, text = row["kind"], attribute_text(value)
    if kind == "integer":
        digits = text.strip()
        if isinstance(value, bool) or isinstance(value, float) and not value.is_integer():
            raise _invalid(row, text)
        if not digits or not digits.isascii() or not digits.isdigit():
            raise _invalid(row, text)
        number = int(digits)
        if not row["min"] <= number <= row["max"]:
            raise _range(row, str(number))
        return number
    if kind == "number":
        if isinstance(value, bool):
            raise _invalid(row, text)
        try:
            number = float(text)
        except ValueError:
            raise _invalid(row, text) from None
        if math.isnan(number):
            raise Refused(f"{row['noun']} must be a number, got NaN")
        if math.isinf(_f32(number)):
            raise Refused(f"{row['noun']} must be finite, got infinity")
        if not _f32(row["min"]) <= _f32(number) <= _f32(row["max"]):
            raise _range(row, _f32_text(number))
        return number
    if kind == "boolean":
        if isinstance(value, bool):
            return value
        word = text.strip().lower()
        if word in ("", "1", "true", "on", "yes"):
            return True
        if word in ("0", "false", "off", "no"):
            return False
        raise _invalid(row, text)
    if kind == "spheres" and isinstance(value, (list, tuple)):
        # The sphere list as the figure reports it: dicts of center, radius, velocity and charge.
        if all(isinstance(s, dict) and "center" in s and "radius" in s for s in value):
            return list(value)
        raise Refused(f"{row['noun'] or row['name']} must be spheres as dicts with center and radius, got {text}")
    if not isinstance(value, str):
        raise _invalid(row, text) if row["expected"] else Refused(f"{row['noun']} must be text, got {text}")
    if kind == "color":
        digits = value.strip().removeprefix("#")
        if len(digits) == 6 and all(c in "0123456789abcdefABCDEF" for c in digits):
            return f"#{digits.lower()}"
        raise _invalid(row, text)
    if kind == "choice":
        word = value.strip().lower()
        if word in row["words"]:
            return word
        raise _invalid(row, text)
    if kind == "list":
        words = value.strip().lower()
        if words in ("all", "none"):
            return words
        aliases = row.get("wordAliases", {})
        items = [aliases.get(item.strip(), item.strip()) for item in words.split(",") if item.strip()]
        if not items or any(item not in row["words"] for item in items):
            raise _invalid(row, text)
        return ",".join(items)
    return value


for _row in TABLE + PLANE_TABLE:
    # The range as the figure's messages print it (single precision for numbers).
    _format = _f32_text if _row["kind"] == "number" else _number_text
    _row["min_text"], _row["max_text"] = _format(_row["min"]), _format(_row["max"])
