"""exactcagd's proof ledger: one module per source-document section.

Each module registers claims with :func:`proofs._ledger.claim`; ``exactcagd verify``
and ``tests/test_proofs.py`` discover and run them.  See ``proofs/README.md``.
"""
