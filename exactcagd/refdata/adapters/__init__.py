"""Kernel adapters for ``exactcagd conformance`` (one small module per kernel).

* ``bezier`` -- :mod:`.bezier_kernel` (the ``bezier`` package: polynomial Bézier curves);
* ``geomdl`` -- :mod:`.geomdl_kernel` (NURBS-Python);
* ``occ`` -- :mod:`.occ_kernel` (OpenCASCADE through ``cadquery-ocp``);
* ``package.module:Class`` -- your own adapter (see :mod:`.base` and ``docs/conformance.md``).

>>> sorted(ADAPTERS)
['bezier', 'geomdl', 'occ']
"""

from __future__ import annotations

import importlib

from ...errors import InputError

__all__ = ["ADAPTERS", "load_adapter"]

#: Built-in adapters: kernel name -> "module:Class".
ADAPTERS = {
    "bezier": "exactcagd.refdata.adapters.bezier_kernel:BezierAdapter",
    "geomdl": "exactcagd.refdata.adapters.geomdl_kernel:GeomdlAdapter",
    "occ": "exactcagd.refdata.adapters.occ_kernel:OCCAdapter",
}
_ALIASES = {"opencascade": "occ", "ocp": "occ", "cadquery-ocp": "occ"}


def load_adapter(name: str):
    """An adapter instance for a built-in kernel name or ``package.module:Class``.

    A kernel whose package is not installed raises :class:`exactcagd.errors.NotSupportedError`
    naming the package; an unknown name or a bad ``module:Class`` raises ``InputError``.
    """
    spec = ADAPTERS.get(_ALIASES.get(name.lower(), name.lower()))
    if spec is None:
        if ":" not in name:
            raise InputError(f"--kernel: unknown kernel {name!r}; choose one of {', '.join(ADAPTERS)} or give package.module:Class")
        spec = name
    module_name, _, cls_name = spec.partition(":")
    try:
        module = importlib.import_module(module_name)
    except ModuleNotFoundError as exc:
        if exc.name and module_name.startswith(exc.name):
            raise InputError(f"--kernel: cannot import {module_name!r} ({exc})") from None
        raise
    cls = getattr(module, cls_name, None)
    if cls is None:
        raise InputError(f"--kernel: module {module_name!r} has no class {cls_name!r}")
    adapter = cls()
    for kind in adapter.kinds:
        if not callable(getattr(adapter, kind, None)):
            raise InputError(f"--kernel: adapter {cls_name} lists kind {kind!r} but has no method of that name")
    return adapter
