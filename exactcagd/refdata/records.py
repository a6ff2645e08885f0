"""Exact numbers in reference records: the shared exchange format of ``exactcagd refdata``.

Every exact value is written twice: the exact form (a JSON integer, or a ``"p/q"``
string in lowest terms with a positive denominator) and, in a parallel field whose
name ends in ``_f64``, the float64 nearest to it (round to nearest, ties to even) as a
``float.hex`` string.  Real algebraic numbers are ``{"poly": [c0, c1, ...], "interval":
["p/q", "p/q"], "f64": "<hex>"}``: an irreducible integer polynomial, lowest degree
first, with exactly one root in the closed interval (``lo == hi`` when rational).

The float companion is computed from the exact value, never through a float
expression: Python's ``int / int`` is correctly rounded (round half to even, including
subnormals), and an algebraic number's interval is bisected until both ends round to
the same double, which is then the correctly rounded value (rounding is monotone).

>>> from gmpy2 import mpq
>>> exact(mpq(6, 4)), f64(mpq(6, 4))
('3/2', '0x1.8000000000000p+0')
>>> with_f64({}, "t", [mpq(1, 3), 1])
{'t': ['1/3', 1], 't_f64': ['0x1.5555555555555p-2', '0x1.0000000000000p+0']}
"""

from __future__ import annotations

import math
import numbers

import numpy as np
from gmpy2 import mpq

from ..exact.algebraic import RealAlgebraic
from ..exact.scalars import rational_str, to_float, to_rational

__all__ = ["FORMAT_VERSION", "algebraic", "exact", "f64", "f64_float", "nested_exact", "nested_f64", "parse_exact", "with_f64"]

#: Version of the record format (bumped on any incompatible change of a record kind).
FORMAT_VERSION = "1.0"


def _as_mpq(x) -> mpq:
    if isinstance(x, RealAlgebraic):
        return x.value
    if isinstance(x, numbers.Integral) and not isinstance(x, bool):
        return mpq(int(x))
    return x if type(x) is type(mpq(0)) else to_rational(x)


def exact(x) -> int | str:
    """The exact JSON form of a rational: an ``int``, or ``"p/q"`` in lowest terms."""
    q = _as_mpq(x)
    return int(q.numerator) if q.denominator == 1 else rational_str(q)


def parse_exact(value) -> mpq:
    """Inverse of :func:`exact` (ints and ``"p/q"`` strings)."""
    if isinstance(value, bool) or not isinstance(value, (int, str)):
        raise TypeError(f"not an exact number: {value!r}")
    return mpq(value)


def _round_rational(q: mpq) -> float:
    """Correctly rounded float64 of ``q`` (overflow gives the signed infinity, as IEEE rounding does)."""
    try:
        return to_float(q)
    except OverflowError:
        return math.inf if q > 0 else -math.inf


def f64_float(x) -> float:
    """The float64 nearest to the exact value ``x`` (rational or :class:`RealAlgebraic`).

    For an irrational number the isolating interval is refined until both ends round
    to the same double (``float(RealAlgebraic)`` takes a midpoint of a relative width
    2^-60 interval instead, which can misround a value very close to a rounding tie).
    """
    if isinstance(x, RealAlgebraic) and not x.is_rational:
        lo, hi = x.interval()
        while _round_rational(lo) != _round_rational(hi):
            x.refine((hi - lo) / 4)
            lo, hi = x.interval()
        return _round_rational(lo)
    return _round_rational(_as_mpq(x))


def f64(x) -> str:
    """``float.hex`` of the correctly rounded float64 of ``x``."""
    return float.hex(f64_float(x))


def algebraic(x) -> dict:
    """A real algebraic number (or a rational) as ``{"poly", "interval", "f64"}``."""
    if not isinstance(x, RealAlgebraic):
        x = RealAlgebraic.from_rational(x)
    hex_value = f64(x)  # refines the interval first: the stored interval is the refined one
    return {
        "poly": [int(c) for c in x.poly.coeffs()],
        "interval": [exact(x.lo), exact(x.hi)],
        "f64": hex_value,
    }


def nested_exact(values):
    """:func:`exact` applied through nested lists / arrays."""
    if isinstance(values, (list, tuple, np.ndarray)):
        return [nested_exact(v) for v in values]
    return exact(values)


def nested_f64(values):
    """:func:`f64` applied through nested lists / arrays."""
    if isinstance(values, (list, tuple, np.ndarray)):
        return [nested_f64(v) for v in values]
    return f64(values)


def with_f64(record: dict, name: str, values) -> dict:
    """Set ``record[name]`` (exact) and ``record[name + "_f64"]`` (hex floats); return ``record``."""
    record[name] = nested_exact(values)
    record[name + "_f64"] = nested_f64(values)
    return record
