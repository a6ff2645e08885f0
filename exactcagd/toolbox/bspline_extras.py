"""B-spline curves beyond the foundation: polar form on arbitrary knot vectors (exact).

Everything here rests on one mechanism, the polar form (blossom) of one B-spline
segment, evaluated by de Boor's triangle with a different argument on every level
(Sederberg's notes (003) 6.1, rule 4; 6.8).  A control point with polar label
``(u_1, ..., u_p)`` of a refined (or coarsened, or elevated) knot vector is the blossom
of a segment of the old spline at that label, so knot insertion, Bézier extraction,
clamping, degree elevation and knot removal are all the same computation.

Contents (notes chapter 6):

* :class:`SplineCurve` -- the name this module has always used for
  :class:`~exactcagd.geometry.bspline.BSplineCurve`, a (rational) B-spline on any knot
  vector, clamped or not, whose methods carry the polar-form operations;
* :func:`periodic_bspline` -- 6.5, closed curves;
* ``clamp`` -- 6.6, Bézier end conditions; ``derivative`` (6.10), ``greville`` (6.9),
  ``elevate`` (Ramshaw's rule (6.7)-(6.8)): methods of
  :class:`~exactcagd.geometry.bspline.BSplineCurve`, built on the polar form;
* :func:`symmetric_basis`, :func:`polar_form_power` -- 6.11, symmetric polynomials;
* :func:`bezier_chain_to_bspline`, :func:`continuity_order` -- 6.12;
* :func:`basis_function`, :func:`basis_function_pieces`, :func:`refine_basis_function`,
  :func:`basis_recurrence` -- 6.14 (explicit B-splines, refinement, recurrence).

Knot vectors use the standard convention ``len(knots) = n_points + p + 1``; the notes'
convention (6.2) drops the outermost knot on each side.

>>> from exactcagd.toolbox.bspline_extras import SplineCurve
>>> c = SplineCurve([[0, 0], [1, 2], [3, 2], [4, 0]], knots=range(7))   # uniform, unclamped
>>> c.domain
(mpq(2,1), mpq(4,1))
>>> c.evaluate(3)
(mpq(2,1), mpq(2,1))
"""

from __future__ import annotations

import bisect

import numpy as np
from gmpy2 import mpq

from .. import limits
from ..errors import DegreeError, DomainError, InputError, KnotError, NotSupportedError
from ..exact import bernstein as bz
from ..exact.scalars import to_count, to_rational
from ..geometry._validate import point_array
from ..geometry.bezier_curve import BezierCurve
from ..geometry.bspline import BSplineCurve

__all__ = [
    "segment_blossom",
    "SplineCurve",
    "periodic_bspline",
    "symmetric_basis",
    "polar_form_power",
    "polar_form_value",
    "continuity_order",
    "bezier_chain_to_bspline",
    "basis_function",
    "basis_function_pieces",
    "refine_basis_function",
    "refine_basis_function_multi",
    "basis_recurrence",
]

ZERO = mpq(0)


