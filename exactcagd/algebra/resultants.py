"""Resultants of two polynomials and their common roots (notes 17.3, 17.4).

Constructions (coefficient lists are lowest degree first: ``a[i]`` multiplies ``t^i``):

* :func:`sylvester_matrix` -- the ``(m + n) x (m + n)`` Sylvester matrix (17.3.5);
* :func:`bezout_matrix` -- the notes' ``n x n`` Bezout matrix built from the
  brackets ``(a_i b_j) = a_i b_j - a_j b_i`` (17.6)-(17.8) and 17.3.4; for
  ``deg f = m > deg g = n`` the hybrid matrix (``m - n`` Sylvester rows
  ``t^k g`` and ``n`` Bezout rows) of size ``m``;
* :func:`bezout_matrix_bernstein` -- the same in Bernstein form (17.6, 18.87);
* :func:`det_bareiss` -- fraction-free ("integer preserving", 17.4) elimination,
  valid over the integers and over polynomial rings (exact division).

Every route of :func:`resultant` returns the SAME value, the Sylvester resultant
``Res(f, g) = a_m^n b_n^m prod (f_i - g_j)`` (17.2).  The notes' Bezout
determinant differs from it by the sign ``(-1)^(n (n - 1) / 2)`` (17.9: -12 vs 12);
the code multiplies it back (:func:`bezout_sign`).

>>> import sympy
>>> t = sympy.Symbol("t")
>>> resultant(t**2 - 7*t + 12, t**2 - 3*t + 2, t)
12
>>> resultant(t**2 - 7*t + 12, t**2 - 3*t + 2, t, method="bezout")
12
"""

from __future__ import annotations

import flint
import sympy
from gmpy2 import mpq

from .. import limits
from ..errors import InputError
from ..exact.scalars import short_repr, to_rational
from ._poly import mpoly_to_sympy, polynomial_input, symbol_input, zctx

__all__ = [
    "bracket",
    "sylvester_matrix",
    "bezout_matrix",
    "bezout_matrix_bernstein",
    "bezout_sign",
    "det_bareiss",
    "echelon_bareiss",
    "resultant_coeffs",
    "resultant",
    "discriminant",
    "common_roots_linear",
    "euclid_steps",
    "gcd_subresultant",
    "common_root_count",
]


# ---------------------------------------------------------------------------- ring helpers
def _zero(e):
    return e * 0


def _exact_div(a, b):
    if isinstance(a, (flint.fmpz_mpoly, flint.fmpq_mpoly)):
        return a / b
    if isinstance(a, mpq) or isinstance(b, mpq):
        return a / b
    if isinstance(a, sympy.Basic) or isinstance(b, sympy.Basic):
        return sympy.expand(sympy.cancel(sympy.sympify(a) / b))  # teaching traces: sympy entries
    return a // b


def det_bareiss(matrix, on_step=None):
    """Determinant by Bareiss' fraction-free elimination (row pivoting), exactly.

    Entries: Python/flint integers, ``mpq``, flint multivariate polynomials or (for
    the teaching traces) sympy polynomial expressions.  Every intermediate entry
    is a minor of the input (so divisions are exact).  ``on_step(k, pivot, M)`` is
    called after elimination step ``k`` with the current matrix (traces).
    """
    M = [list(row) for row in matrix]
    n = len(M)
    if n == 0:
        return 1
    if any(len(row) != n for row in M):
        raise InputError("determinant of a non-square matrix")
    sign = 1
    prev = 1
    for k in range(n - 1):
        if M[k][k] == 0:
            swap = next((i for i in range(k + 1, n) if M[i][k] != 0), None)
            if swap is None:
                return _zero(M[0][0])
            M[k], M[swap] = M[swap], M[k]
            sign = -sign
        pivot = M[k][k]
        for i in range(k + 1, n):
            mik = M[i][k]
            row_i, row_k = M[i], M[k]
            for j in range(k + 1, n):
                num = pivot * row_i[j] - mik * row_k[j]
                row_i[j] = _exact_div(num, prev) if not (isinstance(prev, int) and prev == 1) else num
            row_i[k] = _zero(pivot)
        prev = pivot
        if on_step is not None:
            on_step(k, pivot, [list(row) for row in M])
    return M[n - 1][n - 1] if sign == 1 else -M[n - 1][n - 1]


