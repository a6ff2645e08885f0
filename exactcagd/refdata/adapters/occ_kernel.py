"""Adapter of OpenCASCADE (``cadquery-ocp``) for ``exactcagd conformance``.

Objects reach OCC through :func:`exactcagd.refdata.exporters.to_occ` (each exact number
rounded once; Bézier data as one-span ``Geom(2d)_BSplineCurve`` / ``Geom_BSplineSurface``).
OCC's own calls:

* ``curve_eval``: ``D2`` (point, first, second derivative); ``surface_eval``: ``D1`` and
  ``D1U ^ D1V``; ``bspline_eval``: ``Value``;
* ``knot_insertion``: ``InsertKnot(u, times, 0.0)``; ``degree_elevation``:
  ``IncreaseDegree``; ``subdivision``: ``Segment`` on two copies;
  ``bezier_extraction``: ``GeomConvert_BSplineCurveToBezierCurve`` (2-D:
  ``Geom2dConvert_...``);
* ``inversion``: ``Geom2dAPI_ProjectPointOnCurve`` (parameter of the nearest point);
* ``intersect``: ``Geom2dAPI_InterCurveCurve``'s intersector ``Geom2dInt_GInter`` (its default
  tolerance 1e-6; overlaps are its segments);
* ``roots``: ``Geom2dAPI_InterCurveCurve`` of the graph ``(t, f(t))`` with the segment
  ``[0, 1] x {0}``;
* ``compose``: ``Approx_CurveOnSurface`` (tolerance 1e-6, degree <= 14, <= 30 segments,
  C1), sampled at 200 parameters, with its own ``MaxError3d`` as the claimed error.

OCC's B-splines have degree at most 25 (``Geom_BSplineCurve::MaxDegree``): records of
higher degree are :class:`Unsupported`.
"""

from __future__ import annotations

import numpy as np

from ..exporters import require_peer, to_occ
from .base import Adapter, Unsupported, bezier_curve, bezier_surface, bspline_curve, bspline_surface

__all__ = ["OCCAdapter"]

INTERSECT_TOLERANCE = 1e-6  # Geom2dAPI_InterCurveCurve's default
APPROX_TOLERANCE = 1e-6
COMPOSE_SAMPLES = 200


def _xyz(p) -> list:
    return [p.X(), p.Y()] if not hasattr(p, "Z") else [p.X(), p.Y(), p.Z()]


def _knot_vector(curve) -> list:
    return [curve.Knot(i) for i in range(1, curve.NbKnots() + 1) for _ in range(curve.Multiplicity(i))]


def _poles(curve, rational: bool) -> dict:
    out = {"control_points": [_xyz(curve.Pole(i)) for i in range(1, curve.NbPoles() + 1)]}
    if rational:
        out["weights"] = [curve.Weight(i) for i in range(1, curve.NbPoles() + 1)]
    return out


