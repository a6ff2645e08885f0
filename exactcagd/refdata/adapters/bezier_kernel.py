"""Adapter of the ``bezier`` package for ``exactcagd conformance``.

``bezier`` handles polynomial Bézier curves only (no rational curves, no B-splines, and
only triangular surfaces), so rational records are :class:`Unsupported`.  Calls used:

* ``curve_eval``: ``Curve.evaluate_multi`` and ``bezier.hazmat.curve_helpers.evaluate_hodograph``
  (point and first derivative; the package has no second derivative);
* ``degree_elevation``: ``Curve.elevate`` (once per degree);
* ``subdivision``: ``Curve.specialize(0, t)`` and ``specialize(t, 1)``;
* ``inversion``: ``Curve.locate(point)``;
* ``intersect``: the ``all_intersections`` that ``Curve.intersect`` runs with its default
  geometric strategy (compiled when built), keeping its flag for coincident curves,
  which ``Curve.intersect`` drops;
* ``roots``: ``Curve.intersect`` of the graph ``(t, f(t))`` with the segment ``[0, 1] x {0}``
  (the package has no public root finder; this is how a user of it finds roots).
"""

from __future__ import annotations

import numpy as np

from ..exporters import require_peer
from .base import Adapter, Unsupported

__all__ = ["BezierAdapter"]


class BezierAdapter(Adapter):
    """bezier on polynomial curve evaluation, elevation, subdivision, inversion, intersection, roots."""

    name = "bezier"
    kinds = ("curve_eval", "degree_elevation", "subdivision", "inversion", "intersect", "roots")

    def __init__(self):
        self.bezier = require_peer("bezier")
        self.hazmat = require_peer("bezier.hazmat.curve_helpers")
        self.geometric = require_peer("bezier.curve")._geometric_intersection  # compiled when built

    def version(self) -> str:
        return self.bezier.__version__

    def _curve(self, inp):
        if "weights" in inp:
            raise Unsupported("bezier has no rational curves")
        nodes = np.asfortranarray(inp.floats("control_points").T)
        return self.bezier.Curve(nodes, degree=nodes.shape[1] - 1), nodes

    def curve_eval(self, inp):
        curve, nodes = self._curve(inp)
        ts = inp.floats("params")
        values = curve.evaluate_multi(np.asfortranarray(ts)).T
        firsts = [self.hazmat.evaluate_hodograph(float(t), nodes).ravel() for t in ts]
        return {"values": values, "first_derivatives": firsts}

    def degree_elevation(self, inp):
        curve, _ = self._curve(inp)
        for _ in range(int(inp["times"])):
            curve = curve.elevate()
        return {"control_points": curve.nodes.T}

    def subdivision(self, inp):
        curve, _ = self._curve(inp)
        t = float(inp.floats("param"))
        return {"left": {"control_points": curve.specialize(0.0, t).nodes.T},
                "right": {"control_points": curve.specialize(t, 1.0).nodes.T}}

    def inversion(self, inp):
        curve, _ = self._curve(inp)
        out = []
        for p in inp.floats("points"):
            s = curve.locate(np.asfortranarray(p.reshape(2, 1)))
            out.append(np.nan if s is None else s)
        return {"params": out}

    def intersect(self, inp):
        _, n1 = self._curve(inp.sub("curve1"))
        _, n2 = self._curve(inp.sub("curve2"))
        # what Curve.intersect runs (geometric strategy), keeping its 'coincident' flag
        params, coincident = self.geometric.all_intersections(n1, n2)
        return {"intersections": params.T.tolist(), "overlap": bool(coincident)}

    def roots(self, inp):
        coeffs = inp.floats("coefficients")
        n = coeffs.size - 1
        graph = np.asfortranarray([np.arange(n + 1) / n if n else [0.0], coeffs])
        if n == 0:
            return {"roots": []}
        axis = self.bezier.Curve(np.asfortranarray([[0.0, 1.0], [0.0, 0.0]]), degree=1)
        params = self.bezier.Curve(graph, degree=n).intersect(axis)
        return {"roots": sorted(params[0].tolist())}
