"""Curve-curve intersection by implicitization and inversion (notes 17.8, 7.3.1),
and intersection of two implicit curves (19.3).

``intersect(curve1, curve2)``:

1. implicitize curve 1: ``F(x, y) = 0`` (17.5);
2. substitute curve 2: ``h(t2) = F_hom(X2, Y2, W2)`` of degree ``deg F * n2``
   (17.8, "after multiplying through by W^3");
3. isolate the real roots of ``h`` in ``[0, 1]`` exactly (:func:`real_roots`);
4. recover ``t1`` by the inversion formula of curve 1 evaluated in the algebraic
   number ``t2`` -- an element of ``Q(t2)`` whose minimal polynomial and isolating
   interval are computed exactly (:func:`algebraic_value`).  At a singular point of
   curve 1 the formula is ``0/0``; then the candidates are the roots of
   ``gcd_u(Res_s(m(s), X1(u) W2(s) - X2(s) W1(u)), Res_s(m(s), Y1(u) W2(s) - Y2(s) W1(u)))``
   and each is confirmed by comparing the intersection point's coordinates
   exactly;
5. multiplicity = order of contact (7.3.1): the multiplicity of ``t2`` as a root of
   ``h`` when the point is simple on curve 1 (else the symmetric computation with
   the roles exchanged; ``None`` when the point is singular on both curves).

>>> from exactcagd import BezierCurve
>>> a = BezierCurve([[0, 0], [1, 2], [2, 0]])
>>> b = BezierCurve([[0, 1], [2, 0]])
>>> [(str(i.t1), str(i.t2), i.multiplicity) for i in intersect(a, b)]
[('1/4', '1/4', 1), ('1', '1', 1)]
"""

from __future__ import annotations

from dataclasses import dataclass

import flint
import sympy

from ..errors import InputError, NotSupportedError
from ..exact.algebraic import RealAlgebraic, real_roots
from ._diagnostics import ImproperParametrizationError
from ._poly import X_SYM, Y_SYM, zctx
from .implicitize import implicit_equation, reduced_components
from .numberfield import algebraic_sign, algebraic_value, as_fmpq_poly

__all__ = [
    "CurveIntersection",
    "Overlap",
    "shared_arcs",
    "drop_covered",
    "OverlapError",
    "intersect",
    "intersection_polynomial",
    "substitute",
    "implicit_intersections",
]


@dataclass
class CurveIntersection:
    """One intersection: parameters on both curves, the point, the order of contact.

    ``multiplicity`` is the order of contact (7.3.1) of the two branches; ``None``
    when the point is singular on both curves (not computed).  ``point`` is
    ``(x, y)`` as :class:`RealAlgebraic`.
    """

    t1: RealAlgebraic
    t2: RealAlgebraic
    multiplicity: int | None
    point: tuple

    def __iter__(self):
        return iter((self.t1, self.t2))


class OverlapError(NotSupportedError):
    """The curves lie on the same algebraic curve (infinitely many common points).

    ``mapping``: coefficients ``(a, b, c, d)`` of ``t1 = (a t2 + b) / (c t2 + d)`` when
    both parametrizations are proper (else ``None``); ``t2_intervals``: maximal
    sub-intervals of [0, 1] in ``t2`` mapped into [0, 1] (rational endpoints);
    ``overlaps``: the shared arcs (:class:`Overlap`, exact ends, any reparametrization);
    ``points``: the other common points ``(t1, t2)`` (self-crossings, contacts).
    """

    def __init__(self, message, mapping=None, t2_intervals=None, overlaps=None, points=None):
        super().__init__(message)
        self.mapping = mapping
        self.t2_intervals = t2_intervals or []
        self.overlaps = overlaps or []
        self.points = points or []


# ------------------------------------------------------------------ substitution
def _powers(p, k):
    out = [flint.fmpz_poly([1])]
    for _ in range(k):
        out.append(out[-1] * p)
    return out


