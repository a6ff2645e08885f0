"""Ledger: Sederberg's notes, chapter 12 (interval Bézier curves), checked exactly.

Interval rules and interval Bézier identities are checked with exact rational intervals
(:mod:`exactcagd.numeric.interval`, :mod:`exactcagd.numeric.interval_bezier`) against
brute force over endpoint choices; the Hermite formulas symbolically with sympy; the
worked examples with exact symbolic constants (``e``, ``pi``) and rigorous containment
checks through mpmath's interval arithmetic (every enclosure converted exactly to
rationals).
"""

from __future__ import annotations

import math
import random
from fractions import Fraction

import sympy
from gmpy2 import mpq

from exactcagd.proofs import _ledger as L
from exactcagd.proofs._ledger import claim, erratum, verified, verified_range

T = sympy.Symbol("t")


def _bern(n, k, t=T):
    return sympy.binomial(n, k) * t**k * (1 - t) ** (n - k)


def _rand_interval(rng, scale=20):
    from exactcagd.numeric.interval import Interval

    a, b = (Fraction(rng.randint(-scale * 8, scale * 8), rng.randint(1, 8)) for _ in range(2))
    return Interval(min(a, b), max(a, b))


def _enumerated(op, u, v):
    """[min, max] of x op y over the endpoint choices (the set (12.2) of a monotone operation), written here."""
    vals = [op(x, y) for x in (u.lo, u.hi) for y in (v.lo, v.hi)]
    return min(vals), max(vals)


def _iv_interval(x):
    """An mpmath interval as an exact :class:`Interval` (endpoints are binary numbers)."""
    from mpmath.libmp import to_rational

    from exactcagd.numeric.interval import Interval

    lo, hi = (mpq(*to_rational(p)) for p in x._mpi_)
    return Interval(lo, hi)


def _iv_of(q):
    from mpmath import iv

    q = mpq(q)
    return iv.mpf(int(q.numerator)) / int(q.denominator)


# ---------------------------------------------------------------------------- 12.1
@claim(doc="sederberg", section="12.1", ref="(12.3)",
       statement="[a,b]+[c,d]=[a+c,b+d], [a,b]-[c,d]=[a-d,b-c], [a,b][c,d]=[min,max of ac,ad,bc,bd], "
       "[a,b]/[c,d]=[a,b][1/d,1/c] (0 not in [c,d]); each equals the set {x*y} of (12.2)")
def interval_rules():
    rng = random.Random(123)
    for _ in range(400):
        u, v = _rand_interval(rng), _rand_interval(rng)
        for op, got in (("+", u + v), ("-", u - v), ("*", u * v)):
            vals = [eval(f"x {op} y", {"x": x, "y": y}) for x in (u.lo, u.hi) for y in (v.lo, v.hi)]
            assert (got.lo, got.hi) == (min(vals), max(vals))
            # the set is the whole interval: continuity + the extremes are attained at endpoints
        if not v.contains(0):
            got = u / v
            vals = [x / y for x in (u.lo, u.hi) for y in (v.lo, v.hi)]
            assert (got.lo, got.hi) == (min(vals), max(vals))
    return verified_range("400 random pairs of rational intervals",
                          "each rule equals min/max over endpoint combinations; the operations are monotone "
                          "in each argument on the box, so these extremes bound the set (12.2), which is connected",
                          compared='printed (12.3) rules (exactcagd Interval +, -, x, /) vs min/max of x op y over the four endpoint combinations, enumerated in the check, for 400 random rational interval pairs', reference='enumeration')


@claim(doc="sederberg", section="12.1", ref="(12.5), (12.33)",
       statement="+ and x are commutative and associative, x is not distributive, but alpha([u]+[v]) = alpha[u]+alpha[v]; "
       "([1,2]+[3,4])-[3,4] = [0,3]")
