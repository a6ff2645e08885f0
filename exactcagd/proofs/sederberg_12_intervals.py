"""Sederberg's notes, 12.1-12.2.1: interval arithmetic, interval polynomials and interval Bézier
curves, eqs. (12.1)-(12.21).  Checks by exact rational enumeration and sympy (no package code)."""

from __future__ import annotations

import itertools
import random
from fractions import Fraction as Fr

import sympy as sp

from exactcagd.proofs._ledger import claim, verified, verified_range

DOC = "sederberg"
t = sp.Symbol("t")


def _rand_interval(rng):
    a, b = sorted(Fr(rng.randint(-12, 12), rng.randint(1, 4)) for _ in range(2))
    return a, b


def _sampled(op, u, v, k=6):
    """{x op y} at a grid including the end points (bilinear/monotone ops attain their extremes there)."""
    xs = [u[0] + (u[1] - u[0]) * Fr(i, k) for i in range(k + 1)]
    ys = [v[0] + (v[1] - v[0]) * Fr(i, k) for i in range(k + 1)]
    vals = [op(x, y) for x, y in itertools.product(xs, ys)]
    return min(vals), max(vals)


@claim(doc=DOC, section="12.1", ref="(12.1)-(12.10)", covers=["§12.1"],
       statement="[a,b] * [c,d] = {x * y}: sums [a+c, b+d], differences [a-d, b-c], products [min, max of ac, ad, bc, bd], quotients [a,b][1/d, 1/c]; scalars distribute (12.5), intervals not; [p](t) = [p_min(t), p_max(t)]; width = sum (b_k - a_k)/(n+1)")
def interval_arithmetic():
    rng = random.Random(121)
    count = 0
    for _ in range(40):
        u, v = _rand_interval(rng), _rand_interval(rng)
        (a, b), (c, d) = u, v
        assert _sampled(lambda x, y: x + y, u, v) == (a + c, b + d)
        assert _sampled(lambda x, y: x - y, u, v) == (a - d, b - c)
        assert _sampled(lambda x, y: x * y, u, v) == (min(a * c, a * d, b * c, b * d), max(a * c, a * d, b * c, b * d))
        if c > 0 or d < 0:
            q = (min(a / d, a / c, b / d, b / c), max(a / d, a / c, b / d, b / c))
            assert _sampled(lambda x, y: x / y, u, v) == q  # = [a, b] * [1/d, 1/c]
        count += 1
    mul = lambda u, v: (min(x * y for x in u for y in v), max(x * y for x in u for y in v))  # noqa: E731
    add = lambda u, v: (u[0] + v[0], u[1] + v[1])  # noqa: E731
    u, v, w = (Fr(-1), Fr(2)), (Fr(1), Fr(3)), (Fr(-2), Fr(1))
    assert mul(u, add(v, w)) != add(mul(u, v), mul(u, w))  # no distributivity for an interval factor
    assert (u[0] - u[1], u[1] - u[0]) != (0, 0)  # [u] - [u] != 0
    alpha = Fr(-3, 2)
    scale = lambda s, i: tuple(sorted((s * i[0], s * i[1])))  # noqa: E731
    assert scale(alpha, add(v, w)) == add(scale(alpha, v), scale(alpha, w))  # (12.5)
    # (12.8)-(12.10): Bernstein basis >= 0 on [0, 1], integral 1/(n+1)
    for n in (2, 3, 5):
        B = [sp.binomial(n, k) * t**k * (1 - t) ** (n - k) for k in range(n + 1)]
        assert all(sp.integrate(Bk, (t, 0, 1)) == sp.Rational(1, n + 1) for Bk in B)
        lo = [sp.Rational(rng.randint(-9, 9)) for _ in range(n + 1)]
        hi = [x + sp.Rational(rng.randint(0, 5), 2) for x in lo]
        assert sp.integrate(sum((h - l) * Bk for h, l, Bk in zip(hi, lo, B)), (t, 0, 1)) == sum(h - l for h, l in zip(hi, lo)) / (n + 1)
    return verified_range(f"{count} random rational interval pairs (exact extremes over a grid with the end points)",
                          "(12.3) for +, -, *, / (denominators without 0); (12.5) for a scalar; distributivity fails for an interval factor; (12.10) by sympy integration",
                          compared="printed (12.3), (12.5), (12.10) vs exact evaluation of the set definition (12.2)", reference="exact")


@claim(doc=DOC, section="12.2", ref="(12.11)-(12.21)", covers=["§12.2", "§12.2.1", "(12.34)"],
       statement="boxes add componentwise (12.13); a Bezier curve with control points in [P_k] lies in [P](t) = sum [P_k] B_k; the affine map of intervals, de Casteljau (12.19) with sides (12.20) giving the subdivided curves; centered form [P_k] = center + e_k [-1, 1] (12.21)")
