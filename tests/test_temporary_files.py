"""A run leaves nothing in the temporary folder: not when a worker process built the
precompiled stand-ins, not when the run is stopped by SIGTERM (one worker or several)."""

from __future__ import annotations

import multiprocessing
import os
import signal
import subprocess
import sys
import tempfile
import time
from concurrent.futures import ProcessPoolExecutor

from conftest import FIXTURES

from haros_arch.extract.cpp import headers, toolchain


def _prelude_in_worker(flags: list[str]) -> str | None:
    return headers.precompiled_prelude(flags)


def test_a_prelude_built_in_a_worker_is_removed_when_the_worker_ends(tmp_path, monkeypatch):
    """``models build --jobs 2`` extracts whole packages in pool workers, which end
    without running ``atexit`` handlers: each one's precompiled stand-ins stayed."""
    monkeypatch.setattr(tempfile, "tempdir", str(tmp_path))  # the forked worker's too
    # flags this process never built a prelude for: the worker builds its own
    flags = [*toolchain.base_arguments(False, None), "-DHAROS_ARCH_WORKER_PRELUDE"]
    with ProcessPoolExecutor(1, mp_context=multiprocessing.get_context("fork")) as pool:
        path = pool.submit(_prelude_in_worker, flags).result()
    assert path is not None and path.startswith(str(tmp_path) + os.sep)
    assert os.listdir(tmp_path) == []


# run in a fresh interpreter: the CLI on a fixture, the parse of the first unit sends
# SIGTERM (to the process itself, or from a worker to the main process) after listing
# the temporary folder, which must hold the run's folders by then
STOPPED_RUN = """
import faulthandler, os, signal, sys, tempfile
faulthandler.register(signal.SIGUSR1, all_threads=True)  # where a run that hangs waits
from haros_arch import cli
from haros_arch.extract import cpp

main_pid = os.getpid()
parse = cpp._unit_and_data

def stopped(*args, **kwargs):
    print("held:", *sorted(os.listdir(tempfile.gettempdir())), flush=True)
    os.kill(main_pid, signal.SIGTERM)
    return parse(*args, **kwargs)

cpp._unit_and_data = stopped
sys.exit(cli.main(["extract", sys.argv[1], "--jobs", sys.argv[2], "--no-cache", "-q",
                   "-o", os.devnull]))
"""


def _stopped_run(tmp_path, jobs: str) -> None:
    temporary = tmp_path / "tmp"
    temporary.mkdir()
    env = {**os.environ, "TMPDIR": str(temporary), "XDG_CACHE_HOME": str(tmp_path / "cache")}
    # in a session of its own: workers left behind (as they were) are ended with it
    run = subprocess.Popen(
        [sys.executable, "-c", STOPPED_RUN, str(FIXTURES / "cpp/several_nodes"), jobs],
        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env,
        start_new_session=True)
    try:
        stdout, stderr = run.communicate(timeout=300)  # a loaded machine is slow
    except subprocess.TimeoutExpired:
        os.kill(run.pid, signal.SIGUSR1)  # its threads' stacks, into the message below
        time.sleep(2)
        os.killpg(run.pid, signal.SIGKILL)
        stdout, stderr = run.communicate()
        raise AssertionError(f"the stopped run did not end: {stdout}{stderr}") from None
    held = [line for line in stdout.splitlines() if line.startswith("held:")]
    assert held, stdout + stderr
    assert "haros-arch-cpp-" in held[0] and "haros-arch-pch-" in held[0]
    assert run.returncode == 143, stdout + stderr
    assert "Traceback" not in stderr
    assert os.listdir(temporary) == []


def test_a_run_stopped_by_sigterm_removes_its_temporary_folders(tmp_path):
    _stopped_run(tmp_path, "1")


def test_a_run_with_workers_stopped_by_sigterm_removes_its_temporary_folders(tmp_path):
    _stopped_run(tmp_path, "2")


# a test run's start (tests/conftest.py) then, in the first run, what a killed run leaves:
# folders and a file in its temporary folder, and no exit handler run
KILLED_RUN = """
import os, signal, sys, tempfile
sys.path.insert(0, sys.argv[1])
import conftest
tempfile.mkdtemp(prefix="haros-arch-pch-")
os.makedirs(os.path.join(os.environ["XDG_CACHE_HOME"], "haros-arch"))
with open(os.path.join(tempfile.mkdtemp(prefix="haros-arch-fuzz-"), "a.launch"), "w") as f:
    f.write("<launch/>")
if sys.argv[2] == "kill":
    os.kill(os.getpid(), signal.SIGKILL)
"""


def test_a_killed_test_run_leaves_nothing_after_the_next(tmp_path):
    """The suite's temporary folders (the parse cache, the fuzzing workspace, what the
    code under test makes) are in one folder of the run under the temporary folder; a
    run killed leaves it, and the next run's start removes it, not those of runs still
    going; a run that ends removes its own."""
    temporary = tmp_path / "tmp"
    temporary.mkdir()
    env = {k: v for k, v in os.environ.items() if k != "XDG_CACHE_HOME"}
    env["TMPDIR"] = str(temporary)
    tests = os.path.dirname(os.path.abspath(__file__))
    killed = subprocess.run([sys.executable, "-c", KILLED_RUN, tests, "kill"], env=env,
                            capture_output=True, text=True, timeout=120)
    assert killed.returncode == -signal.SIGKILL, killed.stderr
    left = [p for p in temporary.rglob("*") if p.is_file()]
    assert [p.name for p in left] == ["a.launch"]  # what a kill leaves
    parent = temporary / f"haros-arch-tests-{os.getuid()}"
    live = parent / str(os.getpid())  # a run still going: this one's pid
    live.mkdir(parents=True)
    ended = subprocess.run([sys.executable, "-c", KILLED_RUN, tests, "end"], env=env,
                           capture_output=True, text=True, timeout=120)
    assert ended.returncode == 0, ended.stderr
    assert sorted(temporary.rglob("*")) == [parent, live]
