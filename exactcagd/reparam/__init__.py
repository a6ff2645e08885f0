"""Reparameterizations of rational tensor-product Bézier surfaces (Yang et al. (004), section 4).

All three transformations substitute rational maps ``u = u(s, t)``, ``v = v(s, t)``
into the surface ``X(u, v)`` of bidegree ``(m, n)`` (``m`` in ``u``) and return the
exact rational Bézier surface ``X(s, t) = X(u(s, t), v(s, t))`` over ``[0, 1]^2``:

* :func:`mobius`     eqs. (2), (3): ``u = (1-a) s / (a (1-s) + (1-a) s)`` with constant
  ``a = alpha``, same in ``v`` with ``beta``; bidegree ``(m, n)``, weights
  ``w_ij (1-alpha)^i alpha^(m-i) (1-beta)^j beta^(n-j)``;
* :func:`quadratic`  eq. (4): ``alpha = a1 t + a2 (1-t)``, ``beta = b1 s + b2 (1-s)``;
  bidegree ``(m + n, m + n)``;
* :func:`cubic`      eq. (5): ``alpha(t) = sum a_k B^2_k(t)``, ``beta(s) = sum b_k B^2_k(s)``;
  bidegree ``(m + 2n, 2m + n)`` -- ``m + 2n`` in ``s``, ``2m + n`` in ``t``.

One mechanism does all of them (:func:`substitute`, Bernstein products of the maps;
see :mod:`exactcagd.reparam._mechanism`); the paper's closed forms live in
:mod:`exactcagd.reparam.closed_forms` and are checked against it in
``proofs/yang_reparam.py``.  The coefficients must lie in ``(0, 1)`` (the printed
condition), so each map is a monotone bijection of ``[0, 1]`` and every weight of the
result is positive.

>>> from exactcagd import BezierSurface
>>> from exactcagd.reparam import cubic
>>> X = BezierSurface([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]])
>>> Y = cubic(X, ("1/5", "4/5", "3/10"), ("2/5", "2/5", "2/5"))
>>> Y.degree
(3, 3)
"""

from __future__ import annotations

import numpy as np
from gmpy2 import mpq

from ..errors import DomainError, InputError
from ..exact.scalars import short_repr, to_rational
from ..geometry.bezier_surface import BezierSurface
from ._mechanism import bernstein_of_map, substitute_curve, substitute_tensor

__all__ = ["mobius", "quadratic", "cubic", "substitute", "cubic_maps", "substitute_curve", "substitute_tensor", "bernstein_of_map"]


def _coefficients(values, count: int, name: str) -> list:
    try:
        values = list(values)
    except TypeError:
        raise InputError(f"{name}: expected {count} coefficients, got {short_repr(values)}") from None
    if len(values) != count:
        raise InputError(f"{name}: expected {count} coefficients, got {len(values)}")
    out = [to_rational(x, where=f"{name}[{k}]") for k, x in enumerate(values)]
    for k, x in enumerate(out):
        if not (0 < x < 1):
            raise DomainError(f"{name}[{k}] = {x} must lie in the open interval (0, 1) (Yang et al. (2)-(5))")
    return out


def _check_surface(surface) -> BezierSurface:
    if not isinstance(surface, BezierSurface):
        raise InputError(f"expected a BezierSurface, got {type(surface).__name__}")
    return surface


def _grid(rows) -> np.ndarray:
    """Object array of map coefficients: ints become ``mpq``; other exact entries (mpq,
    QuadraticNumber, sympy symbols for symbolic proofs) are kept."""
    return np.array([[mpq(x) if isinstance(x, int) else x for x in row] for row in rows], dtype=object)


def substitute(surface: BezierSurface, u_map, v_map) -> BezierSurface:
    """``X(U/W_u, V/W_v)`` for tensor Bernstein arrays ``u_map = (U, W_u)``, ``v_map = (V, W_v)``.

    The general mechanism behind :func:`mobius`, :func:`quadratic` and :func:`cubic`
    (axis 0 of every array = ``s``, axis 1 = ``t``).  The caller is responsible for
    the maps sending ``[0, 1]^2`` into the surface's domain with ``W_u, W_v > 0``.
    """
    surface = _check_surface(surface)
    hom = substitute_tensor(surface.homogeneous(), u_map, v_map)
    return BezierSurface.from_homogeneous(hom)


