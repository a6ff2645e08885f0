"""Certification of the float routes' candidate boxes (Sederberg's notes 003, chapter 7).

Candidate boxes are grouped into components, and each component is tested with the
interval Krawczyk operator for ``F(s, t) = P(s) - Q(t)``: ``K(X) ⊂ int X`` proves
exactly one intersection in ``X`` (transversal: the Jacobian is regular there) and
gives a tight enclosure.  Components where this cannot succeed (tangencies, clusters
closer than the float resolution) come back with ``certified=False``; the public
entry hands them to the exact route.  A proven zero whose box crosses an end of a
curve is placed inside or outside [0, 1]^2 by exact Krawczyk steps.
"""

from __future__ import annotations

import math

import numpy as np
from gmpy2 import mpq

from ...errors import NotSupportedError
from ...exact import bernstein as bz
from ...geometry.bezier_curve import BezierCurve
from .. import enclose as iv
from ..interval import Interval
from .curve_data import _W_TANGENT, U, _box, _clip, _Curve, _disjoint, _Piece
from .result import Intersection


def _iv(x):
    return (float(x[0]), float(x[1]))


def _imul(a, b):
    lo, hi = iv.iv_mul(np.float64(a[0]), np.float64(a[1]), np.float64(b[0]), np.float64(b[1]))
    return float(lo), float(hi)


def _iadd(a, b):
    lo, hi = iv.iv_add(np.float64(a[0]), np.float64(a[1]), np.float64(b[0]), np.float64(b[1]))
    return float(lo), float(hi)


def _isub(a, b):
    lo, hi = iv.iv_sub(np.float64(a[0]), np.float64(a[1]), np.float64(b[0]), np.float64(b[1]))
    return float(lo), float(hi)


def _krawczyk(c1: _Curve, c2: _Curve, S, T):
    """Krawczyk operator for F(s, t) = P(s) - Q(t) on the box S x T.

    Returns ``("unique", S', T')`` when ``K(X) ⊂ int X`` (exactly one zero, in
    ``K ∩ X``), ``("empty",)`` when ``K(X) ∩ X = ∅`` (no zero), else
    ``("unknown", singular)`` with ``singular`` = the Jacobian may be singular on X.
    """
    sm, tm = 0.5 * (S[0] + S[1]), 0.5 * (T[0] + T[1])
    plo, phi = c1.value_at(sm)
    qlo, qhi = c2.value_at(tm)
    if not (np.all(np.isfinite(plo)) and np.all(np.isfinite(phi)) and np.all(np.isfinite(qlo)) and np.all(np.isfinite(qhi))):
        return ("unknown", True)
    F = [_isub((plo[k], phi[k]), (qlo[k], qhi[k])) for k in range(2)]
    dp_lo, dp_hi = c1.range_derivative(S[0], S[1])
    dq_lo, dq_hi = c2.range_derivative(T[0], T[1])
    J = [[(float(dp_lo[k]), float(dp_hi[k])), (float(-dq_hi[k]), float(-dq_lo[k]))] for k in range(2)]
    if not all(math.isfinite(x) for row in J for e in row for x in e):
        return ("unknown", True)
    det_iv = _isub(_imul(J[0][0], J[1][1]), _imul(J[0][1], J[1][0]))
    singular = det_iv[0] <= 0.0 <= det_iv[1]
    M = [[0.5 * (J[i][j][0] + J[i][j][1]) for j in range(2)] for i in range(2)]
    det = M[0][0] * M[1][1] - M[0][1] * M[1][0]
    if det == 0.0 or not math.isfinite(det):
        return ("unknown", True)
    Y = [[M[1][1] / det, -M[0][1] / det], [-M[1][0] / det, M[0][0] / det]]
    X = [S, T]
    mvec = [sm, tm]
    K = []
    for i in range(2):
        # m_i - (Y F(m))_i
        yf = _iadd(_imul((Y[i][0], Y[i][0]), F[0]), _imul((Y[i][1], Y[i][1]), F[1]))
        acc = _isub((mvec[i], mvec[i]), yf)
        for j in range(2):
            # (I - Y J)_{ij}
            yj = _iadd(_imul((Y[i][0], Y[i][0]), J[0][j]), _imul((Y[i][1], Y[i][1]), J[1][j]))
            e = _isub((1.0, 1.0) if i == j else (0.0, 0.0), yj)
            acc = _iadd(acc, _imul(e, _isub(X[j], (mvec[j], mvec[j]))))
        K.append(acc)
    if any(K[i][1] < X[i][0] or K[i][0] > X[i][1] for i in range(2)):
        return ("empty",)
    if all(X[i][0] < K[i][0] and K[i][1] < X[i][1] for i in range(2)):
        return ("unique", (max(K[0][0], S[0]), min(K[0][1], S[1])), (max(K[1][0], T[0]), min(K[1][1], T[1])))
    return ("unknown", singular)


