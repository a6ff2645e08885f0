"""Curve-curve intersection by implicitization and inversion (notes 17.8, 7.3.1, 19.3).

References: exact sympy computations (roots of the substituted polynomial, point
equality with mpmath at 50 digits of the algebraic numbers' refined intervals) and
hand-derived examples of the notes' section 7.3.1.
"""

import mpmath
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from exactcagd import BezierCurve
from exactcagd.algebra import OverlapError, curve_from_polynomials, implicit_intersections, intersect
from exactcagd.exact.algebraic import RealAlgebraic

x, y, t = sp.symbols("x y t")


def _float(a: RealAlgebraic, digits=40):
    a.refine(sp.Rational(1, 10**digits) if False else __import__("gmpy2").mpq(1, 10**digits))
    return mpmath.mpf(int(a.lo.numerator)) / int(a.lo.denominator)


def _eval(curve, tv):
    pts, w = curve.control_points, curve.weights_array()
    n = curve.degree
    B = [mpmath.binomial(n, i) * tv**i * (1 - tv) ** (n - i) for i in range(n + 1)]
    W = sum(mpmath.mpf(int(w[i].numerator)) / int(w[i].denominator) * B[i] for i in range(n + 1))
    return [sum(mpmath.mpf(int(w[i].numerator)) / int(w[i].denominator) * mpmath.mpf(int(pts[i][k].numerator)) / int(pts[i][k].denominator) * B[i] for i in range(n + 1)) / W for k in range(2)]


def _check_pairs(c1, c2, found):
    mpmath.mp.dps = 50
    for r in found:
        p1 = _eval(c1, _float(r.t1))
        p2 = _eval(c2, _float(r.t2))
        assert max(abs(a - b) for a, b in zip(p1, p2)) < mpmath.mpf(10) ** -30
        assert 0 <= r.t1 <= 1 and 0 <= r.t2 <= 1


def test_parabola_line():
    a = BezierCurve([[0, 0], [1, 2], [2, 0]])
    b = BezierCurve([[0, 1], [2, 0]])
    res = intersect(a, b)
    assert [(str(r.t1), str(r.t2), r.multiplicity) for r in res] == [("1/4", "1/4", 1), ("1", "1", 1)]
    assert [(str(r.point[0]), str(r.point[1])) for r in res] == [("1/2", "3/4"), ("2", "0")]


def test_irrational_intersections_are_exact():
    # unit quarter circle and the line y = x: t with x = y, point (1/sqrt2, 1/sqrt2)
    quarter = BezierCurve([[1, 0], [1, 1], [0, 1]], weights=[1, 1, 2])
    diag = BezierCurve([[0, 0], [1, 1]])
    (r,) = intersect(quarter, diag)
    assert r.multiplicity == 1
    assert [int(c) for c in r.point[0].poly.coeffs()] == [-1, 0, 2]  # 2 x^2 - 1
    assert r.t2 == r.point[0]  # the diagonal is x = t2
    _check_pairs(quarter, diag, [r])


def test_order_of_contact_7_3_1():
    # the notes' examples use the circle X^2 + Y^2 - W^2 = 0; our curve 1 is its quarter arc
    quarter = BezierCurve([[1, 0], [1, 1], [0, 1]], weights=[1, 1, 2])
    tangent = curve_from_polynomials(1 + t**2, t)  # g(t) = t^2: contact of order 2 at (1, 0)
    (r,) = intersect(quarter, tangent)
    assert (str(r.t1), str(r.t2), r.multiplicity) == ("0", "0", 2)
    # the notes' third example (1 - t^2, t + t^2) gives g = 2t^4 + 2t^3 - t^2 (ledger erratum 7.3.1):
    # contact 2 at t = 0 and a simple intersection at t = (sqrt 3 - 1)/2
    res = intersect(quarter, curve_from_polynomials(1 - t**2, t + t**2))
    assert [(r.multiplicity, [int(c) for c in r.t2.poly.coeffs()]) for r in res] == [(2, [0, 1]), (1, [-1, 2, 2])]
    # curvature-continuous contact: g = 2 t^3 + t^4/4 - t^5 + t^6
    (r,) = intersect(quarter, curve_from_polynomials(1 - t**2 / 2 + t**3, t))
    assert (str(r.t1), str(r.t2), r.multiplicity) == ("0", "0", 3)
    # hyperosculation: g = t^4 / 4
    (r,) = intersect(quarter, curve_from_polynomials(1 - t**2 / 2, t))
    assert r.multiplicity == 4


