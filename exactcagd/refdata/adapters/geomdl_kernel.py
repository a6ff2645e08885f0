"""Adapter of geomdl (NURBS-Python) for ``exactcagd conformance``.

Objects reach geomdl through :func:`exactcagd.refdata.exporters.to_geomdl` (each exact
number rounded once; Bézier data as one-span clamped B-splines).  geomdl's own calls:

* ``curve_eval``: ``Curve.derivatives(t, order=2)`` (point, first, second derivative);
* ``surface_eval``: ``evaluate_single`` and ``operations.normal(normalize=False)``;
* ``bspline_eval``: ``evaluate_single`` (curves and surfaces);
* ``knot_insertion``: ``operations.insert_knot``;
* ``bezier_extraction``: ``operations.decompose_curve`` (control points; geomdl normalises
  each piece's knot vector to [0, 1], so the pieces' intervals are not graded);
* ``degree_elevation``: ``operations.degree_operations``;
* ``subdivision``: ``operations.split_curve``.

geomdl has no root finder, curve intersection or point inversion.
"""

from __future__ import annotations

from ..exporters import require_peer, to_geomdl
from .base import Adapter, Unsupported, bezier_curve, bezier_surface, bspline_curve, bspline_surface

__all__ = ["GeomdlAdapter"]


def _pieces(curve) -> dict:
    out = {"control_points": [list(p) for p in curve.ctrlpts]}
    if curve.rational:
        out["weights"] = list(curve.weights)
    return out


class GeomdlAdapter(Adapter):
    """geomdl on curve/surface evaluation, knot insertion, extraction, elevation, subdivision."""

    name = "geomdl"
    kinds = ("curve_eval", "surface_eval", "bspline_eval", "knot_insertion", "bezier_extraction", "degree_elevation", "subdivision")

    def __init__(self):
        self.geomdl = require_peer("geomdl")
        self.operations = require_peer("geomdl.operations")

    def version(self) -> str:
        return self.geomdl.__version__

    def curve_eval(self, inp):
        geo = to_geomdl(bezier_curve(inp))
        jets = [geo.derivatives(float(t), order=2) for t in inp.floats("params")]
        return {"values": [j[0] for j in jets], "first_derivatives": [j[1] for j in jets], "second_derivatives": [j[2] for j in jets]}

    def surface_eval(self, inp):
        geo = to_geomdl(bezier_surface(inp))
        params = inp.floats("params").tolist()
        values = [geo.evaluate_single(p) for p in params]
        normals = [self.operations.normal(geo, p, normalize=False)[1] for p in params]
        return {"values": values, "normals": normals}

    def bspline_eval(self, inp):
        if inp["object"] == "curve":
            geo = to_geomdl(bspline_curve(inp))
            return {"values": [geo.evaluate_single(float(t)) for t in inp.floats("params")]}
        geo = to_geomdl(bspline_surface(inp))
        return {"values": [geo.evaluate_single(p) for p in inp.floats("params").tolist()]}

    def knot_insertion(self, inp):
        geo = to_geomdl(bspline_curve(inp))
        self.operations.insert_knot(geo, [float(inp.floats("knot"))], [int(inp["times"])])
        return {"knots": list(geo.knotvector), **_pieces(geo)}

    def bezier_extraction(self, inp):
        geo = to_geomdl(bspline_curve(inp))
        segments = []
        for piece in self.operations.decompose_curve(geo):
            # geomdl normalises every piece's knot vector to [0, 1], so it reports no interval
            segments.append(_pieces(piece))
        return {"segments": segments}

    def degree_elevation(self, inp):
        geo = to_geomdl(bezier_curve(inp))
        geo = self.operations.degree_operations(geo, [int(inp["times"])])
        return _pieces(geo)

    def subdivision(self, inp):
        geo = to_geomdl(bezier_curve(inp))
        t = float(inp.floats("param"))
        if not 0 < t < 1:
            raise Unsupported("split parameter rounds to an end of [0, 1]")
        left, right = self.operations.split_curve(geo, t)
        return {"left": _pieces(left), "right": _pieces(right)}
