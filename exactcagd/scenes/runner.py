"""``exactcagd plan`` and ``exactcagd run``: the lazy scene runner.

Steps:

1. validate the whole scene (:mod:`~exactcagd.scenes.spec`), build its exact objects and
   check every product against them (:mod:`~exactcagd.scenes.checks`); check ``--out``.
   Nothing is computed before the scene is known to be sound.
2. plan each product: what it needs, what it skips and why, whether it is cached.
3. run: in a staging folder beside ``<out>/<scene>`` (:func:`exactcagd.outputs.staged_dir`),
   each product is taken from the cache or computed, rendered (exact JSON with float
   companions, PNG pictures), written and cached *as soon as it is done*.  A failing
   product is reported by name and the others still complete; ``summary.json`` lists
   every product and every failure.  The staging folder is renamed onto ``<out>/<scene>``
   at the end, so after an interrupt the folder holds the previous complete outputs or
   the new complete ones, never a mixture; finished products stay in the cache.

Rendered outputs, pictures included, are cached by content (:mod:`~exactcagd.scenes.cache`):
a rerun of an unchanged scene copies bytes and computes nothing.  Wall-clock times go to
``timings.json``; every other file of two runs of one scene is byte-identical.

>>> # exactcagd run examples/scenes/hill_trim.toml --out out
"""

from __future__ import annotations

import json
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path

from .. import __version__
from ..errors import ExactCAGDError, InputError, OutputError
from ..outputs import atomic_write_bytes, check_output_dir, staged_dir
from . import products as handlers
from .build import build_curve, build_surface
from .cache import ProductCache, product_key
from .checks import check_products
from .spec import Scene, SceneError, load_scene

__all__ = ["Runner", "RunReport", "cmd_plan", "cmd_run"]


@dataclass
class PlanItem:
    product: dict
    key: str
    cached: bool
    needs: list[str] = field(default_factory=list)
    skips: list[str] = field(default_factory=list)


@dataclass
class RunReport:
    """What a run did.

    ``infos``: per product ``status`` (computed / cached / failed), ``seconds``, ``summary``
    or ``error``; ``failed``: names of the failed products; ``results``: the exact results
    computed in this run (cached products are not loaded).
    """

    infos: dict
    failed: list
    scene_dir: Path
    results: dict = field(default_factory=dict)


class ProductFailed(ExactCAGDError):
    """A product could not be computed (the message names it and the cause)."""


