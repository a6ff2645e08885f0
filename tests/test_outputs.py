"""Safe output writing (exactcagd.outputs): paths that are not regular files are refused
untouched, writes are atomic, and an interrupted write or staged folder leaves the old output.

The reference for "untouched" is the file system itself (``os.lstat`` before/after), not the
module's own flags.
"""

from __future__ import annotations

import os
import socket
import stat
from pathlib import Path

import pytest

from exactcagd import outputs
from exactcagd.errors import ExactCAGDError, InputError, OutputError
from exactcagd.outputs import (
    atomic_write_bytes,
    atomic_write_text,
    check_output_dir,
    check_output_file,
    staged_dir,
)


def _snapshot(path: Path):
    st = os.lstat(path)
    return (st.st_mode, st.st_ino, st.st_size, st.st_mtime_ns, st.st_rdev)


def test_output_error_is_a_package_input_error():
    assert issubclass(OutputError, InputError) and issubclass(OutputError, ExactCAGDError)


# ---------------------------------------------------------------- refused paths, untouched


@pytest.mark.parametrize("check", [check_output_file, atomic_write_bytes])
def test_dev_null_is_refused_untouched(check):
    before = _snapshot(Path("/dev/null"))
    with pytest.raises(OutputError, match="/dev/null"):
        if check is atomic_write_bytes:
            check("/dev/null", b"x")
        else:
            check("/dev/null")
    after = _snapshot(Path("/dev/null"))
    assert stat.S_ISCHR(after[0]) and after[:2] == before[:2] and after[4] == before[4]


def test_proc_paths_are_refused(tmp_path):
    for check in (check_output_file, check_output_dir):
        with pytest.raises(OutputError, match="/proc/x"):
            check("/proc/x")
    with pytest.raises(OutputError):
        atomic_write_bytes("/proc/x", b"x")
    assert not os.path.lexists("/proc/x")
    with pytest.raises(OutputError):
        check_output_dir("/sys/kernel/x")


def test_directory_is_refused_as_file(tmp_path):
    folder = tmp_path / "d"
    folder.mkdir()
    (folder / "keep").write_text("k")
    with pytest.raises(OutputError, match="--out"):
        check_output_file(folder)
    with pytest.raises(OutputError):
        atomic_write_text(folder, "x")
    assert folder.is_dir() and (folder / "keep").read_text() == "k"
    assert [p.name for p in tmp_path.iterdir()] == ["d"]  # no temp file left behind


def test_fifo_is_refused_untouched(tmp_path):
    fifo = tmp_path / "pipe"
    os.mkfifo(fifo)
    before = _snapshot(fifo)
    with pytest.raises(OutputError, match="not a regular file"):
        check_output_file(fifo, argument="--json-out")
    with pytest.raises(OutputError):
        atomic_write_bytes(fifo, b"x")  # must not block opening the FIFO either
    assert _snapshot(fifo) == before and stat.S_ISFIFO(before[0])
    with pytest.raises(OutputError, match="not a directory"):
        check_output_dir(fifo)


def test_socket_is_refused(tmp_path):
    path = tmp_path / "s"
    sock = socket.socket(socket.AF_UNIX)
    try:
        sock.bind(str(path))
        with pytest.raises(OutputError):
            check_output_file(path)
        with pytest.raises(OutputError):
            atomic_write_text(path, "x")
        assert stat.S_ISSOCK(os.lstat(path).st_mode)
    finally:
        sock.close()


def test_symlink_is_refused_and_its_target_untouched(tmp_path):
    outside = tmp_path / "outside.txt"
    outside.write_text("precious")
    link = tmp_path / "out" / "result.json"
    link.parent.mkdir()
    link.symlink_to(outside)
    with pytest.raises(OutputError, match="symbolic link"):
        check_output_file(link)
    with pytest.raises(OutputError):
        atomic_write_text(link, "replaced")
    assert link.is_symlink() and outside.read_text() == "precious"


def test_file_given_as_output_folder_is_refused(tmp_path):
    f = tmp_path / "f"
    f.write_text("k")
    with pytest.raises(OutputError, match=r"--out: .*not a directory"):
        check_output_dir(f)
    with pytest.raises(OutputError):
        check_output_dir(f / "sub")  # nearest existing ancestor is a file
    with pytest.raises(OutputError):
        with staged_dir(f):
            pass
    assert f.read_text() == "k"


def test_missing_parent_of_output_file_is_refused(tmp_path):
    with pytest.raises(OutputError, match="missing or not writable"):
        check_output_file(tmp_path / "no" / "such" / "r.jsonl")
    with pytest.raises(OutputError, match="cannot write"):
        atomic_write_text(tmp_path / "no" / "r.jsonl", "x")
    (tmp_path / "f").write_text("k")
    with pytest.raises(OutputError, match="cannot create"):
        with staged_dir(tmp_path / "f" / "scene"):
            pass
    assert sorted(p.name for p in tmp_path.iterdir()) == ["f"] and (tmp_path / "f").read_text() == "k"


