"""Independent sympy references and hypothesis strategies shared by the foundation tests.

Nothing here calls exactcagd: every reference value is built from the textbook
definition (Bernstein sum, Cox-de Boor recursion) in sympy / ``fractions``.
"""

from __future__ import annotations

from fractions import Fraction

import sympy as sp
from gmpy2 import mpq
from hypothesis import strategies as st

T, U, V, S = sp.symbols("t u v s")

# ---------------------------------------------------------------- strategies
small_rationals = st.builds(Fraction, st.integers(-12, 12), st.integers(1, 7))
positive_rationals = st.builds(Fraction, st.integers(1, 9), st.integers(1, 5))
unit_params = st.fractions(min_value=0, max_value=1, max_denominator=12)
any_params = st.fractions(min_value=-2, max_value=3, max_denominator=9)


def coeff_lists(min_degree=0, max_degree=7):
    return st.lists(small_rationals, min_size=min_degree + 1, max_size=max_degree + 1)


def point_lists(dim, min_degree=0, max_degree=5):
    return st.integers(min_degree, max_degree).flatmap(
        lambda n: st.lists(st.lists(small_rationals, min_size=dim, max_size=dim), min_size=n + 1, max_size=n + 1)
    )


def weight_lists(n_points):
    return st.lists(positive_rationals, min_size=n_points, max_size=n_points)


# ---------------------------------------------------------------- conversions
def R(x) -> sp.Rational:
    """Exact number (mpq, Fraction, int, str) -> sympy Rational."""
    if isinstance(x, sp.Rational):
        return x
    if isinstance(x, sp.Basic):
        raise TypeError(f"not an exact rational: {x!r}")  # (sympy.nsimplify mangles large Rationals)
    f = Fraction(str(x)) if isinstance(x, str) else Fraction(int(x.numerator), int(x.denominator))
    return sp.Rational(f.numerator, f.denominator)


def Q(x) -> mpq:
    """sympy Rational (or Fraction/int) -> mpq."""
    if isinstance(x, sp.Basic):
        x = sp.Rational(x)
        return mpq(int(x.p), int(x.q))
    return mpq(int(x.numerator), int(x.denominator))


def B(n, i, t=T):
    """Bernstein basis polynomial B^n_i(t) = C(n,i) t^i (1-t)^(n-i) (notes (2.2))."""
    return sp.binomial(n, i) * t**i * (1 - t) ** (n - i)


def bernstein_sum(coeffs, t=T):
    """sum_i c_i B^n_i(t), expanded; ``coeffs`` scalars (any exact type)."""
    n = len(coeffs) - 1
    return sp.expand(sum(R(c) * B(n, i, t) for i, c in enumerate(coeffs)))


def bernstein_vec(points, t=T):
    """Component-wise Bernstein sums of a list of points."""
    dim = len(points[0])
    return [bernstein_sum([p[k] for p in points], t) for k in range(dim)]


def rational_curve(points, weights, t=T):
    """The rational Bézier curve sum w_i P_i B_i / sum w_i B_i as a list of sympy expressions."""
    n = len(points) - 1
    w = sum(R(weights[i]) * B(n, i, t) for i in range(n + 1))
    return [sum(R(weights[i]) * R(points[i][k]) * B(n, i, t) for i in range(n + 1)) / w for k in range(len(points[0]))]


def tensor_sum(net, u=U, v=V, weights=None):
    """Tensor-product Bézier surface from its net (list of lists of points), rational if weights."""
    l, m = len(net) - 1, len(net[0]) - 1
    dim = len(net[0][0])
    w = [[R(1)] * (m + 1) for _ in range(l + 1)] if weights is None else [[R(x) for x in row] for row in weights]
    den = sp.expand(sum(w[i][j] * B(l, i, u) * B(m, j, v) for i in range(l + 1) for j in range(m + 1)))
    out = []
    for k in range(dim):
        num = sp.expand(sum(w[i][j] * R(net[i][j][k]) * B(l, i, u) * B(m, j, v) for i in range(l + 1) for j in range(m + 1)))
        out.append(num if weights is None else num / den)
    return out


