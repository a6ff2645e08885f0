"""Moving lines and mu-bases (notes chapter 18).

References: sympy expansion of L[t] . P[t] and of the cross product p x q from the
Bernstein definition; the resultant route of implicitize as an independent route.
"""

import sympy as sp
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from exactcagd import BezierCurve
from exactcagd.algebra import implicitize, mu_basis, tangent_moving_line
from exactcagd.algebra.moving_lines import MovingLine, axial_moving_line, homogeneous_control_points

t = sp.Symbol("t")


def _P(curve):
    n = curve.degree
    hom = curve.homogeneous()
    return [sp.expand(sum(sp.Rational(str(hom[i, k])) * sp.binomial(n, i) * t**i * (1 - t) ** (n - i) for i in range(n + 1))) for k in range(3)]


def _L(line: MovingLine):
    return [sum(sp.Rational(str(c[k])) * t**i for i, c in enumerate(line.coeffs)) for k in range(3)]


@settings(max_examples=15, deadline=None)
@given(st.integers(2, 6), st.randoms(use_true_random=False), st.sampled_from(["zeroing", "nullspace", "auto"]))
def test_mu_basis_properties(n, rnd, method):
    pts = [(rnd.randint(-7, 7), rnd.randint(-7, 7)) for _ in range(n + 1)]
    w = [rnd.randint(1, 4) for _ in range(n + 1)]
    assume(len(set(pts)) > 1)  # a constant curve is a DegreeError (tested elsewhere)
    curve = BezierCurve(pts, w)
    P = _P(curve)
    assume(sp.degree(sp.gcd(sp.gcd(P[0], P[1]), P[2]), t) == 0)
    try:
        p, q = mu_basis(curve, method)
    except Exception:  # zeroing fails on special curves only
        assume(method != "zeroing")
        raise
    assert p.degree + q.degree == n and p.degree <= q.degree
    for line in (p, q):
        L = _L(line)
        assert sp.expand(sum(a * b for a, b in zip(L, P))) == 0
    Lp, Lq = sp.Matrix(_L(p)), sp.Matrix(_L(q))
    cr = Lp.cross(Lq)
    ratio = [sp.cancel(cr[k] / P[k]) for k in range(3) if P[k] != 0]
    assert all(r_ == ratio[0] for r_ in ratio) and ratio[0].is_constant() and ratio[0] != 0


@settings(max_examples=10, deadline=None)
@given(st.integers(2, 6), st.randoms(use_true_random=False))
def test_moving_line_route_agrees_with_resultant(n, rnd):
    pts = [(rnd.randint(-7, 7), rnd.randint(-7, 7)) for _ in range(n + 1)]
    curve = BezierCurve(pts, [rnd.randint(1, 4) for _ in range(n + 1)])
    assume(len(set(pts)) > 1)
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        assert implicitize(curve, "moving_lines") == implicitize(curve, "resultant")


def test_constant_curve_is_rejected():
    import pytest

    from exactcagd.errors import DegreeError

    with pytest.raises(DegreeError):
        mu_basis(BezierCurve([[1, 2], [1, 2], [1, 2]]))


def test_axial_lines_and_tangent_degree():
    cubic = BezierCurve([[0, 0], [0, 1], [1, 2], [3, 0]])
    P = homogeneous_control_points(cubic)
    line, g = MovingLine.from_bernstein(axial_moving_line((3, 0), P)).remove_base_points()
    assert line.degree == 1 and g.degree() == 2  # base points at t = +-1: the crunode (18.59)
    assert line.axis() == (3, 0)
    cusp = BezierCurve([[0, 0], [1, 1], [0, 1], [1, 0]])
    assert tangent_moving_line(cusp).degree == 2 * 3 - 2 - 1  # one cusp