def _components(rects, slack: float):
    """Connected components of overlapping rectangles (union-find)."""
    n = len(rects)
    parent = list(range(n))

    def find(i):
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    order = sorted(range(n), key=lambda i: rects[i][0][0])
    active: list[int] = []
    for i in order:
        (a0, a1), (b0, b1), _ = rects[i]
        keep = []
        for j in active:
            (c0, c1), (d0, d1), _ = rects[j]
            if c1 + slack < a0:
                continue
            keep.append(j)
            if b0 <= d1 + slack and d0 <= b1 + slack:
                parent[find(i)] = find(j)
        keep.append(i)
        active = keep
    groups: dict[int, list] = {}
    for i in range(n):
        groups.setdefault(find(i), []).append(rects[i])
    return list(groups.values())


def _hull(group):
    s0 = min(r[0][0] for r in group)
    s1 = max(r[0][1] for r in group)
    t0 = min(r[1][0] for r in group)
    t1 = max(r[1][1] for r in group)
    ests = [r[2] for r in group if r[2] is not None]
    return (s0, s1), (t0, t1), ests


def _widen(X, frac: float = 0.25):
    w = X[1] - X[0]
    pad = max(w * frac, abs(X[0]) * 8 * U, abs(X[1]) * 8 * U, 2.0**-1000)
    return (float(iv.down(X[0] - pad)), float(iv.up(X[1] + pad)))


def _certify(c1: _Curve, c2: _Curve, rects, tol: float, ends) -> list[Intersection]:
    out: list[Intersection] = []
    work = list(_components(rects, 0.0))
    guard = 0
    while work:
        group = work.pop()
        S, T, ests = _hull(group)
        guard += 1
        result = _try_box(c1, c2, S, T)
        if result[0] == "empty":
            continue
        if result[0] == "unique":
            S2, T2 = result[1], result[2]
            inside = S2[0] >= 0.0 and S2[1] <= 1.0 and T2[0] >= 0.0 and T2[1] <= 1.0
            outside = S2[1] < 0.0 or S2[0] > 1.0 or T2[1] < 0.0 or T2[0] > 1.0
            if outside:
                continue
            known = [e for e in ends if _in_box(e, S2, T2)]
            s_est, t_est = _estimate(ests, S2, T2)
            side = "inside" if inside or known else _boundary_side(c1, c2, S2, T2)
            if side == "outside":
                continue  # the box's only zero lies beyond an end of a curve (proven)
            if side == "inside":
                exact = known[0] if known else None
                if exact is not None:
                    S2, T2 = _exact_box(exact[0], S2), _exact_box(exact[1], T2)
                    s_est, t_est = float(exact[0]), float(exact[1])
                out.append(_make(c1, s_est, t_est, _clamp(S2), _clamp(T2), True, False, 1, exact))
                continue
            # straddles the domain boundary closer than the exact side test resolves
            out.append(_make(c1, s_est, t_est, _clamp(S2), _clamp(T2), False, False, None, None))
            continue
        singular = result[1]
        if len(group) > 1 and guard < 2000 and not singular:
            # a loose hull of several pieces: try them one by one
            for r in group:
                work.append([r])
            continue
        big = max(S[1] - S[0], T[1] - T[0])
        if guard < 600 and big > 4 * tol and (not singular or big > 4 * _W_TANGENT):
            subs = _split_rect(c1, c2, S, T, ests)
            if len(subs) != 1 or subs[0][:2] != (S, T):
                work.extend(_components(subs, 0.0))
                continue
        s_est, t_est = _estimate(ests, S, T)
        known = [e for e in ends if _in_box(e, S, T)]
        out.append(_make(c1, s_est, t_est, _clamp(S), _clamp(T), False, True, None, known[0] if known else None))
    out.sort(key=lambda x: (x.t1, x.t2))
    return _dedupe(out)


