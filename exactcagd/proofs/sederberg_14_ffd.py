"""Ledger: Sederberg's notes (003) chapter 14, free-form deformation (2-D).

The construction itself lives in :mod:`exactcagd.composition.ffd`; the claims here check
the notes' statements (14.1)-(14.3) and the deformed-line rule of 14.0.1 against sympy
substitution into (14.2).
"""

from __future__ import annotations

import random

import numpy as np
import sympy as sp
from gmpy2 import mpq

from exactcagd import BezierCurve, BezierSurface
from exactcagd.composition import ffd
from exactcagd.composition.ffd import identity_lattice
from exactcagd.exact import bernstein as bz
from exactcagd.proofs._ledger import claim, verified_range

S, T = sp.symbols("s t")


def _R(x):
    return sp.Rational(int(x.numerator), int(x.denominator))


def _lattice(rng, m, n, rational):
    """A displaced (m, n) lattice over [0,1]^2 (m + 1 columns in s, n + 1 rows in t)."""
    net = [[[mpq(i, m) + mpq(rng.randint(-9, 9), 40), mpq(j, n) + mpq(rng.randint(-9, 9), 40)] for j in range(n + 1)] for i in range(m + 1)]
    w = [[mpq(rng.randint(1, 4), rng.randint(1, 2)) for _ in range(n + 1)] for _ in range(m + 1)] if rational else None
    return BezierSurface(net, w)


def _sym_ffd(lattice, projected=True):
    """(14.2) in sympy: X(s, t) = sum B_i^m(s) B_j^n(t) w_ij (x_ij, y_ij, 1), projected."""
    m, n = lattice.degree
    H = lattice.homogeneous()
    B = lambda k, i, x: sp.binomial(k, i) * x**i * (1 - x) ** (k - i)  # noqa: E731
    X, Y, W = (sum(_R(H[i, j, c]) * B(m, i, S) * B(n, j, T) for i in range(m + 1) for j in range(n + 1)) for c in range(3))
    return (X / W, Y / W) if projected else (X, Y, W)


def _sym_curve(curve, u):
    n = curve.degree
    H = curve.homogeneous()
    B = lambda i: sp.binomial(n, i) * u**i * (1 - u) ** (n - i)  # noqa: E731
    X, Y, W = (sum(_R(H[i, c]) * B(i) for i in range(n + 1)) for c in range(3))
    return X / W, Y / W


@claim(doc="sederberg", section="14", ref="(14.1)-(14.3)",
       statement="with unit weights and the rectangular lattice P_ij = (X_min + i/m (X_max - X_min), Y_min + j/n (Y_max - Y_min)) FFD is the identity")
def identity():
    rng = random.Random(14)
    region = ((mpq(-2), mpq(1)), (mpq(3), mpq(7, 2)))
    for m, n in ((1, 1), (2, 3), (3, 2), (4, 4)):
        lattice = identity_lattice(m, n, region)
        X, Y, W = _sym_ffd(lattice, projected=False)
        x, y = sp.symbols("x y")
        s_of = (x - _R(region[0][0])) / (_R(region[1][0]) - _R(region[0][0]))  # (14.1)
        t_of = (y - _R(region[0][1])) / (_R(region[1][1]) - _R(region[0][1]))
        X, Y, W = (sp.Poly(e, S, T).as_expr().subs({S: s_of, T: t_of}) for e in (X, Y, W))
        assert sp.Poly(X - x * W, x, y).is_zero and sp.Poly(Y - y * W, x, y).is_zero
        curve = BezierCurve([[mpq(rng.randint(-19, 29), 10), mpq(rng.randint(11, 34), 10)] for _ in range(3)])
        assert ffd(lattice, curve, region).reduce().same_curve(curve)
    return verified_range("degrees (1,1), (2,3), (3,2), (4,4) over [-2,3] x [1,7/2]",
                          "sympy: the composed map x -> (14.1) -> (14.2) is the identity; a quadratic comes back exactly",
        compared='printed (14.1)-(14.3) identity claim vs the sympy composition (14.1) into (14.2): X - xW and Y - yW vanish as polynomials in x, y',
        reference='sympy')


@claim(doc="sederberg", section="14.0.1", ref="deformed lines",
       statement="a vertical line s = .6 maps to the degree-n Bézier curve with control points H_0(.6), ..., H_n(.6) (H_j: row j of the lattice); "
       "a horizontal line t = .3 maps to the degree-m curve with control points V_0(.3), ..., V_m(.3) (V_i: column i)")