def mobius_maps(alpha, beta):
    """Tensor arrays of eqs. (2), (3): ``u = (1-a) s / (a (1-s) + (1-a) s)``, ``v`` likewise in ``t``."""
    a, b = alpha, beta
    u_map = (_grid([[0], [1 - a]]), _grid([[a], [1 - a]]))
    v_map = (_grid([[0, 1 - b]]), _grid([[b, 1 - b]]))
    return u_map, v_map


def quadratic_maps(alphas, betas):
    """Tensor arrays of eq. (4): ``alpha(t) = a1 t + a2 (1 - t)``, ``beta(s) = b1 s + b2 (1 - s)``."""
    (a1, a2), (b1, b2) = alphas, betas
    at = [a2, a1]  # Bernstein coefficients of alpha(t) (value a2 at t = 0)
    bs = [b2, b1]
    u_map = (_grid([[0, 0], [1 - x for x in at]]), _grid([at, [1 - x for x in at]]))
    v_map = (_grid([[0, 1 - y] for y in bs]), _grid([[y, 1 - y] for y in bs]))
    return u_map, v_map


def cubic_maps(alphas, betas):
    """Tensor arrays of eq. (5): ``alpha(t) = sum_k a_(k+1) B^2_k(t)``, ``beta(s)`` likewise.

    ``u = (1 - alpha(t)) s / (alpha(t) (1 - s) + (1 - alpha(t)) s)`` is of degree
    ``(1, 2)`` in ``(s, t)``; ``v`` of degree ``(2, 1)``.
    """
    at, bs = list(alphas), list(betas)
    u_map = (_grid([[0, 0, 0], [1 - x for x in at]]), _grid([at, [1 - x for x in at]]))
    v_map = (_grid([[0, 1 - y] for y in bs]), _grid([[y, 1 - y] for y in bs]))
    return u_map, v_map


def mobius(surface: BezierSurface, alpha, beta) -> BezierSurface:
    """Möbius reparameterization, Yang et al. eqs. (2), (3); same bidegree ``(m, n)``.

    >>> from exactcagd import BezierSurface
    >>> X = BezierSurface([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]])
    >>> Y = mobius(X, "1/3", "1/2")          # same control points, weights (1-a)^i a^(m-i) ...
    >>> Y.control_net == X.control_net, Y.weights
    (True, ((mpq(1,6), mpq(1,6)), (mpq(1,3), mpq(1,3))))
    """
    alpha = _coefficients([alpha], 1, "alpha")[0]
    beta = _coefficients([beta], 1, "beta")[0]
    u_map, v_map = mobius_maps(alpha, beta)
    return substitute(surface, u_map, v_map)


def quadratic(surface: BezierSurface, alphas, betas) -> BezierSurface:
    """Quadratic reparameterization, eq. (4): bidegree ``(m + n, m + n)``.

    ``alphas = (a1, a2)`` give ``alpha(t) = a1 t + a2 (1 - t)`` in eq. (2),
    ``betas = (b1, b2)`` give ``beta(s) = b1 s + b2 (1 - s)`` in eq. (3).
    """
    alphas = _coefficients(alphas, 2, "alphas")
    betas = _coefficients(betas, 2, "betas")
    u_map, v_map = quadratic_maps(alphas, betas)
    return substitute(surface, u_map, v_map)


def cubic(surface: BezierSurface, alphas, betas) -> BezierSurface:
    """Cubic reparameterization, eq. (5): bidegree ``(m + 2n, 2m + n)`` in ``(s, t)``.

    ``alphas = (a1, a2, a3)`` are the quadratic Bernstein coefficients of
    ``alpha(t)``, ``betas = (b1, b2, b3)`` those of ``beta(s)``.  The iso-line ``s = 1/2``
    is ``t -> X(1 - alpha(t), M_beta(t))`` with ``beta = beta(1/2)`` (section 5: the
    "s-parabola").
    """
    alphas = _coefficients(alphas, 3, "alphas")
    betas = _coefficients(betas, 3, "betas")
    u_map, v_map = cubic_maps(alphas, betas)
    return substitute(surface, u_map, v_map)
