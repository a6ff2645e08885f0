"""Derivation traces (teaching mode): the printed intermediate objects are the notes' values.

References: sympy determinants of Sylvester matrices built here, products of root
differences, sympy substitution of the Bézier parametrization, the printed values
of notes 17.3.3, 17.3.4, 17.5 and (18.86)-(18.87).
"""

import random

import numpy as np
import pytest
import sympy as sp
from gmpy2 import mpq
from hypothesis import given, settings
from hypothesis import strategies as st

from exactcagd import BezierCurve
from exactcagd.errors import InputError
from exactcagd.algebra.traces import trace_bezout, trace_zeroing

t, x, y = sp.symbols("t x y")


def _sylvester_det(f, g):
    a = sp.Poly(f, t).all_coeffs()
    b = sp.Poly(g, t).all_coeffs()
    m, n = len(a) - 1, len(b) - 1
    rows = [[0] * i + a + [0] * (n - 1 - i) for i in range(n)] + [[0] * i + b + [0] * (m - 1 - i) for i in range(m)]
    return sp.expand(sp.Matrix(rows).det())


def test_bezout_trace_17_3_examples():
    lines = []
    r = trace_bezout(t**2 - 7 * t + 12, t**2 - 3 * t + 2, t, out=lines.append)
    assert r["matrix"] == sp.Matrix([[4, -10], [-10, 22]]) and r["det"] == -12 and r["resultant"] == 12
    assert "  det = -12" in lines and any("h2 = (t - 7) g - (t - 3) f" in s for s in lines)
    r = trace_bezout(t**3 - 2 * t**2 + 3 * t + 1, 2 * t**3 + 3 * t**2 - t + 4, t, out=lines.append)
    assert r["matrix"] == sp.Matrix([[7, -7, 2], [-7, -5, -11], [2, -11, 13]]) and r["det"] == -1611
    # the notes' integer-preserving elimination (17.4, example 1): [[7,-7,2],[0,-84,-63],[0,0,-1611]]
    assert any("-84" in s and "-63" in s for s in lines)


def test_bezout_trace_17_5_example_2():
    X, Y, W = 2 * t**3 - 18 * t**2 + 18 * t + 4, 39 * t**3 - 69 * t**2 + 33 * t + 1, -3 * t**2 + 3 * t + 1
    r = trace_bezout(sp.expand(W * x - X), sp.expand(W * y - Y), t, out=lambda s: None)
    printed = sp.Matrix(
        [
            [-117 * x + 6 * y + 564, 117 * x - 6 * y - 636, 39 * x - 2 * y - 154],
            [117 * x - 6 * y - 636, -69 * x - 2 * y + 494, -66 * x + 6 * y + 258],
            [39 * x - 2 * y - 154, -66 * x + 6 * y + 258, 30 * x - 6 * y - 114],
        ]
    )
    assert (r["matrix"] - printed).applyfunc(sp.expand) == sp.zeros(3, 3)
    assert sp.expand(r["det"] - printed.det()) == 0
    # the resultant vanishes on the curve (exact substitution)
    R = sp.Poly(r["resultant"], x, y)
    assert R.total_degree() == 3
    assert sp.Poly(sum(c * X**i * Y**j * W ** (3 - i - j) for (i, j), c in R.terms()), t).is_zero


@settings(max_examples=25, deadline=None)
@given(
    st.lists(st.integers(-4, 4), min_size=1, max_size=4),
    st.lists(st.integers(-4, 4), min_size=1, max_size=4),
    st.integers(1, 3),
    st.integers(-3, 3).filter(lambda v: v != 0),
)
def test_bezout_trace_equals_root_product(fr, gr, lead_f, lead_g):
    f = sp.expand(lead_f * sp.prod([t - r_ for r_ in fr]))
    g = sp.expand(lead_g * sp.prod([t - r_ for r_ in gr]))
    res = trace_bezout(f, g, t, out=lambda s: None)["resultant"]
    expected = lead_f ** len(gr) * lead_g ** len(fr) * sp.prod([a - b for a in fr for b in gr])
    assert res == expected == _sylvester_det(f, g)


