"""``exactcagd conformance``: run another geometry kernel on a reference suite and grade it.

A *suite* is a folder written by ``exactcagd refdata suite`` (``manifest.json`` + one
``<kind>.jsonl`` per kind).  :func:`open_suite` checks it first (manifest present,
known format version, every file's sha256).  A *kernel adapter* (see
:mod:`exactcagd.refdata.adapters`, and ``docs/conformance.md`` for writing one)
answers the records of the kinds it supports in float64; :func:`run_conformance`
compares every answer with the record's correctly rounded exact answer and
:func:`write_report` writes ``report.md``, ``report.json`` and ``errors.png``.

What is measured, per kind (and per family):

* ``records`` / ``unsupported`` (the adapter raised :class:`Unsupported`: a limit the
  kernel documents, e.g. OCC's maximum degree 25) / ``crashes`` (any other exception,
  with the first messages kept);
* for list answers (roots, intersections, Bézier segments): ``missed`` and ``extra``
  items.  A computed root or intersection *matches* an exact one when it lies within
  ``max(2^-20, 16 eps^(1/m))`` of it in the parameter(s) (a root of multiplicity ``m``
  moves by ``eps^(1/m)`` under a perturbation of size ``eps``; Wilkinson); exact
  solutions closer than that form one cluster of their total multiplicity (see
  :func:`_match_solutions`), so a kernel is not charged for the ill-conditioning of a
  tangency or a cluster, only for losing or inventing solutions; the accuracy of the
  matched ones shows in their ulps;
* ``ulps``: for every float in an answer whose exact value is within the float64 range
  (values beyond ``2^1024`` are counted as ``overflows``, not graded), the number of
  float64 values between it and the correctly rounded exact value (0 = correctly
  rounded); and ``scaled ulps``: the error in units of the last place of the largest
  exact value of that field in the record, or of 1 for parameters, knots and intervals
  (``PARAMETER_FIELDS``: their domain is [0, 1]) (a coordinate that is exactly 0 and computed as 1e-17 is 4e18 ulps off but a
  fraction of an ulp of the curve's size, which is what a float algorithm can promise:
  judge kernels by scaled ulps, read raw ulps as "how many bits are right"); for the
  worst records of the evaluation kinds the report adds the *data-rounding floor*, the
  error the float64 rounding of the data alone causes (:func:`rounded_data_answer`);
* ``compose``: kernels that approximate a curve on a surface report their own error
  estimate; the true error at the sampled parameters is measured exactly (float sample
  points against ``S(K(t))`` in rational arithmetic) and ``under-estimates`` counts
  records where the true error exceeds the kernel's claim *and* ``NOISE_ULPS`` ulps of
  the curve's size (an exact reproduction claimed as 3e-16 and sampled at 4e-16 is
  float noise, not an under-estimate).

>>> sorted(Stats().summary())
['max', 'median', 'n', 'p99']
>>> ulp_distance(1.0, 1.0 + 2**-52), ulp_distance(-0.0, 0.0)
(1, 0)
"""

from __future__ import annotations

import json
import math
import signal
import statistics
import struct
import time
import traceback
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
from gmpy2 import mpq

from ..errors import InputError
from .records import FORMAT_VERSION, parse_exact

__all__ = [
    "Unsupported",
    "RecordInput",
    "Suite",
    "open_suite",
    "ulp_distance",
    "Stats",
    "KindResult",
    "run_conformance",
    "write_report",
    "report_markdown",
    "plot_errors",
    "grade_record",
    "rounded_data_answer",
    "scaled_ulps",
    "cmd_conformance",
]

#: Major format versions this reader understands.
SUPPORTED_MAJOR = FORMAT_VERSION.split(".")[0]
#: Worst records kept per kind in the report.
WORST_KEPT = 10
#: Answer fields holding parameters or knots (on [0, 1]): scaled ulps are ulps of 1 at least.
PARAMETER_FIELDS = {"params", "knots", "interval"}
#: A kernel's claimed error is only called an under-estimate when the true error also
#: exceeds this many ulps of the curve's size (below it, the float samples are noise).
NOISE_ULPS = 64
#: Seconds one adapter call may take before it is counted as a crash (timeout).
RECORD_TIMEOUT = 20
EPS = 2.0**-52


class Unsupported(Exception):
    """Raised by an adapter for a record its kernel cannot take (a documented limit).

    Counted apart from crashes; the message is the reason shown in the report.
    """


# ----------------------------------------------------------------------------- suites
class Suite:
    """A checked reference suite: its manifest and a reader of records per kind."""

    def __init__(self, path: Path, manifest: dict):
        self.path = path
        self.manifest = manifest

    @property
    def kinds(self) -> list:
        return list(self.manifest["kinds"])

    def files_of(self, kind: str) -> list:
        return sorted(name for name, entry in self.manifest["files"].items() if entry.get("kind") == kind)

    def records(self, kind: str):
        """The records of ``kind`` one at a time (streamed: constant memory)."""
        for name in self.files_of(kind):
            with open(self.path / name, encoding="utf-8") as handle:
                for number, line in enumerate(handle, 1):
                    if line.strip():
                        try:
                            yield json.loads(line)
                        except json.JSONDecodeError as exc:
                            raise InputError(f"--suite: {name} line {number} is not JSON ({exc.msg})") from None

    def count(self, kind: str) -> int:
        return sum(int(self.manifest["files"][name].get("records", 0)) for name in self.files_of(kind))