# =============================================================== zeros at the domain boundary
_SIDE_STEPS = 8  # exact Krawczyk contractions per side test (each gains ~45 bits)


def _boundary_side(c1: _Curve, c2: _Curve, S, T) -> str:
    """Decide exactly on which side of the boundary of [0, 1]^2 the zero in ``S x T`` lies.

    ``S x T`` holds exactly one zero of ``F(s, t) = P(s) - Q(t)`` (proven by the float
    Krawczyk test) and crosses ``s = 0``, ``s = 1``, ``t = 0`` or ``t = 1``.  Float
    arithmetic cannot place the zero relative to the face when it is closer than the
    float resolution (``s = 1 - 2^-60``), so the box is contracted by exact Krawczyk
    steps (:func:`_krawczyk_exact`; every zero in ``X`` lies in ``K(X) ∩ X``, each step
    gains about as many bits as float resolves) until it lies on one side of every face.

    Returns
    -------
    str
        ``"inside"`` (the zero lies in [0, 1]^2), ``"outside"`` (it does not), or
        ``"unknown"`` (too close to a face to tell in a few steps; a zero exactly on a
        face is found by the exact endpoint test instead).
    """
    unit = Interval(0, 1)
    start = (Interval(S[0], S[1]), Interval(T[0], T[1]))
    box = start
    for _ in range(_SIDE_STEPS):
        if all(unit.contains(X) for X in box):
            return "inside"
        if any(X.intersection(unit) is None for X in box):
            return "outside"
        nxt = _krawczyk_exact(c1, c2, *box)
        if nxt is None or nxt == box:
            # (None cannot happen: the box holds the zero; stay uncommitted if it does)
            return "unknown"
        box = tuple(_round_out(X, Z) for X, Z in zip(nxt, start))
    return "unknown"


def _round_out(X: Interval, within: Interval) -> Interval:
    """``X`` widened to dyadic end points (a 2^-12 fraction of its width), kept in ``within``.

    Keeps the rationals of the exact contraction short (the exact centre of the next
    step would otherwise double their size); widening never loses a zero, and staying
    in ``within`` (the box proven to hold exactly one zero) keeps it the same zero.
    """
    width = X.width()
    if width == 0:
        return X
    e = 12 + int(width.denominator).bit_length() - int(width.numerator).bit_length()
    scale = mpq(2) ** e
    lo = mpq(math.floor(X.lo * scale)) / scale
    hi = mpq(math.ceil(X.hi * scale)) / scale
    return Interval(max(lo, within.lo), min(hi, within.hi))


def _krawczyk_exact(c1: _Curve, c2: _Curve, S: Interval, T: Interval):
    """``K(X) ∩ X`` for ``X = S x T`` with exact rational arithmetic, ``None`` when empty.

    ``K(X) = m - Y F(m) + (I - Y J(X)) (X - m)`` with the exact midpoint ``m``, the exact
    value ``F(m)`` (rational de Casteljau on the exact control points), any rational
    matrix ``Y`` (the float inverse of the midpoint Jacobian) and an outward-rounded
    float enclosure ``J(X)`` of the Jacobian on a float box containing ``X``.  Only
    ``J`` is rounded, and only outward, so ``K(X)`` contains every zero in ``X``
    (mean value theorem).  Returns ``(S, T)`` unchanged when nothing can be computed.
    """
    X = (S, T)
    m = (S.midpoint(), T.midpoint())
    p, q = _exact_point(c1, m[0]), _exact_point(c2, m[1])
    J = _jacobian_enclosure(c1, c2, S, T)
    if p is None or q is None or J is None:
        return X
    F = [p[k] - q[k] for k in range(2)]
    M = [[0.5 * (float(J[i][j].lo) + float(J[i][j].hi)) for j in range(2)] for i in range(2)]
    det = M[0][0] * M[1][1] - M[0][1] * M[1][0]
    if det == 0.0 or not math.isfinite(det):
        return X
    Y = [[mpq(M[1][1] / det), mpq(-M[0][1] / det)], [mpq(-M[1][0] / det), mpq(M[0][0] / det)]]
    out = []
    for i in range(2):
        acc = Interval(m[i] - Y[i][0] * F[0] - Y[i][1] * F[1])
        for j in range(2):
            e = (1 if i == j else 0) - (J[0][j] * Y[i][0] + J[1][j] * Y[i][1])
            acc = acc + e * (X[j] - m[j])
        cut = acc.intersection(X[i])
        if cut is None:
            return None
        out.append(cut)
    return out[0], out[1]