class Runner:
    """Holds a validated scene, its exact objects, the plan and the cache location.

    Building the runner makes every check that the scene file allows (spec, objects,
    products against objects); it computes and writes nothing.
    """

    def __init__(self, scene: Scene, out_dir, use_cache: bool = True):
        self.scene = scene
        self.out_dir = Path(out_dir)
        self.scene_dir = self.out_dir / scene.name
        self.cache_dir = self.out_dir / ".cache"
        self.cache = ProductCache(self.cache_dir)
        self.use_cache = use_cache
        self.objects = self._build_objects()
        self._specs = {p["name"]: p for p in scene.products}
        self._keys: dict = {}
        self.stored: list = []  # products computed and cached by the current run
        self.warnings = check_products(scene, self.objects, cached={p["name"] for p in scene.products if self._is_cached(p)})
        self.published = False

    # ------------------------------------------------------------------ objects
    def _build_objects(self) -> dict:
        objects = {}
        for name, spec in self.scene.surfaces.items():
            objects[name] = _built(build_surface, spec, name, self.scene.float_policy, f"surfaces.{name}")
        for name, spec in self.scene.curves.items():
            objects[name] = _built(build_curve, spec, name, self.scene.float_policy, f"curves.{name}")
        return objects

    def check_outputs(self, argument: str = "--out") -> None:
        """Refuse an output folder that cannot be written (a file, /proc/x, ...) before any work."""
        check_output_dir(self.out_dir, argument=argument)
        for folder in (self.scene_dir, self.cache_dir):
            check_output_dir(folder, argument=argument)
            if folder.is_symlink():  # a link planted in the output folder would send our writes elsewhere
                raise OutputError(f"{argument}: {folder} is a symbolic link; exactcagd writes only into real folders")

    # ------------------------------------------------------------------ planning
    def _dependencies(self, product: dict) -> list[str]:
        """Products (not objects) a product uses: the computed results a picture draws."""
        return [r for r in handlers.references(product) if r in self._specs and self._specs[r]["kind"] != "picture"]

    def cache_key(self, product: dict) -> str:
        """Content key: the product, the specs of its objects, the keys of its products, the code."""
        name = product["name"]
        if name not in self._keys:
            refs = handlers.references(product)
            inputs = {r: self.scene.object_spec(r) for r in refs if r in self.scene.surfaces or r in self.scene.curves}
            dependencies = {r: self.cache_key(self._specs[r]) for r in self._dependencies(product)}
            self._keys[name] = product_key(product, inputs, dependencies, self.scene.float_policy)
        return self._keys[name]

    def _is_cached(self, product: dict) -> bool:
        return self.use_cache and self.cache.lookup(self.cache_key(product)) is not None

    def plan(self) -> list[PlanItem]:
        """What each product computes and skips; a cached product computes nothing (its outputs are copied)."""
        items = []
        for product in self.scene.products:
            cached = self._is_cached(product)
            needs, skips = ([], []) if cached else handlers.plan(product, self)
            items.append(PlanItem(product, self.cache_key(product), cached, needs, skips))
        return items

    # ------------------------------------------------------------------ running
    def run(self, progress=print) -> RunReport:
        """Compute (or copy from the cache) every product; write each one as soon as it is done.

        Returns a :class:`RunReport`; failures are in ``report.failed`` (and in
        ``summary.json``), not raised.  ``KeyboardInterrupt`` propagates after the staging
        folder is removed (``self.published`` says whether the outputs were already in place).
        """
        self.check_outputs()
        plan = self.plan()
        self.stored = []
        self._results: dict = {}
        self._rendered: dict = {}
        self._failed: dict = {}
        infos, timings = {}, {}
        with staged_dir(self.scene_dir) as stage:
            for index, item in enumerate(plan, 1):
                name, kind = item.product["name"], item.product["kind"]
                start = time.perf_counter()
                if not item.cached:
                    progress(f"[{index}/{len(plan)}] {kind:<14} {name} ...")
                try:
                    files, info, status, extra = self._product(item)
                except Exception as exc:  # noqa: BLE001 - one failing product must not lose the others
                    message = _describe(exc)
                    self._failed[name] = message
                    infos[name] = {"status": "failed", "error": message}
                    timings[name] = {"status": "failed", "seconds": round(time.perf_counter() - start, 3)}
                    progress(f"[{index}/{len(plan)}] {kind:<14} {name}: FAILED: {message}")
                    continue
                for suffix, data in files.items():
                    atomic_write_bytes(stage / f"{name}{suffix}", data)
                seconds = time.perf_counter() - start
                infos[name] = {"status": "ok", "summary": info.get("summary", ""), "files": [f"{name}{s}" for s in sorted(files)]}
                timings[name] = {"status": status, "seconds": round(seconds, 3), **({"steps": extra} if extra else {})}
                progress(f"[{index}/{len(plan)}] {kind:<14} {name}: {status} in {seconds:.2f} s")
            summary = {
                "scene": self.scene.name,
                "source": self.scene.source,
                "exactcagd": __version__,
                "products": [{"name": item.product["name"], "kind": item.product["kind"], **infos[item.product["name"]]} for item in plan],
                "failed": sorted(self._failed),
            }
            atomic_write_bytes(stage / "summary.json", (json.dumps(summary, indent=1) + "\n").encode())
            report = {"scene": self.scene.name, "products": [{"name": item.product["name"], **timings[item.product["name"]]} for item in plan]}
            atomic_write_bytes(stage / "timings.json", (json.dumps(report, indent=1) + "\n").encode())
        self.published = True
        merged = {name: {**infos[name], **timings[name]} for name in infos}
        return RunReport(merged, [n for n in infos if n in self._failed], self.scene_dir, self._results)

    def _product(self, item: PlanItem):
        """``(files, info, status, timings)`` of one product: from the cache, or computed and cached."""
        if self.use_cache:
            entry = self.cache.lookup(item.key)
            blobs = entry.read() if entry is not None else None
            if blobs is not None:
                return blobs, entry.info, "cached", {}
        name = item.product["name"]
        self._result(name)
        files, info, extra = self._rendered[name]
        try:
            self.cache.store(item.key, files, {"summary": info.get("summary", "")})
            self.stored.append(name)
        except (OSError, ExactCAGDError) as exc:  # the cache is best effort: a planted FIFO, a full disk
            print(f"note: {name} is not cached ({exc})", file=sys.stderr)
        return files, info, "computed", extra

    def _result(self, name: str):
        """The exact result of product ``name``, computed (and rendered at once) if not yet in memory.

        A product is rendered right after it is computed: later products may refine its
        exact numbers in place (an isolating interval narrowed by a comparison), and its
        output must not depend on what ran after it.
        """
        if name in self._results:
            return self._results[name]
        if name in self._failed:
            raise ProductFailed(f"uses product {name!r}, which failed ({self._failed[name]})")
        product = self._specs[name]
        for dependency in self._dependencies(product):
            self._result(dependency)
        result, info = handlers.compute(product, self, self._results)
        self._results[name] = result
        files, extra = handlers.render(product, result, self, self._results)
        self._rendered[name] = (files, info, extra)
        return result