# ---------------------------------------------------------------------------- the mechanism
def segment_blossom(ctrl: np.ndarray, local_knots, args):
    """Polar form of one B-spline segment at ``args`` (notes 6.1 rule 4, 6.8).

    Parameters
    ----------
    ctrl : array, ``p + 1`` control values (trailing axes carried)
        The control points ``P_0..P_p`` of the segment; ``P_i`` has polar label
        ``(u_{i+1}, ..., u_{i+p})``.
    local_knots : ``2p`` knots ``u_1..u_{2p}``; the segment is ``[u_p, u_{p+1}]`` (non-empty).
    args : ``p`` parameters.

    Returns
    -------
    The polar value ``f(args)``; ``f(t, ..., t)`` is the point at ``t`` (de Boor).

    Examples
    --------
    >>> import numpy as np
    >>> from gmpy2 import mpq
    >>> ctrl = np.array([mpq(0), mpq(1), mpq(0)], dtype=object)   # quadratic, knots 0..3
    >>> segment_blossom(ctrl, [0, 1, 2, 3], [mpq(3, 2), mpq(3, 2)])
    mpq(3,4)
    """
    p = ctrl.shape[0] - 1
    u = [to_rational(k, where="knot") for k in local_knots]
    if len(u) != 2 * p:
        raise KnotError(f"a degree-{p} segment needs {2 * p} local knots, got {len(u)}")
    if len(args) != p:
        raise InputError(f"the polar form of a degree-{p} segment takes {p} arguments, got {len(args)}")
    if p > 0 and not u[p - 1] < u[p]:
        raise KnotError(f"empty segment [{u[p - 1]}, {u[p]}]")
    level = [ctrl[i] for i in range(p + 1)]
    for r in range(1, p + 1):
        x = to_rational(args[r - 1], where="polar argument")
        new = []
        for i in range(r, p + 1):
            # 1-based: alpha = (x - u_i) / (u_{i+p+1-r} - u_i)
            lo, hi = u[i - 1], u[i + p - r]
            alpha = (x - lo) / (hi - lo)
            new.append((1 - alpha) * level[i - r] + alpha * level[i - r + 1])
        level = new
    return level[0]


# ---------------------------------------------------------------------------- spline curve
#: A B-spline (or NURBS) curve on any knot vector: the geometry layer's class, which
#: carries the polar-form operations (``rebase``, ``insert_knots``, ``clamp``,
#: ``greville``, ``derivative``, ``elevate``, ``polar_value``, ...).  Kept under this
#: name for the toolbox's callers; ``SplineCurve is BSplineCurve``.
SplineCurve = BSplineCurve


# ---------------------------------------------------------------------------- periodic (6.5)
def periodic_bspline(control_points, degree: int, intervals=None, weights=None) -> SplineCurve:
    """A closed (periodic) B-spline (notes 6.5) as a :class:`SplineCurve`.

    The ``N`` control points form a closed polygon; ``intervals`` gives the ``N``
    knot intervals of the period (default all 1).  The curve is unrolled: the first
    ``p`` control points are repeated at the end and the knot intervals continue
    periodically, which is exactly the notes' condition "the first n control points
    are identical to the last n, and the first n parameter intervals identical to the
    last n".  The result closes with ``C^{p-1}`` continuity when the intervals are positive.

    Knot interval ``d_i`` is the length of the segment whose middle control point (even
    degree) or middle control edge ``P_i P_{i+1}`` (odd degree) has index ``i`` (6.13).

    Examples
    --------
    >>> c = periodic_bspline([[0, 0], [2, 0], [2, 2], [0, 2]], 2)
    >>> c.evaluate(c.domain[0]) == c.evaluate(c.domain[1])
    True
    """
    pts = point_array(control_points, 1, "control_points")
    n = pts.shape[0]
    p = to_count(degree, where="degree", error=DegreeError)
    limits.check("max_degree", p, "periodic_bspline: degree")
    if p < 1:
        raise DegreeError("a periodic B-spline needs degree >= 1")
    if n < p + 1:
        raise InputError(f"a periodic degree-{p} B-spline needs at least {p + 1} control points, got {n}")
    d = [mpq(1)] * n if intervals is None else [to_rational(x, where="interval") for x in intervals]
    if len(d) != n:
        raise KnotError(f"{n} control points need {n} knot intervals, got {len(d)}")
    if any(x < 0 for x in d) or sum(d) == 0:
        raise KnotError("knot intervals must be non-negative with a positive period")
    knots = periodic_knots(d, p, n + 2 * p + 1)
    w = None
    if weights is not None:
        w = list(weights) + list(weights)[:p]
    return SplineCurve(np.concatenate([pts, pts[:p]]), knots, weights=w)


