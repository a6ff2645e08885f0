"""Implicitization of rational surfaces and their base points (notes 17.9, 17.10).

A rational surface is ``x = X/W, y = Y/W, z = Z/W`` with polynomials in ``(s, t)``:
*triangular* (total degree ``n``, implicit degree generally ``n^2``) or
*tensor-product* (bidegree ``(m, n)``, implicit degree generally ``2 m n``).  Each
base point (common zero of X, Y, Z, W, counted with multiplicity over C,
including parameters at infinity) lowers the degree by one (17.10).

Routes of :func:`implicitize_surface`:

``"linear_algebra"`` (default)
    undetermined coefficients (the idea of 19.6): the smallest ``d`` for which some
    ``F`` of degree ``d`` has ``F_hom(X, Y, Z, W) == 0``; exact null space
    (python-flint).  Needs no knowledge of base points.
``"dixon"``
    Dixon's resultant for tensor-product patches: the ``2mn x 2mn`` matrix of the
    Dixon polynomial, with entries linear in ``x, y, z`` (the Dixon polynomial is
    multilinear and alternating, so ``(x W - X, y W - Y, z W - Z)`` expand linearly).
``"groebner"``
    elimination of ``s, t, v`` from ``<W x - X, W y - Y, W z - Z, 1 - v W>``.

>>> import sympy
>>> s, t, u = sympy.symbols("s t u")
>>> sphere = SurfaceParametrization.from_polynomials(2*s, 2*t, 1 - s**2 - t**2, 1 + s**2 + t**2)
>>> implicitize_surface(sphere).as_expr()
x**2 + y**2 + z**2 - 1
>>> base_point_count(sphere)
2
"""

from __future__ import annotations

import random
from dataclasses import dataclass

import flint
import sympy

from .. import limits
from ..errors import DegreeError, InputError, NotSupportedError
from ..exact.scalars import to_sympy
from ._poly import mpoly_to_sympy, zctx
from .resultants import det_bareiss

__all__ = [
    "SurfaceParametrization",
    "implicitize_surface",
    "surface_implicit_degree_bound",
    "base_point_count",
    "base_points_affine",
]

S_SYM, T_SYM_S = sympy.symbols("s t")
XYZ_SYMS = sympy.symbols("x y z")
XYZ = zctx(("x", "y", "z"))


