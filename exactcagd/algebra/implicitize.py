"""Implicitization of rational planar Bézier curves (notes 17.5, 17.6, 18.4.6).

Three routes give the same implicit polynomial ``f(x, y)``:

``"resultant"``
    ``Res_t(W(t) x - X(t), W(t) y - Y(t))`` (17.5).  When the fibre test
    (:func:`proper_at_fiber`) proves the parametrization proper, the resultant is taken as
    the determinant of its Bezout matrix (17.3.4), whose entries are linear in ``x, y``:
    flint's integer determinant at the ``(n + 1)(n + 2) / 2`` points of a triangular grid,
    interpolated exactly (``_bezout_interpolated``; the whole call is as fast as
    python-flint's subresultant resultant alone at n = 5 and 3x-5x faster at n = 8..16).
    Otherwise python-flint's resultant, whose squarefree factorization gives the index.
``"bezier"``
    the ``n x n`` Bezout determinant in Bernstein form with the
    ``l_ij = C(n,i) C(n,j) w_i w_j |x y 1; x_i y_i 1; x_j y_j 1|`` (17.6).
``"moving_lines"``
    the resultant of a mu-basis (two moving lines of degrees ``mu, n - mu``), a
    determinant of size ``n - mu`` (18.4.6).

Normalization (all routes): integer coefficients, content 1, leading coefficient
in graded reverse lexicographic order (``x > y``) positive.

Degenerate input (documented behaviour):

* constant curve -> :class:`~exactcagd.errors.DegreeError`;
* common factor of ``X, Y, W`` (base points) -> :class:`BasePointWarning`, the
  factor is divided out (the implicit equation of the point set);
* improper parametrization (the resultant is ``F^r``, ``r > 1``) ->
  :class:`ImproperParametrizationWarning`, ``F`` is returned; the index ``r`` is in
  :func:`implicit_equation`'s result.

>>> from exactcagd import BezierCurve
>>> implicitize(BezierCurve([[0, 0], [1, 2], [2, 0]])).as_expr()
x**2 - 2*x + y
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass, field
from functools import lru_cache

import flint
import sympy

from ..errors import InputError
from ._diagnostics import BasePointError, BasePointWarning, ImproperParametrizationError, ImproperParametrizationWarning
from ._poly import X_SYM, XY, Y_SYM, check_not_constant, common_factor, curve_power, grevlex_full_poly, grevlex_triangle_poly, mpoly_to_sympy, normalize_implicit, zctx
from .resultants import bezout_matrix_bernstein, det_bareiss, resultant_coeffs

__all__ = [
    "implicitize",
    "implicit_equation",
    "ImplicitEquation",
    "proper_at_fiber",
    "implicit_resultant",
    "implicit_bezier",
    "implicit_moving_lines",
    "l_matrix",
    "bezier_bezout_matrix",
    "reduced_components",
    "ROUTES",
]

ROUTES = ("resultant", "bezier", "moving_lines")


@dataclass(eq=False, repr=False)
class ImplicitEquation:
    """Implicit equation of a rational curve, with what was found on the way.

    Attributes
    ----------
    poly : sympy.Poly in ``x, y`` (integer, primitive, grevlex-positive), built on first
        access (the conversion costs more than flint's resultant of a cubic)
    mpoly : the same as a python-flint ``fmpz_mpoly`` in ``x, y`` (grevlex); built on first
        access when the resultant route left it in ``Z[x, y, t]`` (``t`` eliminated)
    degree : total degree of ``poly``
    index : ``r``: the resultant was ``c * poly^r`` (``r = 1``: proper parametrization)
    base_factor : common factor of ``X, Y, W`` removed (``1`` if none), as ``fmpz_poly``
    curve_degree : degree of the reduced parametrization
    """

    _raw: object  # the normalized equation: in XY, in _XYT without t, or a _GrevlexTriangle
    degree: int
    index: int
    base_factor: object
    curve_degree: int
    _poly: sympy.Poly | None = field(default=None)

    @property
    def mpoly(self):
        if isinstance(self._raw, _GrevlexTriangle):
            self._raw = self._raw.to_mpoly()
        elif self._raw.context() is not XY:
            self._raw = self._raw.project_to_context(XY)
        return self._raw

    @property
    def poly(self) -> sympy.Poly:
        if self._poly is None:
            # the dense rows straight from the grevlex term list, else the general conversion
            raw = self._raw
            if isinstance(raw, _GrevlexTriangle):
                full = grevlex_triangle_poly(raw.coeffs, raw.degree, (X_SYM, Y_SYM)) if all(raw.coeffs) else None
            else:
                full = grevlex_full_poly(raw, (X_SYM, Y_SYM))
            self._poly = full or mpoly_to_sympy(self.mpoly, (X_SYM, Y_SYM))
        return self._poly

    @property
    def proper(self) -> bool:
        return self.index == 1

    def _key(self) -> tuple:
        return (self.mpoly, self.degree, self.index, self.base_factor, self.curve_degree)

    def __eq__(self, other) -> bool:
        return self._key() == other._key() if isinstance(other, ImplicitEquation) else NotImplemented

    __hash__ = None

    def __repr__(self) -> str:
        return (f"ImplicitEquation(mpoly={self.mpoly!r}, degree={self.degree!r}, index={self.index!r}, "
                f"base_factor={self.base_factor!r}, curve_degree={self.curve_degree!r})")


def _in_t(g) -> sympy.Expr:
    """A flint ``fmpz_poly`` in the curve parameter, for messages (``2*t - 1``, not ``2*x + (-1)``)."""
    return sympy.sympify(g.str(var="t"))


def reduced_components(curve, warn: bool = True):
    """``(X, Y, W)`` with base points removed (warning), constant curves rejected."""
    X, Y, W = curve_power(curve)
    g, (X, Y, W) = common_factor(X, Y, W)
    check_not_constant(X, Y, W)
    if g.degree() > 0 and warn:
        _warn_base_points(g, stacklevel=4)
    return X, Y, W, g


def _warn_base_points(g, stacklevel: int) -> None:
    warnings.warn(
        f"the parametrization has base points (common factor {_in_t(g)} of X, Y, W, notes 18.3.4); "
        "it was divided out",
        BasePointWarning,
        stacklevel=stacklevel,
    )


def _reduced_and_proper(curve, warn: bool):
    """:func:`reduced_components` and :func:`proper_at_fiber` in one pass: a proof of
    properness also proves the curve is not a point (``A`` or ``B`` has degree ``n >= 1``),
    so the constant check runs only when the fibre test is undecided.  Same errors, in the
    same order, before the resultant."""
    X, Y, W = curve_power(curve)
    g, (X, Y, W) = common_factor(X, Y, W)
    proper = proper_at_fiber(X, Y, W)
    if not proper:
        check_not_constant(X, Y, W)
    if g.degree() > 0 and warn:
        _warn_base_points(g, stacklevel=4)
    return X, Y, W, g, proper


def _padded(p, n: int) -> list:
    """The ``n + 1`` integer coefficients of an ``fmpz_poly`` of degree ``<= n``, lowest first."""
    c = [int(v) for v in p.coeffs()]
    return c + [0] * (n + 1 - len(c))


# grevlex with x > y > t: a polynomial free of t lists its terms in XY's order (same leading term)
_XYT = zctx(("x", "y", "_t_"), "degrevlex")


def _flint_resultant_xyt(X, Y, W):
    """``Res_t(W x - X, W y - Y)`` built directly in ``Z[x, y, t]`` for python-flint's
    resultant, left in that ring (free of ``t``): the route of ``resultant_coeffs(..., "flint")``
    without lifting coefficient lists from ``Z[x, y]`` term by term."""
    w = W.coeffs()
    a = {(1, 0, k): v for k, v in enumerate(w) if v}
    a.update({(0, 0, k): -v for k, v in enumerate(X.coeffs()) if v})
    b = {(0, 1, k): v for k, v in enumerate(w) if v}
    b.update({(0, 0, k): -v for k, v in enumerate(Y.coeffs()) if v})
    return _XYT.from_dict(a).resultant(_XYT.from_dict(b), "_t_")


def _flint_resultant_xy(X, Y, W):
    """:func:`_flint_resultant_xyt` projected to ``Z[x, y]``."""
    return _flint_resultant_xyt(X, Y, W).project_to_context(XY)


def _flint_applies(X, Y, W) -> bool:
    """flint needs both ``W x - X`` and ``W y - Y`` non-constant in t (else the curve is a line ``x = c``)."""
    return max(W.degree(), X.degree()) > 0 and max(W.degree(), Y.degree()) > 0


@dataclass
class _GrevlexTriangle:
    """An integer polynomial in ``x, y`` of total degree ``degree`` as the list of its
    coefficients (zeros included) over all monomials of total degree ``<= degree``, in
    grevlex order ``x^d, x^(d-1) y, ..., y^d, x^(d-1), ..., 1``."""

    degree: int
    coeffs: list

    def to_mpoly(self):
        return XY.from_dict({m: c for m, c in zip(_grevlex_monomials(self.degree), self.coeffs) if c})


@lru_cache(maxsize=64)
def _grevlex_monomials(n: int) -> tuple:
    """The exponents ``(i, j)``, ``i + j <= n``, in grevlex order (``x > y``, falling)."""
    return tuple((k - j, j) for k in range(n, -1, -1) for j in range(k + 1))


@lru_cache(maxsize=64)
def _grid_inverse(n: int) -> flint.fmpz_mat:
    """``D V^-1`` for an integer ``D > 0``, ``V`` the matrix of the monomials of
    :func:`_grevlex_monomials` at the points ``(i, j)``, ``i + j <= n`` (``i`` outer, ``j`` inner).
    The triangular grid is unisolvent for polynomials of total degree ``<= n``."""
    V = flint.fmpz_mat([[i**a * j**b for a, b in _grevlex_monomials(n)] for i in range(n + 1) for j in range(n + 1 - i)])
    return flint.fmpq_mat(V).inv().numer_denom()[0]


@lru_cache(maxsize=64)
def _hankel_toeplitz_positions(n: int) -> tuple:
    """Positions in ``c + [0] * n`` (``c`` the ``n + 1`` coefficients, lowest first) of the
    entries of ``H_c = (c_(i+l+1))`` and ``T_c = (c_(j-l))_(l <= j)`` (``n x n``, row-major)."""
    zero = n + 1
    hankel = tuple(i + l + 1 for i in range(n) for l in range(n))
    toeplitz = tuple(j - l if j >= l else zero for l in range(n) for j in range(n))
    return hankel, toeplitz


def _bezout_pencil(X, Y, W, n: int) -> tuple:
    """Integer ``n x n`` matrices ``(A_x, A_y, C)`` with ``Bez_n(W x - X, W y - Y) = x A_x + y A_y + C``.

    ``Bez_n(f, g)`` is the Bezout matrix of formal degree ``n`` (notes 17.3.4: the
    coefficients of ``(f(s) g(t) - f(t) g(s)) / (s - t)``), here in the form
    ``H_f T_g - H_g T_f`` with ``H`` Hankel and ``T`` upper triangular Toeplitz (the brackets
    ``f_k g_m - f_m g_k``, ``k + m = i + j + 1``, of :func:`resultants._bezout_rows`; the
    terms with ``m > min(i, j)`` cancel in pairs).  It is bilinear and alternating, so the
    ``x y`` term vanishes and ``A_x = Bez(Y, W)``, ``A_y = Bez(W, X)``, ``C = Bez(X, Y)``.
    """
    hankel, toeplitz = _hankel_toeplitz_positions(n)
    H, T = [], []
    for p in (X, Y, W):
        c = p.coeffs()
        c = c + [0] * (2 * n + 1 - len(c))
        H.append(flint.fmpz_mat(n, n, [c[k] for k in hankel]))
        T.append(flint.fmpz_mat(n, n, [c[k] for k in toeplitz]))
    (Hx, Hy, Hw), (Tx, Ty, Tw) = H, T
    return Hy * Tw - Hw * Ty, Hw * Tx - Hx * Tw, Hx * Ty - Hy * Tx


def _bezout_interpolated(X, Y, W) -> _GrevlexTriangle | None:
    """The implicit equation of a proper parametrization, normalized, from the determinant of
    the Bezout matrix (notes 17.3.4): ``det Bez_n(W x - X, W y - Y) = c Res_t(W x - X, W y - Y)``
    with an integer ``c != 0`` (one of the leading coefficients ``w_n x - x_n``, ``w_n y - y_n``
    is a non-zero constant when ``w_n = 0``).  Its entries are linear in ``x, y``, so the
    determinant, of total degree ``<= n``, is evaluated exactly (flint's integer determinant)
    at the ``(n + 1)(n + 2) / 2`` points of the triangular grid and interpolated by one
    product with the cached ``D V^-1``: integers, no resultant of polynomials.

    ``None`` when the determinant vanishes (never for reduced, non-constant input).
    """
    n = max(X.degree(), Y.degree(), W.degree())
    return _interpolated_normalized(_grid_determinants(*_bezout_pencil(X, Y, W, n), n), n)


def _grid_determinants(Ax, Ay, C, n: int) -> list:
    """``det(i A_x + j A_y + C)`` at the grid points ``(i, j)``, ``i + j <= n`` (``i`` outer)."""
    values = []
    row = C
    for i in range(n + 1):
        M = row
        for _ in range(n + 1 - i):
            values.append(M.det())
            M = M + Ay
        row = row + Ax
    return values


def _interpolated_normalized(values: list, n: int) -> _GrevlexTriangle | None:
    """The polynomial of total degree ``<= n`` taking ``values`` on the grid of
    :func:`_grid_determinants`, made primitive with a positive grevlex leading coefficient
    (``None`` if it is zero)."""
    coeffs = (_grid_inverse(n) * flint.fmpz_mat(len(values), 1, values)).entries()
    first = 0 if coeffs[0] else next((k for k, c in enumerate(coeffs) if c), None)
    if first is None:  # pragma: no cover - the resultant of a reduced curve is not zero
        return None
    # the content and the exact division by it in one flint polynomial holding the list
    packed = flint.fmpz_poly(coeffs[first:])
    g = packed.content()
    normalized = (packed // (-g if coeffs[first] < 0 else g)).coeffs()
    d = _grevlex_monomials(n)[first]
    d = d[0] + d[1]
    size = (d + 1) * (d + 2) // 2
    return _GrevlexTriangle(d, [0] * (size - (len(coeffs) - first)) + normalized + [0] * (len(coeffs) - first - len(normalized)))


def _xy_coeff_lists(X, Y, W) -> tuple[list, list]:
    """Coefficients (in t) of ``W x - X`` and ``W y - Y`` as integer polynomials in x, y."""
    x, y = XY.gens()
    n = max(p.degree() for p in (X, Y, W))
    cx, cy, cw = (_padded(p, n) for p in (X, Y, W))
    a = [cw[k] * x - cx[k] for k in range(n + 1)]
    b = [cw[k] * y - cy[k] for k in range(n + 1)]
    while len(a) > 1 and a[-1] == 0:
        a.pop()
    while len(b) > 1 and b[-1] == 0:
        b.pop()
    return a, b


def implicit_resultant(X, Y, W, via: str = "flint"):
    """``Res_t(W x - X, W y - Y)`` (17.5) as an ``fmpz_mpoly`` (not normalized).

    ``via``: ``"flint"`` (subresultants), ``"sylvester"`` or ``"bezout"`` (Bareiss
    on the power-form matrices of 17.3).
    """
    if via == "flint" and _flint_applies(X, Y, W):
        return _flint_resultant_xy(X, Y, W)
    a, b = _xy_coeff_lists(X, Y, W)
    return resultant_coeffs(a, b, "sylvester" if via == "flint" else via)


def _bernstein_xy_lists(X, Y, W) -> tuple[list, list]:
    """Bernstein coefficients of ``W x - X`` and ``W y - Y`` (degree n) over Z[x, y]."""
    from .moving_lines import _bernstein_hom

    P = _bernstein_hom(X, Y, W)
    import math

    den = 1
    for p in P:
        for v in p:
            den = den * int(v.denominator) // math.gcd(den, int(v.denominator))
    x, y = XY.gens()
    a = [int(p[2] * den) * x - int(p[0] * den) for p in P]
    b = [int(p[2] * den) * y - int(p[1] * den) for p in P]
    return a, b


def bezier_bezout_matrix(X, Y, W) -> list[list]:
    """The ``n x n`` matrix of 17.6 (entries sums of ``l_ij``) over Z[x, y]."""
    a, b = _bernstein_xy_lists(X, Y, W)
    return bezout_matrix_bernstein(a, b)


def implicit_bezier(X, Y, W):
    """Determinant of the Bernstein Bezout matrix (17.6), ``fmpz_mpoly`` (not normalized)."""
    M = bezier_bezout_matrix(X, Y, W)
    if len(M) == 0:
        raise InputError("degree-0 curve")
    return det_bareiss(M)


def implicit_moving_lines(X, Y, W, via: str = "flint"):
    """Resultant of a mu-basis (18.85), ``fmpz_mpoly`` (not normalized).

    ``via``: how the resultant of the two moving lines is evaluated -- ``"flint"``
    (default, fastest measured) or ``"bezout"`` (the notes' ``(n - mu) x (n - mu)``
    determinant).
    """
    from .moving_lines import _bernstein_hom, _is_basis, implicit_from_moving_lines, mu_basis_nullspace, zeroing_process

    n = max(p.degree() for p in (X, Y, W))
    pair = None
    if n >= 2:
        try:
            res = zeroing_process(_bernstein_hom(X, Y, W))
            if len(res.lines) == 2 and _is_basis(res.lines[0], res.lines[1], X, Y, W):
                pair = res.lines
        except Exception:  # noqa: BLE001 - special curve: fall back to the null space
            pair = None
    if pair is None:
        pair = mu_basis_nullspace(X, Y, W)
    p, q = pair
    if p.degree == 0 or q.degree == 0:
        # a fixed line follows the curve: the curve is (part of) that line
        line = p if p.degree == 0 else q
        return line.xy_coefficients()[0]
    return implicit_from_moving_lines(p, q, via)


def l_matrix(curve) -> dict:
    """The ``l_ij(x, y)`` of 17.6 (``i > j``) as sympy expressions in ``x, y``.

    ``l_ij = C(n,i) C(n,j) w_i w_j |x y 1; x_i y_i 1; x_j y_j 1|`` for the stored
    Bézier form of the curve (no degree reduction).
    """
    from ..exact.bernstein import binomial
    from ..exact.scalars import to_sympy

    hom = curve.homogeneous()
    n = curve.degree
    out = {}
    for i in range(n + 1):
        for j in range(i):
            Pi, Pj = hom[i], hom[j]
            M = sympy.Matrix([[X_SYM, Y_SYM, 1], [to_sympy(Pi[0]), to_sympy(Pi[1]), to_sympy(Pi[2])], [to_sympy(Pj[0]), to_sympy(Pj[1]), to_sympy(Pj[2])]])
            out[(i, j)] = sympy.expand(binomial(n, i) * binomial(n, j) * M.det())
    return out


def proper_at_fiber(X, Y, W, t0: int = 0) -> bool:
    """A cheap proof that the parametrization ``(X : Y : W)`` is proper (index ``r = 1``).

    ``True`` when ``W(t0) != 0``, ``A(s) = X(s) W(t0) - X(t0) W(s)`` or
    ``B(s) = Y(s) W(t0) - Y(t0) W(s)`` has the full degree ``n = max deg(X, Y, W)`` and
    ``deg gcd(A, B) = 1``; ``False`` means "not decided" (never "improper").

    Proof.  ``X, Y, W`` are coprime (base points removed) and the curve is not a point.
    By Lüroth's theorem the parametrization is ``Q(phi(s))`` with ``Q`` proper and ``phi``
    a rational function of degree ``r`` (the index: the resultant is ``c F^r``, notes
    17.5, 18.3).  The fibre ``phi^-1(phi(t0))`` has ``r`` points of the projective line
    counted with multiplicity; each point ``s`` of it has ``(X : Y : W)(s) = (X : Y : W)(t0)``,
    an affine point since ``W(t0) != 0``, so ``W(s) != 0`` and ``x(s) - x(t0)`` (``x = X/W``)
    vanishes at ``s`` to at least the multiplicity of ``phi - phi(t0)`` there; the same
    holds for the homogenized degree-``n`` forms of ``A`` and ``B``.  The fibre point at
    infinity would be a common root at infinity, i.e. ``deg A < n`` and ``deg B < n``;
    with one of them of degree ``n`` all ``r`` fibre points are finite common roots, so
    ``r <= deg gcd(A, B)``, and ``deg gcd = 1`` (``t0`` itself is a root) gives ``r = 1``.

    >>> import flint
    >>> X, Y, W = flint.fmpz_poly([0, 1]), flint.fmpz_poly([0, 0, 1]), flint.fmpz_poly([1])
    >>> proper_at_fiber(X, Y, W), proper_at_fiber(X * X, Y * Y, W)   # (t, t^2) and (t^2, t^4)
    (True, False)
    """
    w0 = W(t0)
    if w0 == 0:
        return False
    n = max(X.degree(), Y.degree(), W.degree())
    A = X * w0 - W * X(t0)
    B = Y * w0 - W * Y(t0)
    if max(A.degree(), B.degree()) < n:
        return False
    return A.gcd(B).degree() == 1


def _finish(R, g, n: int, proper: bool = False) -> ImplicitEquation:
    """Normalized implicit equation from the resultant ``R = c F^r``; ``proper=True``
    (proved by :func:`proper_at_fiber`) skips the squarefree factorization (``r = 1``)."""
    if R == 0:  # pragma: no cover - base points were removed
        raise ArithmeticError("the resultant vanished identically")
    if proper and isinstance(R, flint.fmpz_mpoly) and R.context() is _XYT:
        # normalized where it was computed (its grevlex leading term is XY's), projected on demand
        content = R.content()
        F = R / content if content != 1 else R
        F = -F if F.leading_coefficient() < 0 else F
        return ImplicitEquation(F, int(F.total_degree()), 1, g, n)
    if not isinstance(R, flint.fmpz_mpoly) or R.context() is not XY:
        R = XY.from_dict({tuple(m): int(c) for m, c in R.to_dict().items()}) if isinstance(R, flint.fmpz_mpoly) else XY.from_dict({(0, 0): int(R)})
    if proper:
        F = normalize_implicit(R)
        return ImplicitEquation(F, int(F.total_degree()), 1, g, n)
    _, factors = R.factor_squarefree()
    factors = [(f, int(e)) for f, e in factors if f.total_degree() > 0]
    if len(factors) != 1:  # pragma: no cover - the image of a rational curve is irreducible
        raise ArithmeticError(f"resultant is not a power of one polynomial: {factors}")
    F, r = factors[0]
    F = normalize_implicit(F)
    if r > 1:
        warnings.warn(
            f"the parametrization is not proper: it traces its curve {r} times "
            f"(the resultant is F^{r}); returning F",
            ImproperParametrizationWarning,
            stacklevel=3,
        )
    return ImplicitEquation(F, int(F.total_degree()), r, g, n)


def implicit_equation(curve, method: str = "resultant", strict: bool = False) -> ImplicitEquation:
    """Implicit equation with diagnostics (index of the parametrization, base factor).

    ``strict=True`` rejects degenerate parametrizations instead of warning:
    :class:`BasePointError` for a common factor of ``X, Y, W`` and
    :class:`ImproperParametrizationError` when the resultant is a power ``F^r``.
    """
    if method not in ROUTES:
        raise InputError(f"unknown implicitization method {method!r}; choose one of {ROUTES}")
    X, Y, W, g, proper = _reduced_and_proper(curve, warn=not strict)
    if strict and g.degree() > 0:
        raise BasePointError(f"the parametrization has base points: X, Y, W share the factor {_in_t(g)} (notes 18.3.4)")
    n = max(X.degree(), Y.degree(), W.degree())
    if method == "resultant" and proper and (F := _bezout_interpolated(X, Y, W)) is not None:
        return ImplicitEquation(F, F.degree, 1, g, n)
    if method == "resultant":
        R = _flint_resultant_xyt(X, Y, W) if proper and _flint_applies(X, Y, W) else implicit_resultant(X, Y, W)
    elif method == "bezier":
        R = implicit_bezier(X, Y, W)
    else:
        R = implicit_moving_lines(X, Y, W)
    if strict:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", ImproperParametrizationWarning)
            eq = _finish(R, g, n, proper)
        if eq.index > 1:
            raise ImproperParametrizationError(
                f"the parametrization is not proper: the resultant is F^{eq.index} with F = {eq.poly.as_expr()} "
                f"(the curve is traced {eq.index} times)"
            )
        return eq
    return _finish(R, g, n, proper)


def implicitize(curve, method: str = "resultant", strict: bool = False) -> sympy.Poly:
    """Implicit equation ``f(x, y) = 0`` of a planar (rational) Bézier curve.

    Parameters
    ----------
    curve : BezierCurve
        planar, polynomial or rational.
    method : ``"resultant"`` (17.5), ``"bezier"`` (17.6) or ``"moving_lines"`` (18.4.6).
    strict : reject base points (:class:`BasePointError`) and improper
        parametrizations (:class:`ImproperParametrizationError`, message names the
        power ``F^r``) instead of warning and returning the reduced equation.

    Returns
    -------
    sympy.Poly in ``x, y`` over ZZ: primitive, positive leading coefficient in
    grevlex (``x > y``).  Degree ``n`` for a proper curve of true degree ``n``.

    Examples
    --------
    >>> from exactcagd import BezierCurve
    >>> quarter = BezierCurve([[1, 0], [1, 1], [0, 1]], weights=[1, 1, 2])
    >>> implicitize(quarter, method="moving_lines").as_expr()
    x**2 + y**2 - 1
    """
    return implicit_equation(curve, method, strict).poly