def periodic_knots(intervals, degree: int, count: int, first: int = 0) -> list:
    """Knots ``k(first), ..., k(first + count - 1)`` of a periodic spline.

    ``k(j + 1) - k(j) = d_{(j - c) mod N}`` with ``c = ceil(p / 2)`` and ``k(c) = 0``
    (notes 6.13: the knot interval of control point / edge ``i``).
    """
    d = [to_rational(x) for x in intervals]
    n = len(d)
    c = (degree + 1) // 2

    def k(j):
        # k(c) = 0; k(j) = sum_{i=c}^{j-1} d_{(i-c) mod n} for j >= c, negative sum otherwise
        period = sum(d)
        q, r = divmod(j - c, n)
        return q * period + sum(d[:r])

    return [k(j) for j in range(first, first + count)]


# ---------------------------------------------------------------------------- symmetric polynomials (6.11)
def symmetric_basis(i: int, args):
    """The symmetric polynomial ``p_i[t_1..t_n]`` of notes 6.11, by the printed recursion.

    ``p_0 = 1``, ``p_i[t_1..t_n] = (1/n) sum_j t_j p_{i-1}[t_1..t_{j-1}, t_{j+1}..t_n]``;
    it equals ``e_i(t) / C(n, i)`` (normalized elementary symmetric function).  ``args``
    may be exact numbers or sympy symbols.

    >>> symmetric_basis(2, [1, 2, 3])
    mpq(11,3)
    """
    args = list(args)
    n = len(args)
    if i < 0 or i > n:
        raise InputError(f"p_{i} is defined for 0 <= i <= n = {n}")
    if i == 0:
        return mpq(1) if not _symbolic(args) else 1
    acc = 0
    for j in range(n):
        acc = acc + _num(args[j]) * symmetric_basis(i - 1, args[:j] + args[j + 1 :])
    return acc / n if _symbolic(args) else acc * mpq(1, n)


def _symbolic(args) -> bool:
    return any(type(a).__module__.startswith("sympy") and not getattr(a, "is_Rational", False) for a in args)


def _num(x):
    if type(x).__module__.startswith("sympy") and not getattr(x, "is_Rational", False):
        return x
    return to_rational(x)


def polar_form_power(power_coeffs, n: int | None = None) -> list:
    """Coefficients ``c_i`` of the polar form ``p[t_1..t_n] = sum_i c_i p_i[t_1..t_n]`` (notes 6.11).

    For ``p(t) = sum_k a_k t^k`` the polar form of degree ``n >= deg p`` has ``c_i = a_i``
    (zero beyond the degree): ``p_i[t, ..., t] = t^i``.
    """
    a = [to_rational(x, where="power coefficient") for x in power_coeffs]
    while len(a) > 1 and a[-1] == 0:
        a.pop()
    n = len(a) - 1 if n is None else int(n)
    if n < len(a) - 1:
        raise DegreeError(f"polar form of degree {n} < polynomial degree {len(a) - 1}")
    return a + [ZERO] * (n + 1 - len(a))


def polar_form_value(power_coeffs, args):
    """Evaluate the polar form of ``sum_k a_k t^k`` of degree ``len(args)`` at ``args``.

    >>> [polar_form_value([1, 3, 6, 1], x) for x in ([0, 0, 0], [0, 0, 1], [0, 1, 1], [1, 1, 1])]
    [mpq(1,1), mpq(2,1), mpq(5,1), mpq(11,1)]
    """
    c = polar_form_power(power_coeffs, len(args))
    return sum((c[i] * symmetric_basis(i, args) for i in range(len(c))), start=mpq(0))