def interval_laws():
    from exactcagd.numeric.interval import Interval

    rng = random.Random(5)
    strict = 0
    for _ in range(300):
        u, v, w = (_rand_interval(rng) for _ in range(3))
        alpha = Fraction(rng.randint(-9, 9), rng.randint(1, 5))
        assert u + v == v + u and u * v == v * u
        assert (u + v) + w == u + (v + w) and (u * v) * w == u * (v * w)
        assert alpha * (u + v) == alpha * u + alpha * v
        left, right = u * (v + w), u * v + u * w
        assert right.contains(left)
        strict += left != right
        # independent: the same laws on endpoint enumeration (no exactcagd Interval arithmetic)
        add, mul = (lambda x, y: x + y), (lambda x, y: x * y)
        E = lambda pair: type(u)(*pair)  # noqa: E731
        assert (left.lo, left.hi) == _enumerated(mul, u, E(_enumerated(add, v, w)))
        assert (right.lo, right.hi) == _enumerated(add, E(_enumerated(mul, u, v)), E(_enumerated(mul, u, w)))
        a_u, a_v = _enumerated(mul, type(u)(alpha), u), _enumerated(mul, type(u)(alpha), v)
        assert _enumerated(mul, type(u)(alpha), E(_enumerated(add, u, v))) == (a_u[0] + a_v[0], a_u[1] + a_v[1])
    assert strict > 0
    assert (Interval(1, 2) + Interval(3, 4)) - Interval(3, 4) == Interval(0, 3)
    return verified_range("300 random triples", f"sub-distributivity u(v+w) within uv+uw, strict in {strict} cases; (12.33) exact",
                          compared='printed laws vs endpoint enumeration written in the check: u(v+w) and uv+uw, alpha(u+v) = alpha u + alpha v recomputed from endpoint min/max; commutativity/associativity on exactcagd Interval; (12.33) ([1,2]+[3,4])-[3,4] = [0,3] exactly', reference='enumeration')


@claim(doc="sederberg", section="12.1", ref="(12.8)-(12.10)",
       statement="[p](t) = [p_min(t), p_max(t)] on [0,1]; width = int_0^1 (p_max - p_min) dt = (1/(n+1)) sum (b_k - a_k)")
def interval_polynomial_width():
    from exactcagd.numeric.interval_bezier import interval_polynomial

    rng = random.Random(9)
    for n in range(0, 6):
        for k in range(n + 1):
            assert sympy.integrate(_bern(n, k), (T, 0, 1)) == sympy.Rational(1, n + 1)
        coeffs = [_rand_interval(rng) for _ in range(n + 1)]
        p = interval_polynomial(coeffs)
        for t in (Fraction(0), Fraction(1, 3), Fraction(1)):
            lo = sum(c.lo * math.comb(n, k) * (1 - t) ** (n - k) * t**k for k, c in enumerate(coeffs))
            hi = sum(c.hi * math.comb(n, k) * (1 - t) ** (n - k) * t**k for k, c in enumerate(coeffs))
            box = p.evaluate(t)[0]
            assert (box.lo, box.hi) == (lo, hi)
        assert p.width()[0] == sum(c.hi - c.lo for c in coeffs) / (n + 1)
    return verified_range("degrees 0..5", "integral of each B_k^n is 1/(n+1) (sympy); interval de Casteljau gives [p_min, p_max]",
                          compared='printed (12.8)-(12.10) vs sympy integral of B_k^n over [0,1] (= 1/(n+1)) and vs the bound polynomials p_min, p_max summed in the check (Fraction arithmetic) at t = 0, 1/3, 1; exactcagd width equals the printed sum', reference='sympy')


# ---------------------------------------------------------------------------- 12.2
@claim(doc="sederberg", section="12.2.1-12.2.2", ref="(12.22), (12.24)-(12.26)",
       statement="(1-t)[P0] + t[P1] = (1-t)c0 + t c1 + ((1-t)e0 + t e1)[i] for 0<=t<=1, and "
       "p0(1-t) + p1 t + (e0|1-t| + e1|t|)[i] for all t (cases t<0, t>1 of (12.25))")
def affine_map_centered():
    from exactcagd.numeric.interval import Interval
    from exactcagd.numeric.interval_bezier import affine_map

    rng = random.Random(22)
    for _ in range(300):
        p0, p1 = _rand_interval(rng), _rand_interval(rng)
        t = Fraction(rng.randint(-40, 60), rng.randint(1, 20))
        c0, c1, e0, e1 = p0.midpoint(), p1.midpoint(), p0.radius(), p1.radius()
        radius = e0 * abs(1 - t) + e1 * abs(t)
        printed = (e0 * (1 - t) - e1 * t) if t < 0 else (e0 * (1 - t) + e1 * t) if t <= 1 else (e0 * (t - 1) + e1 * t)
        assert printed == radius  # the three cases of (12.25) are (12.26)
        centre = (1 - t) * c0 + t * c1
        assert affine_map(p0, p1, t) == Interval(centre - radius, centre + radius)
    alpha, beta = Fraction(-3, 2), Fraction(5, 7)
    assert alpha * Interval(-1, 1) + beta * Interval(-1, 1) == (abs(alpha) + abs(beta)) * Interval(-1, 1)  # (12.24)
    return verified_range("300 random interval pairs, t in [-2, 3]", "interval arithmetic result equals the centered form exactly",
                          compared='printed (12.22), (12.24)-(12.26) vs the centred form computed in the check (Fraction arithmetic): the three cases of (12.25) equal e0|1-t| + e1|t|, and exactcagd affine_map equals centre +- radius for 300 random pairs', reference='exact')


