"""How the Python layer reads the numbers and values it is given, before the library checks them
(docs/design.md, "Numbers as typed"): floats and numpy arrays as their binary values, Fractions,
Decimals and numeric strings kept for the library's exact reading, bools refused; and the JSON
text of a scene whose values hold Fractions or Decimals."""

from __future__ import annotations

import json
import math
from dataclasses import dataclass
from decimal import Decimal
from fractions import Fraction
from typing import Any

import numpy as np

from . import _momentlab


@dataclass
class _Table:
    values: Any  # a number or nested lists of numbers (floats, or Fractions and Decimals kept)
    shape: tuple


def _table(value, what) -> _Table:
    """Numbers as _real reads them, or, when they hold a Fraction or a Decimal, kept as given in
    nested lists of the same shape (the scene's reader reads them exactly and checks them)."""
    if not _has_exact(value):
        a = _real(value, what)
        return _Table(a.tolist() if a.ndim else float(a), a.shape)
    if isinstance(value, (Fraction, Decimal)):
        if isinstance(value, Decimal) and not value.is_finite():
            raise ValueError(f"{what}: expected finite numbers")
        return _Table(value, ())
    rows = [_table(v, what) for v in _sequence(value, what)]
    if any(r.shape != rows[0].shape for r in rows):
        raise ValueError(f"{what}: expected numbers: rows of different shapes")
    return _Table([r.values for r in rows], (len(rows),) + rows[0].shape)


def _real(value, what) -> np.ndarray:
    """Real numbers as float64: strings, complex numbers, objects and masked arrays are refused
    (ValueError naming `what`), as are long doubles that would underflow to 0."""
    if np.ma.isMaskedArray(value):
        raise ValueError(f"{what}: a masked array is not read (fill it first)")
    if _holds_bool(value):
        raise ValueError(f"{what}: expected numbers, got a bool")
    try:
        raw = np.asarray(value)
    except ValueError as e:  # ragged nesting
        raise ValueError(f"{what}: expected numbers: {e}") from None
    if raw.dtype.kind == "b":  # numpy reads True as 1
        raise ValueError(f"{what}: expected numbers, got a bool")
    if raw.dtype.kind not in "iuf":
        raise ValueError(f"{what}: expected real numbers, got an array of dtype {raw.dtype}")
    a = np.asarray(raw, dtype=np.float64)
    if a.ndim:
        a = np.ascontiguousarray(a)
    if raw.dtype.kind == "f" and raw.dtype.itemsize > 8 and np.any((a == 0) & (raw != 0)):
        raise ValueError(f"{what}: a number is {_momentlab.TOO_SMALL_FOR_A_DOUBLE}")
    return a


def _holds_bool(value, depth: int = 0) -> bool:
    """True for a bool, or a list or tuple holding one (numpy would read it as 0 or 1)."""
    if isinstance(value, (bool, np.bool_)):
        return True
    if depth > 2 or not isinstance(value, (list, tuple)):
        return False
    return any(_holds_bool(v, depth + 1) for v in value)


def _sequence(value, what) -> list:
    if isinstance(value, (str, bytes, dict)):
        raise ValueError(f"{what}: expected a list")
    try:
        return list(value)
    except TypeError:
        raise ValueError(f"{what}: expected a list") from None


def _has_exact(value, depth: int = 0) -> bool:
    """True when a scene's values hold a Fraction or a Decimal (docs/design.md, "Numbers as
    typed"); deeper than a scene goes (a list holding itself), False: the reader refuses it."""
    if depth > 8:
        return False
    if isinstance(value, (Fraction, Decimal)):
        return True
    if isinstance(value, dict):
        return any(_has_exact(v, depth + 1) for v in value.values())
    if isinstance(value, (list, tuple)):
        return any(_has_exact(v, depth + 1) for v in value)
    return False


def _exact_json(value, where: str) -> str:
    """A scene's values as JSON text whose numbers spell their exact values: a float's full binary
    value, a Decimal as written, a Fraction whose denominator divides a power of ten as its decimal."""
    if isinstance(value, dict):
        return "{" + ",".join(json.dumps(str(k)) + ":" + _exact_json(v, f"{where}.{k}") for k, v in value.items()) + "}"
    if isinstance(value, np.ndarray):
        value = value.tolist()
    if isinstance(value, (list, tuple)):
        return "[" + ",".join(_exact_json(v, f"{where}[{i}]") for i, v in enumerate(value)) + "]"
    if isinstance(value, Fraction):
        d, k = value.denominator, 0
        while d % 2 == 0 or d % 5 == 0:
            d //= 2 if d % 2 == 0 else 5
            k += 1
        if d != 1:
            raise ValueError(f"{where}: {value} is not a decimal: a scene's numbers are decimals (or floats)")
        value = Decimal(f"{value.numerator * 10 ** k // value.denominator}E-{k}")
    if isinstance(value, np.generic):  # a numpy scalar: its Python value
        value = value.item()
    if isinstance(value, float):
        if not math.isfinite(value):
            raise ValueError(f"{where}: expected a finite number")
        value = Decimal(value)  # exactly the double
    if isinstance(value, Decimal):
        if not value.is_finite():
            raise ValueError(f"{where}: expected a finite number")
        return str(value)
    return json.dumps(value)


def _flag(value, what) -> bool:
    # True or False (also numpy's, and the integers 0 and 1); a string such as "false" is refused
    # rather than read as true.
    if isinstance(value, (bool, np.bool_)):
        return bool(value)
    if isinstance(value, (int, np.integer)) and value in (0, 1):
        return bool(value)
    raise ValueError(f"{what}: expected True or False, got {value!r}")


def _exact_wrench(w) -> bool:
    """One wrench given as a list or tuple holding a Fraction, a Decimal or a string."""
    return isinstance(w, (list, tuple)) and len(w) == 3 and any(isinstance(x, (Fraction, Decimal, str)) for x in w)


def _exact_wrenches(w) -> bool:
    """A batch given as a list or tuple of wrenches, one of them holding a Fraction, a Decimal or
    a string."""
    return isinstance(w, (list, tuple)) and any(_exact_wrench(r) for r in w)


def _wrenches(w) -> np.ndarray:
    a = _real(w, "wrench")
    if not (a.shape == (3,) or (a.ndim == 2 and a.shape[1] == 3)):
        raise ValueError(f"wrench: expected shape (3,) or (N, 3), got shape {a.shape}")
    return a  # (the library checks the numbers)


def _forces(forces):
    if forces is None:
        return None
    return [tuple(f) for f in _sequence(forces, "forces")]


def _goal(goal) -> str:
    if not isinstance(goal, str):
        raise ValueError(f"goal: expected a mode string such as 'rr', got {type(goal).__name__}")
    return goal


def _number(x, what) -> float:
    if isinstance(x, (bool, np.bool_)) or not isinstance(x, (int, float, np.integer, np.floating)):
        raise ValueError(f"{what}: expected a number, got {type(x).__name__}")
    return float(x)


def _exact_number(x, what):
    """A number with its exact meaning kept: a Fraction, a Decimal or a numeric string as it
    reads (0.1 is 1/10), anything else as _number."""
    if isinstance(x, (Fraction, Decimal, str)):
        return x
    return _number(x, what)
