"""The figure's parameter table (written from the Rust table by the build, never typed here) and the
checks its parser makes, with the messages the figure gives: a bad value set from Python is refused with
the words the figure would use for the same attribute."""

from __future__ import annotations

import json
import math
import pathlib
import re
import struct
import unicodedata

STATIC = pathlib.Path(__file__).parent / "static"

TABLE: list[dict] = json.loads((STATIC / "parameters.json").read_text(encoding="utf-8"))
# The 2D figure's settings: the rows it shares with the 3D figure, then its own.
PLANE_TABLE: list[dict] = json.loads((STATIC / "plane-parameters.json").read_text(encoding="utf-8"))


def trait_name(name: str) -> str:
    """The Python name of a parameter (``max-pixel-ratio`` → ``max_pixel_ratio``)."""
    return name.replace("-", "_")


def older_names(table: list[dict] | None = None) -> dict:
    """The older Python spellings still accepted (``balls`` → ``sphere_list``; ``levels`` → ``iso_levels``
    in the 2D figure), from the table's aliases."""
    table = TABLE if table is None else table
    names = {}
    for row in table:
        for alias in row["aliases"]:
            old = trait_name(alias)
            if old.isidentifier() and old != row["python"] and not any(old == r["python"] for r in table):
                names[old] = row["python"]
    return names


def _f32(value: float) -> float:
    """`value` rounded to single precision, as the figure holds it (infinite beyond its range)."""
    try:
        return struct.unpack("f", struct.pack("f", value))[0]
    except OverflowError:
        return math.copysign(math.inf, value)


def _plain(text: str) -> str:
    """A decimal in exponent form written out in full, as the figure writes numbers."""
    match = re.fullmatch(r"(-?)([0-9]+)(?:\.([0-9]+))?(?:e([+-]?[0-9]+))?", text)
    sign, whole, fraction, exponent = match.group(1), match.group(2), match.group(3) or "", match.group(4) or "0"
    digits = whole + fraction
    point = len(whole) + int(exponent)
    leading = len(digits) - len(digits.lstrip("0"))
    digits, point = digits[leading:].rstrip("0"), point - leading
    if not digits:
        return f"{sign}0"
    if point <= 0:
        return f"{sign}0.{'0' * -point}{digits}"
    if point >= len(digits):
        return f"{sign}{digits}{'0' * (point - len(digits))}"
    return f"{sign}{digits[:point]}.{digits[point:]}"


def _shortest_f32(single: float) -> str:
    """The shortest decimal that reads back as the single-precision ``single``, the nearest of that length
    where several do (the neighbours of the nearest are tried: below a power of two the single's interval
    is half as wide)."""
    if single == 0:
        return "-0" if math.copysign(1, single) < 0 else "0"
    for length in range(1, 10):
        mantissa, _, power = f"{single:.{length - 1}e}".partition("e")
        digits, exponent = int(mantissa.replace(".", "")), int(power) - (length - 1)
        candidates = [f"{d}e{exponent}" for d in (digits - 1, digits, digits + 1) if _f32(float(f"{d}e{exponent}")) == single]
        if candidates:
            return min(candidates, key=lambda text: abs(float(text) - single))
    return f"{single:.8e}"


def _f32_text(value: float) -> str:
    """A single-precision number as the figure prints it: the shortest text that reads back the same."""
    single = _f32(value)
    return _f64_text(single) if not math.isfinite(single) else _plain(_shortest_f32(single))


def _f64_text(value: float) -> str:
    """A number as the figure prints a double (``4294967295``, ``0.05``, ``inf``)."""
    if math.isnan(value):
        return "NaN"
    if math.isinf(value):
        return "inf" if value > 0 else "-inf"
    return "-0" if value == 0 and math.copysign(1, value) < 0 else _plain(repr(float(value)).replace("e+", "e"))


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


# What Rust's `str::parse::<f64>` reads: no spaces, no hexadecimal, `inf` and `nan` in any case.
_DECIMAL = re.compile(r"([+-]?)(?:(inf|infinity)|(nan)|((?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][+-]?[0-9]+)?))", re.I)
# The white space Rust's `str::trim` takes off.
_SPACE = "\t\n\x0b\x0c\r \x85\xa0\u1680\u2000\u2001\u2002\u2003\u2004\u2005\u2006\u2007\u2008\u2009\u200a\u2028\u2029\u202f\u205f\u3000"
# Characters the figure's messages write as \u{…}: controls, formats, separators but the space,
# private use, unassigned, and combining marks.
_ESCAPED = {"Cc", "Cf", "Co", "Cn", "Zl", "Zp", "Zs", "Cs", "Mn", "Me"}
_SHORT = {"\t": "\\t", "\r": "\\r", "\n": "\\n", "\0": "\\0", '"': '\\"', "\\": "\\\\"}


def _parse_f64(text: str):
    match = _DECIMAL.fullmatch(text)
    if not match:
        return None
    magnitude = math.inf if match.group(2) else math.nan if match.group(3) else float(match.group(4))
    return -magnitude if match.group(1) == "-" else magnitude


