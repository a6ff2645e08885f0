"""Input checks shared by the geometry classes (one place for every message)."""

from __future__ import annotations

import numpy as np

from .. import limits
from ..errors import DomainError, InputError, WeightError
from ..exact.scalars import to_rational, to_rational_array


def point_array(points, ndim: int, what: str, bezier: bool = False) -> np.ndarray:
    """Exact object array of points with ``ndim`` index axes plus one coordinate axis.

    The number of control points is bounded by the limit ``max_control_points`` and, for
    a Bézier object (``bezier=True``), the degree along each index axis by ``max_degree``
    (:mod:`exactcagd.limits`), from the lengths of the nested input before any number is
    converted.
    """
    _check_counts(points, ndim, what, bezier)
    array = to_rational_array(points, where=what)
    if array.ndim != ndim + 1:
        raise InputError(
            f"{what}: expected {ndim} index axis/axes plus a coordinate axis "
            f"(shape like {'(n+1, d)' if ndim == 1 else '(l+1, m+1, d)'}), got shape {array.shape}"
        )
    if 0 in array.shape:
        raise InputError(f"{what}: empty (shape {array.shape})")
    return array


def _check_counts(points, ndim: int, what: str, bezier: bool) -> None:
    lengths = []
    level = points
    for _ in range(ndim):
        try:
            lengths.append(len(level))
            level = level[0] if lengths[-1] else ()
        except (TypeError, IndexError, KeyError):
            return  # not nested as expected: to_rational_array / the shape check report it
    check_size(lengths, what, bezier)


def check_size(lengths, what: str, bezier: bool = True) -> None:
    """Limits of a control array with index-axis ``lengths`` (``(n + 1,)`` or ``(l + 1, m + 1)``).

    >>> check_size((4, 4), "control_net")
    """
    total = 1
    for length in lengths:
        total *= length
        if bezier:
            limits.check("max_degree", length - 1, f"{what}: degree {length - 1} (from {length} control points)")
    limits.check("max_control_points", total, f"{what}: {total} control points")


def instance_of(value, cls, what: str):
    """``value`` if it is a ``cls`` (e.g. a :class:`BezierCurve`), else :class:`InputError` naming ``what``.

    >>> instance_of(3, int, "n")
    3
    """
    if not isinstance(value, cls):
        raise InputError(f"{what}: expected a {cls.__name__}, got {type(value).__name__}")
    return value


def weight_array(weights, shape: tuple, what: str) -> np.ndarray | None:
    """Exact positive weights of the given shape, or ``None`` for a polynomial object."""
    if weights is None:
        return None
    array = to_rational_array(weights, where=what)
    if array.shape != shape:
        raise WeightError(f"{what}: expected shape {shape} (one weight per control point), got {array.shape}")
    bad = [tuple(int(i) for i in idx) for idx in np.ndindex(*shape) if not array[idx] > 0]
    if bad:
        raise WeightError(
            f"{what}: weights must be positive; non-positive at index {bad[0]}"
            + (f" and {len(bad) - 1} more" if len(bad) > 1 else "")
        )
    return array


def unit_parameter(t, what: str = "t", allow_outside: bool = False):
    """Exact parameter, checked to lie in [0, 1] unless ``allow_outside``."""
    value = to_rational(t, where=what)
    if not allow_outside and not (0 <= value <= 1):
        raise DomainError(f"{what} = {value} lies outside the domain [0, 1]")
    return value


def homogeneous(points: np.ndarray, weights: np.ndarray | None) -> np.ndarray:
    """Homogeneous points ``(w P, w)`` stacked on the last axis."""
    if weights is None:
        ones = np.full(points.shape[:-1] + (1,), 1, dtype=object)
        return np.concatenate([points, ones * to_rational(1)], axis=-1)
    return np.concatenate([points * weights[..., None], weights[..., None]], axis=-1)


def dehomogenize(hom: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Split homogeneous points into (points, weights); weights must be non-zero."""
    w = hom[..., -1]
    if any(x == 0 for x in w.reshape(-1)):
        raise WeightError("a homogeneous control point has weight zero (point at infinity)")
    return hom[..., :-1] / w[..., None], w.copy()


def exchange_fields(data, required: tuple, optional: tuple, what: str) -> dict:
    """Check the exact exchange form read by a ``from_dict``: a mapping with exactly these keys.

    Every key in ``required`` must be present; keys outside ``required + optional`` are
    refused (a misspelt ``"wieghts"`` would otherwise silently give a polynomial object).
    """
    if not isinstance(data, dict):
        raise InputError(f"{what}.from_dict: expected a dict (the output of to_dict), got {type(data).__name__}")
    missing = [k for k in required if k not in data]
    if missing:
        raise InputError(f"{what}.from_dict: missing key {missing[0]!r} (required: {', '.join(required)})")
    unknown = sorted(set(data) - set(required) - set(optional))
    if unknown:
        raise InputError(f"{what}.from_dict: unknown key {unknown[0]!r} (allowed: {', '.join(required + optional)})")
    return data


def check_stored_degree(data: dict, actual, what: str) -> None:
    """The ``"degree"`` entry of an exchange dict, if present, must match the data it came with."""
    if "degree" not in data:
        return
    stated = data["degree"]
    stated = list(stated) if isinstance(stated, (list, tuple)) else stated
    expected = list(actual) if isinstance(actual, tuple) else actual
    if stated != expected:
        from ..errors import DegreeError

        raise DegreeError(f"{what}.from_dict: 'degree' is {data['degree']!r} but the control points give {actual!r}")
