"""Remark 1 / Remark 2 (Lasser & Bonneau): trim curves on B-spline and NURBS surfaces.

References: de Boor evaluation of the spline surface at de Boor points of the spline
curve (exact), sympy remainders for the irrational crossing parameters, dense sampling
for the crossed patches.
"""

from __future__ import annotations

from fractions import Fraction as Fr

import pytest
import sympy

from exactcagd import BezierCurve, BezierSurface, BSplineCurve, BSplineSurface
from exactcagd.composition import compose_spline, crossed_patches
from exactcagd.composition.splines import rational_between
from exactcagd.errors import DimensionError, DomainError, InputError
from exactcagd.exact.algebraic import RealAlgebraic


def _surface(rational=False):
    net = [[[Fr(i, 4), Fr(j, 4), Fr((i * i + 2 * j * j + i * j) % 5, 5)] for j in range(5)] for i in range(5)]
    weights = [[Fr(1 + (i * j) % 3, 1 + (i + j) % 2) for j in range(5)] for i in range(5)] if rational else None
    # u: cubic-free quadratic with knots 1/3 (simple), 2/3 (simple); v: quadratic, double knot 1/2 (C0)
    return BSplineSurface(net, [0, 0, 0, Fr(1, 3), Fr(2, 3), 1, 1, 1], [0, 0, 0, Fr(1, 2), Fr(1, 2), 1, 1, 1], weights)


def _curve(rational=False):
    pts = [[Fr(1, 10), Fr(1, 10)], [Fr(9, 10), Fr(2, 10)], [Fr(5, 10), Fr(9, 10)], [Fr(1, 10), Fr(6, 10)]]
    return BSplineCurve(pts, [0, 0, 0, Fr(1, 2), 1, 1, 1], [1, 2, 1, 3] if rational else None)


def _check_values(result, surface, curve):
    for piece in result.pieces:
        a, b = piece.interval
        inner = rational_between(a, b)
        assert piece.evaluate(inner) == surface.evaluate(*curve.evaluate(inner))
        assert result.evaluate(inner) == surface.evaluate(*curve.evaluate(inner))
        for end in (a, b):
            if not isinstance(end, RealAlgebraic):
                assert piece.evaluate(end) == surface.evaluate(*curve.evaluate(end))


@pytest.mark.parametrize("rs,rc", [(False, False), (True, True), (True, False)])
def test_pieces_match_de_boor_evaluation(rs, rc):
    surface, curve = _surface(rs), _curve(rc)
    result = compose_spline(surface, curve)
    assert len(result.pieces) == 7
    _check_values(result, surface, curve)
    for piece in result.pieces:
        assert piece.curve.is_rational == (rs or rc)
        assert piece.curve.degree == 2 * (2 + 2)


def test_irrational_crossings_are_exact_roots():
    surface, curve = _surface(), _curve()
    result = compose_spline(surface, curve)
    t = sympy.Symbol("t")
    segments = curve.to_bezier()
    irrational = [(j.parameter, j.kinds) for j in result.joints if isinstance(j.parameter, RealAlgebraic)]
    assert len(irrational) == 5
    for param, kinds in irrational:
        name, _, _, kappa = kinds[0].split()
        kappa = sympy.Rational(kappa)
        (a, b), seg = next(s for s in segments if s[0][0] <= param <= s[0][1])
        x, y = seg.to_sympy(t)
        s = (t - sympy.Rational(str(a))) / (sympy.Rational(str(b)) - sympy.Rational(str(a)))
        coord = (x if name == "u" else y).subs(t, s)
        numer = sympy.Poly(sympy.numer(sympy.together(coord - kappa)), t)
        minimal = sympy.Poly(sum(int(c) * t**k for k, c in enumerate(param.poly.coeffs())), t)
        assert numer.rem(minimal).is_zero
        assert not param.is_rational


def test_exact_flag_and_carriers():
    surface, curve = _surface(), _curve()
    result = compose_spline(surface, curve)
    for piece in result.pieces:
        lo, hi = piece.local_interval()
        assert 0 <= lo < hi <= 1
        assert piece.exact == (not isinstance(piece.interval[0], RealAlgebraic) and not isinstance(piece.interval[1], RealAlgebraic))
        if piece.exact:
            assert (lo, hi) == (0, 1)