def _describe(exc: Exception) -> str:
    if isinstance(exc, ExactCAGDError):
        return f"{type(exc).__name__}: {exc}"
    return f"internal error {type(exc).__name__}: {exc}"


def _built(builder, spec, name, policy, where):
    try:
        return builder(spec, name, policy)
    except SceneError:
        raise
    except InputError as exc:
        raise SceneError(f"{where}: {exc}") from None


def _format_plan(runner: Runner, items: list[PlanItem]) -> str:
    lines = [f"scene {runner.scene.name!r} ({runner.scene.source}): {len(items)} product(s)"]
    for name, obj in runner.objects.items():
        lines.append(f"  object {name}: {obj!r}")
    for item in items:
        p = item.product
        state = "cached (will be reused)" if item.cached else "to compute"
        lines.append(f"- {p['kind']} {p['name']}: {state}")
        for need in item.needs:
            lines.append(f"    computes: {need}")
        for skip in item.skips:
            lines.append(f"    skips:    {skip}")
    for warning in runner.warnings:
        lines.append(f"warning: {warning}")
    return "\n".join(lines)


def _runner(args) -> Runner:
    check_output_dir(args.out, argument="--out")
    runner = Runner(load_scene(args.scene), args.out, use_cache=not args.no_cache)
    runner.check_outputs()
    return runner


def cmd_plan(args) -> int:
    runner = _runner(args)
    print(_format_plan(runner, runner.plan()))
    return 0


def cmd_run(args) -> int:
    runner = _runner(args)
    print(_format_plan(runner, runner.plan()))
    start = time.perf_counter()
    try:
        report = runner.run(progress=lambda line: print(line, flush=True))
    except KeyboardInterrupt:
        if runner.published:
            print(f"interrupted after the outputs were complete: {runner.scene_dir}/ is written", file=sys.stderr)
        else:
            done = runner.stored
            kept = (
                f"{len(done)} product(s) finished before the interrupt ({', '.join(done)}) are cached in {runner.cache_dir}/ and will be reused"
                if done
                else "no product had finished"
            )
            print(f"interrupted: nothing was written to {runner.scene_dir}/ (an older output there is unchanged); {kept}", file=sys.stderr)
        return 130
    print(f"\n{'product':<24} {'kind':<14} {'status':<9} {'time':>8}  summary")
    for item in runner.scene.products:
        name, info = item["name"], report.infos[item["name"]]
        print(f"{name:<24} {item['kind']:<14} {info['status']:<9} {info['seconds']:>7.2f}s  {info.get('summary') or info.get('error', '')}")
    elapsed = time.perf_counter() - start
    if report.failed:
        print(
            f"\nwrote {report.scene_dir}/ in {elapsed:.2f} s: {len(report.failed)} of {len(report.infos)} product(s) failed "
            f"({', '.join(report.failed)}; see summary.json)",
            file=sys.stderr,
        )
        return 1
    print(f"\nwrote {report.scene_dir}/ in {elapsed:.2f} s")
    return 0