def open_suite(path, check_hashes: bool = True) -> Suite:
    """Open a suite folder, refusing anything that is not a complete, unmodified suite.

    Raises :class:`exactcagd.errors.InputError` (naming ``--suite`` and the file) when the
    folder or its ``manifest.json`` is missing or not JSON, the format version is not
    one this reader knows, a listed file is missing, or a file's sha256 differs from the
    manifest's.
    """
    folder = Path(path)
    if not folder.is_dir():
        raise InputError(f"--suite: {folder} is not a folder (make a suite with: exactcagd refdata suite --out DIR)")
    manifest_file = folder / "manifest.json"
    if not manifest_file.is_file():
        raise InputError(f"--suite: {folder} has no manifest.json; not a reference suite (make one with: exactcagd refdata suite --out DIR)")
    try:
        manifest = json.loads(manifest_file.read_text(encoding="utf-8"))
    except (json.JSONDecodeError, UnicodeDecodeError) as exc:
        raise InputError(f"--suite: {manifest_file} is not valid JSON ({exc})") from None
    if not isinstance(manifest, dict):
        raise InputError(f"--suite: {manifest_file} must hold a JSON object")
    for key in ("format_version", "kinds", "files"):
        if key not in manifest:
            raise InputError(f"--suite: {manifest_file} lacks the field {key!r}")
    version = str(manifest["format_version"])
    if version.split(".")[0] != SUPPORTED_MAJOR:
        raise InputError(
            f"--suite: format_version {version!r} of {manifest_file} is not supported "
            f"(this exactcagd reads {SUPPORTED_MAJOR}.x; regenerate the suite or upgrade exactcagd)"
        )
    if not isinstance(manifest["files"], dict) or not isinstance(manifest["kinds"], list):
        raise InputError(f"--suite: {manifest_file}: 'files' must be an object and 'kinds' a list")
    from .manifest import sha256_file

    for name, entry in sorted(manifest["files"].items()):
        file = folder / name
        if Path(name).name != name or not file.is_file():
            raise InputError(f"--suite: {name}, listed in the manifest, is missing from {folder}")
        if check_hashes and sha256_file(file) != entry.get("sha256"):
            raise InputError(f"--suite: {name} does not match its sha256 in manifest.json (modified or truncated)")
    return Suite(folder, manifest)


# ----------------------------------------------------------------------------- record input for adapters
def _hex_array(values):
    if isinstance(values, list):
        return [_hex_array(v) for v in values]
    return float.fromhex(values) if isinstance(values, str) else float(values)


class RecordInput(dict):
    """A record's ``input`` with helpers for adapters (it is the plain dict otherwise).

    ``floats(name)`` gives the float64 companions of field ``name`` as a numpy array
    (correctly rounded from the exact values, so every kernel gets the same data);
    ``sub(name)`` the nested object ``name`` (e.g. ``"curve1"``) as a ``RecordInput``;
    ``weights()`` the float weights or ``None`` for a polynomial object.

    >>> inp = RecordInput({"params": ["1/3"], "params_f64": ["0x1.5555555555555p-2"]})
    >>> inp.floats("params")
    array([0.33333333])
    """

    def floats(self, name: str) -> np.ndarray:
        if name + "_f64" in self:
            return np.array(_hex_array(self[name + "_f64"]), dtype=float)
        if name in self:
            return np.array(_hex_array(self[name]), dtype=float)
        raise KeyError(name)

    def weights(self):
        return self.floats("weights") if "weights" in self else None

    def sub(self, name: str) -> "RecordInput":
        return RecordInput(self[name])

    def exact(self, name: str) -> np.ndarray:
        """The exact values of field ``name`` as an object array of ``mpq``."""
        return np.vectorize(parse_exact, otypes=[object])(np.array(self[name], dtype=object))


# ----------------------------------------------------------------------------- measures
def _ordered(x: float) -> int:
    """float64 -> integer such that consecutive doubles map to consecutive integers."""
    (bits,) = struct.unpack("<q", struct.pack("<d", x))
    return bits if bits >= 0 else -(bits & 0x7FFFFFFFFFFFFFFF)


def ulp_distance(computed: float, expected: float) -> float:
    """Number of float64 steps from ``expected`` to ``computed`` (``inf`` if either is NaN or they differ in infinity)."""
    if math.isnan(computed) or math.isnan(expected):
        return math.inf
    if math.isinf(computed) or math.isinf(expected):
        return 0 if computed == expected else math.inf
    return abs(_ordered(computed) - _ordered(expected))


def scaled_ulps(computed: float, expected: float, scale: float) -> float:
    """``|computed - expected|`` in ulps of ``scale`` (exact difference, one rounding at the end)."""
    if not (math.isfinite(computed) and math.isfinite(expected)):
        return 0.0 if computed == expected else math.inf
    unit = math.ulp(scale) if scale > 0 and math.isfinite(scale) else math.ulp(0.0)
    ratio = abs(mpq(computed) - mpq(expected)) / mpq(unit)
    return float(ratio) if ratio < mpq(2) ** 1024 else math.inf


