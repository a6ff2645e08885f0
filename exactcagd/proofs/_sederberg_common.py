"""Small helpers shared by the ``sederberg_*`` proof modules (not a proof module itself).

The checks compute with exactcagd and compare against an independent sympy
computation of the printed formula; these helpers only convert between the two.
"""

from __future__ import annotations

import random

import numpy as np
import sympy as sp
from gmpy2 import mpq

t_, s_, u_, v_ = sp.symbols("t s u v")


def Rs(x) -> sp.Rational:
    """mpq / int / Fraction -> sympy Rational (exact)."""
    if isinstance(x, sp.Rational):
        return x
    return sp.Rational(int(x.numerator), int(x.denominator))


def Q(x) -> mpq:
    """sympy Rational / int / str -> mpq."""
    if isinstance(x, sp.Basic):
        x = sp.Rational(x)
        return mpq(int(x.p), int(x.q))
    return mpq(x)


def vec(*xs) -> np.ndarray:
    return np.array([Q(x) for x in xs], dtype=object)


def rng(seed: int) -> random.Random:
    return random.Random(seed)


def rand_q(r: random.Random, lo=-9, hi=9, den=6) -> mpq:
    return mpq(r.randint(lo, hi), r.randint(1, den))


def rand_pos(r: random.Random) -> mpq:
    return mpq(r.randint(1, 9), r.randint(1, 4))


def rand_points(r: random.Random, n_points: int, dim: int = 2) -> list:
    return [[rand_q(r) for _ in range(dim)] for _ in range(n_points)]


def bernstein_expr(coeffs, t=t_):
    """sum c_i C(n,i) t^i (1-t)^(n-i) in sympy (the definition, notes (2.2))."""
    n = len(coeffs) - 1
    return sp.expand(sum(Rs(c) * sp.binomial(n, i) * t**i * (1 - t) ** (n - i) for i, c in enumerate(coeffs)))


def curve_exprs(points, weights=None, t=t_):
    """Components of the (rational) Bézier curve as sympy expressions (definition, notes 2.9)."""
    n = len(points) - 1
    w = [1] * (n + 1) if weights is None else weights
    den = bernstein_expr(w, t)
    return [bernstein_expr([Rs(w[i]) * Rs(points[i][k]) for i in range(n + 1)], t) / den for k in range(len(points[0]))]


def same_rational_function(a, b) -> bool:
    na, da = sp.fraction(sp.together(a))
    nb, db = sp.fraction(sp.together(b))
    return sp.expand(na * db - nb * da) == 0


def identity_coefficients(n_points: int) -> np.ndarray:
    """Control 'points' e_0, ..., e_n: any linear Bernstein operation applied to them
    returns its exact coefficient matrix (row = new point, column = old point)."""
    out = np.empty((n_points, n_points), dtype=object)
    for i in range(n_points):
        for j in range(n_points):
            out[i, j] = mpq(int(i == j))
    return out


def matrix_str(m) -> str:
    return "[" + "; ".join(" ".join(str(x) for x in row) for row in m) + "]"


def polar_value(spline, label) -> tuple:
    """Blossom of a B-spline at a polar label (n knot values), from the Bézier piece whose
    knot span lies between two consecutive distinct label entries (notes 6.1, rule 2).

    ``spline`` is a polynomial exactcagd ``BSplineCurve``; the Bézier pieces come from
    ``to_bezier`` and the blossom of a piece over [a, b] at x is its [0, 1] blossom at
    (x - a)/(b - a) (the blossom commutes with affine reparametrization).
    """
    label = sorted(mpq(x) for x in label)
    pieces = spline.to_bezier()
    if label[0] == label[-1]:  # f(t, ..., t) is the point at t
        return spline.evaluate(label[0])
    for lo, hi in zip(label[:-1], label[1:]):
        if lo < hi:
            for (a, b), piece in pieces:
                if a <= lo and hi <= b:
                    return piece.blossom([(x - a) / (b - a) for x in label])
    raise ValueError(f"no knot span inside the label {label}")

