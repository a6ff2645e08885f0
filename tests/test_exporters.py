"""Exporters to geomdl, bezier and OpenCASCADE: the peer, evaluating the exported object,
agrees with exactcagd's exact evaluation within a few ulps, and files read back.

Reference: the exact rational value of the *original* object (de Casteljau / de Boor in
mpq), rounded once; the peer's float evaluation is compared with it in units of the last
place of the largest coordinate (the data reach the peer rounded once, so a handful of
ulps of rounding of the data and of the peer's arithmetic is all a correct export shows).
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from gmpy2 import mpq

from exactcagd import BezierCurve, BezierSurface, BSplineCurve, BSplineSurface
from exactcagd.errors import InputError, NotSupportedError, OutputError
from exactcagd.refdata import exporters

geomdl = pytest.importorskip("geomdl")
bezier = pytest.importorskip("bezier")

PARAMS = ["0", "1/7", "1/3", "1/2", "5/8", "1"]

CUBIC = BezierCurve([[0, 0], ["1/3", 2], ["5/3", "-1/2"], [2, 1]])
RATIONAL = BezierCurve([[1, 0, 0], [1, 1, "1/2"], [0, 1, 1]], weights=[1, "1/3", 2])
SPLINE = BSplineCurve([[0, 0, 0], [1, 2, 0], [2, -1, 1], [3, 1, 0], [4, 0, 2]], [0, 0, 0, "1/3", "3/4", 1, 1, 1])
NURBS = BSplineCurve([[0, 0], [1, 2], [2, -1], [3, 1]], [0, 0, 0, "2/5", 1, 1, 1], weights=[1, 3, "1/2", 2])
PATCH = BezierSurface([[[i, j, (i * j + i) % 3 - 1] for j in range(3)] for i in range(4)],
                      weights=[[1, 2, 1], ["1/2", 1, 3], [1, 1, 1], [2, 1, "3/2"]])
SURFACE = BSplineSurface([[[i, j, (i + 2 * j) % 3] for j in range(4)] for i in range(3)],
                         [0, 0, "1/2", 1, 1], [0, 0, 0, "1/3", 1, 1, 1])


def ulps(value: float, exact_point) -> float:
    """Largest |value_k - exact_k| in ulps of the largest exact coordinate (mpq arithmetic)."""
    scale = max(abs(float(e)) for e in exact_point) or 1.0
    return max(float(abs(mpq(float(v)) - mpq(e))) for v, e in zip(value, exact_point)) / math.ulp(scale)


def exact_curve(obj, t):
    return obj.evaluate(t)


def _domain_t(obj, t):
    if isinstance(obj, BSplineCurve):
        lo, hi = obj.domain
        return lo + (hi - lo) * mpq(t)
    return mpq(t)


@pytest.mark.parametrize("curve", [CUBIC, RATIONAL, SPLINE, NURBS], ids=["cubic", "rational", "spline", "nurbs"])
def test_geomdl_curve_evaluates_like_exact(curve):
    geo = exporters.to_geomdl(curve)
    for t in PARAMS:
        t = _domain_t(curve, t)
        assert ulps(geo.evaluate_single(float(t)), curve.evaluate(t)) <= 8


@pytest.mark.parametrize("surface", [PATCH, SURFACE], ids=["rational-patch", "spline-surface"])
def test_geomdl_surface_evaluates_like_exact(surface):
    geo = exporters.to_geomdl(surface)
    for u, v in [("0", "0"), ("1/3", "2/3"), ("1/2", "1/7"), ("1", "1")]:
        assert ulps(geo.evaluate_single([float(mpq(u)), float(mpq(v))]), surface.evaluate(u, v)) <= 8


def test_geomdl_json_reads_back(tmp_path):
    path = tmp_path / "curves.json"
    exporters.write_geomdl_json(path, CUBIC, NURBS)
    from geomdl import exchange

    curves = exchange.import_json(str(path))
    assert len(curves) == 2
    for geo, curve in zip(curves, (CUBIC, NURBS)):
        for t in PARAMS:
            t = _domain_t(curve, t)
            assert ulps(geo.evaluate_single(float(t)), curve.evaluate(t)) <= 8
    assert json.loads(exporters.to_geomdl_json(SURFACE))["shape"]["type"] == "surface"
    with pytest.raises(InputError, match="mix of curves and surfaces"):
        exporters.to_geomdl_json(CUBIC, PATCH)


def test_bezier_nodes_layout_and_values():
    nodes = exporters.to_bezier_nodes(CUBIC)
    assert nodes.shape == (2, 4) and nodes.flags.f_contiguous
    assert nodes[:, 1].tolist() == [1 / 3, 2.0]  # one column per control point, correctly rounded
    curve = exporters.to_bezier(CUBIC)
    for t in PARAMS:
        assert ulps(curve.evaluate(float(mpq(t))).ravel(), CUBIC.evaluate(t)) <= 8


def test_bezier_rational_needs_homogeneous():
    with pytest.raises(NotSupportedError, match="homogeneous=True"):
        exporters.to_bezier_nodes(RATIONAL)
    hom = exporters.to_bezier(RATIONAL, homogeneous=True)
    for t in PARAMS:
        h = hom.evaluate(float(mpq(t))).ravel()
        assert ulps(h[:-1] / h[-1], RATIONAL.evaluate(t)) <= 8
    with pytest.raises(InputError, match="Bézier curves only"):
        exporters.to_bezier_nodes(SPLINE)


def test_missing_peer_names_the_extra(monkeypatch):
    import importlib

    real = importlib.import_module

    def fake(name, *args):
        if name.startswith("geomdl"):
            raise ImportError("No module named 'geomdl'")
        return real(name, *args)

    monkeypatch.setattr(importlib, "import_module", fake)
    with pytest.raises(NotSupportedError, match=r"'geomdl' is not installed.*exactcagd\[peers\]"):
        exporters.to_geomdl(CUBIC)


def test_bad_object():
    with pytest.raises(InputError, match="obj: expected a BezierCurve"):
        exporters.to_geomdl([[0, 0], [1, 1]])


# ----------------------------------------------------------------------------- OpenCASCADE
@pytest.fixture(scope="module")
def ocp():
    return pytest.importorskip("OCP")


@pytest.mark.parametrize("curve", [RATIONAL, SPLINE, NURBS], ids=["rational", "spline", "nurbs-2d"])
def test_occ_curve_evaluates_like_exact(ocp, curve):
    occ = exporters.to_occ(curve)
    for t in PARAMS:
        t = _domain_t(curve, t)
        p = occ.Value(float(t))
        value = (p.X(), p.Y()) if curve.dimension == 2 else (p.X(), p.Y(), p.Z())
        assert ulps(value, curve.evaluate(t)) <= 8


@pytest.mark.parametrize("surface", [PATCH, SURFACE], ids=["rational-patch", "spline-surface"])
def test_occ_surface_evaluates_like_exact(ocp, surface):
    occ = exporters.to_occ(surface)
    for u, v in [("0", "0"), ("1/3", "2/3"), ("1/2", "1/7"), ("1", "1")]:
        p = occ.Value(float(mpq(u)), float(mpq(v)))
        assert ulps((p.X(), p.Y(), p.Z()), surface.evaluate(u, v)) <= 8


def test_step_file_reads_back(ocp, tmp_path):
    from OCP.OCP.BRep import BRep_Tool
    from OCP.OCP.STEPControl import STEPControl_Reader
    from OCP.OCP.TopAbs import TopAbs_ShapeEnum
    from OCP.OCP.TopExp import TopExp_Explorer
    from OCP.OCP.TopoDS import TopoDS

    path = tmp_path / "objects.step"
    exporters.write_step(path, SPLINE, NURBS, PATCH)
    assert path.read_text(errors="replace").startswith("ISO-10303-21")
    reader = STEPControl_Reader()
    reader.ReadFile(str(path))
    reader.TransferRoots()
    shape = reader.OneShape()
    faces = TopExp_Explorer(shape, TopAbs_ShapeEnum.TopAbs_FACE)
    n_faces = 0
    while faces.More():
        n_faces += 1
        faces.Next()
    assert n_faces == 1
    # the first free edge is SPLINE.  OCC's STEP writer prints reals with 12 significant
    # digits (the knot 1/3 is written 0.333333333333), so the curve read back is only
    # within ~1e-12 relative of the exact one, not within ulps: a limit of the writer.
    assert "0.333333333333," in path.read_text()
    edges = TopExp_Explorer(shape, TopAbs_ShapeEnum.TopAbs_EDGE, TopAbs_ShapeEnum.TopAbs_FACE)
    curve = BRep_Tool.Curve_s(TopoDS.Edge(edges.Current()), 0.0, 1.0)
    p = curve.Value(float(mpq(1, 3)))
    exact = SPLINE.evaluate("1/3")
    relative = max(abs(mpq(v) - e) for v, e in zip((p.X(), p.Y(), p.Z()), exact)) / max(abs(e) for e in exact)
    assert 1e-15 < relative <= 1e-11
    with pytest.raises(OutputError):
        exporters.write_step(tmp_path, SPLINE)