@dataclass
class Stats:
    """Running distribution of one error measure (values kept for median and p99)."""

    values: list = field(default_factory=list)

    def add(self, x: float) -> None:
        self.values.append(x)

    def summary(self) -> dict:
        v = sorted(self.values)
        if not v:
            return {"n": 0, "max": None, "median": None, "p99": None}
        p99 = v[min(len(v) - 1, math.ceil(0.99 * len(v)) - 1)]
        return {"n": len(v), "max": v[-1], "median": statistics.median(v), "p99": p99}


@dataclass
class KindResult:
    """Everything measured for one kind (and, inside, per family)."""

    kind: str
    records: int = 0
    answered: int = 0
    unsupported: int = 0
    unsupported_reasons: dict = field(default_factory=dict)
    crashes: int = 0
    crash_examples: list = field(default_factory=list)
    missed: int = 0
    extra: int = 0
    wrong_count_records: list = field(default_factory=list)
    under_estimates: int = 0
    overflows: int = 0
    unresolved: int = 0
    estimate_ratios: Stats = field(default_factory=Stats)
    fields: dict = field(default_factory=dict)  # field -> (Stats ulps, Stats scaled)
    families: dict = field(default_factory=dict)  # family -> counters
    worst: list = field(default_factory=list)  # (scaled, ulps, id, field, computed, expected)
    worst_records: dict = field(default_factory=dict)  # id -> record, for the records in ``worst``
    floors: dict = field(default_factory=dict)  # (id, field) -> data-rounding floor in scaled ulps
    seconds: float = 0.0

    def family(self, name: str) -> dict:
        return self.families.setdefault(name, {"records": 0, "unsupported": 0, "crashes": 0, "missed": 0, "extra": 0,
                                               "max_scaled_ulps": 0.0, "max_ulps": 0.0, "under_estimates": 0})

    def field_stats(self, name: str) -> tuple:
        return self.fields.setdefault(name, (Stats(), Stats()))

    def to_json(self) -> dict:
        return {
            "records": self.records,
            "answered": self.answered,
            "unsupported": self.unsupported,
            "unsupported_reasons": self.unsupported_reasons,
            "crashes": self.crashes,
            "crash_examples": self.crash_examples,
            "missed": self.missed,
            "extra": self.extra,
            "wrong_count_records": self.wrong_count_records[:WORST_KEPT],
            "wrong_count_total": len({w["id"] for w in self.wrong_count_records}),
            "under_estimates": self.under_estimates,
            "overflows": self.overflows,
            "unresolved_clusters": self.unresolved,
            "estimate_ratio": self.estimate_ratios.summary(),
            "fields": {name: {"ulps": u.summary(), "scaled_ulps": s.summary()} for name, (u, s) in sorted(self.fields.items())},
            "families": self.families,
            "worst": [
                {"id": rid, "ratio": sc, "true_error": c, "claimed_error": e} if self.kind == "compose" else
                {"id": rid, "field": name, "scaled_ulps": sc, "ulps": ul, "computed": float.hex(c), "expected": float.hex(e),
                 "floor_scaled_ulps": self.floors.get((rid, name))}
                for sc, ul, rid, name, c, e in self.worst
            ],
            "seconds": round(self.seconds, 3),
        }


# ----------------------------------------------------------------------------- comparison
def _flat_pairs(computed, expected_hex, path: str):
    """Pairs (computed float, expected float) of two nested lists of one shape, or ``None`` if shapes differ."""
    c = np.asarray(computed, dtype=float)
    e = np.array(_hex_array(expected_hex), dtype=float)
    if c.shape != e.shape:
        return None
    return c.reshape(-1), e.reshape(-1)