def echelon_bareiss(matrix) -> tuple[list[list], int]:
    """Integer-preserving row echelon form (notes 17.4 "Gauss elimination") and the rank.

    Without pivoting while the pivots are non-zero, the last diagonal entry of a
    full-rank square matrix is its determinant (as the notes use it).
    """
    M = [list(row) for row in matrix]
    rows, cols = len(M), len(M[0]) if M else 0
    prev = 1
    r = 0
    for c in range(cols):
        if r >= rows:
            break
        piv = next((i for i in range(r, rows) if M[i][c] != 0), None)
        if piv is None:
            continue
        if piv != r:
            M[r], M[piv] = M[piv], M[r]
        pivot = M[r][c]
        for i in range(r + 1, rows):
            mic = M[i][c]
            for j in range(c + 1, cols):
                M[i][j] = _exact_div(pivot * M[i][j] - mic * M[r][j], prev)
            M[i][c] = _zero(pivot)
        prev = pivot
        r += 1
    return M, r


# ---------------------------------------------------------------------------- matrices
def _trim(a: list) -> list:
    if isinstance(a, (str, bytes, bytearray)) or not hasattr(a, "__len__") or len(a) == 0:
        raise InputError(f"expected a non-empty list of coefficients, got {short_repr(a, 40)}")
    limits.check("max_degree", len(a) - 1, "coefficient list: degree")
    # plain numbers (ints, strings, Fractions, floats) enter exactly; sympy and flint entries are kept as they are
    a = [x if isinstance(x, sympy.Basic) or type(x).__module__.startswith("flint") else to_rational(x, where=f"coefficient {k}") for k, x in enumerate(a)]
    while len(a) > 1 and a[-1] == 0:
        a.pop()
    return a


def bracket(a: list, b: list, i: int, j: int):
    """The notes' bracket ``(a_i b_j) = a_i b_j - a_j b_i`` (17.6)."""
    return a[i] * b[j] - a[j] * b[i]


def sylvester_matrix(a: list, b: list) -> list[list]:
    """Sylvester matrix of ``f = sum a_i t^i`` (degree m) and ``g`` (degree n) (17.3.5).

    ``n`` rows of shifted ``a`` (highest coefficient first) over ``m`` rows of ``b``.
    """
    a, b = _trim(a), _trim(b)
    m, n = len(a) - 1, len(b) - 1
    zero = _zero(a[0])
    size = m + n
    rows = []
    for i in range(n):
        rows.append([zero] * i + a[::-1] + [zero] * (size - m - 1 - i))
    for i in range(m):
        rows.append([zero] * i + b[::-1] + [zero] * (size - n - 1 - i))
    return rows


def _bezout_rows(a: list, b: list, n: int) -> list[list]:
    """The notes' Bezout matrix of formal degree ``n`` (rows h_1..h_n, columns t^(n-1)..1).

    Entry for indices ``i, j`` (display row ``n-1-i``, column ``n-1-j``):
    ``L_ij = sum_{m <= min(i, j), k + m = i + j + 1, k <= n} (a_k b_m)``  (17.6).
    """
    zero = _zero(a[0])
    a = list(a) + [zero] * (n + 1 - len(a))
    b = list(b) + [zero] * (n + 1 - len(b))
    cache = {}

    def br(k, m):
        if (k, m) not in cache:
            cache[(k, m)] = bracket(a, b, k, m)
        return cache[(k, m)]

    L = [[zero] * n for _ in range(n)]
    for i in range(n):
        for j in range(i, n):
            acc = zero
            for m_ in range(min(i, j) + 1):
                k = i + j + 1 - m_
                if k <= n:
                    acc = acc + br(k, m_)
            L[i][j] = L[j][i] = acc
    return [[L[n - 1 - r][n - 1 - c] for c in range(n)] for r in range(n)]