@claim(doc="sederberg", section="12.2.2", ref="(12.23), (12.27)-(12.29)",
       statement="[P](t) = center(t) + e(t)[i] on [0,1], = center(t) + e~(t)[i] outside with "
       "e~(t) = sum (-1)^k e_k B_k(t); the interval de Casteljau algorithm computes it")
def centered_interval_curve():
    from exactcagd.numeric.interval_bezier import IntervalBezierCurve

    rng = random.Random(27)
    sign_flips = 0
    for _ in range(60):
        n = rng.randint(0, 6)
        lo = [[Fraction(rng.randint(-50, 50), 4) for _ in range(2)] for _ in range(n + 1)]
        hi = [[a + Fraction(rng.randint(0, 20), 8) for a in row] for row in lo]
        curve = IntervalBezierCurve.from_bounds(lo, hi)
        err = [[(b - a) / 2 for a, b in zip(r, s)] for r, s in zip(lo, hi)]
        for t in (Fraction(-3, 2), Fraction(-1, 5), Fraction(0), Fraction(2, 7), Fraction(1), Fraction(9, 5)):
            basis = [math.comb(n, k) * (1 - t) ** (n - k) * t**k for k in range(n + 1)]
            box = curve.evaluate(t, extrapolate=True)
            for j in range(2):
                brute = [(min(lo[k][j] * b, hi[k][j] * b), max(lo[k][j] * b, hi[k][j] * b)) for k, b in enumerate(basis)]
                assert (box[j].lo, box[j].hi) == (sum(x for x, _ in brute), sum(y for _, y in brute))
                tilde = sum((-1) ** k * err[k][j] * basis[k] for k in range(n + 1))
                radius = box[j].radius()
                if 0 <= t <= 1:
                    assert radius == sum(err[k][j] * basis[k] for k in range(n + 1))
                else:
                    assert abs(tilde) == radius
                    sign_flips += t > 1 and n % 2 == 1 and tilde < 0
    return verified_range(
        "60 random interval curves of degree 0..6, t in {-3/2, -1/5, 0, 2/7, 1, 9/5}",
        "interval de Casteljau = exact set of member-curve points (brute force over endpoints) = centered form; "
        f"(12.28) holds up to sign for t > 1 (e~ = (-1)^n x radius there, negative in {sign_flips} odd-degree cases), "
        "as the notes' remark '(-1)^n [i] = [i]' says",
                          compared='printed (12.23), (12.27)-(12.29) vs brute force in the check: sum over k of the endpoint min/max of P_k B_k(t) (exact set of member-curve points), and the radius vs sum e_k B_k / sum (-1)^k e_k B_k; exactcagd interval de Casteljau equals both', reference='enumeration'
    )


@claim(doc="sederberg", section="12.2.3", ref="error monotonicity, (12.30)-(12.32)",
       statement="the components of e~(t) grow monotonically as t departs from [0,1]; de Casteljau inside [0,1] "
       "does not inflate intervals, outside it does")
def error_monotonicity():
    from exactcagd.numeric.interval_bezier import IntervalBezierCurve

    x = sympy.Symbol("x", nonnegative=True)
    for n in range(1, 8):
        e = sympy.symbols(f"e0:{n + 1}", nonnegative=True)
        left = sympy.Poly(sympy.expand(sum(e[k] * sympy.Abs(_bern(n, k, -x)) for k in range(n + 1))), x)  # t = -x
        right = sympy.Poly(sympy.expand(sum(e[k] * sympy.Abs(_bern(n, k, 1 + x)) for k in range(n + 1))), x)  # t = 1 + x
        for poly in (left, right):
            for coeff in poly.all_coeffs():
                assert all(c >= 0 for c in sympy.Poly(coeff, *e).coeffs())  # non-negative combination of e_k >= 0
    rng = random.Random(31)
    for _ in range(30):
        n = rng.randint(1, 5)
        lo = [[Fraction(rng.randint(-9, 9))] for _ in range(n + 1)]
        curve = IntervalBezierCurve.from_bounds(lo, [[a[0] + Fraction(rng.randint(0, 4), 3)] for a in lo])
        tau, s = Fraction(rng.randint(1, 9), 10), Fraction(rng.randint(0, 10), 10)
        left_piece, _ = curve.subdivide(tau)
        assert left_piece.evaluate(s) == curve.evaluate(tau * s)  # no ballooning inside [0, 1]
    return verified(
        "degrees 1..7 symbolic: sum e_k |B_k(t)| at t = -x and t = 1 + x is a polynomial in x >= 0 with coefficients "
        "that are non-negative combinations of the e_k, hence non-decreasing with all derivatives >= 0; "
        "30 random subdivisions reproduce the boxes exactly",
                    compared='printed monotonicity claim vs sympy: sum e_k |B_k(t)| at t = -x and t = 1 + x expands to a polynomial in x >= 0 with non-negative coefficient combinations of e_k >= 0, degrees 1..7; no inflation inside [0,1] by exact subdivision vs evaluation', reference='sympy'
    )


