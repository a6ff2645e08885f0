"""``exactcagd refdata``: exact reference data sets for testing other geometry kernels.

Each record is one random exact problem (deterministic for ``(seed, index)``) with
its exact answer and correctly rounded float64 companions, written as one JSON line.
Tasks run on a local process pool by default, or on a Dask distributed cluster
(``--scheduler ADDRESS``, or ``--dask`` for a local cluster); records are ordered by
index, so the bytes do not depend on where they were computed.

>>> from exactcagd.scenes.refdata import make_record
>>> rec = make_record("implicitize", seed=1, index=0, degrees=(2,))
>>> rec["kind"], rec["index"]
('implicitize', 0)
"""

from __future__ import annotations

import json
import random
import sys
from concurrent.futures import ProcessPoolExecutor

from gmpy2 import mpq

from ..errors import InputError
from ..geometry.bezier_curve import BezierCurve
from ..geometry.bezier_surface import BezierSurface
from .serialize import atomic_write_text, to_json_value

__all__ = ["make_record", "generate", "cmd_refdata"]

MAX_COUNT = 100000


def _rng(seed: int, index: int) -> random.Random:
    return random.Random(f"exactcagd-refdata:{seed}:{index}")


def _rational(rng: random.Random, lo: int = 0, hi: int = 1, den: int = 16) -> mpq:
    d = rng.randint(1, den)
    return mpq(rng.randint(lo * d, hi * d), d)


def _random_domain_curve(rng, degree: int) -> BezierCurve:
    return BezierCurve([[_rational(rng), _rational(rng)] for _ in range(degree + 1)])


def _random_surface(rng, l: int, m: int) -> BezierSurface:
    net = [[[mpq(i, l) if l else mpq(0), mpq(j, m) if m else mpq(0), _rational(rng, -1, 1)] for j in range(m + 1)] for i in range(l + 1)]
    return BezierSurface(net)


def _random_planar_curve(rng, degree: int, rational: bool) -> BezierCurve:
    pts = [[_rational(rng, -2, 2), _rational(rng, -2, 2)] for _ in range(degree + 1)]
    weights = [_rational(rng, 1, 3) for _ in range(degree + 1)] if rational else None
    return BezierCurve(pts, weights)


def make_record(kind: str, seed: int, index: int, degrees: tuple) -> dict:
    """One reference record (pure function of its arguments)."""
    rng = _rng(seed, index)
    if kind == "compose":
        from ..composition import compose

        n, l, m = (degrees + (degrees[-1],) * 3)[:3]
        surface, curve = _random_surface(rng, l, m), _random_domain_curve(rng, n)
        image = compose(surface, curve)
        payload = {"surface": surface, "curve": curve, "image": image}
    elif kind == "implicitize":
        from ..algebra import implicitize

        curve = _random_planar_curve(rng, degrees[0], rational=bool(index % 2))
        poly = implicitize(curve)
        payload = {"curve": curve, "implicit": str(poly.as_expr()), "degree": int(poly.total_degree())}
    elif kind == "intersect":
        from ..algebra import intersect

        a = _random_planar_curve(rng, degrees[0], rational=False)
        b = _random_planar_curve(rng, degrees[-1], rational=False)
        payload = {"curve1": a, "curve2": b, "intersections": intersect(a, b)}
    else:
        raise InputError(f"unknown refdata kind {kind!r}")
    return {"kind": kind, "seed": seed, "index": index, **to_json_value(payload)}


def _record_line(args) -> str:
    return json.dumps(make_record(*args), sort_keys=True, allow_nan=False)


def generate(kind: str, count: int, seed: int, degrees: tuple, jobs: int = 2, scheduler=None, dask_local=False) -> list[str]:
    """All records as JSON lines, in index order."""
    if not 1 <= count <= MAX_COUNT:
        raise InputError(f"count must be in 1..{MAX_COUNT}")
    tasks = [(kind, seed, i, degrees) for i in range(count)]
    if scheduler or dask_local:
        return _on_dask(tasks, scheduler)
    if jobs <= 1:
        return [_record_line(t) for t in tasks]
    with ProcessPoolExecutor(max_workers=jobs) as pool:
        return list(pool.map(_record_line, tasks, chunksize=max(1, count // (4 * jobs))))


def _on_dask(tasks, scheduler) -> list[str]:
    try:
        from dask.distributed import Client, LocalCluster
    except ImportError:
        raise InputError("Dask is not installed: pip install 'exactcagd[dask]'") from None
    if scheduler:
        with Client(scheduler) as client:
            return client.gather(client.map(_record_line, tasks, pure=True))
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster, Client(cluster) as client:
        return client.gather(client.map(_record_line, tasks, pure=True))


def _parse_degrees(text: str) -> tuple:
    try:
        degrees = tuple(int(x) for x in text.split(","))
    except ValueError:
        raise InputError(f"--degree: expected integers like 3 or 2,3,3, got {text!r}") from None
    if not degrees or any(not 1 <= d <= 20 for d in degrees):
        raise InputError("--degree: each degree must be in 1..20")
    return degrees


def cmd_refdata(args) -> int:
    degrees = _parse_degrees(args.degree)
    lines = generate(args.kind, args.count, args.seed, degrees, jobs=args.jobs, scheduler=args.scheduler, dask_local=args.dask)
    text = "\n".join(lines) + "\n"
    if args.out == "-":
        sys.stdout.write(text)
    else:
        atomic_write_text(args.out, text)
        print(f"wrote {len(lines)} record(s) to {args.out}", file=sys.stderr)
    return 0
