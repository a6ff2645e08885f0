"""The JSON output reference (docs/json_output.md) against real outputs: an ``image_curve``
product has the same shape on a Bézier and on a B-spline surface -- exact pieces, each exact
number with a float64 companion that is the correctly rounded value (checked with
``fractions.Fraction``, whose float conversion is correctly rounded, and with sympy's real roots
for algebraic interval ends)."""

from __future__ import annotations

import json
from fractions import Fraction

import sympy as sp

from exactcagd.cli import main

CURVE = {"type": "bezier", "control_points": [["1/10", "1/5"], ["2/5", "9/10"], ["3/5", "-1/10"], ["9/10", "4/5"]]}
BEZIER = {"type": "bezier", "control_net": {"generator": "grid", "size": [3, 3], "z": "x*y + x/3"}}
BSPLINE = {"type": "bspline", "knots_u": [0, 0, 0, "1/2", 1, 1, 1], "knots_v": [0, 0, 0, "1/3", 1, 1, 1],
           "control_net": {"generator": "grid", "size": [4, 4], "z": "x*y + x/3"}}


def _image(tmp_path, surface: dict) -> dict:
    scene = {"scene": {"name": "img", "float_policy": "reject"}, "surfaces": {"s": surface}, "curves": {"k": CURVE},
             "products": [{"kind": "image_curve", "name": "image", "surface": "s", "curve": "k"}]}
    path = tmp_path / "img.json"
    path.write_text(json.dumps(scene))
    assert main(["run", str(path), "--out", str(tmp_path / "out"), "--no-cache"]) == 0
    return json.loads((tmp_path / "out" / "img" / "image.json").read_text())["result"]


def _exact_value(entry: dict):
    """An interval end or joint parameter: a rational, or the root of its polynomial in its interval."""
    if "rational" in entry:
        return sp.Rational(entry["rational"])
    x = sp.Symbol("x")
    poly = sp.Poly([sp.Integer(c) for c in reversed(entry["polynomial"])], x)  # coefficients: constant first
    lo, hi = (sp.Rational(v) for v in entry["interval"])
    (root,) = [r for r in sp.real_roots(poly) if lo <= r <= hi]
    return root


def _check_pieces(result: dict) -> None:
    assert set(result) >= {"domain", "pieces", "joints"}
    assert result["pieces"], "at least one piece"
    for piece in result["pieces"]:
        curve = piece["curve"]
        assert curve["type"] == "bezier_curve"
        exact = [[Fraction(c) for c in p] for p in curve["control_points"]]
        assert curve["control_points_float"] == [[float(c) for c in p] for p in exact]
        for end in piece["interval"]:
            value = _exact_value(end)
            assert end["float"] == float(sp.N(value, 40)), (end, value)


def test_image_curve_on_a_bezier_surface_has_pieces_with_float_companions(tmp_path):
    result = _image(tmp_path, BEZIER)
    _check_pieces(result)
    (piece,) = result["pieces"]
    assert piece["exact"] is True and piece["interval"] == [{"rational": "0", "float": 0.0}, {"rational": "1", "float": 1.0}]
    assert piece["curve"]["degree"] == 3 * (2 + 2)


def test_image_curve_on_a_bspline_surface_has_the_same_shape(tmp_path):
    result = _image(tmp_path, BSPLINE)
    _check_pieces(result)
    assert len(result["pieces"]) > 1
    assert any(not p["exact"] for p in result["pieces"]), "knot-line crossings at irrational parameters expected"
    for joint in result["joints"]:
        assert joint["parameter"]["float"] == float(sp.N(_exact_value(joint["parameter"]), 40))


def test_approximation_bound_and_tolerance_have_float_companions(tmp_path):
    scene = {"scene": {"name": "apx", "float_policy": "reject"}, "surfaces": {"s": BSPLINE}, "curves": {"k": CURVE},
             "products": [{"kind": "approximation", "name": "a", "surface": "s", "curve": "k", "tol": "1/100"}]}
    path = tmp_path / "apx.json"
    path.write_text(json.dumps(scene))
    assert main(["run", str(path), "--out", str(tmp_path / "out"), "--no-cache"]) == 0
    result = json.loads((tmp_path / "out" / "apx" / "a.json").read_text())["result"]
    assert result["tolerance"] == "1/100" and result["tolerance_float"] == 0.01
    assert result["distance_bound_float"] == float(Fraction(result["distance_bound"]))
    assert 0 < result["distance_bound_float"] <= 0.01
    for segment in result["segments"]:
        assert len(segment["control_points_float"]) == segment["degree"] + 1