def _lower(text: str) -> str:
    return "".join(c.lower() if "A" <= c <= "Z" else c for c in text)


def _quoted(text: str) -> str:
    """``text`` in quotes as the figure's messages write it, cut short after 40 characters."""

    def escape(c):
        if c in _SHORT:
            return _SHORT[c]
        if c != " " and unicodedata.category(c) in _ESCAPED:
            return f"\\u{{{ord(c):x}}}"
        return c

    return '"' + "".join(escape(c) for c in text[:40]) + '"' + ("…" if len(text) > 40 else "")


def _short_number(text: str) -> str:
    """A number in a message: as written, or in scientific notation when its digits run long."""
    if len(text) <= 24 or _parse_f64(text) is None:
        return text
    mantissa, _, exponent = repr(float(text)).partition("e")
    mantissa = mantissa.removesuffix(".0")
    return f"{mantissa}e{int(exponent or 0)}" if exponent else f"{mantissa}e0"


def _in_range(noun: str, value: float, low: float, high: float, written) -> float:
    if not low <= value <= high:
        raise Refused(f"{noun} must be between {written(low)} and {written(high)}, got {_short_number(written(value))}")
    return value


def _number(row: dict, noun: str, trimmed: str, text: str) -> float:
    value = _parse_f64(trimmed)
    if value is None:
        raise Refused(f"{noun} must be a number from {_f32_text(row['min'])} to {_f32_text(row['max'])}, got {_quoted(text)}")
    single = _f32(value)
    if math.isnan(single):
        raise Refused(f"{noun} must be a number, got NaN")
    if math.isinf(single):
        raise Refused(f"{noun} must be finite, got infinity")
    _in_range(noun, single, _f32(row["min"]), _f32(row["max"]), _f32_text)
    return float(_shortest_f32(single))


def read(row: dict, text: str, given: str | None = None):
    """Reads ``text`` as the figure reads parameter ``row`` (the table's parser, held to the same test
    vectors as the page's reader): the value as the figure holds it, or ``Refused`` with its message,
    naming the parameter by ``given`` (the spelling it was given by) where the row has no noun."""
    noun = row["noun"] or given or row["name"]
    trimmed = text.strip(_SPACE)

    def invalid(expected):
        return Refused(f"{noun} must be {expected}, got {_quoted(text)}")

    kind = row["kind"]
    if kind == "integer":
        if not trimmed or not all("0" <= c <= "9" for c in trimmed):
            raise invalid(f"a whole number from {_f64_text(row['min'])} to {_f64_text(row['max'])}")
        value = float(trimmed)
        _in_range(noun, value, row["min"], row["max"], _f64_text)
        return int(value)
    if kind == "number":
        return _number(row, noun, trimmed, text)
    if kind == "boolean":
        word = _lower(trimmed)
        if word in ("", "1", "true", "on", "yes"):
            return True
        if word in ("0", "false", "off", "no"):
            return False
        raise invalid("true or false (also 1/0, on/off)")
    if kind == "color":
        digits = trimmed.removeprefix("#")
        if len(digits) == 6 and all(c in "0123456789abcdefABCDEF" for c in digits):
            return f"#{_lower(digits)}"
        raise invalid("a colour written #rrggbb")
    if kind == "choice":
        if _lower(trimmed) in row["words"]:
            return _lower(trimmed)
        raise invalid("one of " + ", ".join(row["words"]))
    if kind == "list":
        words = _lower(trimmed)
        if words in ("all", "none"):
            return words
        older = row.get("wordAliases", {})
        items = [older.get(item, item) for item in (part.strip(_SPACE) for part in words.split(",")) if item]
        if not items or any(item not in row["words"] for item in items):
            raise invalid("all, none, or a comma list of " + ", ".join(row["words"]))
        return ",".join(items)
    if kind == "levels":
        items = (part.strip(_SPACE) for part in trimmed.split(","))
        return ",".join(_f64_text(_number(row, noun, item, item)) for item in items if item)
    return text


def check(row: dict, value):
    """Reads a value set from Python as parameter ``row`` does in the figure: returns it as the figure
    holds it, or raises ``Refused`` with the figure's message. Slices and sphere lists given as text are
    checked by the figure itself."""
    kind, text = row["kind"], attribute_text(value)
    if kind == "boolean" and isinstance(value, bool):
        return value
    if kind == "spheres" and isinstance(value, (list, tuple)):
        # The sphere list as the figure reports it: dicts of center, radius, velocity and charge.
        if all(isinstance(s, dict) and "center" in s and "radius" in s for s in value):
            return list(value)
        raise Refused(f"{row['noun'] or row['name']} must be spheres as dicts with center and radius, got {text}")
    if kind in ("text", "slice", "cell", "spheres"):
        if not isinstance(value, str):
            raise Refused(f"{row['noun'] or row['name']} must be text, got {text}")
        return value
    return read(row, text)