class _Grader:
    """Compares one record's adapter output with its exact answer into a :class:`KindResult`."""

    def __init__(self, result: KindResult, record: dict):
        self.result, self.record = result, record
        self.fam = result.family(record["family"])
        self.rid = record["id"]

    def values(self, name: str, computed, expected_hex) -> None:
        """Elementwise ulps of a float field against its ``_f64`` companions."""
        pairs = _flat_pairs(computed, expected_hex, name)
        if pairs is None:
            self.wrong_count(name, f"shape {np.shape(computed)} vs {np.shape(np.array(_hex_array(expected_hex)))}")
            return
        c, e = pairs
        finite = np.abs(e[np.isfinite(e)])
        scale = float(finite.max()) if finite.size else 0.0
        if name.rsplit(".", 1)[-1] in PARAMETER_FIELDS:
            scale = max(scale, 1.0)  # parameters and knots: the scale is the domain [0, 1]
        ulps_stats, scaled_stats = self.result.field_stats(name)
        for x, y in zip(c.tolist(), e.tolist()):
            self.one(name, x, y, scale, ulps_stats, scaled_stats)

    def one(self, name, x: float, y: float, scale: float, ulps_stats=None, scaled_stats=None) -> None:
        if math.isinf(y):
            # the exact value overflows float64: no float answer can be right; counted, not graded
            self.result.overflows += 1
            return
        if ulps_stats is None:
            ulps_stats, scaled_stats = self.result.field_stats(name)
        ul, sc = ulp_distance(x, y), scaled_ulps(x, y, scale)
        ulps_stats.add(ul)
        scaled_stats.add(sc)
        self.fam["max_ulps"] = max(self.fam["max_ulps"], ul)
        self.fam["max_scaled_ulps"] = max(self.fam["max_scaled_ulps"], sc)
        self.keep_worst((sc, ul, self.rid, name, x, y))

    def keep_worst(self, entry: tuple) -> None:
        """Keep the ``WORST_KEPT`` worst records (one entry each, its worst value), worst first."""
        worst = self.result.worst
        key = entry[:2]
        same = [i for i, w in enumerate(worst) if w[2] == entry[2]]
        if same:
            if key <= worst[same[0]][:2]:
                return
            del worst[same[0]]
        elif len(worst) >= WORST_KEPT and key <= worst[-1][:2]:
            return
        worst.append(entry)
        worst.sort(key=lambda w: (w[0], w[1]), reverse=True)
        del worst[WORST_KEPT:]
        self.result.worst_records[entry[2]] = self.record
        kept = {w[2] for w in worst}
        for rid in [r for r in self.result.worst_records if r not in kept]:
            del self.result.worst_records[rid]

    def wrong_count(self, name: str, detail: str, missed: int = 0, extra: int = 0) -> None:
        self.result.missed += missed
        self.result.extra += extra
        self.fam["missed"] += missed
        self.fam["extra"] += extra
        self.result.wrong_count_records.append({"id": self.rid, "field": name, "detail": detail})

    def structure(self, computed: dict, expected: dict, prefix: str = "") -> None:
        """Walk an adapter's output dict against the answer: floats, lists of dicts, sub-dicts."""
        for key, value in computed.items():
            name = prefix + key
            if isinstance(value, dict) and isinstance(expected.get(key), dict):
                self.structure(value, expected[key], name + ".")
            elif key + "_f64" in expected:
                self.values(name, value, expected[key + "_f64"])
            elif isinstance(expected.get(key), list) and all(isinstance(x, dict) for x in expected[key]):
                exp = expected[key]
                if len(value) != len(exp):
                    self.wrong_count(name, f"{len(value)} items, exact answer has {len(exp)}",
                                     missed=max(0, len(exp) - len(value)), extra=max(0, len(value) - len(exp)))
                for got, want in zip(value, exp):
                    self.structure(got, want, name + "[].")
            else:
                raise InputError(f"adapter output field {name!r} has no counterpart in the {self.record['kind']} answer")


def _tolerance(multiplicity: int) -> float:
    """Parameter distance within which a computed solution counts as found (see module doc).

    ``max(2^-20, 16 eps^(1/m))``: a simple solution computed to 1e-6 is inaccurate (its
    ulps show it), not missing; a root of multiplicity ``m`` may move by ``eps^(1/m)``.
    """
    return max(2.0**-20, 16 * EPS ** (1.0 / max(1, multiplicity)))


def _distance(a, b) -> float:
    return max(abs(x - y) for x, y in zip(a, b))


def _clusters(exact: list) -> list:
    """Group exact solutions that float64 cannot tell apart (single linkage within their tolerances).

    Returns ``[(member indices, total multiplicity), ...]``: a pair of simple roots
    ``2^-41`` apart behaves like a double root once the data are rounded, so it is one
    cluster of multiplicity 2 (``max(2^-20, 16 eps^(1/2))``).
    """
    parent = list(range(len(exact)))

    def find(i):
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    for i in range(len(exact)):
        for j in range(i):
            reach = max(_tolerance(exact[i][1]), _tolerance(exact[j][1]))
            if _distance(exact[i][0], exact[j][0]) <= reach:
                parent[find(i)] = find(j)
    groups: dict = {}
    for i in range(len(exact)):
        groups.setdefault(find(i), []).append(i)
    return [(members, sum(exact[i][1] for i in members)) for members in groups.values()]


def _match_solutions(grader: _Grader, name: str, computed: list, exact: list) -> None:
    """Match computed solution tuples to clusters of exact ones; count misses, extras and unresolved clusters.

    ``computed``: list of tuples of floats; ``exact``: list of (tuple of expected floats,
    multiplicity).  Exact solutions closer than float64 can resolve form a cluster of
    total multiplicity ``M`` (:func:`_clusters`), found by a computed solution within
    ``max(2^-20, 16 eps^(1/M))`` of a member.  A computed solution near no cluster is
    *extra*, and so is every answer beyond ``M`` in one cluster; a cluster with no answer
    is *missed* (all its distinct solutions).  A cluster of several distinct solutions
    answered by fewer is *unresolved*: reported, not charged (the rounding of the data
    alone moves such roots farther than they are apart).  The ulps of each answer are
    taken against the nearest member.
    """
    clusters = _clusters(exact)
    hits = [0] * len(clusters)
    extra = 0
    ulps_stats, scaled_stats = grader.result.field_stats(name)
    for c in sorted(computed):
        best, where, member = math.inf, None, None
        for k, (members, _) in enumerate(clusters):
            for i in members:
                d = _distance(c, exact[i][0])
                if d < best:
                    best, where, member = d, k, i
        if where is None or best > _tolerance(clusters[where][1]):
            extra += 1
            continue
        hits[where] += 1
        if hits[where] > clusters[where][1]:
            extra += 1
            continue
        for a, b in zip(c, exact[member][0]):
            grader.one(name, a, b, 1.0, ulps_stats, scaled_stats)  # parameters live in [0, 1]: scale 1
    missed = sum(len(members) for (members, _), h in zip(clusters, hits) if h == 0)
    unresolved = sum(1 for (members, _), h in zip(clusters, hits) if 0 < h < len(members))
    grader.result.unresolved += unresolved
    if missed or extra:
        grader.wrong_count(name, f"{len(computed)} found, {len(exact)} exact: {missed} missed, {extra} extra",
                           missed=missed, extra=extra)


