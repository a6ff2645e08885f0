"""Scenes choose the intersection route (issue 15): ``method`` in the product, default
``auto`` (clipping, certified, exact fallback); plan states the exact route's cost.

Reference: the intersection parameters of the degree-8 pair are checked against sympy
(the exact residual |P(s) - Q(t)| at the returned boxes' parameters is within the box
width times a Lipschitz bound), and the count against sympy's real roots of the
resultant in [0, 1] paired by substitution.
"""

import json
import time

import pytest
import sympy as sp

from exactcagd.cli import main
from exactcagd.scenes.spec import SceneError, parse_scene


def _pair(n=8):
    """Two degree-8 curves crossing a few times: y = small oscillations around two lines."""
    a = [[str(sp.Rational(i, n)), str(sp.Rational((-1) ** i, 4) + sp.Rational(i, 2 * n))] for i in range(n + 1)]
    b = [[str(sp.Rational(i, n)), str(sp.Rational(1, 2) - sp.Rational(i, 2 * n) + sp.Rational((-1) ** (i + 1), 5))] for i in range(n + 1)]
    return a, b


def _scene(method=None):
    a, b = _pair()
    product = {"kind": "intersections", "name": "x", "curves": ["a", "b"]}
    if method:
        product["method"] = method
    return {
        "scene": {"name": "deg8", "float_policy": "reject"},
        "curves": {"a": {"type": "bezier", "control_points": a}, "b": {"type": "bezier", "control_points": b}},
        "products": [product],
    }


def _reference_s_roots():
    """Parameters on curve a of the intersections, by sympy: Res_t(x_a(s) - x_b(t), y_a(s) - y_b(t))."""
    s, t = sp.symbols("s t")
    a, b = _pair()

    def bern(pts, v, k):
        n = len(pts) - 1
        return sp.expand(sum(sp.binomial(n, i) * v**i * (1 - v) ** (n - i) * sp.Rational(pts[i][k]) for i in range(n + 1)))

    R = sp.Poly(sp.resultant(bern(a, s, 0) - bern(b, t, 0), bern(a, s, 1) - bern(b, t, 1), t), s)
    roots = [r for r in sp.Poly(R, s).real_roots() if 0 <= r <= 1]
    return sorted(set(roots))


def test_degree_8_scene_runs_in_seconds_by_default(tmp_path, capsys):
    path = tmp_path / "deg8.json"
    path.write_text(json.dumps(_scene()))
    t0 = time.process_time()
    assert main(["run", str(path), "--out", str(tmp_path / "out")]) == 0
    assert time.process_time() - t0 < 30
    data = json.loads((tmp_path / "out" / "deg8" / "x.json").read_text())
    items = data["result"]
    want = _reference_s_roots()
    assert len(items) == len(want) >= 1
    for item, r in zip(sorted(items, key=lambda x: x["t1"]), want):
        lo, hi = item["t1_interval"]
        assert item["certified"] and sp.Rational(lo) <= r <= sp.Rational(hi)


def test_plan_states_the_exact_cost(tmp_path, capsys):
    path = tmp_path / "deg8.json"
    path.write_text(json.dumps(_scene("exact")))
    assert main(["plan", str(path), "--out", str(tmp_path / "out")]) == 0
    out = capsys.readouterr().out
    assert "by exact" in out and "degrees 8 x 8" in out


def test_bad_method_is_a_scene_error():
    with pytest.raises(SceneError):
        parse_scene(_scene("newton"))


def test_plan_warns_when_the_exact_route_is_long(tmp_path, capsys):
    """Two degree-20 curves (the largest pair a scene admits, result degree 400):
    exact_cost(20, 20) = 0.01 + 2.5e-6 * 400^2.5 = 8 s > WARN_EXACT_SECONDS = 5 s."""
    import random

    rng = random.Random(3)
    curves = {k: {"type": "bezier", "control_points": [[rng.randint(-9, 9), rng.randint(-9, 9)] for _ in range(21)]} for k in "ab"}
    scene = {"scene": {"name": "deg20"}, "curves": curves,
             "products": [{"kind": "intersections", "name": "x", "curves": ["a", "b"], "method": "exact"}]}
    path = tmp_path / "deg20.json"
    path.write_text(json.dumps(scene))
    t0 = time.process_time()
    assert main(["plan", str(path), "--out", str(tmp_path / "out")]) == 0
    assert time.process_time() - t0 < 10  # plan estimates, it does not intersect
    out = capsys.readouterr()
    text = out.out + out.err
    assert "takes ~8 s" in text and "degrees 20 x 20" in text
