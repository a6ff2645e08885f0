"""Safe output writing: the one place where exactcagd commands check and write output paths.

Application layer (the scene runner, ``refdata``, ``verify`` and the benchmarks use it).
Three rules, enforced before any work starts and again at write time:

* a command writes only where it was told (``--out``) or into the current directory;
* an existing path is replaced only if it is a *regular file* (never a device such as
  ``/dev/null``, a FIFO, a socket, a directory or a symbolic link), and nothing is
  ever written under ``/proc``, ``/sys`` or ``/dev``;
* a write is atomic: readers see the old content or the new one, never a partial file
  (temporary file in the same directory, ``fsync``, ``os.replace``); a folder of outputs
  is built in a hidden staging folder beside its final place and renamed in when
  complete, so after any interrupt the output folder is complete or absent.

Bad paths raise :class:`exactcagd.errors.OutputError` naming the command-line argument.

>>> import tempfile, pathlib
>>> from exactcagd.outputs import atomic_write_text, check_output_file
>>> folder = pathlib.Path(tempfile.mkdtemp())
>>> target = check_output_file(folder / "a.txt")
>>> atomic_write_text(target, "exact")
>>> target.read_text()
'exact'
>>> check_output_file("/dev/null")  # doctest: +IGNORE_EXCEPTION_DETAIL
Traceback (most recent call last):
exactcagd.errors.OutputError: --out: /dev/null exists and is not a regular file
"""

from __future__ import annotations

import contextlib
import os
import shutil
import stat
import tempfile
from collections.abc import Iterator
from pathlib import Path

from .errors import OutputError

__all__ = [
    "atomic_open",
    "check_output_dir",
    "check_output_file",
    "atomic_write_bytes",
    "atomic_write_text",
    "staged_dir",
]

#: Pseudo file systems: writing there changes the machine, not a file.
FORBIDDEN_ROOTS = (Path("/proc"), Path("/sys"), Path("/dev"))


def _read_umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask


_UMASK = _read_umask()  # read once: os.umask can only be read by setting it (not thread-safe)


def _absolute(path) -> Path:
    """``path`` made absolute without following a final symbolic link (``..`` collapsed)."""
    return Path(os.path.abspath(os.fspath(path)))


def _forbidden(path: Path) -> bool:
    """Whether ``path`` (or what its directories resolve to) lies under /proc, /sys or /dev."""
    candidates = {path, path.parent.resolve() / path.name}
    return any(c == root or root in c.parents for c in candidates for root in FORBIDDEN_ROOTS)


def _nearest_existing(path: Path) -> Path:
    while not os.path.lexists(path):
        path = path.parent
    return path


def _writable_dir(path: Path) -> bool:
    return path.is_dir() and os.access(path, os.W_OK | os.X_OK)


def check_output_dir(path, *, argument: str = "--out") -> Path:
    """Check that ``path`` can be used as an output folder, without creating anything.

    Parameters
    ----------
    path : str or os.PathLike
        The folder a command was told to write into.
    argument : str
        The command-line argument (or parameter) the path came from, for the message.

    Returns
    -------
    pathlib.Path
        The absolute path.

    Raises
    ------
    exactcagd.errors.OutputError
        If ``path`` exists and is not a directory, lies under /proc, /sys or /dev, or
        its nearest existing ancestor is not a writable directory.

    Examples
    --------
    >>> check_output_dir("/proc/x")  # doctest: +IGNORE_EXCEPTION_DETAIL
    Traceback (most recent call last):
    exactcagd.errors.OutputError: --out: /proc/x is under /proc
    """
    target = _absolute(path)
    if _forbidden(target):
        raise OutputError(f"{argument}: {target} is under /proc, /sys or /dev; choose an ordinary folder")
    if os.path.lexists(target):
        if not target.is_dir():
            raise OutputError(f"{argument}: {target} exists and is not a directory")
        if not os.access(target, os.W_OK | os.X_OK):
            raise OutputError(f"{argument}: directory {target} is not writable")
        return target
    ancestor = _nearest_existing(target.parent)
    if not _writable_dir(ancestor):
        raise OutputError(f"{argument}: cannot create {target}: {ancestor} is not a writable directory")
    return target


def check_output_file(path, *, argument: str = "--out") -> Path | str:
    """Check that ``path`` can receive an output file, without creating anything.

    Parameters
    ----------
    path : str or os.PathLike
        The file a command was told to write; ``"-"`` means standard output and is
        returned unchanged.
    argument : str
        The command-line argument (or parameter) the path came from, for the message.

    Returns
    -------
    pathlib.Path or str
        The absolute path (or ``"-"``).

    Raises
    ------
    exactcagd.errors.OutputError
        If ``path`` exists and is not a regular file (directory, device, FIFO, socket),
        is a symbolic link, lies under /proc, /sys or /dev, or its folder is missing or
        not writable.

    Examples
    --------
    >>> check_output_file("-")
    '-'
    """
    if isinstance(path, str) and path == "-":
        return path
    target = _absolute(path)
    if _forbidden(target):
        raise OutputError(f"{argument}: {target} is under /proc, /sys or /dev; choose an ordinary file")
    if os.path.lexists(target):
        mode = os.lstat(target).st_mode
        if stat.S_ISLNK(mode):
            raise OutputError(f"{argument}: {target} is a symbolic link; exactcagd replaces only regular files")
        if not stat.S_ISREG(mode):
            raise OutputError(f"{argument}: {target} exists and is not a regular file")
    if not _writable_dir(target.parent):
        raise OutputError(f"{argument}: folder {target.parent} of {target.name} is missing or not writable")
    return target