def _grade_roots(grader: _Grader, computed: dict, answer: dict) -> None:
    exact = [((float.fromhex(r["value"]["f64"]),), r["multiplicity"]) for r in answer["roots"]]
    if computed.get("overlap"):
        grader.wrong_count("roots", "kernel reports the polynomial as zero on an interval")
    _match_solutions(grader, "roots", [(float(t),) for t in computed["roots"]], exact)


def _grade_intersections(grader: _Grader, computed: dict, answer: dict) -> None:
    if answer.get("overlaps"):
        # the curves share an arc: a kernel should say so (then its points are the arc's ends,
        # not graded); an answer without the overlap counts as one missed solution
        said = bool(computed.get("overlap"))
        if not said:
            grader.wrong_count("overlap", "curves overlap; kernel did not report it", missed=1)
        return
    # multiplicity is null for a point whose multiplicity the exact layer does not state: graded as simple
    exact = [((float.fromhex(h["t1"]["f64"]), float.fromhex(h["t2"]["f64"])), h["multiplicity"] or 1)
             for h in answer["intersections"]]
    _match_solutions(grader, "intersections", [tuple(map(float, p)) for p in computed["intersections"]], exact)


def _exact_composed_point(inp: dict, t: mpq) -> list:
    from ..geometry.bezier_curve import BezierCurve
    from ..geometry.bezier_surface import BezierSurface
    from ..geometry.bspline import BSplineSurface

    curve = inp["curve"]
    domain = BezierCurve(curve["control_points"], curve.get("weights"))
    u, v = domain.evaluate(t)
    s = inp["surface"]
    if s["type"] == "bezier":
        surface = BezierSurface(s["control_points"], s.get("weights"))
    else:
        surface = BSplineSurface(s["control_points"], s["knots_u"], s["knots_v"], s.get("weights"))
    return list(surface.evaluate(u, v))


def _grade_compose(grader: _Grader, computed: dict, record: dict) -> None:
    """True error at the adapter's sample parameters (exact) against the kernel's own estimate."""
    worst, size = mpq(0), 0.0
    for t, point in zip(computed["params"], computed["points"]):
        exact = _exact_composed_point(record["input"], mpq(float(t)))
        dist2 = sum((mpq(float(x)) - e) ** 2 for x, e in zip(point, exact))
        worst = max(worst, dist2)
        size = max(size, max(abs(float(e)) for e in exact))
    true_error = math.sqrt(float(worst))
    claimed = float(computed["claimed_error"])
    ratio = true_error / claimed if claimed > 0 else (math.inf if true_error > 0 else 1.0)
    grader.result.estimate_ratios.add(ratio)
    grader.keep_worst((ratio, true_error, grader.rid, "true/claimed error", true_error, claimed))
    if true_error > claimed and true_error > NOISE_ULPS * math.ulp(max(size, 1e-300)):
        grader.result.under_estimates += 1
        grader.fam["under_estimates"] += 1
        grader.wrong_count("claimed_error", f"true error {true_error:.3e} > claimed {claimed:.3e} (x{ratio:.3g})")


def _rounded(values):
    """The float64 companions of a field as exact rationals (nested lists)."""
    if isinstance(values, list):
        return [_rounded(v) for v in values]
    return mpq(float.fromhex(values))


def rounded_data_answer(record: dict) -> dict | None:
    """The exact answer for the record's data *rounded to float64* (evaluation kinds only).

    What a kernel receives is the rounded data; the exact answer for it, compared with the
    correctly rounded answer for the exact data, is the error the rounding alone causes
    (the *floor*): a kernel error far above its floor is the kernel's.  ``None`` for the
    kinds this is not computed for.
    """
    from ..geometry.bezier_curve import BezierCurve
    from ..geometry.bezier_surface import BezierSurface
    from ..geometry.bspline import BSplineCurve, BSplineSurface
    from .kinds import rational_jet, surface_point_normal

    inp, kind = record["input"], record["kind"]
    weights = _rounded(inp["weights_f64"]) if "weights" in inp else None
    params = _rounded(inp["params_f64"]) if "params_f64" in inp else None
    if kind == "curve_eval":
        curve = BezierCurve(_rounded(inp["control_points_f64"]), weights)
        jets = [rational_jet(curve.homogeneous(), t) for t in params]
        return {"values": [j[0] for j in jets], "first_derivatives": [j[1] for j in jets],
                "second_derivatives": [j[2] for j in jets]}
    if kind == "surface_eval":
        surface = BezierSurface(_rounded(inp["control_points_f64"]), weights)
        pairs = [surface_point_normal(surface, u, v) for u, v in params]
        return {"values": [p for p, _ in pairs], "normals": [n for _, n in pairs]}
    if kind == "bspline_eval" and inp["object"] == "curve":
        curve = BSplineCurve(_rounded(inp["control_points_f64"]), _rounded(inp["knots_f64"]), weights)
        return {"values": [list(curve.evaluate(t)) for t in params]}
    if kind == "bspline_eval":
        surface = BSplineSurface(_rounded(inp["control_points_f64"]), _rounded(inp["knots_u_f64"]),
                                 _rounded(inp["knots_v_f64"]), weights)
        return {"values": [list(surface.evaluate(u, v)) for u, v in params]}
    return None