@dataclass
class SurfaceParametrization:
    """``(X, Y, Z, W)`` sympy polynomials in ``s, t`` and the kind of patch.

    ``kind``: ``"triangular"`` (degree = total degree) or ``"tensor"`` (degree =
    bidegree).
    """

    X: sympy.Expr
    Y: sympy.Expr
    Z: sympy.Expr
    W: sympy.Expr
    kind: str = "triangular"

    def __post_init__(self):
        if self.kind not in ("triangular", "tensor"):
            raise InputError("kind must be 'triangular' or 'tensor'")
        comps = [sympy.expand(sympy.sympify(c)) for c in (self.X, self.Y, self.Z, self.W)]
        free = set().union(*(c.free_symbols for c in comps)) - {S_SYM, T_SYM_S}
        if free:
            raise InputError(f"surface polynomials may only use s, t; found {sorted(map(str, free))}")
        if comps[3] == 0:
            raise InputError("W must not vanish identically")
        # clear denominators jointly
        den = 1
        for c in comps:
            for coef in sympy.Poly(c, S_SYM, T_SYM_S).coeffs():
                den = sympy.ilcm(den, sympy.Rational(coef).q)
        self.X, self.Y, self.Z, self.W = (sympy.expand(c * den) for c in comps)

    @classmethod
    def from_polynomials(cls, x, y, z, w=1, kind: str = "triangular") -> "SurfaceParametrization":
        return cls(x, y, z, w, kind)

    @classmethod
    def from_bezier_surface(cls, surface) -> "SurfaceParametrization":
        """Tensor-product :class:`BezierSurface` (3-D), power form in ``(s, t) = (u, v)``."""
        from ..geometry.bezier_surface import BezierSurface

        if not isinstance(surface, BezierSurface):
            raise InputError(f"surface: expected a BezierSurface, got {type(surface).__name__}")
        if surface.dimension != 3:
            raise InputError(f"surface implicitization needs a 3-D surface, got dimension {surface.dimension}")
        l, m = surface.degree
        limits.check("max_surface_implicit", 2 * l * m, f"implicit degree 2 l m of a degree ({l}, {m}) patch")
        hom = surface.homogeneous()
        s, t = S_SYM, T_SYM_S
        Bu = [sympy.binomial(l, i) * s**i * (1 - s) ** (l - i) for i in range(l + 1)]
        Bv = [sympy.binomial(m, j) * t**j * (1 - t) ** (m - j) for j in range(m + 1)]
        comps = [sum(to_sympy(hom[i, j, k]) * Bu[i] * Bv[j] for i in range(l + 1) for j in range(m + 1)) for k in range(4)]
        return cls(*comps, kind="tensor")

    @classmethod
    def from_triangular_bezier(cls, points: dict, weights: dict | None = None) -> "SurfaceParametrization":
        """Triangular Bézier patch ``sum n!/(i! j! k!) s^i t^j u^k w_ijk P_ijk`` with ``u = 1 - s - t``.

        ``points`` maps ``(i, j, k)``, ``i + j + k = n``, to 3-D points.
        """
        n = {sum(k) for k in points}
        if len(n) != 1:
            raise InputError("triangular control points must have indices summing to one degree")
        n = n.pop()
        need = {(i, j, n - i - j) for i in range(n + 1) for j in range(n + 1 - i)}
        if set(points) != need:
            raise InputError(f"a triangular patch of degree {n} needs the {len(need)} indices i + j + k = {n}")
        s, t = S_SYM, T_SYM_S
        u = 1 - s - t
        comps = [0, 0, 0, 0]
        for (i, j, k), p in points.items():
            w = sympy.Rational(str((weights or {}).get((i, j, k), 1)))
            basis = sympy.factorial(n) / (sympy.factorial(i) * sympy.factorial(j) * sympy.factorial(k)) * s**i * t**j * u**k
            vals = [sympy.Rational(str(v)) for v in p]
            if len(vals) != 3:
                raise InputError("triangular patch control points must be 3-D")
            for c in range(3):
                comps[c] += w * vals[c] * basis
            comps[3] += w * basis
        return cls(*comps, kind="triangular")

    def degrees(self):
        polys = [sympy.Poly(c, S_SYM, T_SYM_S) for c in (self.X, self.Y, self.Z, self.W)]
        if self.kind == "triangular":
            return max(p.total_degree() for p in polys)
        return (max(p.degree(S_SYM) for p in polys), max(p.degree(T_SYM_S) for p in polys))

    def components(self):
        return (self.X, self.Y, self.Z, self.W)


def surface_implicit_degree_bound(param: SurfaceParametrization) -> int:
    """``n^2`` (triangular) or ``2 m n`` (tensor): the generic implicit degree (17.9)."""
    d = param.degrees()
    return d * d if param.kind == "triangular" else 2 * d[0] * d[1]


# ------------------------------------------------------------------ helpers
def _st_mpoly(expr, ctx):
    P = sympy.Poly(expr, S_SYM, T_SYM_S)
    return ctx.from_dict({m: int(c) for m, c in P.terms()}) if not P.is_zero else ctx.from_dict({})


def _normalize3(vec_poly):
    content = vec_poly.content()
    if content != 1:
        vec_poly = vec_poly / content
    if vec_poly.leading_coefficient() < 0:
        vec_poly = -vec_poly
    return vec_poly


def _implicit_linear_algebra(param: SurfaceParametrization, max_degree: int):
    ctx = zctx(("s", "t"))
    X, Y, Z, W = (_st_mpoly(c, ctx) for c in param.components())
    for d in range(1, max_degree + 1):
        monos = [(a, b, c) for a in range(d + 1) for b in range(d + 1 - a) for c in range(d + 1 - a - b)]
        pw = {}

        def power(p, k, tag):
            key = (tag, k)
            if key not in pw:
                pw[key] = p**k
            return pw[key]

        columns = []
        rowkeys = {}
        for (a, b, c) in monos:
            q = power(X, a, "x") * power(Y, b, "y") * power(Z, c, "z") * power(W, d - a - b - c, "w")
            col = {tuple(int(e) for e in m): int(v) for m, v in q.to_dict().items()}
            for m in col:
                rowkeys.setdefault(m, len(rowkeys))
            columns.append(col)
        rows = len(rowkeys)
        if rows < len(monos) - 1 and rows == 0:
            continue
        entries = [0] * (rows * len(monos))
        for j, col in enumerate(columns):
            for m, v in col.items():
                entries[rowkeys[m] * len(monos) + j] = v
        mat = flint.fmpz_mat(rows, len(monos), entries)
        basis, nullity = mat.nullspace()
        if int(nullity) >= 1:
            vec = [int(basis[i, 0]) for i in range(len(monos))]
            F = XYZ.from_dict({m: v for m, v in zip(monos, vec) if v})
            return _normalize3(F)
    raise DegreeError(f"no implicit equation of degree <= {max_degree} (degenerate parametrization?)")