def test_rational_crossings_give_exact_pieces():
    net = [[[i, j, (i + j) % 2] for j in range(4)] for i in range(4)]
    surface = BSplineSurface(net, [0, 0, 0, Fr(1, 2), 1, 1, 1], [0, 0, 0, Fr(1, 2), 1, 1, 1])
    line = BezierCurve([[Fr(1, 8), Fr(1, 4)], [Fr(7, 8), Fr(5, 8)]])
    result = compose_spline(surface, line)
    assert all(p.exact for p in result.pieces)
    assert [str(p.interval[1]) for p in result.pieces] == ["1/2", "2/3", "1"]
    _check_values_bezier(result, surface, line)


def _check_values_bezier(result, surface, curve):
    for piece in result.pieces:
        inner = rational_between(*piece.interval)
        assert piece.evaluate(inner) == surface.evaluate(*curve.evaluate(inner))


def test_crossed_patches_match_dense_sampling():
    surface, curve = _surface(), _curve()
    bu, bv = surface.breakpoints()
    sampled = set()
    for k in range(801):
        u, v = curve.evaluate(Fr(k, 800))
        i = min(max(i for i in range(len(bu) - 1) if bu[i] <= u), len(bu) - 2)
        j = min(max(j for j in range(len(bv) - 1) if bv[j] <= v), len(bv) - 2)
        sampled.add((i, j))
    assert crossed_patches(surface, curve) == sampled


def test_only_crossed_patches_are_extracted(monkeypatch):
    surface = _surface()
    calls = []
    original = BSplineSurface.to_bezier_patches

    def spy(self, u_spans=None, v_spans=None, pairs=None):
        built = original(self, u_spans, v_spans, pairs)
        calls.append(set(built))
        return built

    monkeypatch.setattr(BSplineSurface, "to_bezier_patches", spy)
    short = BezierCurve([[Fr(1, 20), Fr(1, 20)], [Fr(3, 10), Fr(1, 5)]])  # stays in patch (0, 0)
    result = compose_spline(surface, short)
    assert calls == [{(0, 0)}]
    assert result.patches == [(0, 0)] and result.joints == []
    # a diagonal crossing 3 of the 3 x 2 patches: the rows x columns product would be 4 (or 6)
    calls.clear()
    diagonal = BezierCurve([[Fr(1, 10), Fr(1, 10)], [Fr(5, 10), Fr(2, 10)], [Fr(9, 10), Fr(9, 10)]])
    result = compose_spline(surface, diagonal)
    assert calls == [set(result.patches)] and len(calls[0]) < 3 * 2


def test_joint_continuity_remark1():
    """Measured order >= min(a, b), with equality at the C0 line v = 1/2 and the C1 u-lines."""
    surface, curve = _surface(), _curve()
    result = compose_spline(surface, curve)
    for joint in result.joints:
        assert joint.measured is None or joint.remark_bound is None or joint.measured >= joint.remark_bound
    by_kind = {j.kinds[0].split()[0] + j.kinds[0].split()[-1]: j for j in result.joints}
    assert by_kind["v1/2"].surface_continuity == 0 and by_kind["v1/2"].measured == 0
    assert by_kind["u1/3"].surface_continuity == 1 and by_kind["u1/3"].measured == 1
    knot = next(j for j in result.joints if j.kinds[0] == "curve knot")
    assert knot.curve_continuity == 1 and knot.surface_continuity is None and knot.measured >= 1


def test_smooth_surface_gives_curve_continuity():
    """A Bézier surface (C-infinity) composed with a C1 spline: e = a = 1."""
    surface = BezierSurface([[[i, j, (i * i + j) % 3] for j in range(3)] for i in range(3)])
    result = compose_spline(surface, _curve())
    assert len(result.pieces) == 2
    (joint,) = result.joints
    assert joint.remark_bound == 1 and joint.measured == 1


