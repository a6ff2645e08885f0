"""Checked options of ``exactcagd refdata``: degrees, counts, jobs, families, progress.

Every check runs before any work and raises :class:`exactcagd.errors.InputError`
naming the command-line argument.

>>> parse_degrees("2,1,2", "compose")
(2, 1, 2)
>>> families_for("roots", None)
['random']
"""

from __future__ import annotations

import sys

from ..errors import InputError
from .kinds import kind_named

__all__ = ["MAX_COUNT", "MAX_JOBS", "check_count", "check_jobs", "families_for", "parse_degrees", "progress_enabled"]

MAX_COUNT = 10_000_000
MAX_JOBS = 256


def parse_degrees(text, kind: str) -> tuple:
    """``"3"`` or ``"2,1,2"`` (``None``: the kind's default) -> the kind's degrees, checked.

    A kind takes up to ``len(default_degrees)`` degrees (compose: ``N,l,m``; surface and
    B-spline evaluation: ``l,m``; intersect: ``n1,n2``), each in ``1 .. max_degree``.
    """
    spec = kind_named(kind)
    if text is None:
        return spec.default_degrees
    try:
        degrees = tuple(int(x) for x in str(text).split(","))
    except ValueError:
        raise InputError(f"--degree: expected integers like 3 or 2,1,2, got {text!r}") from None
    arity = len(spec.default_degrees)
    if not 1 <= len(degrees) <= arity:
        raise InputError(f"--degree: {kind} takes 1 to {arity} degree(s), got {text!r}")
    if any(not 1 <= d <= spec.max_degree for d in degrees):
        raise InputError(f"--degree: {kind} degrees must be in 1..{spec.max_degree}, got {text!r}")
    return degrees


def check_count(count, argument: str = "--count") -> int:
    """``--count``: an integer in ``1 .. MAX_COUNT``."""
    if isinstance(count, bool) or not isinstance(count, int) or not 1 <= count <= MAX_COUNT:
        raise InputError(f"{argument}: the number of records must be an integer in 1..{MAX_COUNT}, got {count!r}")
    return count


def check_jobs(jobs) -> int:
    """``--jobs``: an integer in ``1 .. MAX_JOBS``."""
    if isinstance(jobs, bool) or not isinstance(jobs, int) or not 1 <= jobs <= MAX_JOBS:
        raise InputError(f"--jobs: expected an integer in 1..{MAX_JOBS}, got {jobs!r}")
    return jobs


def families_for(kind: str, family) -> list:
    """``--family``: ``None``/``random``, one hard family of the kind, or ``all``."""
    spec = kind_named(kind)
    if family in (None, "random"):
        return ["random"]
    if family == "all":
        return list(spec.families)
    if family not in spec.families:
        raise InputError(f"--family: kind {kind!r} has no family {family!r}; choose one of {', '.join(spec.families)} or all")
    return [family]


def progress_enabled(progress) -> bool:
    """A progress bar when asked (``--progress``) or, by default, when stderr is a terminal."""
    return bool(progress) if progress is not None else sys.stderr.isatty()
