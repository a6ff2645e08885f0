"""``exactcagd refdata``: one kind to a JSON Lines file, or the standard suite to a folder.

``exactcagd refdata KIND [--count N --seed S --degree D --family F --out FILE]`` streams
``N`` records of one family (default ``random``; ``--family all``: ``N`` of each) to
``FILE`` (default stdout).  ``exactcagd refdata suite --out DIR`` writes the standard
suite: every kind, random records and every hard family, one ``<kind>.jsonl`` each,
the JSON Schemas under ``schemas/`` and ``manifest.json``.  Output is byte-identical
for ``--jobs 1``, ``--jobs N`` and ``--dask`` (records are pure functions of their id
and are written in index order).

Input is checked before any work: unknown kind or family, too many degrees or
degrees outside the kind's range (``1..40``; 8 to 20 for the costly kinds), a count
outside ``1..10^7``, an output path that is a directory, a device or in a missing
folder all raise :class:`exactcagd.errors.InputError` /
:class:`exactcagd.errors.OutputError` naming the argument.

>>> import tempfile, pathlib, json
>>> out = pathlib.Path(tempfile.mkdtemp()) / "suite"
>>> manifest = write_suite(out, seed=0, count=1, kinds=["roots"], jobs=1)
>>> manifest["counts"]["roots"]["random"], (out / "roots.jsonl").exists()
(1, True)
"""

from __future__ import annotations

import hashlib
import shutil
import sys

from ..errors import InputError
from ..outputs import atomic_open, atomic_write_text, check_output_dir, check_output_file, staged_dir
from .kinds import KINDS, kind_named
from .manifest import build_manifest, manifest_text, schema_path
from .options import (
    MAX_COUNT,
    check_count,
    check_jobs,
    families_for,
    parse_degrees,
    progress_enabled,
)
from .stream import Progress, RecordExecutor, ordered_lines, plan_batches

__all__ = ["MAX_COUNT", "STANDARD_COUNTS", "check_count", "cmd_refdata", "parse_degrees", "write_kind", "write_suite"]


#: Records per family in the standard suite: ``(random, each hard family)`` per kind,
#: sized so the whole suite (~3,700 records) takes about a minute on 2 cores.
STANDARD_COUNTS = {
    "curve_eval": (300, 40),
    "surface_eval": (300, 40),
    "bspline_eval": (300, 40),
    "knot_insertion": (300, 40),
    "bezier_extraction": (300, 40),
    "degree_elevation": (300, 40),
    "subdivision": (300, 40),
    "compose": (200, 40),
    "implicitize": (200, 40),
    "inversion": (60, 20),
    "intersect": (100, 20),
    "roots": (300, 40),
}
#: Families too slow for the standard counts get at most this many records.
_SLOW_FAMILY_CAP = {("intersect", "weights_wide"): 8, ("curve_eval", "high_degree"): 20, ("surface_eval", "high_degree"): 10}


def _stream_to(handle, lines) -> tuple[int, str]:
    """Write lines (each + newline) to a binary handle; return (records, sha256)."""
    digest = hashlib.sha256()
    n = 0
    for line in lines:
        data = (line + "\n").encode("ascii")
        handle.write(data)
        digest.update(data)
        n += 1
    return n, digest.hexdigest()


def write_kind(out, kind: str, count: int, seed: int = 0, degrees=None, family=None, jobs: int = 1, dask: bool = False, scheduler=None, progress=None) -> int:
    """Stream ``count`` records of ``kind`` (per family) to the file ``out`` (``"-"``: stdout).

    The file appears atomically when complete (temporary file in the same folder,
    then rename).  Returns the number of records written.
    """
    spec = kind_named(kind)
    check_count(count)
    jobs = check_jobs(jobs)
    if isinstance(degrees, (tuple, list)):
        degrees = ",".join(map(str, degrees))
    degrees = parse_degrees(degrees, kind)
    families = families_for(kind, family)
    target = check_output_file(out)
    specs = [b for f in families for b in plan_batches(spec.name, f, count, seed, degrees, jobs)]
    bar = Progress(count * len(families), kind, progress_enabled(progress))
    lines = ordered_lines(specs, jobs=jobs, dask=dask, scheduler=scheduler, progress=bar)
    try:
        if target == "-":
            n = 0
            for line in lines:
                sys.stdout.write(line + "\n")
                n += 1
            sys.stdout.flush()
            return n
        with atomic_open(target) as handle:
            n, _ = _stream_to(handle, lines)
        return n
    finally:
        bar.close()