def bezout_matrix(a: list, b: list) -> list[list]:
    """The Bezout matrix of the notes (17.3.4, 17.4), size ``max(deg f, deg g)``.

    Equal degrees: the ``n x n`` matrix of brackets.  Unequal degrees
    ``m = deg f > n = deg g``: the hybrid matrix whose first ``m - n`` rows are
    ``g, t g, ..., t^(m-n-1) g`` and whose last ``n`` rows are the Bezout rows
    ``h_(m-n+1), ..., h_m`` of ``f`` and ``g`` (``g`` padded to degree ``m``).  The
    Bezout rows ``h_k, k <= m - n`` equal ``(a_m t^(k-1) + ...) g``; replacing them by
    the shifts divides the determinant by ``a_m^(m - n)`` and keeps its sign.
    The determinant is ``bezout_sign(max(m, n)) * Res(f, g)`` (up to the row swap
    sign when ``deg g > deg f``, see :func:`resultant_coeffs`).
    """
    a, b = _trim(a), _trim(b)
    m, n = len(a) - 1, len(b) - 1
    if m < n:
        raise InputError("bezout_matrix expects deg f >= deg g (swap the arguments)")
    rows = _bezout_rows(a, b, m)
    zero = _zero(a[0])
    for k in range(m - n):
        shift = k  # row k holds t^k * g (as h_(k+1) = a_m t^k g + ...), columns t^(m-1) .. t^0
        coeffs = [zero] * m
        for i, bi in enumerate(b):
            coeffs[m - 1 - (i + shift)] = bi
        rows[k] = coeffs
    return rows


def bezout_matrix_bernstein(a: list, b: list) -> list[list]:
    """Bezout matrix of two polynomials of the same degree n in Bernstein form (17.6).

    ``f(t) = sum a_i B_i^n(t)``.  With the scaled coefficients ``a_i C(n, i)`` this
    is the power-form matrix in ``u = t / (1 - t)``, acting on
    ``(t^(n-1), t^(n-2) (1 - t), ..., (1 - t)^(n-1))`` (17.10), (17.12); its
    determinant is ``bezout_sign(n)`` times the resultant of ``f`` and ``g`` as
    degree-``n`` polynomials.
    """
    from ..exact.bernstein import binomial

    if len(a) != len(b):
        raise InputError("Bernstein Bezout matrix needs equal degrees (elevate first)")
    n = len(a) - 1
    sa = [binomial(n, i) * a[i] for i in range(n + 1)]
    sb = [binomial(n, i) * b[i] for i in range(n + 1)]
    return _bezout_rows(sa, sb, n)