def substitute(coeffs: dict, X, Y, W, degree: int | None = None) -> flint.fmpz_poly:
    """``sum c_ij X^i Y^j W^(m-i-j)``: an implicit polynomial (dict ``(i, j) -> c``)
    homogenized to degree ``m`` and evaluated on ``(X, Y, W)``; keys ``(i, j, k)``
    are taken as a homogeneous form.

    Homogeneous Horner scheme: ``sum_j Y^j S_j`` with ``S_j = sum_i c_ij X^i W^(m-j-i)``,
    each ``S_j`` by Horner in ``X`` (one product by ``X`` per term instead of a product of
    three powers): half the polynomial products of the direct sum, and those of
    degree ``m n`` (curve 2 of degree 20 in a degree-20 implicit equation: 1.1 -> 0.4 s).
    """
    if not coeffs:
        return flint.fmpz_poly([])
    m = degree if degree is not None else max(sum(k[:2]) if len(k) == 2 else sum(k) for k in coeffs)
    rows: dict[int, dict[int, int]] = {}
    for key, c in coeffs.items():
        i, j = key[0], key[1]
        if len(key) == 3 and i + j + key[2] != m:
            raise InputError(f"substitute: the form is not homogeneous of degree {m} (term {key})")
        rows.setdefault(j, {})[i] = rows.get(j, {}).get(i, 0) + int(c)
    PW = _powers(W, m) if W.degree() > 0 else None
    acc = flint.fmpz_poly([])
    for j in range(m, -1, -1):
        d = m - j
        row = rows.get(j, {})
        s_j = flint.fmpz_poly([])
        for i in range(d, -1, -1):
            s_j = s_j * X
            c = row.get(i, 0)
            if c:
                s_j += c * PW[d - i] if PW is not None else c * W ** (d - i)
        acc = acc * Y + s_j
    return acc


def _mpoly_dict(p) -> dict:
    return {tuple(int(e) for e in m): int(c) for m, c in p.to_dict().items()}


def intersection_polynomial(curve1, curve2) -> flint.fmpz_poly:
    """``h(t2) = F1(P2(t2))`` cleared of the weight denominator (17.8), integer coefficients."""
    eq = implicit_equation(curve1)
    X2, Y2, W2, _ = reduced_components(curve2, warn=False)
    return substitute(_mpoly_dict(eq.mpoly), X2, Y2, W2, eq.degree)


def _root_multiplicity(h: flint.fmpz_poly, alpha: RealAlgebraic) -> int:
    m = alpha.poly
    k = 0
    while h != 0 and h.degree() >= m.degree():
        q, r = divmod(h, m)
        if r != 0:
            break
        h, k = q, k + 1
    return k


def _gradient_forms(mpoly, degree):
    """Homogeneous partials of F (as dicts of homogeneous monomials)."""
    hom = {}
    for (i, j), c in _mpoly_dict(mpoly).items():
        hom[(i, j, degree - i - j)] = c
    parts = []
    for v in range(3):
        d = {}
        for key, c in hom.items():
            if key[v] > 0:
                nk = list(key)
                nk[v] -= 1
                d[tuple(nk)] = d.get(tuple(nk), 0) + c * key[v]
        parts.append(d)
    return parts


def _singular_at(grad, comps, alpha) -> bool:
    X, Y, W = comps
    return all(algebraic_sign(alpha, as_fmpq_poly(substitute(g, X, Y, W))) == 0 for g in grad if g)


def _point(alpha, comps):
    X, Y, W = comps
    return (algebraic_value(alpha, as_fmpq_poly(X), as_fmpq_poly(W)), algebraic_value(alpha, as_fmpq_poly(Y), as_fmpq_poly(W)))


def _candidates_by_elimination(alpha, comps1, comps2) -> list[RealAlgebraic]:
    """Parameters u on curve 1 with P1(u) = P2(alpha): roots of the gcd of two norms."""
    X1, Y1, W1 = comps1
    X2, Y2, W2 = comps2
    ctx = zctx(("s", "u"), "lex")
    s, u = ctx.gens()

    def lift(p, var):
        return sum((int(c) * var**k for k, c in enumerate(p.coeffs())), ctx.from_dict({}))

    m = lift(alpha.poly, s)
    norms = []
    for A1, A2 in ((X1, X2), (Y1, Y2)):
        F = lift(A1, u) * lift(W2, s) - lift(A2, s) * lift(W1, u)
        N = m.resultant(F, "s")
        if N != 0:
            norms.append(flint.fmpz_poly([int(N.to_dict().get((0, k), 0)) for k in range(max((e[1] for e in N.to_dict()), default=0) + 1)]))
    if not norms:  # pragma: no cover - curve 1 constant
        return []
    G = norms[0]
    for N in norms[1:]:
        G = G.gcd(N)
    if G.degree() < 1:
        return []
    target = _point(alpha, comps2)
    out = []
    for u0, _ in real_roots([int(c) for c in G.coeffs()], 0, 1):
        if algebraic_sign(u0, as_fmpq_poly(W1)) == 0:
            continue
        if _point(u0, comps1) == target:
            out.append(u0)
    return out