def _add_floors(result: KindResult) -> None:
    """Data-rounding floor (scaled ulps) of each listed worst record, where computable."""
    from .records import f64_float

    for _, _, rid, name, _, _ in result.worst:
        record = result.worst_records.get(rid)
        answer = rounded_data_answer(record) if record is not None else None
        if answer is None or name not in answer:
            continue
        expected = np.array(_hex_array(record["answer"][name + "_f64"]), dtype=float).reshape(-1)
        got = np.array([f64_float(x) for x in np.array(answer[name], dtype=object).reshape(-1)])
        finite = np.abs(expected[np.isfinite(expected)])
        scale = float(finite.max()) if finite.size else 0.0
        pairs = [(a, b) for a, b in zip(got.tolist(), expected.tolist()) if math.isfinite(b)]
        result.floors[(rid, name)] = max((scaled_ulps(a, b, scale) for a, b in pairs), default=0.0)


#: Kinds whose answers are sets of solutions (matched, not compared by position).
SPECIAL = {"roots": _grade_roots, "intersect": _grade_intersections}


# ----------------------------------------------------------------------------- runner
class _Timeout(Exception):
    pass


def _call_with_timeout(func, arg, seconds: int):
    import threading

    if seconds <= 0 or not hasattr(signal, "SIGALRM") or threading.current_thread() is not threading.main_thread():
        return func(arg)  # SIGALRM only exists on POSIX and only reaches the main thread

    def alarm(signum, frame):
        raise _Timeout(f"no answer within {seconds} s")

    old = signal.signal(signal.SIGALRM, alarm)
    signal.alarm(seconds)
    try:
        return func(arg)
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, old)


def grade_record(result: KindResult, adapter, record: dict, timeout: int = RECORD_TIMEOUT) -> None:
    """Run the adapter on one record and add what it got right and wrong to ``result``."""
    grader = _Grader(result, record)
    result.records += 1
    grader.fam["records"] += 1
    method = getattr(adapter, record["kind"])
    try:
        computed = _call_with_timeout(method, RecordInput(record["input"]), timeout)
    except Unsupported as exc:
        result.unsupported += 1
        grader.fam["unsupported"] += 1
        reason = str(exc) or "unsupported"
        result.unsupported_reasons[reason] = result.unsupported_reasons.get(reason, 0) + 1
        return
    except Exception as exc:  # noqa: BLE001 - the kernel's failure is the measurement
        _crash(result, grader, record, exc)
        return
    result.answered += 1
    try:
        if record["kind"] == "compose":
            _grade_compose(grader, computed, record)
        elif record["kind"] in SPECIAL:
            SPECIAL[record["kind"]](grader, computed, record["answer"])
        else:
            grader.structure(computed, record["answer"])
    except (KeyError, TypeError, ValueError) as exc:
        _crash(result, grader, record, exc, stage="output")


def _crash(result: KindResult, grader: _Grader, record: dict, exc: BaseException, stage: str = "call") -> None:
    result.crashes += 1
    grader.fam["crashes"] += 1
    if len(result.crash_examples) < WORST_KEPT:
        where = traceback.extract_tb(exc.__traceback__)[-1] if exc.__traceback__ else None
        result.crash_examples.append({
            "id": record["id"],
            "error": f"{type(exc).__name__}: {str(exc).strip().splitlines()[0][:200] if str(exc).strip() else ''}",
            "stage": stage,
            "where": f"{Path(where.filename).name}:{where.lineno}" if where else "",
        })


def run_conformance(adapter, suite: Suite, kinds=None, limit: int | None = None, progress=None,
                    timeout: int = RECORD_TIMEOUT) -> dict:
    """Grade ``adapter`` on every record of the kinds it supports; returns the report dict.

    ``kinds`` restricts the kinds; ``limit`` takes the first ``limit`` records of each
    kind (quick runs); ``progress`` is called as ``progress(kind, done, total)``.
    """
    wanted = [k for k in suite.kinds if k in set(adapter.kinds) and (kinds is None or k in kinds)]
    if kinds is not None:
        unknown = sorted(set(kinds) - set(suite.kinds))
        if unknown:
            raise InputError(f"--kinds: {unknown[0]!r} is not in this suite (it has {', '.join(suite.kinds)})")
    results = {}
    for kind in wanted:
        result = KindResult(kind)
        total = suite.count(kind) if limit is None else min(limit, suite.count(kind))
        start = time.perf_counter()
        for n, record in enumerate(suite.records(kind)):
            if limit is not None and n >= limit:
                break
            grade_record(result, adapter, record, timeout)
            if progress is not None:
                progress(kind, n + 1, total)
        _add_floors(result)
        result.seconds = time.perf_counter() - start
        results[kind] = result
    return {
        "kernel": adapter.name,
        "kernel_version": adapter.version(),
        "suite": {
            "name": suite.path.name,
            "format_version": suite.manifest.get("format_version"),
            "exactcagd": suite.manifest.get("exactcagd"),
            "seed": suite.manifest.get("seed"),
        },
        "not_supported_kinds": [k for k in suite.kinds if k not in set(adapter.kinds)],
        "limit": limit,
        "kinds": {kind: r.to_json() for kind, r in results.items()},
    }