@claim(doc="sederberg", section="12.2.4", ref="envelope",
       statement="if the center curve progresses NE or SW the upper/lower envelope are the top-left/bottom-right corner "
       "curves (NW/SE: top-right/bottom-left); at a horizontal or vertical tangency straight segments of length "
       "twice the interval error enter the envelope")
def envelope():
    from exactcagd.numeric.interval_bezier import IntervalBezierCurve

    # center (2t(1-t), 2t) has a vertical tangency at t = 1/2; x-errors (0, 0, 1/2), y-errors 1/4
    curve = IntervalBezierCurve.from_centered([[0, 0], [1, 1], [0, 2]], [[0, "1/4"], [0, "1/4"], ["1/2", "1/4"]])
    lower, upper = curve.bound_curves()

    def x_hi(t):
        return upper.evaluate(t)[0]

    def box(t):
        return curve.evaluate(t)

    # 1. the right edge at the center's tangency t = 1/2 is interior to the region (box at t = 9/16 contains it)
    point = (x_hi(Fraction(1, 2)), Fraction(1))
    later = box(Fraction(9, 16))
    assert later[0].lo < point[0] < later[0].hi and later[1].lo < point[1] < later[1].hi
    # 2. the right edge at the stationary point of x_hi (t* = 2/3, global maximum) is on the boundary
    stationary = [(r, j, side) for r, j, side in curve.stationary_parameters() if j == 0 and side == "hi"]
    assert len(stationary) == 1 and stationary[0][0] == Fraction(2, 3)
    x_max = x_hi(Fraction(2, 3))
    assert all(x_hi(Fraction(k, 300)) <= x_max for k in range(301))
    assert all(c <= x_max for c in upper.subdivide(Fraction(2, 3))[0].points_array()[:, 0])  # hull: max on [0, 2/3]
    assert all(c <= x_max for c in upper.subdivide(Fraction(2, 3))[1].points_array()[:, 0])  # and on [2/3, 1]
    # 3. at t = 7/12 the center moves NW, yet the bottom-right corner curve bounds the region:
    #    x_hi' = 2 - 3t > 0 on [0, 7/12] and y_lo' = 2 > 0, so no box reaches right of/below that corner
    t0 = Fraction(7, 12)
    centre_velocity = curve.center_curve().derivative().evaluate(t0)
    assert centre_velocity[0] < 0 < centre_velocity[1]  # NW
    hodo_hi = upper.derivative()
    assert hodo_hi.evaluate(0)[0] > 0 and hodo_hi.evaluate(t0)[0] > 0  # linear: positive on [0, 7/12]
    assert lower.derivative().evaluate(t0)[1] > 0 and lower.derivative().degree == 1
    def right_edge_on_boundary(tstar):
        # a box edge belongs to the envelope only if no other box reaches beyond it
        later_ = box(Fraction(9, 16))
        px_ = x_hi(tstar)
        inside = later_[0].lo < px_ < later_[0].hi and later_[1].lo < Fraction(2) * tstar < later_[1].hi
        return None if not inside and all(x_hi(Fraction(k, 300)) <= px_ for k in range(301)) else f"the right edge at t = {tstar} lies inside the box at t = 9/16"
    return erratum(
        printed="corner curves chosen by the direction of the center curve; segments at horizontal/vertical "
        "tangencies of the center curve",
        corrected="a corner curve bounds the region where its own bound coordinates move outward (signs of "
        "x_lo', x_hi', y_lo', y_hi'); straight segments (box edges, length 2 e(t)) can only occur at stationary "
        "points of a bound coordinate x_lo, x_hi, y_lo, y_hi, plus the end boxes t = 0 and t = 1; "
        "this coincides with the printed rule when the error curve is stationary",
        detail="exact example: center (2t(1-t), 2t), x-errors (0, 0, 1/2), y-error 1/4. The right edge at the "
        "center's vertical tangency t = 1/2 lies inside the box at t = 9/16; the right edge at t* = 2/3 "
        "(x_hi' = 0, found exactly by stationary_parameters) is the global maximum of x_hi; at t = 7/12 the center "
        "moves NW while the bottom-right corner curve (moving NE) bounds the region",
        printed_form=Fraction(1, 2), corrected_form=Fraction(2, 3), check=L.predicate(right_edge_on_boundary), reference='exact',
    )