# ---------------------------------------------------------------------------- continuity (6.12, 15.5)
def continuity_order(first: BezierCurve, second: BezierCurve, h_first=1, h_second=1, max_order: int | None = None) -> int:
    """Exact order ``r`` of parametric continuity ``C^r`` where ``first`` ends and ``second`` begins.

    The curves live on consecutive parameter intervals of lengths ``h_first`` and
    ``h_second``.  With ``y`` the global parameter measured from the junction,
    ``r1 = N1/W1`` and ``r2 = N2/W2`` agree to order ``r`` iff ``N1 W2 - N2 W1`` vanishes to
    order ``r + 1`` at ``y = 0``.  Returns ``-1`` for a gap, and ``max_order`` (default:
    the larger degree; beyond it two polynomial pieces agreeing to that order are one
    polynomial) when all orders up to it agree.

    >>> a = BezierCurve([[0, 0], [1, 1], [2, 1], [3, 0]])
    >>> b = BezierCurve([[3, 0], [4, -1], [5, -1], [6, 0]])
    >>> continuity_order(a, b)
    1
    """
    if first.dimension != second.dimension:
        raise InputError("curves of different dimension")
    h1, h2 = to_rational(h_first, where="h_first"), to_rational(h_second, where="h_second")
    if h1 <= 0 or h2 <= 0:
        raise DomainError("parameter interval lengths must be positive")
    a = bz.to_power(bz.restrict(first.homogeneous(), 1, 1 + 1 / h1))  # y -> first(1 + y/h1)
    b = bz.to_power(bz.restrict(second.homogeneous(), 0, 1 / h2))  # y -> second(y/h2)
    top = max(first.degree, second.degree) if max_order is None else int(max_order)
    na, wa, nb, wb = a[:, :-1], a[:, -1], b[:, :-1], b[:, -1]
    for k in range(top + 1):
        coeff = sum((na[i] * wb[k - i] - nb[k - i] * wa[i] for i in range(k + 1) if i < len(wa) and k - i < len(wb)), start=na[0] * 0)
        if np.any(coeff != 0):
            return k - 1
    return top


def bezier_chain_to_bspline(curves, spans=None) -> BSplineCurve:
    """Combine a chain of Bézier curves of one degree into one B-spline (notes 6.12, any degree).

    The exact continuity order ``r`` at every junction (:func:`continuity_order`) sets
    the knot multiplicity ``p - r``; the control points are the blossoms of the pieces
    (exact knot removal), so the result reproduces every input curve exactly.

    Parameters
    ----------
    curves : sequence of BezierCurve
        Polynomial, of one degree, each starting where the previous one ends.
    spans : sequence of numbers, optional
        Parameter interval lengths.  Default: the first curve gets 1;
        each next curve gets the length that makes the junction ``C^1`` when the last
        leg of the previous control polygon and the first leg of the next are
        parallel and equally directed (notes 6.12, in the corrected form of the ledger:
        ``|P_n - P_{n-1}| (e - k_{i+1}) = |Q_1 - P_n| (k_{i+1} - k_i)``), else 1.
    """
    curves = list(curves)
    if not curves:
        raise InputError("need at least one Bézier curve")
    p = curves[0].degree
    for i, c in enumerate(curves):
        if c.is_rational:
            raise NotSupportedError("rational chains: combine the homogeneous curves instead")
        if c.degree != p:
            raise DegreeError(f"curve {i} has degree {c.degree}, expected {p}")
        if i and tuple(curves[i - 1].control_points[-1]) != tuple(c.control_points[0]):
            raise InputError(f"curve {i} does not start where curve {i - 1} ends")
    if p == 0:
        raise DegreeError("degree-0 pieces cannot be chained")
    if spans is None:
        lengths = [mpq(1)]
        for prev, nxt in zip(curves[:-1], curves[1:]):
            lengths.append(lengths[-1] * _c1_ratio(prev, nxt))
    else:
        lengths = [to_rational(h, where="span") for h in spans]
        if len(lengths) != len(curves) or any(h <= 0 for h in lengths):
            raise InputError("spans: one positive length per curve")
    breaks = [mpq(0)]
    for h in lengths:
        breaks.append(breaks[-1] + h)
    knots = [breaks[0]] * (p + 1)
    for i in range(1, len(curves)):
        r = continuity_order(curves[i - 1], curves[i], lengths[i - 1], lengths[i], max_order=p)
        if r < 0:
            raise InputError(f"curves {i - 1} and {i} do not meet")
        knots += [breaks[i]] * max(p - r, 0)
    knots += [breaks[-1]] * (p + 1)
    chain = _c0_chain(curves, breaks)
    return chain.rebase(knots)


