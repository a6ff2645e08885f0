"""Exact reference data for testing other geometry kernels (``exactcagd refdata``).

Application layer: builds records with the exact layers below it and writes them as
suites (``manifest.json`` + one ``<kind>.jsonl`` per kind) that validate against the
published JSON Schemas in ``exactcagd/refdata/schemas/``.

* :mod:`.records` -- exact numbers, float64 companions, algebraic numbers (the format);
* :mod:`.families` -- random inputs and the hard families;
* :mod:`.kinds` -- the record kinds and :func:`make_record`;
* :mod:`.stream` -- batched, ordered, constant-memory generation (processes or Dask);
* :mod:`.suite` -- single-kind files, the standard suite and the CLI (:mod:`.options` checks its arguments);
* :mod:`.manifest` -- versions, counts, schema and file hashes;
* :mod:`.formats` -- the ``bezier`` package's functional-test fixture layout;
* :mod:`.schemagen` -- builds the published JSON Schemas (``python -m exactcagd.refdata.schemagen``).

>>> from exactcagd.refdata import make_record
>>> make_record("roots", "random", seed=0, index=0, degrees=(3,))["id"]
'roots/random/0'
"""

from .kinds import KINDS, make_record
from .records import FORMAT_VERSION

__all__ = ["FORMAT_VERSION", "KINDS", "make_record"]
