"""Derivation traces (teaching mode) for the resultant and moving-line constructions.

Two printers show every intermediate exact object, for ``exactcagd verify --trace``
(the ledger's ``@claim(..., trace=...)`` hook) and for readers of the notes:

* :func:`trace_bezout` -- the Bezout resultant of notes 17.3.3-17.3.4 and 17.5:
  coefficients, brackets ``(a_i b_j)``, the auxiliary polynomials ``h_k``, the
  matrix (its rows are the ``h_k``), fraction-free elimination step by step, and
  the determinant with its sign relative to the Sylvester resultant.
* :func:`trace_zeroing` -- the moving-line matrix (18.78)-(18.79), the zeroing
  process (18.80)-(18.84) operation by operation (with the (18.82) check that the
  pivot column is a set of lines through ``P_0``), the two final moving lines
  dotted with ``(x, y, 1)`` (18.85)-(18.86), their resultant (18.87) and its ratio to
  the implicit equation.

Both accept ``out`` (default :func:`print`) and return the main exact values, so
the traces are tested like any other function.

>>> import sympy
>>> t = sympy.Symbol("t")
>>> lines = []
>>> trace_bezout(t**2 - 7*t + 12, t**2 - 3*t + 2, t, out=lines.append)["resultant"]
12
"""

from __future__ import annotations

import sympy

from ..errors import InputError
from .moving_lines import MovingLine, _power_of_scaled_bernstein, cross, dot, homogeneous_control_points, moving_line_matrix, zeroing_process
from .resultants import bezout_matrix, bezout_sign, det_bareiss

__all__ = ["trace_bezout", "trace_zeroing"]

X_, Y_ = sympy.symbols("x y")


def _q(v) -> sympy.Rational:
    """mpq / int -> sympy Rational."""
    return sympy.Rational(int(v.numerator), int(v.denominator)) if hasattr(v, "denominator") else sympy.Integer(v)


def _fmt_matrix(M, indent: str = "    ") -> list[str]:
    cells = [[str(sympy.expand(e)) for e in row] for row in M]
    width = max((len(c) for row in cells for c in row), default=1)
    return [indent + "[ " + " | ".join(c.rjust(width) for c in row) + " ]" for row in cells]


def _to_flint(M):
    """Sympy matrix entries -> ``mpq`` or flint ``fmpq_mpoly`` (fast exact division); and back."""
    import flint
    from gmpy2 import mpq

    syms = sorted(set().union(*(sympy.sympify(e).free_symbols for row in M for e in row)), key=str)
    if not syms:
        return [[mpq(int(sympy.Rational(e).p), int(sympy.Rational(e).q)) for e in row] for row in M], lambda v: _q(v)
    ctx = flint.fmpq_mpoly_ctx.get(tuple(str(s_) for s_ in syms), "degrevlex")

    def conv(e):
        P = sympy.Poly(e, *syms)
        return ctx.from_dict({m: flint.fmpq(int(c.p), int(c.q)) for m, c in P.terms()})

    def back(v):
        return sympy.Poly.from_dict({tuple(m): sympy.Rational(int(c.p), int(c.q)) for m, c in v.to_dict().items()} or {(0,) * len(syms): 0}, *syms).as_expr()

    return [[conv(e) for e in row] for row in M], back


def _bareiss_trace(M, out, label: str):
    """Determinant of ``M`` (sympy entries) printing every fraction-free step."""
    F, back = _to_flint(M)

    def step(k, pivot, current):
        out(f"  {label} step {k + 1}: pivot {back(pivot)}; rows below divided exactly by the previous pivot")
        for line in _fmt_matrix([[back(e) for e in row] for row in current]):
            out(line)

    return sympy.expand(back(det_bareiss(F, on_step=step)))


