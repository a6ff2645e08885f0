"""Numeric layer: float evaluators with certified error bounds, interval arithmetic,
Bernstein root finding and curve intersection.  Sits on top of the exact layer;
every float result can come with an enclosure of the exact value.

Public entry points (stable):

* :func:`evaluate`, :func:`evaluate_surface` — in ``numeric/evaluation.py``;
* :func:`intersect` (curve/curve intersection, notes ch. 7) and :class:`Intersection`
  — in ``numeric/intersection/`` (one module per route, one result type);
* :func:`bernstein_roots`, :func:`line_roots` (notes ch. 9) — in ``numeric/roots.py``.

No module is named like a function it exports, so the package attributes
``evaluate`` and ``intersect`` are always the functions.
"""

from .evaluation import evaluate, evaluate_surface
from .intersection import Intersection, intersect
from .roots import Root, bernstein_roots, line_roots

__all__ = ["evaluate", "evaluate_surface", "intersect", "Intersection", "bernstein_roots", "line_roots", "Root"]
