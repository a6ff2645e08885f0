"""Isoparametric domain curves: the shortcut of Lasser & Bonneau (000) sections IV and VI.

If the domain curve keeps ``v = v*`` fixed (a "u parameter line", Statement 1), then
``F(K(t)) = G(u(t))`` with the iso-curve ``G(u) = F(u, v*)`` of degree ``l`` (de Casteljau in
v at ``v*``), composed with the 1-D reparametrization ``u(t) = X(t)/W(t)``:

    W^l (G_hom)(X/W) = sum_i G_i C(l,i) X^i (W - X)^(l-i),      degree l N,

i.e. the composition of a degree-(l, 0) "surface" with ``K`` (route (b) with ``m = 0``).
For ``u = u*`` fixed the roles swap (degree ``m N``).  For ``N = 1`` and a polynomial
``K`` this is the paper's ``B_R = F^{l,m}_{0,0}(u^l_{I^u}, v*^m)``, ``|I^u| = R``: the
polar values ``G(u_0^{l-R}, u_1^R)``, i.e. ``G`` restricted to ``[u_0, u_1]``.  For a
rational linear ``K`` with weights ``beta_0, beta_1`` the weights carry the factors
``beta_0^(l-R) beta_1^R`` (the paper normalizes ``beta_0 = beta_1 = 1`` "w.l.o.g.", which
reparametrizes ``K``; see ``proofs/lasser_isoparametric.py``).

Statements 1, 2: Theorems 1, 2 applied to such a curve give the same curve with the
homogeneous net multiplied by ``W(t)^m`` -- for a polynomial ``K`` exactly the degree
elevation by ``N m`` (proved in the tests by exact degree reduction).

Detection is exact: all control points ``K_I`` have the same v (or u) coordinate; for a
rational curve with positive weights this is equivalent to ``v(t)`` being constant.

>>> from exactcagd import BezierCurve
>>> isoparametric_direction(BezierCurve([[0, "1/3"], ["1/2", "1/3"]]).homogeneous())
('v', mpq(1,3))
"""

from __future__ import annotations

import numpy as np

from ..exact import bernstein as bz
from .fast import compose_homogeneous_fast
from .lasser import compose_homogeneous_lasser, polar_value

__all__ = ["isoparametric_direction", "iso_net", "compose_isoparametric_homogeneous", "statement1_points"]


def isoparametric_direction(curve: np.ndarray):
    """Which coordinate of the homogeneous domain curve ``(X, Y, W)`` is constant.

    Returns ``("v", v*)`` when ``v(t) == v*`` (the image is a u-iso-curve, degree ``l N``),
    ``("u", u*)`` when ``u(t) == u*`` (degree ``m N``), ``("point", (u*, v*))`` when both
    are constant, or ``None``.
    """
    w = curve[:, 2]
    us = {x / b for x, b in zip(curve[:, 0], w)}
    vs = {y / b for y, b in zip(curve[:, 1], w)}
    if len(us) == 1 and len(vs) == 1:
        return ("point", (us.pop(), vs.pop()))
    if len(vs) == 1:
        return ("v", vs.pop())
    if len(us) == 1:
        return ("u", us.pop())
    return None


def iso_net(net: np.ndarray, direction: str, value) -> np.ndarray:
    """The iso-curve's homogeneous net as a degenerate tensor net.

    ``direction == "v"``: ``G(u) = F(u, value)``, shape ``(l + 1, 1, D)``;
    ``direction == "u"``: ``G(v) = F(value, v)``, shape ``(1, m + 1, D)``.
    """
    if direction == "v":
        return bz.de_casteljau(np.moveaxis(net, 1, 0), value)[:, None, :]
    return bz.de_casteljau(net, value)[None, :, :]


def compose_isoparametric_homogeneous(net: np.ndarray, curve: np.ndarray, method: str = "fast", **options):
    """Homogeneous coefficients of ``F(K(t))`` for an isoparametric ``K`` (degree ``l N`` or ``m N``).

    Returns ``None`` when ``K`` is not isoparametric.  A constant ``K`` (a point) is treated
    as a v-line (degree ``l N``).
    """
    iso = isoparametric_direction(curve)
    if iso is None:
        return None
    direction, value = iso
    if direction == "point":
        direction, value = "v", value[1]
    small = iso_net(net, direction, value)
    if method == "lasser":
        return compose_homogeneous_lasser(small, curve, options.get("enumeration", "multisets"))
    return compose_homogeneous_fast(small, curve, options.get("strategy", "flint"))


def statement1_points(net: np.ndarray, curve: np.ndarray) -> np.ndarray:
    """Statement 1/2 as printed in section IV/VI for ``N = 1``, v-line ``v_0 = v_1 = v*``.

    ``Omega_R B_R = beta_0^(l-R) beta_1^R (omega F)^{l,m}_{0,0}(u_0^(l-R), u_1^R, v*^m)`` --
    the printed recipe has no beta factors (it assumes ``beta_0 = beta_1 = 1``); they are
    included here so that the result is ``F(K(t))`` for any weights.
    """
    l, m = net.shape[0] - 1, net.shape[1] - 1
    (x0, y0, b0), (x1, _, b1) = curve
    u0, u1, vstar = x0 / b0, x1 / b1, y0 / b0
    rows = [b0 ** (l - R) * b1**R * polar_value(net, [u0] * (l - R) + [u1] * R, [vstar] * m) for R in range(l + 1)]
    return np.array(rows, dtype=object)