def _dixon(param: SurfaceParametrization):
    if param.kind != "tensor":
        raise NotSupportedError("the Dixon route is implemented for tensor-product patches")
    s, t = S_SYM, T_SYM_S
    al, be = sympy.symbols("alpha beta")
    X, Y, Z, W = param.components()

    def rows(f):
        return (f, f.subs(s, al), f.subs({s: al, t: be}, simultaneous=True))

    def dixon_poly(a, b, c):
        M = sympy.Matrix([rows(a), rows(b), rows(c)]).T
        num = sympy.expand(M.det())
        q, r = sympy.div(sympy.Poly(num, s, t, al, be), sympy.Poly((s - al) * (t - be), s, t, al, be))
        if not r.is_zero:  # pragma: no cover - the determinant vanishes at s = alpha, t = beta
            raise ArithmeticError("Dixon division not exact")
        return q

    # det(xW - X, yW - Y, zW - Z) = -det(X,Y,Z) + x det(W,Y,Z) + y det(X,W,Z) + z det(X,Y,W)
    parts = [(-1, None, dixon_poly(X, Y, Z)), (1, 0, dixon_poly(W, Y, Z)), (1, 1, dixon_poly(X, W, Z)), (1, 2, dixon_poly(X, Y, W))]
    rowset, colset = set(), set()
    for _, _, q in parts:
        for (i, j, k, l), _c in q.terms():
            rowset.add((i, j))
            colset.add((k, l))
    rows_, cols_ = sorted(rowset), sorted(colset)
    if len(rows_) != len(cols_):
        raise NotSupportedError(f"Dixon matrix is {len(rows_)} x {len(cols_)} (degenerate patch); use linear_algebra")
    gens = XYZ.gens()
    zero = XYZ.from_dict({})
    M = [[zero for _ in cols_] for _ in rows_]
    ri = {r: i for i, r in enumerate(rows_)}
    ci = {c: i for i, c in enumerate(cols_)}
    for sign, var, q in parts:
        for (i, j, k, l), c in q.terms():
            c = sympy.Rational(c)
            if c.q != 1:  # pragma: no cover - integer input
                raise ArithmeticError("non-integer Dixon coefficient")
            term = int(c) * sign
            M[ri[(i, j)]][ci[(k, l)]] += term * (gens[var] if var is not None else 1)
    D = det_bareiss(M)
    if D == 0:
        raise NotSupportedError("the Dixon determinant vanishes (base points); use linear_algebra")
    _, factors = D.factor_squarefree()
    factors = [(f, int(e)) for f, e in factors if f.total_degree() > 0]
    F = factors[0][0] if len(factors) == 1 else D
    return _normalize3(F)


def _groebner_route(param: SurfaceParametrization):
    from .groebner import eliminate

    v = sympy.Symbol("v_")
    x, y, z = XYZ_SYMS
    X, Y, Z, W = param.components()
    G = eliminate([W * x - X, W * y - Y, W * z - Z, 1 - v * W], [v, S_SYM, T_SYM_S], [x, y, z])
    if not G:
        raise DegreeError("elimination ideal is zero")
    best = min(G, key=lambda g: g.total_degree())
    P = sympy.Poly(best.as_expr() * sympy.ilcm(*[sympy.Rational(c).q for c in best.coeffs()]), x, y, z)
    return _normalize3(XYZ.from_dict({m: int(c) for m, c in P.terms()}))


def implicitize_surface(param, method: str = "linear_algebra") -> sympy.Poly:
    """Implicit equation ``F(x, y, z) = 0`` of a rational surface (17.9), exact.

    Parameters
    ----------
    param : :class:`SurfaceParametrization` or a 3-D ``BezierSurface``
    method : ``"linear_algebra"`` | ``"dixon"`` | ``"groebner"``

    Returns
    -------
    sympy.Poly in ``x, y, z``: integer, primitive, positive leading coefficient
    (grevlex).
    """
    from ..geometry.bezier_surface import BezierSurface

    if isinstance(param, BezierSurface):
        param = SurfaceParametrization.from_bezier_surface(param)
    if not isinstance(param, SurfaceParametrization):
        raise InputError("expected a SurfaceParametrization or a BezierSurface")
    if method == "linear_algebra":
        F = _implicit_linear_algebra(param, surface_implicit_degree_bound(param))
    elif method == "dixon":
        F = _dixon(param)
    elif method == "groebner":
        F = _groebner_route(param)
    else:
        raise InputError(f"unknown surface implicitization method {method!r}")
    return mpoly_to_sympy(F, XYZ_SYMS)