def test_through_a_double_point_of_curve_1():
    # crunode of x^3 + 9x^2 - 12y^2 at the origin, passed twice for t in [0, 1]
    node = BezierCurve([[3, 3], [-13, -15], [-13, 15], [3, -3]])
    line = BezierCurve([[-1, -1], [1, 1]])
    res = intersect(node, line)
    at_origin = [r for r in res if str(r.point[0]) == "0" and str(r.point[1]) == "0"]
    assert len(at_origin) == 2 and all(r.multiplicity == 1 for r in at_origin)
    assert {str(r.t2) for r in at_origin} == {"1/2"}
    _check_pairs(node, line, res)
    # symmetric roles: the line's point is singular on curve 2 -> multiplicity from curve 2's equation
    res2 = intersect(line, node)
    assert sorted(r.multiplicity for r in res2 if str(r.point[0]) == "0") == [1, 1]


def test_notes_nine_intersections():
    c1 = curve_from_polynomials("2*t**3-18*t**2+18*t+4", "39*t**3-69*t**2+33*t+1", "-3*t**2+3*t+1")
    c2 = curve_from_polynomials("-52*t**3+63*t**2-15*t+7", "4", "-3*t**2+3*t+1")
    res = intersect(c1, c2)
    assert len(res) == 9
    _check_pairs(c1, c2, res)


@settings(max_examples=10, deadline=None)
@given(st.randoms(use_true_random=False), st.integers(1, 3), st.integers(1, 3))
def test_random_pairs(rnd, n1, n2):
    c1 = BezierCurve([[rnd.randint(-5, 5), rnd.randint(-5, 5)] for _ in range(n1 + 1)], [rnd.randint(1, 3) for _ in range(n1 + 1)])
    c2 = BezierCurve([[rnd.randint(-5, 5), rnd.randint(-5, 5)] for _ in range(n2 + 1)])
    try:
        res = intersect(c1, c2)
    except OverlapError:
        return
    except Exception as exc:  # degenerate random input (constant curve) is an input error
        from exactcagd.errors import ExactCAGDError

        assert isinstance(exc, ExactCAGDError)
        return
    _check_pairs(c1, c2, res)


def test_overlap():
    a = BezierCurve([[0, 0], [1, 2], [2, 0]])
    left, right = a.subdivide("1/2")
    with pytest.raises(OverlapError) as info:
        intersect(a, right)
    a_, b_, c_, d_ = info.value.mapping
    # t1 = (t2 + 1) / 2 on the right half
    assert c_ == 0 and sp.Rational(a_, d_) == sp.Rational(1, 2) and sp.Rational(b_, d_) == sp.Rational(1, 2)
    assert info.value.t2_intervals == [(0, 1)]
    # the shared arc with exact ends: t1 in [1/2, 1] is t2 in [0, 1] (t1 = (t2 + 1) / 2)
    ((S, T),) = [(o.t1_interval, o.t2_interval) for o in info.value.overlaps]
    assert (S[0], S[1], T[0], T[1]) == (sp.Rational(1, 2), 1, 0, 1) or [str(v) for v in (*S, *T)] == ["1/2", "1", "0", "1"]
    # same parabola, pieces meeting only at left(1) = other(0): one point, not an error
    other = BezierCurve([[1, 1], [2, 1], [3, -3]])
    X = x - 1  # by hand: left is y = 2x - x^2 on x in [0, 1], other is the same on [1, 3]
    assert sp.expand((2 * x - x**2).subs(x, 1 + 2 * X) - (1 - 4 * X**2)) == 0
    (hit,) = intersect(left, other)
    assert (hit.t1, hit.t2, hit.multiplicity) == (1, 0, None)


def test_implicit_curves_19_3():
    pts = implicit_intersections(6 * x**2 + 6 * y**2 - 2 * x - 15 * y - 4, x**2 - y**2 - 1)
    assert [(str(a), str(b)) for a, b in pts] == [("-5/4", "3/4"), ("-13/12", "5/12"), ("1", "0"), ("5/3", "4/3")]
    pts = implicit_intersections(x**2 + y**2 - 2, x**2 - 2 * y**2 + y)
    mpmath.mp.dps = 30
    for px, py in pts:
        fx, fy = _float(px, 30), _float(py, 30)
        assert abs(fx**2 + fy**2 - 2) < 1e-25 and abs(fx**2 - 2 * fy**2 + fy) < 1e-25
    assert len(pts) == len([s for s in sp.solve([x**2 + y**2 - 2, x**2 - 2 * y**2 + y], [x, y]) if all(v.is_real for v in s)])