# ----------------------------------------------------------------------------- report
def _fmt(x) -> str:
    if x is None:
        return "-"
    if isinstance(x, float) and math.isinf(x):
        return "inf"
    if isinstance(x, (int,)) or float(x).is_integer() and abs(x) < 1e15:
        return f"{int(x):,}"
    return f"{x:.3g}"


def report_markdown(report: dict) -> str:
    """The human-readable report (markdown)."""
    lines = [f"# Conformance of {report['kernel']} {report['kernel_version']}", ""]
    suite = report["suite"]
    lines.append(f"Suite: `{suite['name']}` (format {suite['format_version']}, exactcagd "
                 f"{(suite.get('exactcagd') or {}).get('version')}, seed {suite['seed']})"
                 + (f"; first {report['limit']} records per kind" if report.get("limit") else "") + ".")
    lines.append("Errors: *ulps* = float64 steps between the kernel's value and the correctly rounded exact value; "
                 "*scaled* = error in ulps of the largest exact value of the same field in the record (see "
                 "`exactcagd.refdata.conformance`). A few ulps is float64 arithmetic working as designed, not a defect.")
    lines.append("")
    if report["not_supported_kinds"]:
        lines.append("Kinds this kernel has no operation for: " + ", ".join(f"`{k}`" for k in report["not_supported_kinds"]) + ".")
        lines.append("")
    lines.append("| kind | records | unsupported | crashes | missed | extra | wrong-count records | under-estimates | max ulps | p99 ulps | median ulps | max scaled | p99 scaled | s |")
    lines.append("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for kind, r in report["kinds"].items():
        ul = _merge_fields(r, "ulps")
        sc = _merge_fields(r, "scaled_ulps")
        lines.append(f"| {kind} | {r['records']} | {r['unsupported']} | {r['crashes']} | {r['missed']} | {r['extra']} | "
                     f"{r['wrong_count_total']} | {r['under_estimates'] if kind == 'compose' else '-'} | {_fmt(ul['max'])} | "
                     f"{_fmt(ul['p99'])} | {_fmt(ul['median'])} | {_fmt(sc['max'])} | {_fmt(sc['p99'])} | {r['seconds']:.1f} |")
    for kind, r in report["kinds"].items():
        lines += ["", f"## {kind}", ""]
        if r.get("unresolved_clusters"):
            lines.append(f"{r['unresolved_clusters']} clusters of distinct solutions closer than float64 resolves "
                         "were answered by fewer solutions (not charged).")
            lines.append("")
        if r["overflows"]:
            lines.append(f"{r['overflows']} exact values overflow float64 (|x| >= 2^1024); not graded.")
            lines.append("")
        if r["unsupported_reasons"]:
            lines.append("Unsupported: " + "; ".join(f"{why} ({n})" for why, n in r["unsupported_reasons"].items()) + ".")
            lines.append("")
        lines.append("| family | records | unsupported | crashes | missed | extra | under-estimates | max ulps | max scaled ulps |")
        lines.append("|---|---|---|---|---|---|---|---|---|")
        for fam, f in r["families"].items():
            lines.append(f"| {fam} | {f['records']} | {f['unsupported']} | {f['crashes']} | {f['missed']} | {f['extra']} | "
                         f"{f['under_estimates']} | {_fmt(f['max_ulps'])} | {_fmt(f['max_scaled_ulps'])} |")
        if r["fields"]:
            lines += ["", "| field | values | max ulps | p99 | median | max scaled | p99 scaled | median scaled |", "|---|---|---|---|---|---|---|---|"]
            for name, f in r["fields"].items():
                u, s = f["ulps"], f["scaled_ulps"]
                lines.append(f"| {name} | {u['n']} | {_fmt(u['max'])} | {_fmt(u['p99'])} | {_fmt(u['median'])} | "
                             f"{_fmt(s['max'])} | {_fmt(s['p99'])} | {_fmt(s['median'])} |")
        if kind == "compose" and r["estimate_ratio"]["n"]:
            e = r["estimate_ratio"]
            lines += ["", f"True error / kernel's estimate: max {_fmt(e['max'])}, median {_fmt(e['median'])} over {e['n']} records."]
        if r["worst"] and kind == "compose":
            lines += ["", "Largest true error / claimed error (reproduce with the record id):", ""]
            lines += [f"- `{w['id']}`: true error {w['true_error']:.3g}, claimed {w['claimed_error']:.3g} (x{w['ratio']:.3g})"
                      for w in r["worst"]]
        elif r["worst"]:
            lines += ["", "Worst records (reproduce with the record id):", ""]
            lines += [f"- `{w['id']}` {w['field']}: {_fmt(w['scaled_ulps'])} scaled ulps, {_fmt(w['ulps'])} ulps "
                      f"(got {float.fromhex(w['computed']):.17g}, exact rounds to {float.fromhex(w['expected']):.17g})"
                      + (f"; data-rounding floor {_fmt(w['floor_scaled_ulps'])} scaled ulps" if w.get("floor_scaled_ulps") is not None else "")
                      for w in r["worst"]]
        if r["wrong_count_records"]:
            lines += ["", f"Wrong counts ({r['wrong_count_total']} records; first {len(r['wrong_count_records'])}):", ""]
            lines += [f"- `{w['id']}` {w['field']}: {w['detail']}" for w in r["wrong_count_records"]]
        if r["crash_examples"]:
            lines += ["", "Crashes (first ones):", ""]
            lines += [f"- `{c['id']}` ({c['stage']}, {c['where']}): {c['error']}" for c in r["crash_examples"]]
    return "\n".join(lines) + "\n"


def _merge_fields(r: dict, which: str) -> dict:
    fields = [f[which] for f in r["fields"].values() if f[which]["n"]]
    if not fields:
        return {"max": None, "median": None, "p99": None}
    return {"max": max(f["max"] for f in fields), "p99": max(f["p99"] for f in fields),
            "median": max(f["median"] for f in fields)}


def plot_errors(report: dict, path: Path) -> None:
    """``errors.png``: per kind, max / p99 / median scaled ulps (log scale) and failure counts."""
    from ..plotting import pyplot

    plt = pyplot(headless=True)
    with np.errstate(all="ignore"):  # log axes of values up to 1e300 overflow inside matplotlib's transforms
        _plot(report, path, plt)


def _plot(report: dict, path: Path, plt) -> None:
    kinds = list(report["kinds"])
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(12, 4.5))
    x = np.arange(len(kinds))
    for offset, stat, color in ((-0.25, "max", "tab:red"), (0.0, "p99", "tab:orange"), (0.25, "median", "tab:blue")):
        vals = [_merge_fields(report["kinds"][k], "scaled_ulps")[stat] for k in kinds]
        vals = [min(max(v, 0.1), 1e300) if v is not None else np.nan for v in vals]
        ax1.bar(x + offset, vals, width=0.25, color=color, label=stat)
    ax1.set_yscale("log")
    ax1.set_xticks(x, kinds, rotation=45, ha="right")
    ax1.set_ylabel("scaled ulps (floored at 0.1)")
    ax1.set_title(f"{report['kernel']}: float error vs correctly rounded exact")
    ax1.legend()
    for offset, key, color in ((-0.3, "crashes", "black"), (-0.1, "missed", "tab:red"), (0.1, "extra", "tab:purple"),
                               (0.3, "unsupported", "tab:gray")):
        ax2.bar(x + offset, [report["kinds"][k][key] for k in kinds], width=0.2, color=color, label=key)
    ax2.set_xticks(x, kinds, rotation=45, ha="right")
    ax2.set_ylabel("count")
    ax2.set_title("failures")
    ax2.legend()
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    plt.close(fig)


