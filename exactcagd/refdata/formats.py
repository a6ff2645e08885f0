"""``--format bezier``: reference records in the layout of the ``bezier`` package's functional tests.

The ``bezier`` project (dhermes/bezier) keeps its curve-curve intersection cases in
``tests/functional/curves.json`` (an object: curve id -> ``{"control_points",
"implicitized", "note"}``) and ``tests/functional/curve_intersections.json`` (a list of
``{"curve1", "curve2", "id", "type", "intersections", "curve1_params",
"curve1_polys", "curve2_params", "curve2_polys", "note"}``); its harness
(``tests/functional/utils.py``) reads them.  Their conventions, followed here:

* ``control_points`` is ``[xs, ys]`` (one row per coordinate, bezier's ``nodes``);
* a number is a JSON integer, a ``"p/q"`` string, or a ``float.hex`` string for an
  irrational value (the harness converts each with ``_convert_float``);
* ``implicitized`` is a list of ``[coefficient, x exponent, y exponent]`` sorted by
  total degree then x exponent, primitive, the first coefficient positive;
* ``type`` is ``no-intersection``, ``standard``, ``tangent`` or ``coincident``;
  parameters are sorted by ``curve1_params``; ``curveK_polys`` are the integer
  minimal polynomials of the parameters, lowest degree first; a coincident case lists
  the two ends of the common arc.

Only polynomial curves are written (bezier has no rational curves): records with
weights are skipped.  ``intersect`` fills both files; ``implicitize`` fills
``curves.json`` and writes an empty intersection list.

>>> _implicitized([[0, 0, "-3"], [1, 0, "8"]])
[[3, 0, 0], [-8, 1, 0]]
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

from ..errors import InputError
from ..outputs import check_output_dir, staged_dir
from .kinds import kind_named
from .options import (
    check_count,
    check_jobs,
    families_for,
    parse_degrees,
    progress_enabled,
)
from .stream import Progress, ordered_lines, plan_batches

__all__ = ["BEZIER_KINDS", "bezier_curve_entry", "bezier_intersection_entry", "write_bezier_fixtures"]

BEZIER_KINDS = ("intersect", "implicitize")


def _algebraic_number(alg: dict):
    """Rational -> int / ``"p/q"``; irrational -> its correctly rounded ``float.hex``."""
    lo, hi = alg["interval"]
    return lo if lo == hi else alg["f64"]


def _implicitized(terms: list) -> list:
    """``[[i, j, "c"], ...]`` -> bezier's ``[[c, i, j], ...]`` with the first coefficient positive."""
    triples = [[int(c), i, j] for i, j, c in terms]
    if triples and triples[0][0] < 0:
        triples = [[-c, i, j] for c, i, j in triples]
    return triples


def bezier_curve_entry(curve: dict, equation: list | None = None, note: str | None = None) -> dict:
    """A record's polynomial curve as an entry of bezier's ``curves.json``."""
    points = curve["control_points"]
    entry = {"control_points": [[p[k] for p in points] for k in range(len(points[0]))]}
    if equation is not None:
        entry["implicitized"] = _implicitized(equation)
    if note:
        entry["note"] = note
    return entry


def bezier_intersection_entry(case_id: int, id1: str, id2: str, answer: dict, note: str) -> dict:
    """An ``intersect`` answer as an entry of bezier's ``curve_intersections.json``."""
    if answer["overlaps"]:
        rows = [(t1, t2, pt) for ov in answer["overlaps"] for t1, t2, pt in zip(ov["t1"], ov["t2"], ov["points"])]
        rows.sort(key=lambda row: float.fromhex(row[0]["f64"]))  # the harness wants curve1_params increasing
        kind = "coincident"
        points = [[_algebraic_number(pt[0]) for _, _, pt in rows], [_algebraic_number(pt[1]) for _, _, pt in rows]]
    else:
        hits = answer["intersections"]
        kind = "no-intersection" if not hits else ("tangent" if any((h["multiplicity"] or 1) > 1 for h in hits) else "standard")
        rows = [(h["t1"], h["t2"], None) for h in hits]
        points = [[_algebraic_number(h["point"][0]) for h in hits], [_algebraic_number(h["point"][1]) for h in hits]]
    entry = {
        "curve1": id1,
        "curve2": id2,
        "id": case_id,
        "type": kind,
        "note": note,
        "intersections": points,
        "curve1_params": [_algebraic_number(t1) for t1, _, _ in rows],
        "curve1_polys": [t1["poly"] for t1, _, _ in rows],
        "curve2_params": [_algebraic_number(t2) for _, t2, _ in rows],
        "curve2_polys": [t2["poly"] for _, t2, _ in rows],
    }
    return entry