@claim(doc="sederberg", section="12.2.5", ref="interval hodograph",
       statement="the hodograph control boxes n([P_{k+1}] - [P_k]) bound P'(t) for every curve with fixed P_k in [P_k]")
def interval_hodograph():
    from exactcagd.numeric.interval_bezier import IntervalBezierCurve

    rng = random.Random(25)
    for _ in range(20):
        n = rng.randint(1, 6)
        lo = [[Fraction(rng.randint(-20, 20), 3) for _ in range(2)] for _ in range(n + 1)]
        hi = [[a + Fraction(rng.randint(0, 9), 4) for a in row] for row in lo]
        curve = IntervalBezierCurve.from_bounds(lo, hi)
        member = [[a + Fraction(rng.randint(0, 10), 10) * (b - a) for a, b in zip(r, s)] for r, s in zip(lo, hi)]
        t = Fraction(rng.randint(0, 12), 12)
        deriv = [sympy.diff(sum(sympy.Rational(member[k][j]) * _bern(n, k) for k in range(n + 1)), T).subs(T, sympy.Rational(t))
                 for j in range(2)]
        box = curve.hodograph().evaluate(t)
        assert all(b.contains(Fraction(int(d.p), int(d.q))) for b, d in zip(box, deriv))
    return verified_range("20 random interval curves and member curves", "derivative by sympy differentiation; "
                          "the 'moving control point' caveat of the notes is a remark, not checked",
                          compared='printed hodograph boxes (exactcagd) vs the derivative of a random member curve by sympy differentiation: the box contains it, 20 random curves', reference='sympy')


# ---------------------------------------------------------------------------- 12.3-12.4
@claim(doc="sederberg", section="12.3.1", ref="(12.40)-(12.43), (12.69), (12.74)",
       statement="f(t) in F_n(t) + [f^(n+1)]/(n+1)! prod (t - t_k), expressible as an interval polynomial of degree n+1 "
       "in Bernstein form; derivative bounds from the hull of n!/(n-r)! Delta^r p_k")
def lagrange_remainder():
    from exactcagd import BezierCurve
    from exactcagd.numeric.interval_bezier import derivative_bounds, lagrange_interval

    rng = random.Random(40)
    for _ in range(12):
        n = rng.randint(1, 8)
        curve = BezierCurve([[Fraction(rng.randint(-30, 30), 7) for _ in range(2)] for _ in range(n + 1)])
        nodes = sorted({Fraction(rng.randint(0, 20), 20) for _ in range(rng.randint(1, 4))})
        approx = lagrange_interval(curve, nodes)
        for k in range(21):
            t = Fraction(k, 20)
            assert approx.contains_point(t, curve.evaluate(t))
        r = min(len(nodes), n)
        bounds = derivative_bounds(curve, r)
        expr = curve.to_sympy(T)
        for k in range(0, 11, 2):
            values = [sympy.diff(expr[j], T, r).subs(T, sympy.Rational(k, 10)) for j in range(2)]
            assert all(b.contains(Fraction(int(v.p), int(v.q))) for b, v in zip(bounds, values))
    return verified_range("12 random polynomial plane curves of degree 1..8 with 1..4 nodes, 21 parameters each",
                          "exact containment of the curve in the interval curve; derivative bounds vs sympy",
                          compared='printed (12.40)-(12.43) enclosure (exactcagd lagrange_interval) vs the exact curve values at 21 parameters; printed derivative bounds (12.69) vs sympy r-th derivatives at 6 parameters', reference='sympy')


@claim(doc="sederberg", section="12.3.2", ref="(12.57)-(12.60)",
       statement="f(t) in F_1(t) - [f'']/2 t(1-t) = sum [F_2k] B_k^2 with [F_21] = (2f0 + 2f1 - [f''])/4; "
       "F_2min uses f''_max, F_2max uses f''_min")