def same_function(a, b) -> bool:
    """Exact identity test of two rational functions (numerator of the difference vanishes)."""
    na, da = sp.fraction(sp.together(a))
    nb, db = sp.fraction(sp.together(b))
    return sp.expand(na * db - nb * da) == 0


def bernstein_coeffs(expr, n, t=T):
    """Bernstein coefficients of degree n of a polynomial expression, from its power
    coefficients a_k: c_i = sum_{k<=i} C(i,k)/C(n,k) a_k (notes 3.3, inverted)."""
    poly = sp.Poly(sp.expand(expr), t)
    a = poly.all_coeffs()[::-1] if not poly.is_zero else [0]
    assert len(a) - 1 <= n
    a = a + [0] * (n + 1 - len(a))
    return [sum(sp.binomial(i, k) / sp.binomial(n, k) * sp.Rational(a[k]) for k in range(i + 1)) for i in range(n + 1)]


def poly_eq(a, b, *gens) -> bool:
    return sp.Poly(sp.expand(a - b), *gens).is_zero


# ---------------------------------------------------------------- Cox-de Boor (plain recursion on Fractions)
def cox_de_boor(i: int, p: int, knots, t) -> Fraction:
    """N_{i,p}(t) by the Cox-de Boor recursion, standard convention (half-open spans;
    at the right end of the domain the last non-empty span is closed)."""
    knots = [Fraction(k) for k in knots]
    t = Fraction(t)
    if p == 0:
        lo, hi = knots[i], knots[i + 1]
        if lo <= t < hi:
            return Fraction(1)
        # right end of the whole domain belongs to the last non-empty span
        if t == knots[-1] and hi == knots[-1] and lo < hi:
            return Fraction(1)
        return Fraction(0)
    out = Fraction(0)
    d1 = knots[i + p] - knots[i]
    if d1 != 0:
        out += (t - knots[i]) / d1 * cox_de_boor(i, p - 1, knots, t)
    d2 = knots[i + p + 1] - knots[i + 1]
    if d2 != 0:
        out += (knots[i + p + 1] - t) / d2 * cox_de_boor(i + 1, p - 1, knots, t)
    return out


def spline_point(points, knots, p, t, weights=None):
    """sum N_i(t) w_i P_i / sum N_i(t) w_i with Fractions."""
    n = len(points)
    w = [Fraction(1)] * n if weights is None else [Fraction(x) for x in weights]
    basis = [cox_de_boor(i, p, knots, t) for i in range(n)]
    den = sum(b * wi for b, wi in zip(basis, w))
    return tuple(sum(b * wi * Fraction(pt[k]) for b, wi, pt in zip(basis, w, points)) / den for k in range(len(points[0])))


def cox_de_boor_sym(i: int, p: int, knots, t, span):
    """N_{i,p} restricted to the knot span ``span = (a, b)`` as a sympy polynomial in ``t``.

    The degree-0 functions are 1 on the chosen span and 0 elsewhere, so the
    recursion yields the polynomial piece valid on that span.
    """
    knots = [R(k) for k in knots]
    a, b = R(span[0]), R(span[1])
    if p == 0:
        return sp.Integer(1) if (knots[i] == a and knots[i + 1] == b) else sp.Integer(0)
    out = sp.Integer(0)
    d1 = knots[i + p] - knots[i]
    if d1 != 0:
        out += (t - knots[i]) / d1 * cox_de_boor_sym(i, p - 1, knots, t, span)
    d2 = knots[i + p + 1] - knots[i + 1]
    if d2 != 0:
        out += (knots[i + p + 1] - t) / d2 * cox_de_boor_sym(i + 1, p - 1, knots, t, span)
    return sp.expand(out)


def frac(x) -> Fraction:
    return Fraction(int(x.numerator), int(x.denominator))