def trace_bezout(f, g, var, out=print) -> dict:
    """Print the Bezout resultant of ``f`` and ``g`` step by step (notes 17.3.3, 17.3.4, 17.5).

    The auxiliary polynomials (17.6), (17.7) and 17.3.4 are
    ``h_k = (a_N t^(k-1) + ... + a_(N-k+1)) g - (b_N t^(k-1) + ... + b_(N-k+1)) f``
    (``N = deg f >= deg g``); each has degree ``N - 1`` and row ``k`` of the Bezout
    matrix holds its coefficients of ``t^(N-1), ..., 1``.  For ``deg g < N`` the
    first ``N - deg g`` rows are replaced by ``t^(k-1) g`` (hybrid matrix).  The
    determinant is ``(-1)^(N(N-1)/2)`` times the Sylvester resultant (17.9).

    Parameters
    ----------
    f, g : sympy expressions, polynomial in ``var`` (coefficients may contain x, y).
    var : the eliminated symbol.
    out : callable receiving each printed line.

    Returns
    -------
    dict with ``matrix`` (sympy Matrix), ``h`` (list of the ``h_k``), ``det`` and
    ``resultant`` (the Sylvester normalization).
    """
    var = sympy.sympify(var)
    F, G = sympy.Poly(sympy.expand(f), var), sympy.Poly(sympy.expand(g), var)
    if F.is_zero or G.is_zero:
        raise InputError("trace_bezout: both polynomials must be non-zero")
    swapped = F.degree() < G.degree()
    if swapped:
        F, G = G, F
    N, n = F.degree(), G.degree()
    if N < 1:
        raise InputError("trace_bezout needs a polynomial of degree >= 1 in the variable")
    a = [sympy.expand(c) for c in F.all_coeffs()[::-1]]
    b = [sympy.expand(c) for c in G.all_coeffs()[::-1]] + [sympy.Integer(0)] * (N - n)
    out(f"Bezout resultant in {var} (notes 17.3.3-17.3.4){' (arguments swapped: deg f < deg g)' if swapped else ''}")
    out(f"  f = {F.as_expr()}")
    out(f"  g = {G.as_expr()}")
    out("  coefficients (lowest first): a = [" + ", ".join(map(str, a)) + "], b = [" + ", ".join(map(str, b)) + "]")
    out("  brackets (a_i b_j) = a_i b_j - a_j b_i:")
    for i in range(N, 0, -1):
        for j in range(i - 1, -1, -1):
            br = sympy.expand(a[i] * b[j] - a[j] * b[i])
            out(f"    (a{i} b{j}) = {br}")
    rows = [[sympy.expand(e) for e in row] for row in bezout_matrix(a, b[: n + 1] if n < N else b)]
    hs = []
    out("  auxiliary polynomials (each of degree N - 1; row k of the matrix = its coefficients):")
    for k in range(1, N + 1):
        if k <= N - n:
            h = sympy.expand(var ** (k - 1) * G.as_expr())
            out(f"    row {k}: t^{k - 1} g = {h}   (hybrid row, deg g < N)")
        else:
            A = sum(a[N - i] * var ** (k - 1 - i) for i in range(k))
            B = sum(b[N - i] * var ** (k - 1 - i) for i in range(k))
            h = sympy.expand(A * G.as_expr() - B * F.as_expr())
            out(f"    h{k} = ({sympy.expand(A)}) g - ({sympy.expand(B)}) f = {h}")
        coeffs = [sympy.expand(sympy.Poly(h, var).coeff_monomial(var**p)) for p in range(N - 1, -1, -1)]
        assert coeffs == rows[k - 1], (k, coeffs, rows[k - 1])
        hs.append(h)
    out(f"  Bezout matrix ({N} x {N}), columns t^{N - 1} .. t^0:")
    for line in _fmt_matrix(rows):
        out(line)
    det = _bareiss_trace(rows, out, "Bareiss") if N > 1 else rows[0][0]
    sign = bezout_sign(N)
    res = sympy.expand(sign * det)
    if swapped and (N * n) % 2:
        res = -res
    out(f"  det = {det}")
    out(f"  sign (-1)^(N(N-1)/2) = {sign}{'; argument swap sign (-1)^(mn) = -1' if swapped and (N * n) % 2 else ''}")
    out(f"  Sylvester resultant Res_{var}(f, g) = {res}")
    return {"matrix": sympy.Matrix(rows), "h": hs, "det": det, "resultant": res}


def _line_str(L) -> str:
    return "(" + ", ".join(str(_q(v)) for v in L) + ")"


def _dot_xy(L) -> sympy.Expr:
    return sympy.expand(_q(L[0]) * X_ + _q(L[1]) * Y_ + _q(L[2]))


