"""The ledger mechanism: register a claim of a source document and the check that decides it.

A claim is a function decorated with :func:`claim`.  It runs exactcagd's exact
machinery and returns one of the outcomes below; a failed check raises
``AssertionError`` (the runner then reports the claim as ``FAILED``, never hides it).

Outcomes
--------
``verified``        the printed claim holds, checked symbolically;
``verified-range``  it holds over the stated finite range (plus random exact instances);
``erratum``         the printed form is wrong; the corrected form is given and verified;
``reconstructed``   the extracted text was damaged; the reconstruction is verified;
``not-checkable``   cannot be decided by computation (with why).

Example
-------
>>> from exactcagd.proofs._ledger import claim, verified
>>> @claim(doc="sederberg", section="2.3", ref="de Casteljau", statement="P(1/2) of (0,1,0) is 1/2")
... def _example():
...     return verified("exact evaluation")
"""

from __future__ import annotations

import dataclasses
import importlib
import pkgutil
import time
from typing import Callable

STATUSES = ("verified", "verified-range", "erratum", "reconstructed", "not-checkable")
DOCS = {
    "lasser": "Lasser & Bonneau, Bezier Representation of Trim Curves (1993)",
    "yang": "Yang et al., G1 continuous approximate curves on NURBS surfaces (2012)",
    "sederberg": "Sederberg, Computer Aided Geometric Design course notes (2012)",
}


@dataclasses.dataclass
class Outcome:
    status: str
    detail: str = ""
    printed: str | None = None
    corrected: str | None = None
    range: str | None = None

    def __post_init__(self):
        if self.status not in STATUSES:
            raise ValueError(f"unknown ledger status {self.status!r}")


def verified(detail: str = "") -> Outcome:
    return Outcome("verified", detail)


def verified_range(range: str, detail: str = "") -> Outcome:
    return Outcome("verified-range", detail, range=range)


def erratum(printed: str, corrected: str, detail: str) -> Outcome:
    return Outcome("erratum", detail, printed=printed, corrected=corrected)


def reconstructed(printed: str, corrected: str, detail: str) -> Outcome:
    return Outcome("reconstructed", detail, printed=printed, corrected=corrected)


def not_checkable(why: str) -> Outcome:
    return Outcome("not-checkable", why)


@dataclasses.dataclass
class Claim:
    doc: str
    section: str
    ref: str
    statement: str
    slow: bool
    func: Callable[[], Outcome]
    trace: Callable[[], None] | None = None

    @property
    def key(self) -> str:
        return f"{self.func.__module__}.{self.func.__name__}"


REGISTRY: list[Claim] = []


def claim(doc: str, section: str, ref: str, statement: str, slow: bool = False, trace: Callable | None = None):
    """Register the decorated function as the check of one printed claim.

    Parameters
    ----------
    doc : "lasser" | "yang" | "sederberg"
    section : section of the document (e.g. "III", "4.3", "17.4")
    ref : equation / theorem / example label as printed (e.g. "(7)", "Theorem 1")
    statement : the claim as printed (plain text, short)
    slow : heavy checks (run by ``exactcagd verify`` and ``pytest -m slow``)
    trace : optional function printing the derivation step by step (teaching mode)
    """
    if doc not in DOCS:
        raise ValueError(f"unknown document {doc!r}")

    def decorate(func):
        REGISTRY.append(Claim(doc, section, ref, statement, slow, func, trace))
        return func

    return decorate


def discover() -> list[Claim]:
    """Import every proof module in the ``proofs`` package; return the registry."""
    import exactcagd.proofs as proofs

    for info in pkgutil.iter_modules(proofs.__path__):
        if not info.name.startswith("_"):
            importlib.import_module(f"exactcagd.proofs.{info.name}")
    return list(REGISTRY)


@dataclasses.dataclass
class Row:
    claim: Claim
    outcome: Outcome | None
    error: str | None
    seconds: float

    @property
    def status(self) -> str:
        return "FAILED" if self.outcome is None else self.outcome.status


def run_claim(c: Claim) -> Row:
    """Run one claim; an exception becomes a ``FAILED`` row with its message."""
    start = time.perf_counter()
    try:
        outcome = c.func()
        if not isinstance(outcome, Outcome):
            raise TypeError(f"proof returned {outcome!r}, not an Outcome")
        error = None
    except Exception as exc:  # noqa: BLE001 - the ledger reports every failure
        outcome, error = None, f"{type(exc).__name__}: {exc}"
    return Row(c, outcome, error, time.perf_counter() - start)