def linear_hermite():
    from exactcagd.numeric.interval import Interval
    from exactcagd.numeric.interval_bezier import hermite_interval_from_data

    f0, f1, d = sympy.symbols("f0 f1 d")
    lhs = f0 * (1 - T) + f1 * T - d / 2 * T * (1 - T)
    rhs = f0 * _bern(2, 0) + (2 * f0 + 2 * f1 - d) / 4 * _bern(2, 1) + f1 * _bern(2, 2)
    assert sympy.expand(lhs - rhs) == 0
    approx = hermite_interval_from_data([3], [-1], Interval(-4, 6))
    middle = approx.control_boxes[1][0]
    assert middle == Interval(Fraction(2 * 3 + 2 * -1 - 6, 4), Fraction(2 * 3 + 2 * -1 + 4, 4))  # min uses f''_max
    return verified("symbolic identity (sympy); hermite_interval_from_data reproduces (12.59)/(12.60)",
                    compared="printed (12.57)-(12.60) vs sympy expansion of the linear Hermite remainder in Bernstein form; printed [F_21] endpoints (min uses f''_max) vs exactcagd hermite_interval_from_data", reference='sympy')


@claim(doc="sederberg", section="12.3.2", ref="(12.61)-(12.63)",
       statement="cubic Hermite: F_3 = f0 B0 + (3f0+f0')/3 B1 + (3f1-f1')/3 B2 + f1 B3; f in F_3 + [f4]/24 t^2(t-1)^2 = "
       "sum [F_4k] B_k^4 with F_41 = f0 + f0'/4, F_42 = (f0+f1)/2 + (f0'-f1')/6 + [f4]/144, F_43 = f1 - f1'/4")
def cubic_hermite():
    from exactcagd.numeric.interval import Interval
    from exactcagd.numeric.interval_bezier import hermite_interval_from_data

    f0, f1, d0, d1, D = sympy.symbols("f0 f1 d0 d1 D")
    F3 = f0 * _bern(3, 0) + (3 * f0 + d0) / 3 * _bern(3, 1) + (3 * f1 - d1) / 3 * _bern(3, 2) + f1 * _bern(3, 3)
    assert [sympy.simplify(x) for x in (F3.subs(T, 0) - f0, sympy.diff(F3, T).subs(T, 0) - d0,
                                        F3.subs(T, 1) - f1, sympy.diff(F3, T).subs(T, 1) - d1)] == [0, 0, 0, 0]
    F4 = (f0 * _bern(4, 0) + (f0 + d0 / 4) * _bern(4, 1) + ((f0 + f1) / 2 + (d0 - d1) / 6 + D / 144) * _bern(4, 2)
          + (f1 - d1 / 4) * _bern(4, 3) + f1 * _bern(4, 4))
    assert sympy.expand(F3 + D / 24 * T**2 * (T - 1) ** 2 - F4) == 0
    rng = random.Random(61)
    for _ in range(20):
        a, b, c, e = (Fraction(rng.randint(-20, 20), rng.randint(1, 6)) for _ in range(4))
        bound = _rand_interval(rng)
        boxes = [x[0] for x in hermite_interval_from_data([a, c], [b, e], bound).control_boxes]
        assert boxes[1] == Interval(a + c / 4) and boxes[3] == Interval(b - e / 4)
        assert boxes[2] == (a + b) / 2 + (c - e) / 6 + bound / 144
    return verified("Hermite conditions and the quartic identity symbolically (sympy); 20 random exact instances "
                    "of hermite_interval_from_data equal (12.63)",
                    compared='printed F_3 vs the four Hermite conditions by sympy substitution/differentiation; printed F_4 vs sympy expansion of F_3 + [f4]/24 t^2(t-1)^2; 20 random instances of exactcagd hermite_interval_from_data vs the printed (12.63)', reference='sympy')


@claim(doc="sederberg", section="12.3.2", ref="(12.64)",
       statement="symmetric Hermite of odd degree n: only the middle coefficient of [F_{n+1}] has width, "
       "(f_max^(n+1) - f_min^(n+1)) / ((n+1) n ... (n+3)/2)^2")