class OCCAdapter(Adapter):
    """OpenCASCADE on evaluation, knot insertion, extraction, elevation, subdivision, inversion,
    intersection, roots and curve-on-surface approximation."""

    name = "occ"
    kinds = ("curve_eval", "surface_eval", "bspline_eval", "knot_insertion", "bezier_extraction", "degree_elevation",
             "subdivision", "inversion", "intersect", "roots", "compose")

    def __init__(self):
        require_peer("OCP")
        from OCP.OCP.Geom import Geom_BSplineCurve

        self.max_degree = Geom_BSplineCurve.MaxDegree_s()

    def version(self) -> str:
        from importlib import metadata

        try:
            return f"cadquery-ocp {metadata.version('cadquery-ocp')}"
        except metadata.PackageNotFoundError:  # pragma: no cover
            return "unknown"

    def _check_degree(self, degree) -> None:
        if max(np.atleast_1d(degree)) > self.max_degree:
            raise Unsupported(f"degree above OCC's maximum {self.max_degree}")

    def _occ(self, obj):
        self._check_degree(obj.degree)
        return to_occ(obj)

    # --------------------------------------------------------------- evaluation
    def curve_eval(self, inp):
        curve = bezier_curve(inp)
        occ = self._occ(curve)
        if curve.dimension == 2:
            from OCP.OCP.gp import gp_Pnt2d as P, gp_Vec2d as V
        else:
            from OCP.OCP.gp import gp_Pnt as P, gp_Vec as V
        out = {"values": [], "first_derivatives": [], "second_derivatives": []}
        for t in inp.floats("params"):
            p, v1, v2 = P(), V(), V()
            occ.D2(float(t), p, v1, v2)
            out["values"].append(_xyz(p))
            out["first_derivatives"].append(_xyz(v1))
            out["second_derivatives"].append(_xyz(v2))
        return out

    def surface_eval(self, inp):
        from OCP.OCP.gp import gp_Pnt, gp_Vec

        occ = self._occ(bezier_surface(inp))
        out = {"values": [], "normals": []}
        for u, v in inp.floats("params"):
            p, du, dv = gp_Pnt(), gp_Vec(), gp_Vec()
            occ.D1(float(u), float(v), p, du, dv)
            out["values"].append(_xyz(p))
            out["normals"].append(_xyz(du.Crossed(dv)))
        return out

    def bspline_eval(self, inp):
        if inp["object"] == "curve":
            occ = self._occ(bspline_curve(inp))
            return {"values": [_xyz(occ.Value(float(t))) for t in inp.floats("params")]}
        occ = self._occ(bspline_surface(inp))
        return {"values": [_xyz(occ.Value(float(u), float(v))) for u, v in inp.floats("params")]}

    # --------------------------------------------------------------- knot and degree algorithms
    def knot_insertion(self, inp):
        curve = bspline_curve(inp)
        occ = self._occ(curve)
        occ.InsertKnot(float(inp.floats("knot")), int(inp["times"]), 0.0)
        return {"knots": _knot_vector(occ), **_poles(occ, curve.is_rational)}

    def bezier_extraction(self, inp):
        curve = bspline_curve(inp)
        occ = self._occ(curve)
        if curve.dimension == 2:
            from OCP.OCP.Geom2dConvert import Geom2dConvert_BSplineCurveToBezierCurve as Convert
        else:
            from OCP.OCP.GeomConvert import GeomConvert_BSplineCurveToBezierCurve as Convert
        from OCP.OCP import collections as C

        conv = Convert(occ)
        knots = C.Array1_double(1, conv.NbArcs() + 1)
        conv.Knots(knots)
        segments = []
        for i in range(1, conv.NbArcs() + 1):
            arc = conv.Arc(i)
            seg = {"interval": [knots.Value(i), knots.Value(i + 1)], **_poles(arc, curve.is_rational)}
            segments.append(seg)
        return {"segments": segments}

    def degree_elevation(self, inp):
        curve = bezier_curve(inp)
        self._check_degree(curve.degree + int(inp["times"]))
        occ = to_occ(curve)
        occ.IncreaseDegree(curve.degree + int(inp["times"]))
        return _poles(occ, curve.is_rational)

    def subdivision(self, inp):
        curve = bezier_curve(inp)
        t = float(inp.floats("param"))
        left, right = self._occ(curve), to_occ(curve)
        left.Segment(0.0, t)
        right.Segment(t, 1.0)
        return {"left": _poles(left, curve.is_rational), "right": _poles(right, curve.is_rational)}

    # --------------------------------------------------------------- algebraic problems
    def inversion(self, inp):
        from OCP.OCP.Geom2dAPI import Geom2dAPI_ProjectPointOnCurve
        from OCP.OCP.gp import gp_Pnt2d

        occ = self._occ(bezier_curve(inp))
        params = []
        for x, y in inp.floats("points"):
            proj = Geom2dAPI_ProjectPointOnCurve(gp_Pnt2d(float(x), float(y)), occ)
            params.append(proj.LowerDistanceParameter() if proj.NbPoints() else np.nan)
        return {"params": params}

    def _intersections(self, c1, c2) -> tuple:
        # what Geom2dAPI_InterCurveCurve(c1, c2, tol) runs; its Intersector() accessor
        # returns an unfinished copy in OCP 8, so the parameters are read from our own
        from OCP.OCP.Geom2dAdaptor import Geom2dAdaptor_Curve
        from OCP.OCP.Geom2dInt import Geom2dInt_GInter

        core = Geom2dInt_GInter(Geom2dAdaptor_Curve(c1), Geom2dAdaptor_Curve(c2), INTERSECT_TOLERANCE, INTERSECT_TOLERANCE)
        if not core.IsDone():
            raise RuntimeError("Geom2dInt_GInter is not done")
        hits = [[core.Point(i).ParamOnFirst(), core.Point(i).ParamOnSecond()] for i in range(1, core.NbPoints() + 1)]
        return hits, core.NbSegments() > 0

    def intersect(self, inp):
        c1 = self._occ(bezier_curve(inp.sub("curve1")))
        c2 = self._occ(bezier_curve(inp.sub("curve2")))
        hits, overlap = self._intersections(c1, c2)
        return {"intersections": hits, "overlap": overlap}

    def roots(self, inp):
        from ...geometry.bezier_curve import BezierCurve

        coeffs = inp.exact("coefficients")
        n = len(coeffs) - 1
        if n == 0:
            return {"roots": []}
        graph = self._occ(BezierCurve([[f"{i}/{n}", c] for i, c in enumerate(coeffs)]))
        axis = to_occ(BezierCurve([[0, 0], [1, 0]]))
        hits, overlap = self._intersections(graph, axis)
        return {"roots": [h[0] for h in hits], "overlap": overlap}

    def compose(self, inp):
        from OCP.OCP.Approx import Approx_CurveOnSurface
        from OCP.OCP.Geom2dAdaptor import Geom2dAdaptor_Curve
        from OCP.OCP.GeomAbs import GeomAbs_Shape
        from OCP.OCP.GeomAdaptor import GeomAdaptor_Surface

        s = inp["surface"]
        surface = bezier_surface(s) if s["type"] == "bezier" else bspline_surface(s)
        domain = bezier_curve(inp["curve"])
        occ_s, occ_d = self._occ(surface), self._occ(domain)
        approx = Approx_CurveOnSurface(Geom2dAdaptor_Curve(occ_d), GeomAdaptor_Surface(occ_s), 0.0, 1.0, APPROX_TOLERANCE)
        approx.Perform(30, 14, GeomAbs_Shape.GeomAbs_C1, True, False)
        if not approx.IsDone() or not approx.HasResult():
            raise RuntimeError("Approx_CurveOnSurface found no approximation")
        curve = approx.Curve3d()
        ts = np.linspace(0.0, 1.0, COMPOSE_SAMPLES)
        return {"params": ts.tolist(), "points": [_xyz(curve.Value(float(t))) for t in ts], "claimed_error": approx.MaxError3d()}