def _c1_ratio(prev: BezierCurve, nxt: BezierCurve):
    """``|Q_1 - Q_0| / |P_n - P_{n-1}|`` when the two legs are parallel and equally directed, else 1."""
    a = np.array(prev.control_points[-1], dtype=object) - np.array(prev.control_points[-2], dtype=object)
    b = np.array(nxt.control_points[1], dtype=object) - np.array(nxt.control_points[0], dtype=object)
    if all(x == 0 for x in a) or all(x == 0 for x in b):
        return mpq(1)
    k = next(i for i in range(len(a)) if a[i] != 0)
    ratio = b[k] / a[k]
    if ratio > 0 and all(b[i] == ratio * a[i] for i in range(len(a))):
        return ratio
    return mpq(1)


def _c0_chain(curves, breaks) -> SplineCurve:
    p = curves[0].degree
    pts = [curves[0].points_array()[0]]
    for c in curves:
        pts.extend(c.points_array()[1:])
    knots = [breaks[0]] * (p + 1) + [b for b in breaks[1:-1] for _ in range(p)] + [breaks[-1]] * (p + 1)
    return SplineCurve(np.stack(pts), knots)


# ---------------------------------------------------------------------------- basis functions (6.14)
def _basis_setup(knots):
    s = [to_rational(k, where="knot") for k in knots]
    if len(s) < 2:
        raise KnotError("a basis function needs at least two knots")
    for i in range(len(s) - 1):
        if s[i] > s[i + 1]:
            raise KnotError(f"knot vector decreases at index {i}")
    if s[0] == s[-1]:
        raise KnotError("a basis function needs a non-degenerate support")
    p = len(s) - 2
    padded = [s[0]] * p + s + [s[-1]] * p
    return s, p, padded


def _basis_span_coeffs(s, p, padded, i) -> tuple[np.ndarray, list]:
    """Local control values and knots of ``N[s]`` on its span ``[s_i, s_{i+1}]``: an explicit
    B-spline whose y-coordinates vanish except the one of ``N`` (notes 6.14)."""
    k = p + i  # span index in the padded vector
    ctrl = np.array([mpq(1) if (j == p) else mpq(0) for j in range(k - p, k + 1)], dtype=object)
    return ctrl, padded[k - p + 1 : k + p + 1]


def basis_function(knots, t):
    """``N[s_0, ..., s_{p+1}](t)``: the degree-``p`` B-spline basis function (notes 6.14, 15.7).

    Evaluated as an explicit B-spline (polar form ``f(t, ..., t)``).  The support is the
    closed interval ``[s_0, s_{p+1}]``; at a discontinuity (a ``(p+1)``-fold end knot) the
    value is the limit from inside the support.

    >>> basis_function([0, 1, 2, 4, 5], 3)            # notes 15.7.1: 11/24
    mpq(11,24)
    """
    s, p, padded = _basis_setup(knots)
    t = to_rational(t, where="t")
    if t < s[0] or t > s[-1]:
        return mpq(0)
    if p == 0:
        return mpq(1)
    if t == s[-1]:
        i = max(j for j in range(p + 1) if s[j] < s[j + 1])
    else:
        i = max(j for j in range(p + 1) if s[j] <= t and s[j] < s[j + 1])
    ctrl, local = _basis_span_coeffs(s, p, padded, i)
    return segment_blossom(ctrl, local, [t] * p)


def basis_function_pieces(knots) -> list[tuple[tuple, np.ndarray]]:
    """Polynomial pieces of ``N[s_0..s_{p+1}]``: ``[((s_i, s_{i+1}), Bernstein coefficients)]``.

    Each piece is in Bernstein form over its own span (polar values ``f(a^{p-j}, b^j)``).
    """
    s, p, padded = _basis_setup(knots)
    out = []
    for i in range(p + 1):
        if s[i] < s[i + 1]:
            if p == 0:
                out.append(((s[i], s[i + 1]), np.array([mpq(1)], dtype=object)))
                continue
            ctrl, local = _basis_span_coeffs(s, p, padded, i)
            a, b = s[i], s[i + 1]
            coeffs = [segment_blossom(ctrl, local, [a] * (p - j) + [b] * j) for j in range(p + 1)]
            out.append(((a, b), np.array(coeffs, dtype=object)))
    return out