def test_curve_along_and_tangent_to_knot_lines():
    surface = _surface()
    along = BezierCurve([[Fr(1, 3), Fr(1, 10)], [Fr(1, 3), Fr(2, 5)]])  # on u = 1/3
    result = compose_spline(surface, along)
    assert len(result.pieces) == 1
    _check_values_bezier(result, surface, along)
    # u(t) = 1/3 - (2t - 1)^2 / 6 touches u = 1/3 at t = 1/2 from below: one patch
    touch = BezierCurve([[Fr(1, 6), Fr(1, 10)], [Fr(1, 2), Fr(1, 5)], [Fr(1, 6), Fr(3, 10)]])
    result = compose_spline(surface, touch)
    assert len(result.pieces) == 1 and result.patches == [(0, 0)]
    _check_values_bezier(result, surface, touch)


def test_bad_input():
    surface = _surface()
    with pytest.raises(DomainError):
        compose_spline(surface, BezierCurve([[0, 0], [Fr(3, 2), Fr(1, 2)]]))
    with pytest.raises(DimensionError):
        compose_spline(surface, BezierCurve([[0, 0, 0], [1, 1, 1]]))
    # only the second Bézier segment of the spline leaves [0, 1]^2 (u(t) > 1 near t = 3/4): the message names it
    leaving = BSplineCurve([[Fr(1, 10), Fr(1, 10)], [Fr(1, 2), Fr(1, 5)], [Fr(1, 2), Fr(1, 2)], [Fr(19, 10), Fr(1, 2)], [Fr(9, 10), Fr(9, 10)]], [0, 0, 0, Fr(1, 2), Fr(1, 2), 1, 1, 1])
    with pytest.raises(DomainError, match=r"segment 1, t in \[1/2, 1\].*u\(t\) > 1"):
        compose_spline(surface, leaving)
    with pytest.raises(DomainError):
        crossed_patches(surface, leaving)
    result = compose_spline(surface, _curve())
    for t in (-1, Fr(3, 2)):
        with pytest.raises(DomainError, match="outside the curve's domain"):
            result.evaluate(t)
    with pytest.raises(InputError):
        compose_spline(surface, [[0, 0], [1, 1]])
    with pytest.raises(InputError):
        compose_spline(_curve(), _curve())


@pytest.mark.parametrize("rational", [False, True])
def test_cubic_approximation_across_irrational_crossings(rational):
    """Section VIII on a spline: snapped joints share an exact point (and direction where the
    exact curve is C1); the certified bound holds against exact de Boor points."""
    import numpy as np

    from exactcagd.composition import approximate_cubic

    surface, curve = _surface(rational), _curve(rational)
    tol = Fr(1, 100)
    result = approximate_cubic(surface, curve, "1/100")
    assert result.tolerance_met and result.distance_bound <= tol
    cubics = [s.curve for s in result.segments]
    assert tuple(cubics[0].evaluate(0)) == surface.evaluate(*curve.evaluate(0))
    assert tuple(cubics[-1].evaluate(1)) == surface.evaluate(*curve.evaluate(1))
    exact = compose_spline(surface, curve)
    corners = [j.parameter for j in exact.joints if j.remark_bound == 0]
    for left, right in zip(result.segments[:-1], result.segments[1:]):
        a, b = left.curve.points_array(), right.curve.points_array()
        assert all(x == y for x, y in zip(a[3], b[0]))  # G0 exactly
        u, v = a[3] - a[2], b[1] - b[0]
        cross = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
        at_corner = any(left.interval[1] - Fr(1, 2**40) < c < left.interval[1] + Fr(1, 2**40) for c in corners)
        if not at_corner:
            assert all(c == 0 for c in cross) and sum(x * y for x, y in zip(u, v)) > 0  # G1 exactly
    # Hausdorff check: exact points of S(K(t)) against dense float samples of the cubics
    dense = np.vstack([np.array([[float(x) for x in c.evaluate(Fr(k, 400))] for k in range(401)]) for c in cubics])
    for k in range(0, 101):
        t = Fr(k, 100)
        p = np.array([float(x) for x in surface.evaluate(*curve.evaluate(t))])
        assert np.min(np.linalg.norm(dense - p, axis=1)) <= float(result.distance_bound)


def test_to_dict_is_exact():
    result = compose_spline(_surface(), _curve())
    data = result.to_dict()
    assert data["pieces"][0]["interval"][0] == {"rational": "0"}
    assert "polynomial" in data["pieces"][0]["interval"][1]
    assert data["joints"][0]["kinds"] == ["u knot line 1/3"]