def deformed_lines():
    rng = random.Random(1401)
    u = sp.Symbol("u")
    for m, n, rational in ((3, 2, False), (3, 2, True), (2, 4, True)):
        lattice = _lattice(rng, m, n, rational)
        Xs, Ys = _sym_ffd(lattice)
        H = lattice.homogeneous()
        s0, t0 = mpq(3, 5), mpq(3, 10)
        # rows H_j(s) are curves in s through P_{0j}..P_{mj}; their homogeneous values at s0 are the new control points
        rows = BezierCurve.from_homogeneous(np.stack([bz.de_casteljau(H[:, j], s0) for j in range(n + 1)]))
        cols = BezierCurve.from_homogeneous(np.stack([bz.de_casteljau(H[i, :], t0) for i in range(m + 1)]))
        assert rows.degree == n and cols.degree == m
        vertical = ffd(lattice, BezierCurve([[s0, 0], [s0, 1]]))
        horizontal = ffd(lattice, BezierCurve([[0, t0], [1, t0]]))
        assert vertical.same_curve(rows) and horizontal.same_curve(cols)
        for (cx, cy), (ex, ey) in ((_sym_curve(rows, u), (Xs.subs({S: _R(s0), T: u}), Ys.subs({S: _R(s0), T: u}))),
                                   (_sym_curve(cols, u), (Xs.subs({S: u, T: _R(t0)}), Ys.subs({S: u, T: _R(t0)})))):
            assert sp.cancel(cx - ex) == 0 and sp.cancel(cy - ey) == 0
    return verified_range("lattices of degree (3,2) as in Figures 14.6-14.9 (polynomial and rational) and (2,4)",
                          "the control points H_j(.6), V_i(.3) (homogeneous de Casteljau along rows / columns) give exactly the "
                          "sympy image of the line under (14.2); exactcagd's ffd returns the same curve",
        compared='printed 14.0.1 control points H_j(.6), V_i(.3) vs the sympy image of the lines s = .6, t = .3 under (14.2)',
        reference='sympy')


@claim(doc="sederberg", section="14", ref="Figure 14.5", statement="points outside of the rectangle are not moved; freezing rows of control points controls the continuity between deformed and undeformed portions")
def continuity_control():
    checked = 0
    line = BezierCurve([[mpq(-1, 2), mpq(1, 2)], [mpq(3, 2), mpq(1, 2)]])  # crosses the region boundary at t = 1/4, 3/4
    for n in (3, 4, 5):
        for frozen in (1, 2):
            net = [[[mpq(i, n), mpq(j, n)] for j in range(n + 1)] for i in range(n + 1)]
            for i in range(frozen, n - frozen + 1):
                for j in range(frozen, n - frozen + 1):
                    net[i][j] = [net[i][j][0] + mpq(1, 7 + i), net[i][j][1] - mpq(1, 5 + j)]
            result = ffd(BezierSurface(net), line, outside="keep")
            u = sp.Symbol("u")
            deformed = [sp.expand(x) for x in result.pieces[1].curve.to_sympy(u)]  # the moved piece, global parameter
            undeformed = [sp.expand(x) for x in line.to_sympy(u)]
            for t in (sp.Rational(1, 4), sp.Rational(3, 4)):
                assert [x.subs(u, t) for x in deformed] == [x.subs(u, t) for x in undeformed]  # C0 at the region boundary
                same_tangent = [x.diff(u).subs(u, t) for x in deformed] == [x.diff(u).subs(u, t) for x in undeformed]
                assert same_tangent == (frozen >= 2), (n, frozen, t)
            for t in (mpq(1, 10), mpq(9, 10)):
                assert result.evaluate(t) == line.evaluate(t)  # outside: not moved
            checked += 1
    return verified_range("lattices of degree n x n, n = 3, 4, 5, with 1 or 2 frozen outer rows/columns, interior points displaced",
                          f"exact split at the boundary (ffd outside='keep'); 1 frozen row: C0 but not C1; 2 frozen rows: C1 ({checked} cases)",
        compared='printed Figure 14.5 claims (outside points fixed; frozen rows give C0 / C1) vs the undeformed line: sympy values and first derivatives of the moved piece at the region boundary t = 1/4, 3/4, exact points outside',
        reference='sympy')