def _inversion_forms(curve):
    """Homogeneous inversion forms (f_h, g_h) as dicts, or None (improper)."""
    from .inversion import inversion_linear_algebra

    try:
        formula = inversion_linear_algebra(curve)
    except ImproperParametrizationError:
        return None
    w = sympy.Symbol("w")
    f_h, g_h = formula.homogeneous
    conv = lambda e: {k: int(v) for k, v in sympy.Poly(e, X_SYM, Y_SYM, w).as_dict().items()}  # noqa: E731
    return conv(f_h), conv(g_h)


def intersect(curve1, curve2) -> list[CurveIntersection]:
    """All intersections of two planar Bézier curves for parameters in [0, 1], exactly.

    Returns
    -------
    list of :class:`CurveIntersection` ``(t1, t2, multiplicity, point)`` sorted by
    ``(t1, t2)``; ``t1, t2`` are :class:`RealAlgebraic`.  A point where curve 1
    passes twice (a double point hit by curve 2) gives one entry per branch.

    Two curves on one algebraic curve that share no arc meet in finitely many points
    (end-point contacts, self-crossings of the shared curve); they are returned with
    ``multiplicity=None`` (the curves coincide there as algebraic curves).

    Raises
    ------
    OverlapError
        when the curves share an arc (infinitely many points); ``overlaps`` holds the
        arcs with exact end parameters, ``points`` the other common points.
    """
    eq1 = implicit_equation(curve1)
    comps1 = reduced_components(curve1, warn=False)[:3]
    comps2 = reduced_components(curve2, warn=False)[:3]
    X2, Y2, W2 = comps2
    h = substitute(_mpoly_dict(eq1.mpoly), X2, Y2, W2, eq1.degree)
    if h == 0:
        # one algebraic curve: shared arcs (an error: infinitely many points), or only
        # finitely many common points (end-point contacts, self-crossings): returned
        overlaps, points = _shared_curve(comps1, comps2)
        if overlaps:
            err = _overlap(curve1, curve2, comps2)
            err.overlaps, err.points = overlaps, points
            raise err
        out = [CurveIntersection(a, b, None, _point(b, comps2)) for a, b in points]
        return sorted(out, key=lambda r: (r.t1, r.t2))
    grad1 = _gradient_forms(eq1.mpoly, eq1.degree)
    inv = _inversion_forms(curve1) if eq1.proper else None
    eq2 = None
    out = []
    for t2, mult in real_roots([int(c) for c in h.coeffs()], 0, 1):
        if algebraic_sign(t2, as_fmpq_poly(W2)) == 0:
            continue  # intersection at infinity
        t1_list = None
        if inv is not None:
            A = as_fmpq_poly(substitute(inv[0], X2, Y2, W2))
            B = as_fmpq_poly(substitute(inv[1], X2, Y2, W2))
            if algebraic_sign(t2, B) != 0:
                t1_list = [algebraic_value(t2, A, B)]
        if t1_list is None:
            t1_list = _candidates_by_elimination(t2, comps1, comps2)
        simple1 = not _singular_at(grad1, comps2, t2)
        for t1 in t1_list:
            if t1 < 0 or t1 > 1:
                continue
            if simple1:
                k = _root_multiplicity(h, t2)
            else:
                if eq2 is None:
                    eq2 = implicit_equation(curve2)
                    grad2 = _gradient_forms(eq2.mpoly, eq2.degree)
                    h1 = substitute(_mpoly_dict(eq2.mpoly), *comps1, eq2.degree)
                k = None if _singular_at(grad2, comps1, t1) else _root_multiplicity(h1, t1)
            out.append(CurveIntersection(t1, t2, k, _point(t2, comps2)))
    out.sort(key=lambda r: (r.t1, r.t2))
    return out


