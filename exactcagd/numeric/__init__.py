"""Numeric layer: float evaluators with certified error bounds, interval arithmetic,
Bernstein root finding and curve intersection.  Sits on top of the exact layer;
every float result can come with an enclosure of the exact value.

Public entry points (stable): :func:`evaluate`, :func:`evaluate_surface`
(``numeric/evaluation.py``) and :func:`intersect` (``numeric/intersect.py``).

Modules are not named like the functions they hold, so the package attributes
``evaluate`` and ``intersect`` are always the functions.
"""

from .evaluation import evaluate, evaluate_surface

__all__ = ["evaluate", "evaluate_surface", "intersect"]


def __getattr__(name):
    if name == "intersect":
        from .intersect import intersect

        globals()["intersect"] = intersect
        return intersect
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