# ------------------------------------------------------------------ base points (17.10)
def base_points_affine(param: SurfaceParametrization) -> list[tuple]:
    """Real base points ``(s, t)`` in the affine parameter plane (exact, RealAlgebraic)."""
    from .solve import common_points

    comps = [sympy.expand(c.subs({S_SYM: XYZ_SYMS[0], T_SYM_S: XYZ_SYMS[1]})) for c in param.components()]
    comps = [c for c in comps if c != 0]
    try:
        return common_points(comps, (XYZ_SYMS[0], XYZ_SYMS[1]))
    except InputError:
        raise NotSupportedError("the components share a curve of zeros (not isolated base points)")


def base_point_count(param: SurfaceParametrization, seed: int = 1) -> int:
    """Number of base points over C with multiplicity, including those at infinity.

    Triangular: in the projective plane (homogeneous ``s, t, u``); tensor: in
    ``P^1 x P^1``.  A random integer change of coordinates moves every base point
    into the affine chart, where ``dim Q[s, t] / <X, Y, Z, W>`` counts them.
    """
    from .groebner import quotient_dimension

    rng = random.Random(seed)
    s, t, u = sympy.symbols("s t u")
    comps = param.components()
    for _ in range(20):
        if param.kind == "triangular":
            n = param.degrees()
            hom = [sympy.expand(u**n * c.subs({S_SYM: s / u, T_SYM_S: t / u})) for c in comps]
            A = sympy.Matrix(3, 3, lambda i, j: rng.randint(-3, 3))
            if A.det() == 0:
                continue
            sp, tp, up = sympy.symbols("sp tp up")
            new = A * sympy.Matrix([sp, tp, up])
            moved = [sympy.expand(h.subs({s: new[0], t: new[1], u: new[2]}, simultaneous=True)) for h in hom]
            at_inf = [sympy.expand(m.subs(up, 0)) for m in moved]
            if _binary_forms_common_zero(at_inf, sp, tp):
                continue
            affine = [sympy.expand(m.subs(up, 1)) for m in moved]
            return quotient_dimension(affine, [sp, tp])
        else:
            m_, n_ = param.degrees()
            sp, tp = sympy.symbols("sp tp")
            a, b, c, d = (rng.randint(-3, 3) for _ in range(4))
            e, f, g, h = (rng.randint(-3, 3) for _ in range(4))
            if a * d - b * c == 0 or e * h - f * g == 0:
                continue
            moved = [
                sympy.expand(sympy.cancel(comp.subs({S_SYM: (a * sp + b) / (c * sp + d), T_SYM_S: (e * tp + f) / (g * tp + h)}, simultaneous=True) * (c * sp + d) ** m_ * (g * tp + h) ** n_))
                for comp in comps
            ]
            if _tensor_infinity_clash(moved, sp, tp, m_, n_):
                continue
            return quotient_dimension(moved, [sp, tp])
    raise NotSupportedError("could not move the base points into the affine chart")


def _binary_forms_common_zero(forms, a, b) -> bool:
    forms = [f for f in forms if f != 0]
    if not forms:
        return True
    # point (1 : 0)
    if all(f.subs({a: 1, b: 0}) == 0 for f in forms):
        return True
    g = 0
    for f in forms:
        g = sympy.gcd(g, sympy.expand(f.subs(b, 1)))
    return sympy.Poly(g, a).degree() > 0 if g != 0 else True


def _tensor_infinity_clash(polys, sp, tp, m, n) -> bool:
    """Base point with ``s' = oo`` or ``t' = oo`` (bihomogeneous leading parts)."""
    lead_s = [sympy.Poly(p, sp).coeff_monomial(sp**m) if sympy.Poly(p, sp).degree() >= 0 else 0 for p in polys]
    lead_t = [sympy.Poly(p, tp).coeff_monomial(tp**n) if sympy.Poly(p, tp).degree() >= 0 else 0 for p in polys]
    lead_st = [sympy.Poly(p, sp, tp).coeff_monomial(sp**m * tp**n) for p in polys]
    if all(c == 0 for c in lead_st):
        return True

    def common(polys1, var):
        g = 0
        for q in polys1:
            g = sympy.gcd(g, sympy.expand(q))
        return g == 0 or sympy.Poly(g, var).degree() > 0

    return common(lead_s, tp) or common(lead_t, sp)