def bezout_sign(n: int) -> int:
    """``det(Bezout_n) = bezout_sign(n) * Res(f, g)``: ``(-1)^(n (n - 1) / 2)``."""
    return -1 if (n * (n - 1) // 2) % 2 else 1


# ---------------------------------------------------------------------------- values
def resultant_coeffs(a: list, b: list, method: str = "sylvester"):
    """Resultant of two coefficient lists (lowest degree first), Sylvester normalization.

    Entries may be integers, ``mpq`` or flint multivariate polynomials.  ``method``:
    ``"sylvester"`` (Bareiss on the Sylvester matrix), ``"bezout"`` (Bareiss on the
    (hybrid) Bezout matrix, sign corrected) or ``"flint"`` (python-flint's
    subresultant algorithm; integer / integer-polynomial entries only).
    """
    a, b = _trim(a), _trim(b)
    m, n = len(a) - 1, len(b) - 1
    if (m == 0 and a[0] == 0) or (n == 0 and b[0] == 0):
        return _zero(a[0])
    if m == 0:
        return a[0] ** n
    if n == 0:
        return b[0] ** m
    if method == "sylvester":
        return det_bareiss(sylvester_matrix(a, b))
    if method == "bezout":
        if m >= n:
            return bezout_sign(m) * det_bareiss(bezout_matrix(a, b))
        sign = -1 if (m * n) % 2 else 1
        return sign * bezout_sign(n) * det_bareiss(bezout_matrix(b, a))
    if method == "flint":
        return _flint_resultant(a, b)
    raise InputError(f"unknown resultant method {method!r} (sylvester, bezout, flint)")


def _flint_resultant(a: list, b: list):
    sample = a[-1]
    if isinstance(sample, flint.fmpz_mpoly):
        ctx = sample.context()
        names = ctx.names() + ("_t_",)
        big = zctx(names, "lex")
        k = len(names) - 1

        def lift(coeffs):
            data = {}
            for deg, c in enumerate(coeffs):
                for mono, v in c.to_dict().items():
                    data[tuple(mono) + (deg,)] = v
            return big.from_dict(data)

        r = lift(a).resultant(lift(b), "_t_")
        return ctx.from_dict({tuple(mono)[:k]: v for mono, v in r.to_dict().items()})
    ints = []
    for coeffs in (a, b):
        qs = [mpq(c) for c in coeffs]
        if any(q.denominator != 1 for q in qs):
            raise InputError("flint resultant route needs integer coefficients")
        ints.append(flint.fmpz_poly([int(q) for q in qs]))
    return int(ints[0].resultant(ints[1]))


# ---------------------------------------------------------------------------- sympy front end
def _split(f, g, var):
    """Common generators, coefficient lists in ``var`` over Z[others], denominators."""
    f, g, var = polynomial_input(f, "f"), polynomial_input(g, "g"), symbol_input(var, "var")
    fe = f.as_expr() if isinstance(f, sympy.Poly) else sympy.sympify(f)
    ge = g.as_expr() if isinstance(g, sympy.Poly) else sympy.sympify(g)
    if isinstance(f, sympy.Poly) and isinstance(g, sympy.Poly):
        others = [s for s in dict.fromkeys(list(f.gens) + list(g.gens)) if s != var]
    else:
        others = sorted((fe.free_symbols | ge.free_symbols) - {var}, key=str)
    gens = [var] + list(others)
    out = []
    for e in (fe, ge):
        p = sympy.Poly(e, *gens)
        if not (p.domain.is_ZZ or p.domain.is_QQ):
            raise InputError(f"resultant needs rational coefficients, got domain {p.domain}")
        terms = p.terms()
        den = 1
        for _, c in terms:
            den = sympy.ilcm(den, sympy.Rational(c).q)
        deg = p.degree(var) if not p.is_zero else 0
        coeffs = [dict() for _ in range(max(deg, 0) + 1)]
        for mono, c in terms:
            coeffs[mono[0]][tuple(mono[1:])] = int(sympy.Rational(c) * den)
        out.append((coeffs, int(den)))
    return gens, others, out


def resultant(f, g, var, method: str = "flint"):
    """Resultant of ``f`` and ``g`` with respect to ``var`` (notes 17.3).

    Parameters
    ----------
    f, g : sympy expressions or ``Poly`` with rational coefficients; the coefficients
        (in ``var``) may be polynomials in other variables (17.5: ``p(x, t)``, ``q(y, t)``).
    var : sympy Symbol eliminated.
    method : ``"flint"`` (default: python-flint's subresultant algorithm on ``fmpz_poly`` /
        ``fmpz_mpoly``, 7x faster than Bareiss at n = 12), ``"sylvester"`` (Bareiss on the
        Sylvester matrix, 17.4: the route whose steps ``--trace`` shows) or ``"bezout"`` --
        all give the same value, the Sylvester resultant (degrees = actual degrees in ``var``).

    Returns
    -------
    A sympy expression, or a ``Poly`` in the remaining generators when both inputs
    are ``Poly`` objects (a constant ``Poly`` when none remain).

    Examples
    --------
    >>> x, y, t = sympy.symbols("x y t")
    >>> sympy.factor(resultant(x - t**2 - 1, y - t**2 - 2*t + 2, t))
    x**2 - 2*x*y - 10*x + y**2 + 6*y + 13
    """
    gens, others, ((fc, fden), (gc, gden)) = _split(f, g, var)
    m, n = len(fc) - 1, len(gc) - 1
    if others:
        ctx = zctx([str(s) for s in others], "lex")
        a = [ctx.from_dict(c) if c else ctx.from_dict({}) for c in fc]
        b = [ctx.from_dict(c) if c else ctx.from_dict({}) for c in gc]
    else:
        a = [int(c.get((), 0)) for c in fc]
        b = [int(c.get((), 0)) for c in gc]
    if not method in ("sylvester", "bezout", "flint"):
        raise InputError(f"unknown resultant method {method!r} (sylvester, bezout, flint)")
    if method != "flint":  # Bareiss on an (m + n)-square matrix of polynomials: far slower than flint's
        limits.check("max_implicit_degree", max(m, n), f"resultant by the {method} matrix: degree in {var}")
    value = resultant_coeffs(a, b, method)
    scale = sympy.Rational(1, fden**n * gden**m)
    if isinstance(f, sympy.Poly) and isinstance(g, sympy.Poly):
        if others:
            return mpoly_to_sympy(value, others) * scale
        return sympy.Poly(sympy.Integer(int(value)) * scale, *(gens[1:] or [var]))
    if others:
        return sympy.expand(mpoly_to_sympy(value, others).as_expr() * scale)
    return sympy.Integer(int(value)) * scale


def discriminant(f, var, normalized: bool = False):
    """``Res(f, df/dvar)`` (notes 19.4); with ``normalized`` the classical discriminant.

    The notes state that for ``a t^2 + b t + c`` the resultant with the derivative
    is ``a^2 (b^2 - 4ac)``; the Sylvester resultant is ``-a (b^2 - 4ac)``
    (ledger erratum 19.4).  ``normalized=True`` divides by
    ``(-1)^(n (n - 1) / 2) * a_n`` to give the classical ``b^2 - 4ac``.
    """
    f, var = polynomial_input(f, "f"), symbol_input(var, "var")
    fe = f.as_expr() if isinstance(f, sympy.Poly) else sympy.sympify(f)
    r = resultant(fe, sympy.diff(fe, var), var)
    if not normalized:
        return r
    p = sympy.Poly(fe, var)
    n = p.degree()
    sign = -1 if (n * (n - 1) // 2) % 2 else 1
    return sympy.factor(sympy.cancel(r / (sign * p.LC())))


# ---------------------------------------------------------------------------- common roots
def _univariate(f, var=None) -> tuple[list[mpq], sympy.Symbol]:
    if var is not None:
        var = symbol_input(var, "var")
    if isinstance(f, (list, tuple)):
        return [to_rational(c, where=f"coefficient {k}") for k, c in enumerate(f)], (var or sympy.Symbol("t"))
    f = polynomial_input(f, "f")
    e = f.as_expr() if isinstance(f, sympy.Poly) else sympy.sympify(f)
    if var is None:
        free = sorted(e.free_symbols, key=str)
        if len(free) > 1:
            raise InputError(f"univariate polynomial expected, found variables {free}")
        var = free[0] if free else sympy.Symbol("t")
    try:
        p = sympy.Poly(e, var, domain="QQ")
    except sympy.polys.polyerrors.BasePolynomialError:
        raise InputError(f"{short_repr(e, 60)}: expected a univariate polynomial in {var} with rational coefficients") from None
    return [mpq(int(c.p), int(c.q)) for c in p.all_coeffs()[::-1]], var


def common_roots_linear(f, g, var=None) -> dict:
    """Common roots by the linear-equation approach of the notes (17.4).

    The Bezout matrix ``B`` (rows = polynomials of degree < n in the ideal
    ``(f, g)``) is brought to row echelon form by integer-preserving elimination.
    ``n - rank(B)`` is the number of common roots (the degree of the gcd), and the
    last non-zero row of the echelon form holds the coefficients of the gcd
    (highest power first).  With one common root, Cramer's rule on the first
    ``n - 1`` rows gives it as the ratio ``TU / U^2`` (17.4).

    Returns
    -------
    dict with keys ``matrix`` (the Bezout matrix), ``echelon``, ``rank``, ``count``
    (number of common roots with multiplicity), ``gcd`` (sympy expression in
    ``var``) and ``root`` (the common root by Cramer's rule when ``count == 1``).
    """
    a, var = _univariate(f, var)
    b, _ = _univariate(g, var)
    a, b = _trim(a), _trim(b)
    if len(a) < len(b):
        a, b = b, a
    n = len(a) - 1
    B = bezout_matrix(a, b)
    E, rank = echelon_bareiss(B)
    count = n - rank
    out = {"matrix": B, "echelon": E, "rank": rank, "count": count, "gcd": sympy.Integer(1), "root": None}
    if count > 0 and rank > 0:
        last = E[rank - 1]
        expr = sum(sympy.Rational(int(c.numerator), int(c.denominator)) * var ** (n - 1 - j) for j, c in enumerate(last))
        out["gcd"] = sympy.expand(expr)
    elif count > 0:
        out["gcd"] = sympy.Poly(a[::-1], var).as_expr()
    if count == 1 and n >= 2:
        rows = B[: n - 1]
        minor = lambda skip: det_bareiss([[r[c] for c in range(n) if c != skip] for r in rows])  # noqa: E731
        # solution v_j = (-1)^j det(rows without column j); t = v_(n-2) / v_(n-1)
        num = (-1) ** (n - 2) * minor(n - 2)
        den = (-1) ** (n - 1) * minor(n - 1)
        if den != 0:
            out["root"] = mpq(num) / mpq(den)
    elif count == 1 and n == 1:
        out["root"] = -mpq(a[0]) / mpq(a[1])
    return out


def euclid_steps(f, g, var=None) -> tuple[list[dict], sympy.Expr]:
    """Euclid's algorithm as the notes run it (17.4): ``f`` is divided by ``g`` (they are
    swapped when ``deg f < deg g``), then each step divides the previous divisor by
    the previous remainder.  Returns ``(steps, gcd)`` with steps
    ``{"dividend", "divisor", "quotient", "remainder"}`` (sympy expressions) and the
    last non-zero remainder as gcd (not normalized, as printed in the notes).
    """
    a, var = _univariate(f, var)
    b, _ = _univariate(g, var)
    P = lambda c: sympy.Poly([sympy.Rational(int(x.numerator), int(x.denominator)) for x in c[::-1]], var, domain="QQ")  # noqa: E731
    num, den = P(a), P(b)
    if den.degree() > num.degree():
        num, den = den, num
    steps = []
    while not den.is_zero:
        q, r = num.div(den)
        steps.append({"dividend": num.as_expr(), "divisor": den.as_expr(), "quotient": q.as_expr(), "remainder": r.as_expr()})
        num, den = den, r
    return steps, num.as_expr()


def gcd_subresultant(f, g, var=None):
    """Monic gcd via the subresultant polynomial remainder sequence (sympy)."""
    a, var = _univariate(f, var)
    b, _ = _univariate(g, var)
    fa = sympy.Poly([sympy.Rational(int(x.numerator), int(x.denominator)) for x in a[::-1]], var)
    fb = sympy.Poly([sympy.Rational(int(x.numerator), int(x.denominator)) for x in b[::-1]], var)
    prs = sympy.subresultants(fa.as_expr(), fb.as_expr(), var)
    last = [p for p in prs if p != 0][-1]
    lp = sympy.Poly(last, var)
    return lp.monic().as_expr() if lp.degree() > 0 else sympy.Integer(1)


def common_root_count(f, g, var=None) -> int:
    """Number of common roots (with multiplicity, over C) = degree of the gcd (17.4)."""
    a, _ = _univariate(f, var)
    b, _ = _univariate(g, var)
    pa = flint.fmpq_poly([flint.fmpq(int(c.numerator), int(c.denominator)) for c in a])
    pb = flint.fmpq_poly([flint.fmpq(int(c.numerator), int(c.denominator)) for c in b])
    return max(pa.gcd(pb).degree(), 0)