def _exact_point(curve: _Curve, s):
    """Exact (scaled) Cartesian point of the curve at a rational ``s`` (None at a pole)."""
    h = bz.de_casteljau(curve.exact, s)
    if not curve.rational:
        return h[0], h[1]
    if h[2] == 0:
        return None
    return h[0] / h[2], h[1] / h[2]


def _jacobian_enclosure(c1: _Curve, c2: _Curve, S: Interval, T: Interval):
    """Exact intervals enclosing ``J = [P'(s), -Q'(t)]`` on ``S x T`` (None if unbounded)."""
    dp = c1.range_derivative(*_outward(S))
    dq = c2.range_derivative(*_outward(T))
    values = [float(x) for pair in (dp, dq) for x in np.concatenate(pair)]
    if not all(math.isfinite(x) for x in values):
        return None
    (dp_lo, dp_hi), (dq_lo, dq_hi) = dp, dq
    return [[Interval(float(dp_lo[k]), float(dp_hi[k])), Interval(-float(dq_hi[k]), -float(dq_lo[k]))] for k in range(2)]


def _outward(X: Interval) -> tuple[float, float]:
    """A float box of positive width containing the rational interval ``X``."""
    return float(iv.down(iv.enclose_scalar(X.lo)[0])), float(iv.up(iv.enclose_scalar(X.hi)[1]))


def _split_rect(c1: _Curve, c2: _Curve, S, T, ests):
    """Quarter a parameter box; keep the quarters not excluded by boxes or fat lines."""
    out = []
    sm, tm = 0.5 * (S[0] + S[1]), 0.5 * (T[0] + T[1])
    for s0, s1 in ((S[0], sm), (sm, S[1])):
        for t0, t1 in ((T[0], tm), (tm, T[1])):
            if s1 <= s0 or t1 <= t0:
                continue
            p = _Piece(*iv.restrict(c1.lo, c1.hi, s0, s1), (s0, s0), (s1, s1))
            q = _Piece(*iv.restrict(c2.lo, c2.hi, t0, t1), (t0, t0), (t1, t1))
            if _disjoint(_box(c1, p), _box(c2, q)):
                continue
            if _clip(c1, p, c2, q) is None or _clip(c2, q, c1, p) is None:
                continue
            inside = [e for e in ests if s0 <= e[0] <= s1 and t0 <= e[1] <= t1]
            out.append(((s0, s1), (t0, t1), inside[0] if inside else None))
    return out


def _try_box(c1, c2, S, T):
    """Krawczyk on a slightly widened box (the zero may sit on a face), a few contractions."""
    S1, T1 = _widen(S), _widen(T)
    res = _krawczyk(c1, c2, S1, T1)
    for pad in (2.0**-44, 2.0**-36):
        # a box near the float resolution of the coordinates is too small for the
        # operator to contract (e.g. a crossing at a corner of the domain, where the
        # widening relative to |s| is tiny): retry on absolutely padded boxes; a
        # "unique" answer there is just as proven, only less tight before contraction
        if res[0] != "unknown" or res[1]:
            break
        res = _krawczyk(c1, c2, _pad(S1, pad), _pad(T1, pad))
    if res[0] != "unique":
        return res
    for _ in range(3):
        S2, T2 = res[1], res[2]
        nxt = _krawczyk(c1, c2, S2, T2)
        if nxt[0] != "unique" or (nxt[1][1] - nxt[1][0] >= 0.5 * (S2[1] - S2[0]) and nxt[2][1] - nxt[2][0] >= 0.5 * (T2[1] - T2[0])):
            break
        res = nxt
    # a contraction step of the operator keeps the zero: K(X) ∩ X
    return res


def _pad(X, pad: float):
    return (float(iv.down(X[0] - pad)), float(iv.up(X[1] + pad)))


def _in_box(e, S, T) -> bool:
    s, t = e
    return bool(mpq(S[0]) <= s) and bool(s <= mpq(S[1])) and bool(mpq(T[0]) <= t) and bool(t <= mpq(T[1]))


