"""One mechanism for every reparameterization: substitute rational maps into a net.

If ``u = U / W_u`` and ``v = V / W_v`` with polynomial ``U, W_u, V, W_v`` (Bernstein
form, univariate for a curve, tensor-product for a surface), then

    B^m_i(u) = C(m, i) U^i (W_u - U)^(m-i) / W_u^m,
    B^n_j(v) = C(n, j) V^j (W_v - V)^(n-j) / W_v^n,

and the common factor ``W_u^m W_v^n`` cancels between numerator and denominator of
the rational surface (Yang et al. (004), section 4; the closed forms (2)-(5) are
special cases).  So the homogeneous coefficients of ``X(u(.), v(.))`` are

    sum_ij (w_ij P_ij, w_ij) * A_i * B_j,   A_i = C(m,i) U^i (W_u-U)^(m-i), B_j likewise,

a sum of exact Bernstein products (Sederberg's notes 9.3).  Entries may be ``mpq``
or :class:`exactcagd.exact.quadratic.QuadraticNumber` (anything closed under + - *).

>>> import numpy as np
>>> from gmpy2 import mpq
>>> hom = np.array([[[mpq(0), mpq(1)], [mpq(1), mpq(1)]]], dtype=object)   # X(u, v) = v, degree (0, 1)
>>> V, Wv = [mpq(0), mpq(1, 2)], [mpq(1, 2), mpq(1, 2)]                     # v = t (a trivial Möbius map)
>>> out = substitute_curve(hom, ([mpq(0)], [mpq(1)]), (V, Wv))
>>> [x / w for x, w in out]
[mpq(0,1), mpq(1,1)]
"""

from __future__ import annotations

import numpy as np
from gmpy2 import mpq

from ..exact import bernstein as bz

__all__ = ["substitute_curve", "substitute_tensor", "bernstein_of_map"]


def _as_array(c, ndim: int) -> np.ndarray:
    a = np.array(c, dtype=object)
    if a.ndim != ndim:
        raise ValueError(f"expected a {ndim}-D Bernstein array, got shape {a.shape}")
    return a


def _elevate_to(a: np.ndarray, degrees: tuple) -> np.ndarray:
    for axis, d in enumerate(degrees):
        r = d - (a.shape[axis] - 1)
        if r > 0:
            a = bz.along(axis, bz.elevate, a, r)
    return a


def _one(ndim: int) -> np.ndarray:
    return np.full((1,) * ndim, mpq(1), dtype=object)


def bernstein_of_map(U, W, degree: int, mul) -> list:
    """``[C(k, i) U^i (W - U)^(k-i) for i in 0..k]`` (scalar Bernstein arrays).

    ``U`` and ``W`` are lifted to a common degree first; ``mul`` is
    :func:`bernstein.product` (curves) or :func:`bernstein.product_tensor` (surfaces).
    """
    ndim = U.ndim
    common = tuple(max(U.shape[a], W.shape[a]) - 1 for a in range(ndim))
    U, W = _elevate_to(U, common), _elevate_to(W, common)
    rest = W - U
    pu, pr = [_one(ndim)], [_one(ndim)]
    for _ in range(degree):
        pu.append(mul(pu[-1], U))
        pr.append(mul(pr[-1], rest))
    return [mul(pu[i], pr[degree - i]) * bz.binomial(degree, i) for i in range(degree + 1)]


def _substitute(hom: np.ndarray, u_map, v_map, ndim: int, mul) -> np.ndarray:
    m, n = hom.shape[0] - 1, hom.shape[1] - 1
    U, Wu = (_as_array(x, ndim) for x in u_map)
    V, Wv = (_as_array(x, ndim) for x in v_map)
    A = bernstein_of_map(U, Wu, m, mul)
    B = bernstein_of_map(V, Wv, n, mul)
    k = hom.shape[2]
    out = None
    for i in range(m + 1):
        # C_i = sum_j B_j (x) hom_ij : shape B.shape + (k,)
        Ci = None
        for j in range(n + 1):
            term = B[j][..., None] * hom[i, j].reshape((1,) * ndim + (k,))
            Ci = term if Ci is None else Ci + term
        term = mul(A[i][..., None], Ci)
        out = term if out is None else out + term
    return bz._zeros_to_mpq(out)


def substitute_curve(hom: np.ndarray, u_map, v_map) -> np.ndarray:
    """Homogeneous Bézier coefficients of ``t -> X(U(t)/W_u(t), V(t)/W_v(t))``.

    Parameters
    ----------
    hom : array ``(m + 1, n + 1, k)``, the homogeneous net ``(w P, w)`` of ``X``
    u_map, v_map : pairs ``(U, W_u)``, ``(V, W_v)`` of univariate Bernstein coefficient lists

    Returns
    -------
    array ``(m deg(u_map) + n deg(v_map) + 1, k)``.
    """
    return _substitute(np.asarray(hom, dtype=object), u_map, v_map, 1, bz.product)


def substitute_tensor(hom: np.ndarray, u_map, v_map) -> np.ndarray:
    """Homogeneous net of ``(s, t) -> X(U/W_u, V/W_v)`` for tensor-product maps.

    ``u_map = (U, W_u)`` and ``v_map = (V, W_v)`` are 2-D Bernstein arrays (axis 0 =
    ``s``, axis 1 = ``t``).  The result has bidegree
    ``m deg(u_map) + n deg(v_map)`` componentwise.
    """
    return _substitute(np.asarray(hom, dtype=object), u_map, v_map, 2, bz.product_tensor)
