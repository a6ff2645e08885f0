"""Exact range checks for domain curves: does ``K(t)`` stay inside a rectangle for t in [0, 1]?

A point of a (rational) domain curve ``K = (X/W, Y/W)`` lies in ``[a, b] x [c, d]`` iff the
four polynomials ``X - a W``, ``b W - X``, ``Y - c W``, ``d W - Y`` are >= 0 (for ``W > 0``).
Non-negativity of a Bernstein polynomial on [0, 1] is decided exactly:

* all Bernstein coefficients >= 0 is sufficient (convex hull, notes 2.2);
* otherwise the polynomial is >= 0 on [0, 1] iff it is >= 0 just right of 0 (sign of its
  lowest non-zero power coefficient) and it has no root of odd multiplicity in (0, 1)
  (exact isolation by :func:`exactcagd.exact.algebraic.real_roots`).

>>> from exactcagd.exact.bernstein import as_coefficients
>>> nonnegative_on_unit(as_coefficients([1, -1, 1]))      # 1 - 4t + 4t^2 = (1 - 2t)^2
(True, None)
>>> nonnegative_on_unit(as_coefficients([1, -2, 1]))[0]   # 1 - 6t + 6t^2 dips below 0
False
"""

from __future__ import annotations

import numpy as np
from gmpy2 import mpq

from ..errors import DomainError, WeightError
from ..exact import bernstein as bz
from ..exact.algebraic import real_roots

__all__ = ["nonnegative_on_unit", "check_inside", "check_weight_function", "first_negative_witness"]


def nonnegative_on_unit(c: np.ndarray):
    """Decide exactly whether the Bernstein polynomial ``c`` (1-D) is >= 0 on [0, 1].

    Returns ``(True, None)`` or ``(False, witness)`` where ``witness`` is an exact
    parameter (``mpq`` or :class:`RealAlgebraic`) at or next to which the polynomial is
    negative: 0, 1 or the odd-multiplicity root where it changes sign.
    """
    if all(x >= 0 for x in c):
        return True, None
    a = bz.to_power(c)
    nonzero = [k for k in range(a.shape[0]) if a[k] != 0]
    if not nonzero:
        return True, None
    if a[nonzero[0]] < 0:
        return False, mpq(0)
    for root, mult in real_roots(list(a), 0, 1):
        if mult % 2 == 1 and root != 0 and root != 1:
            return False, root
    return True, None


def first_negative_witness(c: np.ndarray):
    """The witness of :func:`nonnegative_on_unit` (``None`` when non-negative)."""
    return nonnegative_on_unit(c)[1]


def _fmt(t) -> str:
    if isinstance(t, type(mpq(0))):
        return f"t = {t}"
    text = str(t)
    return f"t ~ {float(t):.6g} ({text})"


def check_weight_function(w: np.ndarray, what: str = "weight function") -> int:
    """Check that the Bernstein polynomial ``w`` has no zero on [0, 1]; return its sign.

    Raises :class:`WeightError` when ``w`` vanishes somewhere on [0, 1] (a pole).
    """
    if all(x > 0 for x in w):
        return 1
    if all(x < 0 for x in w):
        return -1
    if all(x == 0 for x in w):
        raise WeightError(f"{what} is identically zero")
    roots = real_roots(list(bz.to_power(w)), 0, 1)
    if roots:
        raise WeightError(f"{what} vanishes at {_fmt(roots[0][0])} in [0, 1] (a pole of the rational curve)")
    return 1 if bz.de_casteljau(w, mpq(1, 2)) > 0 else -1


def check_inside(hom: np.ndarray, box=((0, 1), (0, 1)), what: str = "domain curve") -> None:
    """Raise :class:`DomainError` unless the planar curve ``hom = (X, Y, W)`` stays in ``box``.

    ``hom`` holds homogeneous Bernstein coefficients (shape ``(N + 1, 3)``) whose weight
    function ``W`` is positive on [0, 1] (check it first with :func:`check_weight_function`).
    The test is exact (see the module docstring).
    """
    (ulo, uhi), (vlo, vhi) = ((mpq(a), mpq(b)) for a, b in box)
    if all(ulo * w <= x <= uhi * w and vlo * w <= y <= vhi * w for x, y, w in hom.tolist()):
        return  # the four polynomials below have only >= 0 Bernstein coefficients (no array arithmetic)
    w = hom[:, 2]
    for axis, name in ((0, "u"), (1, "v")):
        lo, hi = (mpq(x) for x in box[axis])
        x = hom[:, axis]
        for poly, side in ((x - lo * w, f"{name}(t) < {lo}"), (hi * w - x, f"{name}(t) > {hi}")):
            ok, witness = nonnegative_on_unit(poly)
            if not ok:
                raise DomainError(
                    f"{what} leaves the parameter domain [{box[0][0]}, {box[0][1]}] x [{box[1][0]}, {box[1][1]}]: "
                    f"{side} at/near {_fmt(witness)}; pass allow_outside=True to compose the polynomial "
                    "extension of the surface anyway"
                )