def _json_safe(obj):
    if isinstance(obj, float) and not math.isfinite(obj):
        return "inf" if obj > 0 else ("-inf" if obj < 0 else "nan")
    if isinstance(obj, dict):
        return {k: _json_safe(v) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [_json_safe(v) for v in obj]
    return obj


def write_report(report: dict, out) -> Path:
    """Write ``report.md``, ``report.json`` and ``errors.png`` into the folder ``out`` (replaced as a whole)."""
    from ..outputs import check_output_dir, staged_dir

    target = check_output_dir(out, argument="--out")
    with staged_dir(target) as stage:
        (stage / "report.json").write_text(json.dumps(_json_safe(report), indent=1, sort_keys=False) + "\n", encoding="utf-8")
        (stage / "report.md").write_text(report_markdown(report), encoding="utf-8")
        plot_errors(report, stage / "errors.png")
    return target


# ----------------------------------------------------------------------------- CLI
def cmd_conformance(args) -> int:
    """``exactcagd conformance --kernel NAME --suite DIR --out DIR``."""
    import sys

    from ..outputs import check_output_dir
    from .adapters import load_adapter

    check_output_dir(args.out, argument="--out")
    suite = open_suite(args.suite)
    adapter = load_adapter(args.kernel)
    kinds = None if not args.kinds else [k.strip() for k in args.kinds.split(",") if k.strip()]
    if args.limit is not None and args.limit < 1:
        raise InputError(f"--limit: expected a positive count, got {args.limit}")
    started = time.perf_counter()
    last = [0.0, None, 0.0]  # last print, current kind, its start

    def progress(kind, done, total):
        now = time.perf_counter()
        if kind != last[1]:
            last[1], last[2] = kind, now
        if done == total or now - last[0] > 0.5:
            last[0] = now
            rate = done / max(now - last[2], 1e-9)
            eta = (total - done) / rate if rate > 0 else 0.0
            print(f"\r{adapter.name} {kind:<18} {done}/{total}  {rate:,.0f} records/s  ETA {eta:4.0f} s",
                  end="\n" if done == total else "", file=sys.stderr, flush=True)

    report = run_conformance(adapter, suite, kinds=kinds, limit=args.limit, progress=None if args.quiet else progress)
    target = write_report(report, args.out)
    print(f"{adapter.name}: {sum(r['records'] for r in report['kinds'].values())} records in "
          f"{time.perf_counter() - started:.1f} s; report in {target}/report.md")
    return 0