def refine_basis_function(knots, k) -> list[tuple[object, tuple]]:
    """Split ``N[s_0..s_{n+1}]`` by inserting ``k`` (notes 6.14.2, (15.14)-(15.17)).

    Returns ``[(c, left_knots), (d, right_knots)]`` (a single ``(1, knots)`` when ``k``
    lies outside the open support) with ``N = c N[left] + d N[right]``, where
    ``c = (k - s_0)/(s_n - s_0)`` if ``k < s_n`` else 1 and
    ``d = (s_{n+1} - k)/(s_{n+1} - s_1)`` if ``k > s_1`` else 1 (the notes print
    ``s_{n+1} - s_0`` in ``c``: see the ledger).

    >>> refine_basis_function([0, 1, 2, 4, 5], 3)
    [(mpq(3,4), (mpq(0,1), mpq(1,1), mpq(2,1), mpq(3,1), mpq(4,1))), (mpq(1,2), (mpq(1,1), mpq(2,1), mpq(3,1), mpq(4,1), mpq(5,1)))]
    """
    s = [to_rational(x, where="knot") for x in knots]
    k = to_rational(k, where="inserted knot")
    n = len(s) - 2
    if k <= s[0] or k >= s[-1]:
        return [(mpq(1), tuple(s))]
    merged = s[:]
    bisect.insort_right(merged, k)
    c = (k - s[0]) / (s[n] - s[0]) if k < s[n] else mpq(1)
    d = (s[n + 1] - k) / (s[n + 1] - s[1]) if k > s[1] else mpq(1)
    return [(c, tuple(merged[: n + 2])), (d, tuple(merged[1:]))]


def refine_basis_function_multi(knots, new_knots) -> list[tuple[object, tuple]]:
    """Write ``N[knots]`` over the refined knot vector ``new_knots`` (15.7.3, 15.21).

    ``new_knots`` must contain ``knots`` as a sub-multiset; returns ``[(coefficient,
    window)]`` over the consecutive windows of ``new_knots`` (zero coefficients dropped),
    by repeated single-knot refinement.
    """
    s = [to_rational(x) for x in knots]
    big = sorted(to_rational(x) for x in new_knots)
    extra = list(big)
    for v in s:
        if v not in extra:
            raise KnotError(f"refined knot vector lacks the knot {v}")
        extra.remove(v)
    pieces = {tuple(s): mpq(1)}
    for k in extra:
        nxt: dict = {}
        for ks, coef in pieces.items():
            for c, sub in refine_basis_function(ks, k):
                nxt[sub] = nxt.get(sub, mpq(0)) + coef * c
        pieces = nxt
    return [(c, ks) for ks, c in sorted(pieces.items()) if c != 0]


def basis_recurrence(knots, i: int, k: int, t):
    """``B_i^k(t)`` by the recurrence (6.14), corrected: ``w_i^k(t) = (t - t_i)/(t_{i+k} - t_i)``.

    ``B_i^0`` is the indicator of ``[t_i, t_{i+1})`` (half-open; the notes' closed interval
    would double-count at knots).  ``knots`` are indexed from 0.
    """
    ts = [to_rational(x) for x in knots]
    t = to_rational(t, where="t")
    if i < 0 or k < 0 or i + k + 1 > len(ts) - 1:
        raise InputError(f"B_{i}^{k} needs knots t_{i}..t_{i + k + 1}")
    if k == 0:
        return mpq(1) if ts[i] <= t < ts[i + 1] else mpq(0)

    def omega(j):
        den = ts[j + k] - ts[j]
        return (t - ts[j]) / den if den != 0 else mpq(0)

    return omega(i) * basis_recurrence(ts, i, k - 1, t) + (1 - omega(i + 1)) * basis_recurrence(ts, i + 1, k - 1, t)