QUARTIC = BezierCurve([[0, 0], [0, 1], [1, 2], [3, 2], [2, 0]])  # notes figure 18.12


def test_zeroing_trace_quartic_18_86_18_87():
    lines = []
    r = trace_zeroing(QUARTIC, out=lines.append)
    assert r["entries"] == [[2 * y, 4 * x + 4 * y - 8, 4 * x - 2 * y - 8], [8 * x + 6 * y, 28 * x + 4 * y - 24, 20 * x - 14 * y - 40]]
    F = y**4 + 4 * x**3 + 2 * x * y**2 - 16 * x**2 - 6 * y**2 + 16 * x
    assert sp.expand(r["det"] - 512 * F) == 0 and r["ratio"] == 512
    assert any("row 2 -= (-4) row 0 + (2) row 1" in s for s in lines)
    assert any("(18.82)" in s and "['0', '0', '0', '0']" in s for s in lines)


def _bern(points, weights):
    n = len(points) - 1
    B = [sp.binomial(n, i) * t**i * (1 - t) ** (n - i) for i in range(n + 1)]
    W = sum(w * b for w, b in zip(weights, B))
    return [sum(w * p[k] * b for p, w, b in zip(points, weights, B)) for k in range(2)] + [W]


@pytest.mark.parametrize("n", [3, 4, 5, 6])
def test_zeroing_trace_lines_follow_and_det_is_implicit(n):
    r_ = random.Random(400 + n)
    pts = [[r_.randint(-5, 5), r_.randint(-5, 5)] for _ in range(n + 1)]
    ws = [r_.randint(1, 3) for _ in range(n + 1)]
    curve = BezierCurve(pts, weights=ws)
    res = trace_zeroing(curve, out=lambda s: None)
    X, Y, W = _bern(pts, ws)
    for row in res["rows"]:  # each final row is a moving line following P[t] (18.83)/(18.84)
        d = len(row) - 1
        L = [sum(sp.Rational(str(e[k])) * (1 - t) ** (d - j) * t**j for j, e in enumerate(row)) for k in range(3)]
        assert sp.expand(L[0] * X + L[1] * Y + L[2] * W) == 0
    det = sp.Poly(res["det"], x, y)  # has degree n and vanishes on the curve
    assert det.total_degree() == n
    # W^n det(X/W, Y/W) has degree <= n^2 in t: n^2 + 1 exact zeros make it vanish identically
    for k in range(n * n + 1):
        tv = sp.Rational(k, n * n + 3)
        Xv, Yv, Wv = (sp.Poly(e, t).eval(tv) for e in (X, Y, W))
        assert det.eval({x: Xv / Wv, y: Yv / Wv}) == 0


def test_trace_bad_input():
    with pytest.raises(InputError):
        trace_bezout(0, t + 1, t)
    with pytest.raises(InputError):
        trace_bezout(sp.Integer(3), sp.Integer(2), t)
    with pytest.raises(InputError):
        trace_zeroing(BezierCurve([[0, 0], [1, 1]]))


def test_zeroing_trace_cubic_pencil_axis_is_the_double_point():
    lines = []
    r = trace_zeroing(BezierCurve([[0, 0], [0, 1], [1, 2], [3, 0]]), out=lines.append)  # notes figure 18.11
    assert any("('3', '0') is the double point" in s for s in lines)
    f = sp.Poly(r["det"], x, y).as_expr()
    # independent: (3, 0) is singular on the determinant curve (f = f_x = f_y = 0, sympy)
    assert all(e.subs({x: 3, y: 0}) == 0 for e in (f, sp.diff(f, x), sp.diff(f, y)))
    assert r["entries"][1] == [3 * y, 3 * x + 3 * y - 9]  # the pencil (0,3,0)(1-t) + (3,3,-9)t of (18.63)