def _overlap(curve1, curve2, comps2) -> OverlapError:
    inv = _inversion_forms(curve1)
    if inv is None:
        return OverlapError("the curves lie on the same algebraic curve (infinitely many common points)")
    X2, Y2, W2 = comps2
    A = substitute(inv[0], X2, Y2, W2)
    B = substitute(inv[1], X2, Y2, W2)
    g = A.gcd(B)
    A, B = A // g, B // g
    get = lambda p, k: int(p.coeffs()[k]) if 0 <= k <= p.degree() else 0  # noqa: E731
    if max(A.degree(), B.degree()) > 1:
        return OverlapError("the curves lie on the same algebraic curve (curve 2 not proper)")
    a, b, c, d = get(A, 1), get(A, 0), get(B, 1), get(B, 0)
    # t2 in [0, 1] with phi(t2) in [0, 1]: phi is monotone between poles
    from gmpy2 import mpq

    cuts = {mpq(0), mpq(1)}
    for num in ((b, a), (b - d, a - c), (d, c)):  # phi = 0, phi = 1, pole
        if num[1] != 0:
            r = mpq(-num[0], num[1])
            if 0 < r < 1:
                cuts.add(r)
    cuts = sorted(cuts)
    intervals = []
    for lo, hi in zip(cuts, cuts[1:]):
        mid = (lo + hi) / 2
        den = c * mid + d
        if den != 0 and 0 <= (a * mid + b) / den <= 1:
            if intervals and intervals[-1][1] == lo:
                intervals[-1] = (intervals[-1][0], hi)
            else:
                intervals.append((lo, hi))
    return OverlapError(
        "the curves lie on the same algebraic curve (infinitely many common points)",
        mapping=(a, b, c, d),
        t2_intervals=intervals,
    )


# ------------------------------------------------------------------ shared algebraic curve
@dataclass(frozen=True)
class Overlap:
    """An arc shared by both curves: ``curve1([a, b])`` and ``curve2([c, d])`` coincide.

    Attributes
    ----------
    t1_interval, t2_interval : (RealAlgebraic, RealAlgebraic)
        Exact end parameters on each curve (``lo < hi``); on the arc the parameters
        correspond one to one (arcs are cut where the relation folds).
    relation : str
        ``C(s, t) = 0`` between ``s = t1`` and ``t = t2`` on the arc (the common factor
        of ``X1 W2 - X2 W1`` and ``Y1 W2 - Y2 W1``), e.g. ``"2*s - t - 1"``.
    """

    t1_interval: tuple
    t2_interval: tuple
    relation: str

    def contains(self, s, t) -> bool:
        """True when exact parameters lie in the parameter box of the arc."""
        (a, b), (c, d) = self.t1_interval, self.t2_interval
        return bool(a <= s) and bool(s <= b) and bool(c <= t) and bool(t <= d)


def _rows(f, var: int) -> list:
    """``f = sum_k c_k(other) v^k`` for the variable ``var`` (0 = s, 1 = t): the ``c_k``."""
    d = f.to_dict()
    deg = max((e[var] for e in d), default=0)
    rows = [[] for _ in range(deg + 1)]
    for e, c in d.items():
        row, i = rows[e[var]], e[1 - var]
        if len(row) <= i:
            row.extend([0] * (i + 1 - len(row)))
        row[i] += int(c)
    return [flint.fmpz_poly(r) for r in rows]


def _roots01(p) -> list:
    return [r for r, _ in real_roots([int(c) for c in p.coeffs()], 0, 1)] if p.degree() >= 1 else []


def _between(a: RealAlgebraic, b: RealAlgebraic):
    """A rational strictly between ``a < b``."""
    while not a.hi < b.lo:
        for x in (a, b):
            if not x.is_rational:
                x.refine((x.hi - x.lo) / 2)
    return (a.hi + b.lo) / 2


def _monotone_arcs(num, den, v0, v1) -> list:
    """``[((a, b), (u_min, u_max))]``: ``[v0, v1]`` cut where ``u = num / den`` turns (roots
    of ``num' den - num den'``), so each arc is a one-to-one piece of the overlap."""
    cuts = [v0] + [r for r in _roots01(num.derivative() * den - num * den.derivative()) if v0 < r < v1] + [v1]
    out = []
    for a, b in zip(cuts, cuts[1:]):
        ends = sorted([algebraic_value(a, num, den), algebraic_value(b, num, den)])
        out.append(((a, b), (ends[0], ends[1])))
    return out