@pytest.mark.skipif(os.geteuid() == 0, reason="root can write into read-only folders")
def test_unwritable_ancestor_is_refused(tmp_path):
    ro = tmp_path / "ro"
    ro.mkdir()
    ro.chmod(0o500)
    try:
        with pytest.raises(OutputError):
            check_output_dir(ro / "a" / "b")
    finally:
        ro.chmod(0o700)


def test_accepted_paths_are_absolute_and_nothing_is_created(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    assert check_output_dir("new/deeper") == tmp_path / "new" / "deeper"
    assert check_output_file("r.jsonl") == tmp_path / "r.jsonl"
    assert check_output_file("-") == "-"
    assert list(tmp_path.iterdir()) == []


# ---------------------------------------------------------------- atomic writes


def test_atomic_write_replaces_a_regular_file(tmp_path):
    target = tmp_path / "a.json"
    target.write_text("old")
    atomic_write_text(target, "new ∞")
    assert target.read_text(encoding="utf-8") == "new ∞"
    assert [p.name for p in tmp_path.iterdir()] == ["a.json"]
    umask = os.umask(0)
    os.umask(umask)
    assert stat.S_IMODE(target.stat().st_mode) == 0o666 & ~umask


@pytest.mark.parametrize("failure", [KeyboardInterrupt, OSError])
def test_interrupt_mid_write_leaves_old_file_intact(tmp_path, monkeypatch, failure):
    target = tmp_path / "summary.json"
    target.write_text("old complete content")

    def interrupted_fsync(fd):
        raise failure("interrupted while flushing")

    monkeypatch.setattr(outputs.os, "fsync", interrupted_fsync)
    with pytest.raises(failure):
        atomic_write_bytes(target, b"new partial" * 1000)
    assert target.read_text() == "old complete content"
    assert [p.name for p in tmp_path.iterdir()] == ["summary.json"]  # temp file removed


def test_interrupt_at_rename_leaves_old_file_intact(tmp_path, monkeypatch):
    target = tmp_path / "r.txt"
    target.write_text("old")

    def interrupted_replace(src, dst):
        raise KeyboardInterrupt

    monkeypatch.setattr(outputs.os, "replace", interrupted_replace)
    with pytest.raises(KeyboardInterrupt):
        atomic_write_text(target, "new")
    assert target.read_text() == "old" and [p.name for p in tmp_path.iterdir()] == ["r.txt"]


# ---------------------------------------------------------------- staged folders


def test_staged_dir_replaces_an_older_complete_output(tmp_path):
    final = tmp_path / "scene"
    final.mkdir()
    (final / "old.json").write_text("old")
    with staged_dir(final) as stage:
        assert stage.parent == tmp_path and stage.name.startswith(".") and stage != final
        assert (final / "old.json").exists()  # the old output stays readable while we work
        atomic_write_text(stage / "new.json", "new")
    assert sorted(p.name for p in final.iterdir()) == ["new.json"]
    assert [p.name for p in tmp_path.iterdir()] == ["scene"]  # no staging or old folder left


@pytest.mark.parametrize("failure", [KeyboardInterrupt, RuntimeError])
def test_interrupted_staged_dir_leaves_older_output_untouched(tmp_path, failure):
    final = tmp_path / "scene"
    final.mkdir()
    (final / "summary.json").write_text("complete")
    with pytest.raises(failure):
        with staged_dir(final) as stage:
            atomic_write_text(stage / "product.json", "half")
            raise failure("stop")
    assert sorted(p.name for p in final.iterdir()) == ["summary.json"]
    assert (final / "summary.json").read_text() == "complete"
    assert [p.name for p in tmp_path.iterdir()] == ["scene"]


def test_interrupted_first_staged_dir_leaves_nothing(tmp_path):
    with pytest.raises(KeyboardInterrupt):
        with staged_dir(tmp_path / "out" / "scene") as stage:
            (stage / "x").write_text("x")
            raise KeyboardInterrupt
    assert list((tmp_path / "out").iterdir()) == []


def test_failed_rename_in_restores_the_older_output(tmp_path, monkeypatch):
    final = tmp_path / "scene"
    final.mkdir()
    (final / "summary.json").write_text("complete")
    real_rename = os.rename

    def rename(src, dst):
        if Path(src).name.startswith(".scene.staging-"):
            raise KeyboardInterrupt
        return real_rename(src, dst)

    monkeypatch.setattr(outputs.os, "rename", rename)
    with pytest.raises(KeyboardInterrupt):
        with staged_dir(final) as stage:
            (stage / "new").write_text("n")
    assert (final / "summary.json").read_text() == "complete"
    assert [p.name for p in tmp_path.iterdir()] == ["scene"]
