"""Teach sympy that gmpy2's ``mpq`` is an exact rational, whatever the import order.

Without this, ``sympify(mpq(1, 3))`` gives the Float 0.3333 (sympy falls back on
``__float__``), so ``mpq * Symbol`` silently loses exactness.  ``import exactcagd``
calls :func:`install`, which registers the converter at once when sympy is already
loaded and otherwise right after ``sympy.core.sympify`` is first imported, so importing
exactcagd loads neither sympy nor gmpy2.
"""

from __future__ import annotations

import importlib.abc
import importlib.util
import sys

__all__ = ["install"]


def _mpq_to_sympy(q):
    import sympy

    return sympy.Rational(int(q.numerator), int(q.denominator))


def _register(converter: dict) -> None:
    from gmpy2 import mpq

    converter[type(mpq(0))] = _mpq_to_sympy


class _SympyHook(importlib.abc.MetaPathFinder):
    """Registers the converter right after ``sympy.core.sympify`` is first imported."""

    def find_spec(self, name, path, target=None):
        if name != "sympy.core.sympify":
            return None
        sys.meta_path.remove(self)
        spec = importlib.util.find_spec(name)
        if spec is None or spec.loader is None:  # pragma: no cover
            return spec
        original = spec.loader.exec_module

        def exec_module(module):
            original(module)
            _register(module.converter)

        spec.loader.exec_module = exec_module
        return spec


def install() -> None:
    """Register the converter now (sympy loaded) or when sympy gets loaded."""
    module = sys.modules.get("sympy.core.sympify")
    if module is not None:
        _register(module.converter)
    elif not any(isinstance(f, _SympyHook) for f in sys.meta_path):
        sys.meta_path.insert(0, _SympyHook())