def _check_replaceable(path: Path) -> None:
    """Refuse to replace anything but a regular file (checked right before the rename)."""
    if _forbidden(path):
        raise OutputError(f"refusing to write {path}: it is under /proc, /sys or /dev")
    try:
        mode = os.lstat(path).st_mode
    except FileNotFoundError:
        return
    if not stat.S_ISREG(mode):
        kind = "a symbolic link" if stat.S_ISLNK(mode) else "not a regular file"
        raise OutputError(f"refusing to replace {path}: it is {kind}")


@contextlib.contextmanager
def atomic_open(path) -> Iterator:
    """Open ``path`` for writing bytes atomically: the one mechanism behind every output file.

    Yields a binary file handle on a temporary file in the same folder; when the block
    ends normally the file is flushed to disk (``fsync``) and renamed onto ``path``
    (``os.replace``, atomic on POSIX).  On any failure, ``KeyboardInterrupt`` included,
    the temporary file is removed and an existing ``path`` keeps its old content.
    Streams of any length can be written without holding them in memory.  The folder
    must exist.

    Raises
    ------
    exactcagd.errors.OutputError
        If ``path`` exists and is not a regular file (a device, FIFO, socket,
        directory or symbolic link), or lies under /proc, /sys or /dev; checked before
        writing and again before the rename.

    Examples
    --------
    >>> import tempfile, pathlib
    >>> p = pathlib.Path(tempfile.mkdtemp()) / "lines.jsonl"
    >>> with atomic_open(p) as handle:
    ...     _ = handle.write(b"1\\n"); _ = handle.write(b"2\\n")
    >>> p.read_bytes()
    b'1\\n2\\n'
    """
    path = _absolute(path)
    _check_replaceable(path)
    try:
        fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=".tmp")
    except OSError as exc:  # folder missing, not a folder, not writable
        raise OutputError(f"cannot write {path}: {exc.strerror or exc}") from None
    try:
        with os.fdopen(fd, "wb") as handle:
            yield handle
            handle.flush()
            os.fsync(handle.fileno())
        os.chmod(tmp, 0o666 & ~_UMASK)  # mkstemp makes 0600 files; outputs get the usual mode
        _check_replaceable(path)  # again: the path may have changed while we wrote
        os.replace(tmp, path)
    except BaseException:
        with contextlib.suppress(FileNotFoundError):
            os.unlink(tmp)
        raise


def atomic_write_bytes(path, data: bytes) -> None:
    """Write ``data`` to ``path`` atomically (:func:`atomic_open`); replace only an absent
    path or a regular file.

    Examples
    --------
    >>> import tempfile, pathlib
    >>> p = pathlib.Path(tempfile.mkdtemp()) / "x.bin"
    >>> atomic_write_bytes(p, b"1/3")
    >>> p.read_bytes()
    b'1/3'
    """
    with atomic_open(path) as handle:
        handle.write(data)


def atomic_write_text(path, text: str) -> None:
    """:func:`atomic_write_bytes` of ``text`` encoded as UTF-8."""
    atomic_write_bytes(path, text.encode("utf-8"))


@contextlib.contextmanager
def staged_dir(final) -> Iterator[Path]:
    """Build a folder of outputs in a hidden staging folder, then rename it onto ``final``.

    Yields a fresh empty folder beside ``final`` (same parent, hidden name, so the
    rename stays on one file system).  On normal exit the staging folder becomes
    ``final``: an older ``final`` folder is renamed away, the new one renamed in,
    the old one removed (each rename is atomic; between the two, ``final`` is briefly
    absent, which is as close as POSIX gets to swapping two directories).  On an
    exception or ``KeyboardInterrupt`` the staging folder is removed and an older
    ``final`` is left untouched.

    Raises
    ------
    exactcagd.errors.OutputError
        If ``final`` exists and is not a directory (or is a symbolic link), or lies
        under /proc, /sys or /dev.

    Examples
    --------
    >>> import tempfile, pathlib
    >>> final = pathlib.Path(tempfile.mkdtemp()) / "scene"
    >>> with staged_dir(final) as stage:
    ...     atomic_write_text(stage / "summary.json", "{}")
    >>> sorted(p.name for p in final.iterdir())
    ['summary.json']
    """
    final = _absolute(final)
    if _forbidden(final):
        raise OutputError(f"refusing to write {final}: it is under /proc, /sys or /dev")
    if os.path.lexists(final) and (os.path.islink(final) or not final.is_dir()):
        raise OutputError(f"refusing to replace {final}: it exists and is not a directory")
    try:
        final.parent.mkdir(parents=True, exist_ok=True)
        stage = Path(tempfile.mkdtemp(dir=final.parent, prefix=f".{final.name}.staging-"))
    except OSError as exc:  # an ancestor is a file, or not writable
        raise OutputError(f"cannot create the output folder {final}: {exc.strerror or exc}") from None
    try:
        os.chmod(stage, 0o777 & ~_UMASK)  # mkdtemp makes 0700 folders
        yield stage
        _swap_in(stage, final)
    except BaseException:
        shutil.rmtree(stage, ignore_errors=True)
        raise


def _swap_in(stage: Path, final: Path) -> None:
    """Rename ``stage`` onto ``final``, moving an older complete ``final`` away first."""
    if not os.path.lexists(final):
        os.rename(stage, final)
        return
    if os.path.islink(final) or not final.is_dir():
        raise OutputError(f"refusing to replace {final}: it exists and is not a directory")
    old = Path(tempfile.mkdtemp(dir=final.parent, prefix=f".{final.name}.old-"))
    os.rmdir(old)  # only the unique name is wanted: rename needs an absent (or empty) target
    os.rename(final, old)
    try:
        os.rename(stage, final)
    except BaseException:
        os.rename(old, final)  # put the older complete output back
        raise
    shutil.rmtree(old, ignore_errors=True)