def hermite_middle_width():
    from exactcagd.numeric.interval import Interval
    from exactcagd.numeric.interval_bezier import hermite_interval_from_data

    for n in range(1, 12, 2):
        m = (n + 1) // 2
        # t^m (t-1)^m / (n+1)! = (-1)^m B_m^{2m} / (C(2m, m) (n+1)!)
        assert sympy.expand(T**m * (T - 1) ** m - (-1) ** m * _bern(2 * m, m) / sympy.binomial(2 * m, m)) == 0
        denominator = math.prod(range((n + 3) // 2, n + 2)) ** 2
        assert denominator == math.factorial(n + 1) * math.comb(n + 1, m)
        approx = hermite_interval_from_data([0] * m, [0] * m, Interval(-1, 2))
        widths = [b[0].width() for b in approx.control_boxes]
        assert widths == [0] * m + [Fraction(3, denominator)] + [0] * m
    return verified_range("odd n = 1..11", "symbolic factorization of the remainder and the interval curve's widths",
                          compared='printed (12.64) vs sympy: t^m (t-1)^m = (-1)^m B_m^(2m)/C(2m,m) (expand) and the printed denominator = (n+1)! C(n+1, m); exactcagd widths vs that value, odd n = 1..11', reference='sympy')


def _exp_example():
    from mpmath import iv

    from exactcagd.numeric.interval_bezier import hermite_interval_from_data

    iv.prec = 120
    e = _iv_interval(iv.e)
    return hermite_interval_from_data([1, 1], [e, e], e.hull(1)), e


@claim(doc="sederberg", section="12.3.2", ref="Example 1, (12.65)",
       statement="f = e^t: [F_41] = 5/4, [F_42] = [97+48e, 96+49e]/144 ~ [1.5797, 1.5916], [F_43] = 3e/4; "
       "width (e-1)/720 ~ 0.0024; bounds deviate by no more than 1 per cent")
def example_exp():
    from mpmath import iv

    from exactcagd.numeric.interval import Interval

    E = sympy.E
    mid_lo = (1 + E) / 2 + (1 - E) / 6 + 1 / sympy.Integer(144)
    mid_hi = (1 + E) / 2 + (1 - E) / 6 + E / 144
    assert sympy.simplify(mid_lo - (97 + 48 * E) / 144) == 0 and sympy.simplify(mid_hi - (96 + 49 * E) / 144) == 0
    assert round(float(mid_lo), 4) == 1.5797 and round(float(mid_hi), 4) == 1.5916
    width = (mid_hi - mid_lo) / 5
    assert sympy.simplify(width - (E - 1) / 720) == 0 and round(float(width), 4) == 0.0024
    approx, e = _exp_example()
    boxes = [b[0] for b in approx.control_boxes]
    assert boxes[1] == Interval(Fraction(5, 4))
    assert Interval("2.0387113713", "2.0387113714").contains(boxes[3])  # 3e/4 = 2.03871137138...
    assert Interval("1.57970", "1.57971").contains(boxes[2].lo) and Interval("1.59163", "1.59164").contains(boxes[2].hi)
    worst = Fraction(0)
    for k in range(1, 40):
        t = Fraction(k, 40)
        value = _iv_interval(iv.exp(_iv_of(t)))
        box = approx.evaluate(t)[0]
        assert box.contains(value)
        worst = max(worst, box.width() / value.lo)
    assert worst < Fraction(1, 100)
    return verified(f"symbolic (sympy, exact e); containment of e^t (mpmath interval enclosures) at 39 interior parameters; "
                    f"largest relative width {float(worst):.4f} < 1%",
                    compared="printed (12.65) values vs sympy with exact e (simplify) and rounding to the printed digits; containment of e^t (mpmath interval enclosures, converted exactly) in exactcagd's interval curve at 39 parameters; relative width < 1%", reference='mpmath')


@claim(doc="sederberg", section="12.3.2", ref="Example 2, (12.66)",
       statement="f = sin(pi t/2): [F_41] = pi/8, [F_42] = [192(6+pi), 192(6+pi)+pi^4]/2304 ~ [0.7618, 0.8041], "
       "[F_43] = [F_44] = 1; width pi^4/11520 ~ 0.0085")
def example_sin():
    from mpmath import iv

    from exactcagd.numeric.interval import Interval
    from exactcagd.numeric.interval_bezier import hermite_interval_from_data

    P = sympy.pi
    lo = sympy.Rational(1, 2) + (P / 2) / 6
    hi = lo + P**4 / 16 / 144
    assert sympy.simplify(lo - 192 * (6 + P) / 2304) == 0 and sympy.simplify(hi - (192 * (6 + P) + P**4) / 2304) == 0
    assert (round(float(lo), 4), round(float(hi), 4)) == (0.7618, 0.8041)
    assert sympy.simplify((hi - lo) / 5 - P**4 / 11520) == 0 and round(float(P**4 / 11520), 4) == 0.0085
    iv.prec = 120
    pi = _iv_interval(iv.pi)
    approx = hermite_interval_from_data([0, pi / 2], [1, 0], Interval(0, 0).hull(pi**4 / 16))
    boxes = [b[0] for b in approx.control_boxes]
    assert Interval("0.3926990816", "0.3926990817").contains(boxes[1]) and boxes[3] == Interval(1) == boxes[4]
    assert approx.evaluate(0)[0] == Interval(0) and approx.evaluate(1)[0] == Interval(1)  # sin 0, sin pi/2
    for k in range(1, 40):
        t = Fraction(k, 40)
        value = _iv_interval(iv.sin(iv.pi * _iv_of(t) / 2))
        assert approx.evaluate(t)[0].contains(value)
    return verified("symbolic (sympy, exact pi); containment of sin(pi t/2) (mpmath interval enclosures) at 39 "
                    "interior parameters, exact values at t = 0, 1",
                    compared="printed (12.66) values vs sympy with exact pi and rounding to the printed digits; containment of sin(pi t/2) (mpmath interval enclosures, converted exactly) in exactcagd's interval curve at 39 parameters and exact end values", reference='mpmath')


@claim(doc="sederberg", section="12.4", ref="Example 3, (12.76)-(12.79)",
       statement="quarter circle (cos pi t/2, sin pi t/2) as quartic interval Bezier with the coefficients of "
       "'equation (12.67)': [P41] = (1, pi/8), [P42] = ([0.7618, 0.8041], [0.7618, 0.8041]), [P43] = (pi/8, 1); "
       "(12.76) [P](t) = sum [P_4k] B_k^n(t); largest error at t = 0.5: 6 (0.8041-0.7618)/2 (1/2)^4 = 0.0079")
def example_quarter_circle():
    from mpmath import iv

    from exactcagd.numeric.interval import Interval
    from exactcagd.numeric.interval_bezier import hermite_interval_from_data

    iv.prec = 120
    pi = _iv_interval(iv.pi)
    d4 = Interval(0).hull(pi**4 / 16)  # x'''' = (pi/2)^4 cos, y'''' = (pi/2)^4 sin, both in [0, pi^4/16]
    approx = hermite_interval_from_data([(1, 0), (0, pi / 2)], [(0, 1), (-(pi / 2), 0)], (d4, d4))
    boxes = approx.control_boxes
    assert boxes[1][0] == Interval(1) and boxes[3][1] == Interval(1)
    pi_8 = Interval("0.3926990816", "0.3926990817")
    assert pi_8.contains(boxes[1][1]) and pi_8.contains(boxes[3][0]) and boxes[1][1] == boxes[3][0]
    for j in range(2):
        assert (round(float(boxes[2][j].lo), 4), round(float(boxes[2][j].hi), 4)) == (0.7618, 0.8041)
    assert approx.evaluate(0) == (Interval(1), Interval(0)) and approx.evaluate(1) == (Interval(0), Interval(1))
    for k in range(1, 40):
        t = Fraction(k, 40)
        x = _iv_interval(iv.cos(iv.pi * _iv_of(t) / 2))
        y = _iv_interval(iv.sin(iv.pi * _iv_of(t) / 2))
        box = approx.evaluate(t)
        assert box[0].contains(x) and box[1].contains(y)
    bound = 6 * (boxes[2][0].hi - boxes[2][0].lo) / 2 / 16
    assert round(float(bound), 4) == 0.0079
    assert sympy.simplify(6 * (sympy.pi**4 / 2304) / 2 / 16 - sympy.pi**4 / 12288) == 0
    def basis_degree(deg):
        return None if deg == len(boxes) - 1 else f"B_k^{deg} with {len(boxes)} coefficients"
    return erratum(
        printed="coefficients 'expressed in equation (12.67)'; (12.76) with basis B_k^n(t)",
        corrected="the coefficients are those of (12.77) (with [P^(4)] = [0, pi^4/16] per coordinate); the basis of "
        "(12.76) is B_k^4(t)",
        detail="values (12.78) reproduced with exact pi enclosures; the quarter circle lies in the interval curve at "
        "39 interior parameters (mpmath interval enclosures, exact comparison) and exactly at t = 0, 1; the bound of (12.79) is pi^4/12288 ~ 0.0079",
        printed_form='n', corrected_form=4, check=L.predicate(basis_degree), reference='text',
    )
