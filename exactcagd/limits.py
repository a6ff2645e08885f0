"""Resource limits: one documented table, checked from an estimate before the work starts.

Exact arithmetic has no natural size bound: elevating a curve to degree 10**6, composing
a 40 x 40 surface with a degree-40 curve (an image of degree 3200) or implicitizing a
degree-40 curve would run for hours or exhaust memory.  Every public entry point
estimates the size of what it is asked to build (output degree, number of control
points, size of the numbers) and calls :func:`check` before it starts; a request over a
limit raises :class:`~exactcagd.errors.LimitError` naming the argument, the estimate,
the limit and how to raise it.

==========================  =========  ==============================================
limit                       default    what it bounds (and where it is checked)
==========================  =========  ==============================================
``max_degree``              1000       degree of a Bézier curve/surface given (per
                                       parameter) or built: elevation, Bernstein
                                       products, composition ``N (l + m)``; B-spline
                                       degree; exponents of algebra inputs; degrees and
                                       orders asked of the toolbox.  A degree-1000
                                       composition takes ~1-3 s; the 40 x 40 surface
                                       composed with a degree-40 curve (3200) took 27 s
``max_control_points``      100000     control points of one curve or surface (Bézier
                                       or B-spline), values generated on request
                                       (forward differencing), entries of dense exact
                                       matrices (Gram matrices, integral tables)
``max_implicit_degree``     24         degree of a curve entering the implicit algebra
                                       (implicitization, inversion, moving lines, ...),
                                       total degree in bivariate solving, degree of
                                       Sylvester/Bezout resultants.  Implicitizing a
                                       random degree-24 curve: 1.9 s; 30: 14 s; 40: > 60 s
``max_surface_implicit``    12         implicit degree ``2 l m`` of a tensor patch
``max_input_bits``          1000000    bits of the numerator or denominator of one
                                       input number (ints, Fractions, number strings --
                                       bounded before they are built: ``"1e100000000"``
                                       -- and ``snap_bits``); ``gmpy2.mpq`` values, the
                                       package's own exact type, are taken as they are
==========================  =========  ==============================================

Counts (degrees, amounts, numbers of points) of ``2^62`` or more are refused by
:func:`exactcagd.exact.scalars.to_count` whatever the limits.

A limit is raised for a block with :func:`raised` or for the process with
:func:`set_limits`; ``None`` removes a limit.

>>> from exactcagd import limits
>>> limits.get("max_degree")
1000
>>> with limits.raised(max_degree=5000):
...     limits.get("max_degree")
5000
>>> limits.check("max_degree", 1200, "elevate(r=1197)")
Traceback (most recent call last):
...
exactcagd.errors.LimitError: elevate(r=1197): estimated 1200 exceeds the limit max_degree = 1000; raise it deliberately with exactcagd.limits.raised(max_degree=...) or exactcagd.limits.set_limits(max_degree=...)

This module sits at the bottom of the layers (it imports only :mod:`exactcagd.errors`).
"""

from __future__ import annotations

import contextlib
import threading

from .errors import InputError, LimitError

__all__ = ["DEFAULTS", "check", "current", "get", "raised", "set_limits"]

#: The documented defaults (see the table above).
DEFAULTS: dict[str, int | None] = {
    "max_degree": 1000,
    "max_control_points": 100_000,
    "max_implicit_degree": 24,
    "max_surface_implicit": 12,
    "max_input_bits": 1_000_000,
}

_process: dict[str, int | None] = dict(DEFAULTS)
_local = threading.local()


def _table() -> dict:
    return getattr(_local, "table", None) or _process


def current() -> dict[str, int | None]:
    """A copy of the limits in force in this thread."""
    return dict(_table())


def get(name: str) -> int | None:
    """The limit ``name`` in force (``None``: unlimited)."""
    table = _table()
    if name not in table:
        raise InputError(f"unknown limit {name!r}; known limits: {sorted(DEFAULTS)}")
    return table[name]


def _checked(values: dict) -> dict:
    for name, value in values.items():
        if name not in DEFAULTS:
            raise InputError(f"unknown limit {name!r}; known limits: {sorted(DEFAULTS)}")
        if value is not None and (isinstance(value, bool) or not isinstance(value, int) or value < 0):
            raise InputError(f"limit {name} must be a non-negative int or None, got {value!r}")
    return values


def set_limits(**values: int | None) -> None:
    """Set limits for the whole process, e.g. ``set_limits(max_degree=4000)``."""
    _process.update(_checked(values))


@contextlib.contextmanager
def raised(**values: int | None):
    """Context manager: the given limits (``None`` = unlimited) hold inside the block, in this thread."""
    _checked(values)
    previous = getattr(_local, "table", None)
    _local.table = {**(previous or _process), **values}
    try:
        yield
    finally:
        _local.table = previous


def check(name: str, estimate, what: str) -> None:
    """Raise :class:`LimitError` when ``estimate`` exceeds the limit ``name``.

    Parameters
    ----------
    name : str
        A key of :data:`DEFAULTS`.
    estimate : int
        The estimated size of the request, computed before any work.
    what : str
        The argument or call the estimate comes from (``"elevate(r=...)"``), used in the message.
    """
    limit = get(name)
    if limit is not None and estimate > limit:
        raise LimitError(
            f"{what}: estimated {_short(estimate)} exceeds the limit {name} = {limit}; raise it deliberately "
            f"with exactcagd.limits.raised({name}=...) or exactcagd.limits.set_limits({name}=...)"
        )


def _short(n) -> str:
    n = int(n)
    return str(n) if n.bit_length() < 64 else f"about 2^{n.bit_length() - 1}"