def interval_bezier_curves():
    rng = random.Random(1211)
    # (12.13): Minkowski sum of boxes = box of the sums (corners attain the extremes)
    for _ in range(10):
        p1 = (_rand_interval(rng), _rand_interval(rng))
        p2 = (_rand_interval(rng), _rand_interval(rng))
        corners = [(x1 + x2, y1 + y2) for x1 in p1[0] for y1 in p1[1] for x2 in p2[0] for y2 in p2[1]]
        assert (min(c[0] for c in corners), max(c[0] for c in corners)) == (p1[0][0] + p2[0][0], p1[0][1] + p2[0][1])
    # (12.15): every curve with P_k in [P_k] lies in [P](t); (12.19), (12.20) subdivide
    n = 3
    boxes = [(_rand_interval(rng), _rand_interval(rng)) for _ in range(n + 1)]
    B = lambda k, s: sp.binomial(n, k) * s**k * (1 - s) ** (n - k)  # noqa: E731
    for _ in range(20):
        pts = [tuple(iv[0] + (iv[1] - iv[0]) * Fr(rng.randint(0, 8), 8) for iv in box) for box in boxes]
        for s in (Fr(1, 5), Fr(1, 2), Fr(4, 5)):
            for j in range(2):
                val = sum(Fr(int(sp.numer(B(k, sp.Rational(s.numerator, s.denominator)))), int(sp.denom(B(k, sp.Rational(s.numerator, s.denominator))))) * pts[k][j] for k in range(n + 1))
                lo = sum(Fr(int(sp.numer(B(k, sp.Rational(s.numerator, s.denominator)))), int(sp.denom(B(k, sp.Rational(s.numerator, s.denominator))))) * boxes[k][j][0] for k in range(n + 1))
                hi = sum(Fr(int(sp.numer(B(k, sp.Rational(s.numerator, s.denominator)))), int(sp.denom(B(k, sp.Rational(s.numerator, s.denominator))))) * boxes[k][j][1] for k in range(n + 1))
                assert lo <= val <= hi
    P = [sp.Matrix(sp.symbols(f"x{k} y{k}")) for k in range(n + 1)]
    tau = sp.Symbol("tau")
    tri = {(k, 0): P[k] for k in range(n + 1)}
    for r in range(n):
        for k in range(r + 1, n + 1):
            tri[(k, r + 1)] = (1 - tau) * tri[(k - 1, r)] + tau * tri[(k, r)]  # (12.19)
    curve = sum((B(k, t) * P[k] for k in range(n + 1)), sp.zeros(2, 1))
    assert (tri[(n, n)] - curve.subs(t, tau)).applyfunc(sp.expand) == sp.zeros(2, 1)
    left = [tri[(k, k)] for k in range(n + 1)]  # P_0^(0), P_1^(1), ..., P_n^(n)
    right = [tri[(n, n - k)] for k in range(n + 1)]  # P_n^(n), ..., P_n^(0)
    assert (sum((B(k, t) * left[k] for k in range(n + 1)), sp.zeros(2, 1)) - curve.subs(t, tau * t)).applyfunc(sp.expand) == sp.zeros(2, 1)
    assert (sum((B(k, t) * right[k] for k in range(n + 1)), sp.zeros(2, 1)) - curve.subs(t, tau + (1 - tau) * t)).applyfunc(sp.expand) == sp.zeros(2, 1)
    # (12.17): for t in [0, 1] the affine map of [a,b], [c,d] is [(1-t)a + tc, (1-t)b + td], width between the two widths
    for _ in range(10):
        (a, b), (c, d) = _rand_interval(rng), _rand_interval(rng)
        s = Fr(rng.randint(0, 10), 10)
        got = _sampled(lambda x, y: (1 - s) * x + s * y, (a, b), (c, d))
        assert got == ((1 - s) * a + s * c, (1 - s) * b + s * d)
        assert min(b - a, d - c) <= got[1] - got[0] <= max(b - a, d - c)
    # (12.21): centered form reproduces the box
    for box in boxes:
        centre = [(iv[0] + iv[1]) / 2 for iv in box]
        e = [(iv[1] - iv[0]) / 2 for iv in box]
        assert all(e_ >= 0 for e_ in e) and [(c_ - e_, c_ + e_) for c_, e_ in zip(centre, e)] == [tuple(iv) for iv in box]
    return verified("random rational boxes and curves: (12.13), containment of every curve with P_k in [P_k], the de Casteljau array (12.19) "
                    "and its sides (12.20) as subdivisions (symbolic, sympy), (12.17) for t in [0, 1], centred form (12.21)",
                    compared="printed (12.13)-(12.21) vs exact evaluation and sympy expansion", reference="sympy")
