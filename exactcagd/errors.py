"""Exception hierarchy of exactcagd.

Every error the package raises on bad input derives from :class:`ExactCAGDError`,
so a caller can catch the whole family with one ``except``.  The subclasses say
*what* was wrong; the message says *where*.

>>> from exactcagd.errors import ExactCAGDError, WeightError
>>> issubclass(WeightError, ExactCAGDError)
True
"""


class ExactCAGDError(Exception):
    """Base class of all exactcagd errors."""


class InputError(ExactCAGDError, ValueError):
    """Input of the wrong shape, type or value (ragged nets, wrong lengths, ...)."""


class InexactInputError(InputError):
    """A value cannot enter the exact layer: NaN/inf, or a float under the strict policy."""


class WeightError(InputError):
    """Weights of a rational object are zero, negative or of the wrong count."""


class KnotError(InputError):
    """A knot vector is decreasing, of the wrong length, has a knot of too high a multiplicity, or
    is not clamped where an operation needs a clamped one."""


class DomainError(ExactCAGDError, ValueError):
    """A parameter lies outside the domain where the operation is defined."""


class DegreeError(ExactCAGDError, ValueError):
    """A requested degree operation is impossible (e.g. inexact degree reduction)."""


class DimensionError(InputError):
    """Objects of incompatible dimension were combined."""


class OutputError(InputError):
    """An output path cannot be written safely (a device, directory, link, /proc path, unwritable folder)."""


class NotSupportedError(ExactCAGDError, NotImplementedError):
    """The construction exists in principle but this case is not supported."""


class LimitError(ExactCAGDError):
    """The estimated work or size of a request exceeds a documented resource limit.

    Raised before the work starts; the message names the argument, the estimate, the
    limit and how to raise it (:mod:`exactcagd.limits`).
    """