def suite_plan(count=None, kinds=None) -> dict:
    """``{kind: {family: records}}`` of the standard suite (``count``: the same count for every family)."""
    chosen = list(KINDS) if kinds is None else [kind_named(k).name for k in kinds]
    plan = {}
    for kind in chosen:
        random_n, hard_n = STANDARD_COUNTS[kind]
        per_family = {}
        for family in KINDS[kind].families:
            n = count if count is not None else (random_n if family == "random" else min(hard_n, _SLOW_FAMILY_CAP.get((kind, family), hard_n)))
            per_family[family] = n
        plan[kind] = per_family
    return plan


def write_suite(out, seed: int = 0, count=None, kinds=None, jobs: int = 1, dask: bool = False, scheduler=None, progress=None) -> dict:
    """Write the standard suite into the folder ``out`` (built in a staging folder, renamed in when complete).

    Returns the manifest.
    """
    target = check_output_dir(out)
    if count is not None:
        check_count(count)
    jobs = check_jobs(jobs)
    plan = suite_plan(count, kinds)
    files = {}
    with staged_dir(target) as stage, RecordExecutor(jobs, dask, scheduler, kinds=plan) as executor:
        (stage / "schemas").mkdir()
        for kind, per_family in plan.items():
            shutil.copyfile(schema_path(kind), stage / "schemas" / f"{kind}.schema.json")
            degrees = KINDS[kind].default_degrees
            specs = [b for family, n in per_family.items() for b in plan_batches(kind, family, n, seed, degrees, jobs)]
            bar = Progress(sum(per_family.values()), f"{kind:<18}", progress_enabled(progress))
            try:
                with open(stage / f"{kind}.jsonl", "wb") as handle:
                    n, digest = _stream_to(handle, executor.lines(specs, progress=bar))
            finally:
                bar.close()
            files[f"{kind}.jsonl"] = {"kind": kind, "records": n, "sha256": digest}
        manifest = build_manifest(seed, list(plan), plan, files)
        atomic_write_text(stage / "manifest.json", manifest_text(manifest))
    return manifest


def cmd_refdata(args) -> int:
    """The ``refdata`` subcommand (see the module docstring)."""
    fmt = getattr(args, "format", "jsonl")
    if args.kind == "suite":
        if fmt != "jsonl":
            raise InputError("--format: a suite is written as JSON Lines; use --format bezier with the intersect or implicitize kind")
        if args.out in (None, "-"):
            raise InputError("--out: refdata suite needs an output folder (--out DIR)")
        for name, value in (("--degree", args.degree), ("--family", args.family)):
            if value is not None:
                raise InputError(f"{name}: the standard suite uses every family at each kind's default degrees; {name} applies to a single kind")
        count = None if args.count is None else check_count(args.count)
        manifest = write_suite(args.out, seed=args.seed, count=count, jobs=args.jobs, dask=args.dask, scheduler=args.scheduler, progress=args.progress)
        total = sum(f["records"] for f in manifest["files"].values())
        print(f"wrote {total} record(s) of {len(manifest['kinds'])} kinds to {args.out}", file=sys.stderr)
        return 0
    kind = kind_named(args.kind).name
    count = 10 if args.count is None else args.count
    if fmt == "bezier":
        from .formats import write_bezier_fixtures

        if args.out in (None, "-"):
            raise InputError("--out: --format bezier writes curves.json and curve_intersections.json into a folder (--out DIR)")
        n = write_bezier_fixtures(args.out, kind, count, seed=args.seed, degrees=args.degree, family=args.family, jobs=args.jobs, dask=args.dask, scheduler=args.scheduler, progress=args.progress)
        print(f"wrote {n} {kind} case(s) in the bezier fixture layout to {args.out}", file=sys.stderr)
        return 0
    if fmt != "jsonl":
        raise InputError(f"--format: expected jsonl or bezier, got {fmt!r}")
    out = "-" if args.out is None else args.out
    n = write_kind(out, kind, count, seed=args.seed, degrees=args.degree, family=args.family, jobs=args.jobs, dask=args.dask, scheduler=args.scheduler, progress=args.progress)
    if out != "-":
        print(f"wrote {n} record(s) to {out}", file=sys.stderr)
    return 0
