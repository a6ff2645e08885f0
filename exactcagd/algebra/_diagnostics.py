"""Warnings and errors specific to the algebra layer (documented in :mod:`exactcagd.algebra`).

* :class:`BasePointWarning` -- the parametrization ``(X, Y, W)`` had a common factor
  (base points, notes 18.3.4); it was divided out and the result describes the
  reduced curve.
* :class:`ImproperParametrizationWarning` -- the parametrization traces its curve
  ``r > 1`` times (the resultant came out as ``F^r``); the implicit equation
  returned is ``F``.
* :class:`ImproperParametrizationError` -- an operation that needs a one-to-one
  parametrization (inversion) was asked for an improper one.
"""

from ..errors import InputError


class AlgebraWarning(UserWarning):
    """Base class of the warnings of :mod:`exactcagd.algebra`."""


class BasePointWarning(AlgebraWarning):
    """A common factor of X(t), Y(t), W(t) (base points) was removed."""


class ImproperParametrizationWarning(AlgebraWarning):
    """The parametrization is not proper: its resultant is a power F^r, r > 1."""


class BasePointError(InputError):
    """Strict mode: the parametrization has base points (a common factor of X, Y, W)."""


class ImproperParametrizationError(InputError):
    """The operation needs a proper (generically one-to-one) parametrization."""
