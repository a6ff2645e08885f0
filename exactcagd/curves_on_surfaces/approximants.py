"""Approximating domain curves: the G1 s/t-parabolas of Yang et al. (004), section 5, and the
two baselines they compare with (hyperbolas of ref. [15], line segments of ref. [2]).

Every approximant is a pair of rational maps ``u(t) = U(t) / W_u(t)``,
``v(t) = V(t) / W_v(t)`` in the *local* coordinates of one patch; its image on the
surface is ``X(u(t), v(t))``, computed exactly by
:func:`exactcagd.reparam.substitute_curve`.

**s-parabola** (Theorem 1, Types 1 and 3).  The iso-line ``s = 1/2`` of the cubic
reparameterization (5) with ``beta_1 = beta_2 = beta_3 = beta`` is
``u(t) = 1 - alpha(t)`` (quadratic Bernstein polynomial with coefficients
``1 - alpha_k``), ``v(t) = M_beta(t) = (1-beta) t / (beta (1-t) + (1-beta) t)``.
After normalizing the ``v``-range of the joint data to ``[0, 1]`` (section 5, "the
two end points lie on opposite boundary edges") the G1 conditions (10)-(13) read,
with ``k_1 = m_0 (v_1 - v_0) / n_0`` and ``k_2 = m_1 (v_1 - v_0) / n_1``,

    Type 1 (m_0 = 0):  alpha_2 = alpha_1 (14),  beta = 2 (u_1 - u_0) / (2 (u_1 - u_0) + k_2)
    Type 1 (m_1 = 0):  alpha_2 = alpha_3,       beta = k_1 / (2 (u_1 - u_0) + k_1)
    Type 3:            alpha_2 = (alpha_1 + alpha_3 + sqrt(Delta)) / 2 (16),
                       Delta = (u_0 - u_1)^2 - k_1 k_2 (17),
                       beta = 2 (alpha_2 - alpha_3) / (2 (alpha_2 - alpha_3) + k_2) (15).

In the original ``u`` coordinate (no normalization of ``u`` is needed: the construction
is affine-invariant) the middle Bernstein coefficient is ``u_m = 1 - alpha_2``.
``sqrt(Delta)`` is carried exactly (:mod:`exactcagd.exact.quadratic`).  The
**t-parabola** (Types 2 and 4) is the same with ``u/v``, ``s/t``, ``alpha/beta``
exchanged.  A degenerate s-parabola with ``m_0 = m_1 = 0`` and ``u_0 = u_1`` is the
iso-parametric segment ``u = u_0`` (any ``beta``; we take 1/2).

>>> from gmpy2 import mpq
>>> a = s_parabola((mpq(0), mpq(0)), (mpq(1), mpq(1)), (mpq(1), mpq(1)), (mpq(1), mpq(1)))
>>> a.kind, [str(x) for x in a.u_map[0]], a.beta                  # a straight line, linear speed
('s-parabola', ['0', '1/2', '1'], mpq(1,2))
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from gmpy2 import mpq

from ..exact import bernstein as bz
from ..exact.quadratic import QuadraticNumber, field_of, sqrt_rational
from ..reparam import substitute_curve
from ..reparam._mechanism import bernstein_product

__all__ = ["Approximant", "s_parabola", "t_parabola", "parabola", "hyperbola", "segment"]


def _sign(x) -> int:
    if isinstance(x, QuadraticNumber):
        return x.sign()
    return (x > 0) - (x < 0)


@dataclass
class Approximant:
    """``u(t) = U/W_u``, ``v(t) = V/W_v`` (Bernstein coefficient lists, local coordinates)."""

    kind: str
    u_map: tuple
    v_map: tuple
    params: dict = field(default_factory=dict)

    def domain_hom(self) -> np.ndarray:
        """Planar homogeneous Bézier coefficients ``(U W_v, V W_u, W_u W_v)`` (cached)."""
        cached = self.params.get("_domain_hom")
        if cached is None:
            cached = self.params["_domain_hom"] = self._domain_hom()
        return cached

    def _domain_hom(self) -> np.ndarray:
        U, Wu = (np.array(x, dtype=object) for x in self.u_map)
        V, Wv = (np.array(x, dtype=object) for x in self.v_map)
        du = max(len(U), len(Wu)) - 1
        dv = max(len(V), len(Wv)) - 1
        U, Wu = bz.elevate(U, du - len(U) + 1), bz.elevate(Wu, du - len(Wu) + 1)
        V, Wv = bz.elevate(V, dv - len(V) + 1), bz.elevate(Wv, dv - len(Wv) + 1)
        cols = [_times(U, Wv), _times(V, Wu), _times(Wu, Wv)]
        return np.stack(cols, axis=1)

    def image_hom(self, patch_hom: np.ndarray) -> np.ndarray:
        """Homogeneous coefficients of ``X(u(t), v(t))`` (exact, Bernstein products)."""
        return substitute_curve(patch_hom, self.u_map, self.v_map)

    @property
    def image_degree_formula(self):
        """Degree of the image for a patch of bidegree ``(m, n)``: ``m deg u + n deg v``."""
        du = max(len(self.u_map[0]), len(self.u_map[1])) - 1
        dv = max(len(self.v_map[0]), len(self.v_map[1])) - 1
        return lambda m, n: m * du + n * dv

    @property
    def beta(self):
        """Möbius coefficient ``w0 / (w0 + w1)`` of the rational-linear coordinate (``None`` if none)."""
        for _, W in (self.v_map, self.u_map):
            if len(W) == 2 and W[0] != W[1]:
                return W[0] / (W[0] + W[1])
        for _, W in (self.v_map, self.u_map):
            if len(W) == 2:
                return W[0] / (W[0] + W[1])
        return None

    @property
    def radicand(self):
        """``D`` if some coefficient lies in ``Q(sqrt(D))`` (irrational), else ``None``."""
        return field_of(list(self.u_map[0]) + list(self.u_map[1]) + list(self.v_map[0]) + list(self.v_map[1]))

    def proxy(self, bits: int = 64) -> tuple["Approximant", mpq]:
        """A rational approximant ``A~`` and ``delta`` with ``max_t |A(t) - A~(t)| <= delta``.

        Used to certify distances in rational arithmetic: ``H(C, A) <= H(C, A~) + delta``.
        A coordinate map that is a polynomial (weight 1) moves by at most the largest
        coefficient change; a rational-linear (Möbius) map ``x_0 + (x_1 - x_0) M_beta``
        moves by at most ``|x_1 - x_0| |beta - beta~| / (4 min(beta, 1 - beta)^2)``
        (``|dM_beta/d beta| = t (1 - t) / (beta (1-t) + (1-beta) t)^2``), with ``beta`` and
        ``beta~`` in an exact rational interval.
        """
        if self.radicand is None:
            return self, mpq(0)
        maps, delta = [], mpq(0)
        for N, W in (self.u_map, self.v_map):
            if len(W) == 1:
                new = []
                for x in N:
                    lo, hi = _interval(x, bits)
                    new.append(lo)
                    delta += 0 if lo == hi else hi - lo
                maps.append((new, list(W)))
                continue
            w0, w1 = W
            x0, x1 = N[0] / w0, N[1] / w1
            x0, x1 = _rational(x0), _rational(x1)
            (l0, h0), (l1, h1) = _interval(w0, bits), _interval(w1, bits)
            b_lo, b_hi = l0 / (l0 + h1), h0 / (h0 + l1)
            m = min(b_lo, 1 - b_hi)
            delta += abs(x1 - x0) * (b_hi - b_lo) / (4 * m * m)
            maps.append(_mobius_map(x0, x1, l0, l1))
        params = {k: v for k, v in self.params.items() if not k.startswith("_")}
        return Approximant(self.kind, maps[0], maps[1], dict(params, proxy_of=self.radicand)), delta

    def swapped(self) -> "Approximant":
        params = {k: v for k, v in self.params.items() if not k.startswith("_")}
        return Approximant(self.kind, self.v_map, self.u_map, params)


def _times(a: np.ndarray, w: np.ndarray) -> np.ndarray:
    """Bernstein product ``a w`` (flint, :func:`exactcagd.reparam.bernstein_product`); with
    rational coefficients, a factor that is the constant 1 (all coefficients 1) only raises
    the degree (notes 2.5: the product with ``sum_k B_k = 1`` is degree elevation)."""
    if not any(isinstance(x, QuadraticNumber) for x in (*a, *w)):
        if all(x == 1 for x in w):
            return bz.elevate(a, len(w) - 1)
        if all(x == 1 for x in a):
            return bz.elevate(w, len(a) - 1)
    if all(isinstance(x, (type(mpq(0)), int, QuadraticNumber)) for x in (*a, *w)):
        return bernstein_product(a, w)
    return bz.product(a, w)  # pragma: no cover - other scalar types


def _interval(x, bits: int) -> tuple:
    if isinstance(x, QuadraticNumber):
        return x.bounds(bits)
    return mpq(x), mpq(x)


def _rational(x) -> mpq:
    if isinstance(x, QuadraticNumber):
        return x.rational
    return mpq(x)


def _mobius_map(x0, x1, w0, w1) -> tuple:
    """``x(t) = x_0 + (x_1 - x_0) M_beta(t)`` with ``beta = w0 / (w0 + w1)``: rational linear
    with weights ``(w0, w1)`` (homogeneous: no division, so ``Q(sqrt(Delta))`` entries stay small)."""
    return [x0 * w0, x1 * w1], [w0, w1]


def s_parabola(p0, d0, p1, d1, root: str = "paper") -> Approximant | None:
    """The s-parabola through ``p0, p1`` with tangent directions ``d0, d1`` (local coordinates).

    Returns ``None`` when Theorem 1's s-cases do not apply (horizontal end tangent,
    ``Delta < 0``, non-monotonic data).  ``root="paper"`` takes the ``+ sqrt(Delta)`` of
    (16); ``"other"`` the second root (both are valid for monotonic data).
    """
    (u0, v0), (u1, v1) = p0, p1
    (m0, n0), (m1, n1) = d0, d1
    dv = v1 - v0
    if dv == 0 or n0 == 0 or n1 == 0 or _sign(n0) != _sign(dv) or _sign(n1) != _sign(dv):
        return None
    k1 = m0 * dv / n0
    k2 = m1 * dv / n1
    du = u1 - u0
    sg = _sign(du)
    params = {"k1": k1, "k2": k2}
    if k1 == 0 and k2 == 0:
        if du != 0:
            return None
        um, w0, w1, kind = u0, mpq(1), mpq(1), "iso-u"
    elif k1 == 0:  # (14): alpha_2 = alpha_1;  beta = 2 du / (2 du + k2)
        if sg == 0 or _sign(k2) != sg:
            return None
        um, w0, w1, kind = u0, 2 * du * sg, k2 * sg, "type-1"
    elif k2 == 0:  # alpha_2 = alpha_3;  beta = k1 / (2 du + k1)
        if sg == 0 or _sign(k1) != sg:
            return None
        um, w0, w1, kind = u1, k1 * sg, 2 * du * sg, "type-1"
    else:
        if sg == 0 or _sign(k1) != sg or _sign(k2) != sg:
            return None
        delta = du * du - k1 * k2  # (17)
        if delta < 0:
            return None
        r = sqrt_rational(delta)
        if root == "other":
            r = -r
        um = (u0 + u1 - r) / 2  # 1 - alpha_2 with alpha_2 from (16)
        x = du + r  # 2 (alpha_2 - alpha_3);  beta = x / (x + k2)  (15)
        w0, w1, kind = x * sg, k2 * sg, "type-3"
        params["Delta"] = delta
    if not (w0 > 0 and w1 > 0):
        return None
    lo, hi = (u0, u1) if u0 <= u1 else (u1, u0)
    if not (lo <= um <= hi):  # pragma: no cover - guaranteed by the sign checks above
        return None
    params.update({"alpha": (1 - u0, 1 - um, 1 - u1), "beta_weights": (w0, w1), "type": kind})
    return Approximant("s-parabola", ([u0, um, u1], [mpq(1)]), _mobius_map(v0, v1, w0, w1), params)


def t_parabola(p0, d0, p1, d1, root: str = "paper") -> Approximant | None:
    """The t-parabola (Types 2 and 4): :func:`s_parabola` with ``u`` and ``v`` exchanged."""
    a = s_parabola(p0[::-1], d0[::-1], p1[::-1], d1[::-1], root)
    if a is None:
        return None
    b = a.swapped()
    b.kind = "t-parabola"
    b.params["type"] = {"type-1": "type-2", "type-3": "type-4", "iso-u": "iso-v"}[a.params["type"]]
    # exchange alpha/beta as the paper does (Type 2/4): the quadratic coordinate is v here
    b.params["beta"] = b.params.pop("alpha")
    b.params["alpha_weights"] = b.params.pop("beta_weights")
    return b


def parabola(p0, d0, p1, d1, root: str = "paper") -> Approximant | None:
    """Theorem 1: an s-parabola if Type 1/3 applies, else a t-parabola (Type 2/4), else ``None``."""
    return s_parabola(p0, d0, p1, d1, root) or t_parabola(p0, d0, p1, d1, root)


def hyperbola(p0, p1, mid, d0=None, d1=None) -> Approximant | None:
    """Iso-line ``s = 1/2`` (or ``t = 1/2``) of the quadratic reparameterization (4).

    ``u(t)`` linear, ``v(t) = M_beta(t)`` (the s-hyperbola; three free coefficients
    ``alpha_1, alpha_2, beta``).  Ref. [15] is not reproduced in the source; our
    documented choice: interpolate the end points and the target's parametric
    midpoint ``mid``, which fixes ``beta`` rationally.  Between the s- and the
    t-hyperbola the one whose end tangents deviate less from ``d0, d1`` is taken
    (float heuristic; the result is exact either way).
    """
    cands = [c for c in (_s_hyperbola(p0, p1, mid), _t_hyperbola(p0, p1, mid)) if c is not None]
    if not cands:
        return None
    if len(cands) == 1 or d0 is None:
        return cands[0]
    return min(cands, key=lambda c: _tangent_error(c, d0, d1))


def _s_hyperbola(p0, p1, mid) -> Approximant | None:
    (u0, v0), (u1, v1), (um, vm) = p0, p1, mid
    if v0 == v1:
        return None
    if u0 == u1:
        if um != u0:
            return None
        return Approximant("s-hyperbola", ([u0], [mpq(1)]), ([v0, v1], [mpq(1), mpq(1)]), {})
    ts = (um - u0) / (u1 - u0)
    vs = (vm - v0) / (v1 - v0)
    if not (0 < ts < 1 and 0 < vs < 1):
        return None
    beta = ts * (1 - vs) / (ts * (1 - vs) + vs * (1 - ts))
    return Approximant("s-hyperbola", ([u0, u1], [mpq(1), mpq(1)]), _mobius_map(v0, v1, beta, 1 - beta), {})


def _t_hyperbola(p0, p1, mid) -> Approximant | None:
    a = _s_hyperbola(p0[::-1], p1[::-1], mid[::-1])
    if a is None:
        return None
    b = a.swapped()
    b.kind = "t-hyperbola"
    return b


def _tangent_error(a: Approximant, d0, d1) -> float:
    h = np.array([[float(x) for x in row] for row in a.domain_hom()])
    n = h.shape[0] - 1
    err = 0.0
    for end, d in ((0, d0), (1, d1)):
        if end == 0:
            p, q = h[0, :2] / h[0, 2], h[1, :2] / h[1, 2]
            t = q - p
        else:
            p, q = h[n, :2] / h[n, 2], h[n - 1, :2] / h[n - 1, 2]
            t = p - q
        dd = np.array([float(d[0]), float(d[1])])
        den = np.linalg.norm(t) * np.linalg.norm(dd)
        err = max(err, np.arccos(np.clip(t @ dd / den, -1, 1)) if den > 0 else np.pi)
    return err


def segment(p0, p1) -> Approximant:
    """The straight segment ``p0 -> p1`` with linear speed (polyline method of ref. [2])."""
    (u0, v0), (u1, v1) = p0, p1
    return Approximant("segment", ([u0, u1], [mpq(1), mpq(1)]), ([v0, v1], [mpq(1), mpq(1)]), {})
