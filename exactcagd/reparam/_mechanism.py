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
from gmpy2 import mpq, mpz

from ..exact import bernstein as bz
from ..exact.quadratic import QuadraticNumber, field_of
from ..exact.scalars import to_fmpq as _fq

__all__ = ["substitute_curve", "substitute_tensor", "bernstein_of_map", "bernstein_product"]


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


# ---------------------------------------------------------------------------------- fast curve path
# A univariate Bernstein polynomial ``sum b_i C(d, i) t^i (1-t)^(d-i)`` equals
# ``(1-t)^d P(x)`` with ``x = t / (1-t)`` and ``P(x) = sum b_i C(d, i) x^i`` ("scaled" form), so
# Bernstein products are products of ``P`` (flint ``fmpq_poly``, in C) and degree elevation by
# ``r`` is multiplication by ``(1 + x)^r``.  Entries in ``Q(sqrt(D))`` are carried as pairs
# ``(A, B)`` meaning ``A + B sqrt(D)``.  Same result as the generic route (tested), 5-20x faster.


def _pair(coeffs, D):
    import flint

    d = len(coeffs) - 1
    a, b = [], []
    for i, c in enumerate(coeffs):
        k = bz.binomial(d, i)
        if isinstance(c, QuadraticNumber):
            a.append(_fq(c.a) * k)
            b.append(_fq(c.b) * k)
        else:
            a.append(_fq(mpq(c)) * k)
            b.append(flint.fmpq(0))
    return [flint.fmpq_poly(a), flint.fmpq_poly(b) if D is not None else None, d]


def _mul(p, q, D):
    a1, b1, d1 = p
    a2, b2, d2 = q
    if D is None:
        return [a1 * a2, None, d1 + d2]
    return [a1 * a2 + b1 * b2 * int(D), a1 * b2 + a2 * b1, d1 + d2]


def _lift(p, d):
    import flint

    r = d - p[2]
    if r == 0:
        return p
    f = flint.fmpq_poly([1, 1]) ** r
    return [p[0] * f, None if p[1] is None else p[1] * f, d]


def _bernstein_pairs(N, W, degree, D):
    """``[C(k, i) N^i (W - N)^(k-i)]`` as scaled pairs."""
    d = max(len(N), len(W)) - 1
    n, w = _lift(_pair(N, D), d), _lift(_pair(W, D), d)
    rest = [w[0] - n[0], None if D is None else w[1] - n[1], d]
    one = _pair([mpq(1)], D)
    pn, pr = [one], [one]
    for _ in range(degree):
        pn.append(_mul(pn[-1], n, D))
        pr.append(_mul(pr[-1], rest, D))
    out = []
    for i in range(degree + 1):
        p = _mul(pn[i], pr[degree - i], D)
        k = bz.binomial(degree, i)
        out.append([p[0] * k, None if D is None else p[1] * k, p[2]])
    return out


def _unscale(p, D) -> list:
    a, b, d = p
    ca, cb = a.coeffs(), (b.coeffs() if b is not None else [])
    out = []
    for i in range(d + 1):
        k = bz.binomial(d, i)
        x = ca[i] if i < len(ca) else 0
        x = mpq(int(x.p), int(x.q)) / k if x else mpq(0)
        y = cb[i] if i < len(cb) else 0
        if y:
            out.append(QuadraticNumber._make(x, mpq(int(y.p), int(y.q)) / k, D))
        else:
            out.append(x)
    return out


def bernstein_product(a, b) -> np.ndarray:
    """Bernstein product of two coefficient lists with entries in ``Q`` or one ``Q(sqrt(D))``,
    as a product of scaled forms in flint (the route of :func:`substitute_curve`): the values
    of :func:`exactcagd.exact.bernstein.product` (notes 9.3), entries whose ``sqrt(D)`` part
    is zero returned as rationals.

    >>> from gmpy2 import mpq
    >>> [str(x) for x in bernstein_product([mpq(0), mpq(1)], [mpq(1), mpq(3)])]
    ['0', '1/2', '3']
    """
    D = field_of([*a, *b])
    D = None if D is None else mpz(D)
    return np.array(_unscale(_mul(_pair(list(a), D), _pair(list(b), D), D), D), dtype=object)


def _substitute_curve_fast(hom: np.ndarray, u_map, v_map):
    """Flint route of :func:`substitute_curve` for rational patches (map entries in ``Q`` or one
    ``Q(sqrt(D))``); ``None`` when it does not apply."""
    import flint

    if not all(isinstance(x, type(mpq(0))) for x in hom.reshape(-1)):
        return None
    entries = [x for part in (*u_map, *v_map) for x in part]
    if not all(isinstance(x, (type(mpq(0)), int, QuadraticNumber)) for x in entries):
        return None
    D = field_of(entries)
    if D is not None:
        D = mpz(D)
    m, n, k = hom.shape[0] - 1, hom.shape[1] - 1, hom.shape[2]
    A = _bernstein_pairs(list(u_map[0]), list(u_map[1]), m, D)
    B = _bernstein_pairs(list(v_map[0]), list(v_map[1]), n, D)
    cols = []
    for c in range(k):
        total = None
        for i in range(m + 1):
            ci_a = flint.fmpq_poly([])
            ci_b = flint.fmpq_poly([]) if D is not None else None
            for j in range(n + 1):
                h = hom[i, j, c]
                if h == 0:
                    continue
                q = _fq(h)
                ci_a += B[j][0] * q
                if D is not None:
                    ci_b += B[j][1] * q
            term = _mul(A[i], [ci_a, ci_b, B[0][2]], D)
            total = term if total is None else [total[0] + term[0], None if D is None else total[1] + term[1], term[2]]
        cols.append(_unscale(total, D))
    out = np.empty((len(cols[0]), k), dtype=object)
    for c, col in enumerate(cols):
        out[:, c] = col
    return out


def substitute_curve(hom: np.ndarray, u_map, v_map, fast: bool = True) -> np.ndarray:
    """Homogeneous Bézier coefficients of ``t -> X(U(t)/W_u(t), V(t)/W_v(t))``.

    Parameters
    ----------
    hom : array ``(m + 1, n + 1, k)``, the homogeneous net ``(w P, w)`` of ``X``
    u_map, v_map : pairs ``(U, W_u)``, ``(V, W_v)`` of univariate Bernstein coefficient lists

    Returns
    -------
    array ``(m deg(u_map) + n deg(v_map) + 1, k)``.
    """
    hom = np.asarray(hom, dtype=object)
    if fast:
        out = _substitute_curve_fast(hom, u_map, v_map)
        if out is not None:
            return out
    return _substitute(hom, u_map, v_map, 1, bz.product)


def substitute_tensor(hom: np.ndarray, u_map, v_map) -> np.ndarray:
    """Homogeneous net of ``(s, t) -> X(U/W_u, V/W_v)`` for tensor-product maps.

    ``u_map = (U, W_u)`` and ``v_map = (V, W_v)`` are 2-D Bernstein arrays (axis 0 =
    ``s``, axis 1 = ``t``).  The result has bidegree
    ``m deg(u_map) + n deg(v_map)`` componentwise.
    """
    return _substitute(np.asarray(hom, dtype=object), u_map, v_map, 2, bz.product_tensor)