def trace_zeroing(curve, out=print) -> dict:
    """Print the moving-line implicitization of a rational Bézier curve (notes 18.4.5-18.4.6).

    Steps: homogeneous control points ``P_i``; the ``n x n`` matrix (18.78) with
    ``L_ij = sum_{l + m = i + j + 1, l <= min(i, j)} C(n,l) C(n,m) P_l x P_m`` (18.79,
    as corrected in the ledger); every row operation of the zeroing process (18.80)
    with the (18.82) check ``L . P_0 = 0`` on the pivot column; the two final moving
    lines (18.83)/(18.84); the entries ``L . (x, y, 1)`` (18.85)-(18.86); their Bezout
    determinant in ``u = t / (1 - t)`` (18.87) by fraction-free elimination; its
    ratio to the implicit equation of :func:`~exactcagd.algebra.implicitize`.

    Parameters
    ----------
    curve : planar BezierCurve of degree >= 2 without special structure (the
        zeroing process of the notes; a triple point makes it fail with
        :class:`~exactcagd.errors.DegreeError`, 18.4.4).

    Returns
    -------
    dict with ``matrix`` (18.78), ``rows`` (the two final rows of scaled Bernstein
    entries), ``entries`` (18.86), ``det`` and ``ratio`` (``det / f``, a constant).
    """
    from .implicitize import implicitize

    P = homogeneous_control_points(curve)
    n = len(P) - 1
    if n < 2:
        raise InputError("trace_zeroing needs a curve of degree >= 2")
    out(f"Moving-line implicitization of a degree-{n} curve (notes 18.4.5-18.4.6)")
    for i, p in enumerate(P):
        out(f"  P{i} = {_line_str(p)}")
    M = moving_line_matrix(P)
    out(f"  (18.78) matrix of control lines L_ij (row i: a degree-{n - 1} moving line following P[t]):")
    for i, row in enumerate(M):
        out(f"    row {i}: " + "  ".join(_line_str(e) for e in row))
    Z = zeroing_process(P)
    for s in range(len(Z.steps) - 1):
        out(f"  zeroing step {s + 1} (18.80)-(18.82): column {s}, pivot rows {2 * s}, {2 * s + 1}")
        pivot_col = [Z.steps[s][r][s] for r in range(2 * s, n)]
        checks = [dot(L, P[0]) for L in pivot_col]
        out(f"    (18.82) column {s} entries dotted with P0: {[str(_q(v)) for v in checks]} (all lines through P0)")
        for step, r, piv, coef in Z.ops:
            if step == s:
                terms = " + ".join(f"({_q(c)}) row {p}" for p, c in zip(piv, coef))
                out(f"    row {r} -= {terms}")
        for i, row in enumerate(Z.steps[s + 1]):
            if i >= 2 * s + 2:
                out(f"    row {i}: " + "  ".join(_line_str(e) for e in row))
    m = n // 2
    if n % 2 == 0:
        rows = [Z.steps[-1][n - 2][m - 1 :], Z.steps[-1][n - 1][m - 1 :]]
        out(f"  (18.83) n = 2m = {n}: two moving lines of degree {m}")
    else:
        rows = [Z.steps[-1][n - 2][m - 1 :], Z.steps[-1][n - 1][m:]]
        out(f"  (18.84) n = 2m + 1 = {n}: moving lines of degrees {m + 1} and {m}")
    rows = [_integral(row) for row in rows]
    out("    (each row times the lcm of its denominators; a moving line is defined up to a factor, 18.1.3)")
    for k, row in enumerate(rows):
        out(f"    L{k} = [" + ", ".join(_line_str(e) for e in row) + f"]  against (1-t)^({len(row) - 1}-j) t^j")
        power = MovingLine(_power_of_scaled_bernstein(row))
        out(f"    L{k}[t] . P[t] == 0: {power.follows(*_power_components(curve))}")
        if power.degree == 1 and power.axis() is not None:
            out(f"    L{k} is a pencil; its axis L{k}0 x L{k}1 = {tuple(str(_q(v)) for v in power.axis())} is the double point (18.66)")
    entries = [[_dot_xy(e) for e in row] for row in rows]
    out("  (18.85)-(18.86) entries L . (x, y, 1):")
    for row in entries:
        out("    [" + ", ".join(map(str, row)) + "]")
    # as polynomials in u = t / (1 - t): coefficient lists lowest first
    a, b = entries
    if len(a) < len(b):
        a, b = b, a
    B = [[sympy.expand(e) for e in row] for row in bezout_matrix(a, b)]
    kind = "brackets |L_i.P L_j.P|" if len(a) == len(b) else "hybrid: first rows are shifts of the lower-degree line, then brackets"
    out(f"  (18.87) Bezout matrix of the two moving lines in u = t/(1-t) ({len(B)} x {len(B)}, {kind}):")
    for line in _fmt_matrix(B):
        out(line)
    det = _bareiss_trace(B, out, "Bareiss") if len(B) > 1 else B[0][0]
    F = implicitize(curve).as_expr()
    ratio = sympy.cancel(det / F)
    out(f"  determinant = {det}")
    out(f"  implicit equation f = {F}; determinant / f = {ratio}")
    assert ratio.is_number and ratio != 0
    return {"matrix": M, "rows": rows, "entries": entries, "det": det, "ratio": ratio}


def _integral(row: list) -> list:
    """The triples of ``row`` times the lcm of their denominators (integer entries)."""
    import math

    den = 1
    for e in row:
        for v in e:
            den = den * int(v.denominator) // math.gcd(den, int(v.denominator))
    return [tuple(v * den for v in e) for e in row]


def _power_components(curve):
    from ._poly import curve_power

    return curve_power(curve)