def _exact_box(x, X):
    from ...exact.algebraic import RealAlgebraic

    if isinstance(x, RealAlgebraic):
        if x.is_rational:
            v = x.value
            lo, hi = iv.enclose_scalar(v)
            return (lo, hi)
        x.refine(mpq(1, 2**60))
        return (iv.enclose_scalar(x.lo)[0], iv.enclose_scalar(x.hi)[1])
    lo, hi = iv.enclose_scalar(x)
    return (lo, hi)


def _clamp(X):
    return (max(0.0, X[0]), min(1.0, X[1]))


def _estimate(ests, S, T):
    inside = [e for e in ests if S[0] <= e[0] <= S[1] and T[0] <= e[1] <= T[1]]
    if inside:
        return float(np.mean([e[0] for e in inside])), float(np.mean([e[1] for e in inside]))
    return 0.5 * (S[0] + S[1]), 0.5 * (T[0] + T[1])


def _make(c1, s, t, S, T, certified, tangent, mult, exact):
    s = min(max(s, S[0]), S[1])
    t = min(max(t, T[0]), T[1])
    kind = "transversal" if certified else "unresolved"
    return Intersection(float(s), float(t), (float(S[0]), float(S[1])), (float(T[0]), float(T[1])), c1.point_float(s), certified, tangent, mult, exact, kind)


def _dedupe(items: list[Intersection]) -> list[Intersection]:
    """Certified boxes that overlap hold the same unique zero only if one holds the other's
    estimate; boxes of uncertified clusters that overlap are merged."""
    out: list[Intersection] = []
    for x in items:
        merged = False
        for k, y in enumerate(out):
            overlap = not (x.t1_interval[1] < y.t1_interval[0] or y.t1_interval[1] < x.t1_interval[0] or x.t2_interval[1] < y.t2_interval[0] or y.t2_interval[1] < x.t2_interval[0])
            if not overlap:
                continue
            if x.certified and y.certified:
                # each box holds exactly one zero; if one box holds the other, they are the same
                if _inside(x, y):
                    out[k] = x
                    merged = True
                elif _inside(y, x):
                    merged = True
                if merged:
                    break
                continue
            if not x.certified and not y.certified:
                S = (min(x.t1_interval[0], y.t1_interval[0]), max(x.t1_interval[1], y.t1_interval[1]))
                T = (min(x.t2_interval[0], y.t2_interval[0]), max(x.t2_interval[1], y.t2_interval[1]))
                out[k] = Intersection(y.t1, y.t2, S, T, y.point, False, x.tangent or y.tangent, None, y.exact or x.exact, "unresolved")
                merged = True
                break
        if not merged:
            out.append(x)
    return out


def _inside(x: Intersection, y: Intersection) -> bool:
    return y.t1_interval[0] <= x.t1_interval[0] and x.t1_interval[1] <= y.t1_interval[1] and y.t2_interval[0] <= x.t2_interval[0] and x.t2_interval[1] <= y.t2_interval[1]


# =============================================================== endpoint intersections
def _endpoint_intersections(curve1: BezierCurve, curve2: BezierCurve):
    """Exact parameter pairs where an end point of one curve lies on the other (gcd test)."""
    import flint

    from ...exact.algebraic import RealAlgebraic, real_roots

    def on_curve(point, curve):
        px, py = point
        power = bz.to_power(curve.homogeneous())

        def fq(col):
            return flint.fmpq_poly([flint.fmpq(int(x.numerator), int(x.denominator)) for x in col])

        gx = fq(power[:, 0]) - fq(power[:, 2]) * flint.fmpq(int(px.numerator), int(px.denominator))
        gy = fq(power[:, 1]) - fq(power[:, 2]) * flint.fmpq(int(py.numerator), int(py.denominator))
        if gx == 0 and gy == 0:
            raise NotSupportedError("a curve is constant at an end point of the other; degenerate input")
        g = gx.gcd(gy) if (gx != 0 and gy != 0) else (gx if gy == 0 else gy)
        if g.degree() < 1:
            return []
        coeffs = [mpq(int(c.p), int(c.q)) for c in g.coeffs()]
        return [r for r, _ in real_roots(coeffs, 0, 1)]

    out = []
    for s in (0, 1):
        for t in on_curve(curve1.evaluate(s), curve2):
            out.append((RealAlgebraic.from_rational(s), t))
    for t in (0, 1):
        for s in on_curve(curve2.evaluate(t), curve1):
            if not any(e[0] == s and e[1] == t for e in out):
                out.append((s, RealAlgebraic.from_rational(t)))
    return out