class _JsonListWriter:
    """Write a JSON array (or object) one entry at a time: constant memory, indent 4 like bezier's files."""

    def __init__(self, handle, opening: str, closing: str):
        self.handle, self.closing, self.first = handle, closing, True
        handle.write(opening)

    def add(self, text: str) -> None:
        self.handle.write(("\n" if self.first else ",\n") + text)
        self.first = False

    def close(self) -> None:
        self.handle.write(("\n" if not self.first else "") + self.closing + "\n")


def _indented(obj) -> str:
    return "\n".join("    " + line for line in json.dumps(obj, indent=4).splitlines())


def write_bezier_fixtures(out, kind: str, count: int, seed: int = 0, degrees=None, family=None, jobs: int = 1, dask: bool = False, scheduler=None, progress=None) -> int:
    """Write ``curves.json`` and ``curve_intersections.json`` for ``count`` records into the folder ``out``.

    Returns the number of records written (rational records are skipped).
    """
    spec = kind_named(kind)
    if spec.name not in BEZIER_KINDS:
        raise InputError(f"--format bezier: kind {kind!r} has no bezier fixture layout; choose one of {', '.join(BEZIER_KINDS)}")
    check_count(count)
    jobs = check_jobs(jobs)
    if isinstance(degrees, (tuple, list)):
        degrees = ",".join(map(str, degrees))
    degrees = parse_degrees(degrees, spec.name)
    families = families_for(spec.name, family)
    target = check_output_dir(out)
    specs = [b for f in families for b in plan_batches(spec.name, f, count, seed, degrees, jobs)]
    bar = Progress(count * len(families), f"{kind} (bezier)", progress_enabled(progress))
    written = 0
    try:
        with staged_dir(target) as stage, open(Path(stage) / "curves.json", "w", encoding="ascii") as curves_f, open(Path(stage) / "curve_intersections.json", "w", encoding="ascii") as cases_f:
            curves = _JsonListWriter(curves_f, "{", "}")
            cases = _JsonListWriter(cases_f, "[", "]")
            next_curve = 1
            for line in ordered_lines(specs, jobs=jobs, dask=dask, scheduler=scheduler, progress=bar):
                record = json.loads(line)
                inp, ans = record["input"], record["answer"]
                if spec.name == "implicitize":
                    if "weights" in inp:
                        continue
                    curves.add(f'    "{next_curve}": ' + _indented(bezier_curve_entry(inp, ans["equation"], f"exactcagd {record['id']}")).lstrip())
                    next_curve += 1
                    written += 1
                    continue
                if "weights" in inp["curve1"] or "weights" in inp["curve2"]:
                    continue
                ids = []
                for name in ("curve1", "curve2"):
                    ids.append(str(next_curve))
                    curves.add(f'    "{next_curve}": ' + _indented(bezier_curve_entry(inp[name], note=f"exactcagd {record['id']} {name}")).lstrip())
                    next_curve += 1
                written += 1
                cases.add(_indented(bezier_intersection_entry(written, ids[0], ids[1], ans, f"exactcagd {record['id']}")))
            curves.close()
            cases.close()
    finally:
        bar.close()
    if written == 0:
        print("note: every record had rational curves; the bezier files are empty", file=sys.stderr)
    return written
