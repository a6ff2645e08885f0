"""Numeric layer: float evaluators with certified error bounds, interval arithmetic,
Bernstein root finding and curve intersection.  Sits on top of the exact layer;
every float result can come with an enclosure of the exact value.

Public entry points (stable): :func:`evaluate` (``numeric/evaluate.py``) and
:func:`intersect` (``numeric/intersect.py``).
"""

from importlib import import_module

_LAZY = {"evaluate": "evaluate", "intersect": "intersect"}


def __getattr__(name):
    if name in _LAZY:
        return getattr(import_module(f".{_LAZY[name]}", __name__), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


__all__ = ["evaluate", "intersect"]