def _arcs(c0, c1):
    """Arcs and isolated points of ``u = -c0(v) / c1(v)`` inside [0, 1]^2.

    The graph can enter or leave the square only where ``v`` is 0 or 1, ``u`` is 0 or 1,
    or at a pole: between consecutive such cuts it is inside or outside throughout
    (tested at a rational point).  Inside stretches joined at a cut that is not a pole
    form one arc; a cut inside the square with no arc on either side is a contact point.
    """
    from gmpy2 import mpq

    num = -c0
    zero, one = RealAlgebraic.from_rational(0), RealAlgebraic.from_rational(1)
    cuts = sorted([zero, one] + [r for p in (c1, c0, c0 + c1) for r in _roots01(p)])
    cuts = [c for k, c in enumerate(cuts) if k == 0 or not c == cuts[k - 1]]

    def inside(v) -> bool:
        if algebraic_sign(v, as_fmpq_poly(c1)) == 0:
            return False
        return zero <= algebraic_value(v, num, c1) <= one

    segments = [inside(RealAlgebraic.from_rational(mpq(_between(a, b)))) for a, b in zip(cuts, cuts[1:])]
    arcs, points = [], []
    k = 0
    while k < len(segments):
        if not segments[k]:
            k += 1
            continue
        j = k
        while j + 1 < len(segments) and segments[j + 1] and algebraic_sign(cuts[j + 1], as_fmpq_poly(c1)) != 0:
            j += 1
        arcs.extend(_monotone_arcs(num, c1, cuts[k], cuts[j + 1]))
        k = j + 1
    for i, c in enumerate(cuts):
        near = (i > 0 and segments[i - 1]) or (i < len(segments) and segments[i])
        if not near and inside(c):
            points.append((c, algebraic_value(c, num, c1)))
    return arcs, points


def shared_arcs(C) -> tuple[list, list]:
    """Arcs (:class:`Overlap`) and contact points ``(s, t)`` of ``C(s, t) = 0`` in [0, 1]^2.

    ``C`` (an ``fmpz_mpoly`` in ``s, t``) is the common factor of ``A = X1 W2 - X2 W1`` and
    ``B = Y1 W2 - Y2 W1`` of two curves on one algebraic curve.  Each irreducible factor
    linear in one parameter is a rational reparametrization ``t = phi(s)`` (Möbius for
    proper parametrizations, of higher degree when one is improper, notes 17.5).

    Raises
    ------
    NotSupportedError
        A factor of degree > 1 in both parameters (both parametrizations improper with
        no common rational reparametrization).
    """
    overlaps, points = [], []
    _, factors = C.factor()
    for f, _e in factors:
        deg_s, deg_t = f.degrees()
        if deg_s == 0 or deg_t == 0:
            continue  # a factor in one parameter only: no arc (a constant coordinate)
        if deg_t == 1:
            arcs, pts = _arcs(*_rows(f, 1))
            overlaps.extend(Overlap(S, T, str(f)) for S, T in arcs)
            points.extend(pts)
        elif deg_s == 1:
            arcs, pts = _arcs(*_rows(f, 0))
            overlaps.extend(Overlap(S, T, str(f)) for T, S in arcs)
            points.extend((a, b) for b, a in pts)
        else:
            raise NotSupportedError(
                f"the curves lie on one algebraic curve, related by {f} = 0 of degree > 1 in both parameters; not supported")
    return overlaps, points


def drop_covered(points: list, overlaps: list) -> list:
    """Points not on a shared arc, without repeats."""
    out = []
    for a, b in points:
        if any(o.contains(a, b) for o in overlaps) or any(a == x and b == y for x, y in out):
            continue
        out.append((a, b))
    return out


def _shared_curve(comps1, comps2) -> tuple[list, list]:
    """Overlaps and the finitely many other common points of curves on one algebraic curve."""
    from .solve import common_points

    ctx = zctx(("s", "t"), "lex")
    s, t = ctx.gens()

    def lift(p, var):
        return sum((int(c) * var**k for k, c in enumerate(p.coeffs())), ctx.from_dict({}))

    X1, Y1, W1 = (lift(p, s) for p in comps1)
    X2, Y2, W2 = (lift(p, t) for p in comps2)
    A, B = X1 * W2 - X2 * W1, Y1 * W2 - Y2 * W1
    C = A.gcd(B)
    overlaps, points = shared_arcs(C)
    A1, B1 = A // C, B // C
    if not (A1.is_constant() or B1.is_constant()):
        points.extend((a, b) for a, b in common_points([A1, B1]) if 0 <= a <= 1 and 0 <= b <= 1)
    return overlaps, drop_covered(points, overlaps)



def implicit_intersections(f, g) -> list[tuple[RealAlgebraic, RealAlgebraic]]:
    """Real intersection points of two implicit curves ``f = g = 0`` (19.3).

    The x-resultant (eliminating ``x``) gives the ``y`` coordinates; for each real
    root the ``x`` coordinate is found exactly by Euclid's algorithm over ``Q(y0)``
    (19.3), after a shear ``x -> x + c y`` if two points share a ``y``.

    Parameters
    ----------
    f, g : sympy expressions / Poly in ``x, y``.
    """
    from .solve import common_points

    return common_points([f, g])
