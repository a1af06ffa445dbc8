"""A run that handles Ctrl-C and SIGTERM (``processes.stop_signals``, as the CLI does)
stops on them, also when they come while libclang visits a tree and runs our callbacks
(where ctypes printed the exception and went on)."""

from __future__ import annotations

import os
import signal

import pytest
from test_extract_cpp_cursors import _unit

from haros_arch import processes
from haros_arch.extract.cpp import cursors


@pytest.fixture(autouse=True)
def _default_dispositions():
    """Each test starts from the default dispositions of SIGINT and SIGTERM, as a run
    from a terminal has them: a shell that starts the suite in the background (``cmd
    &`` without job control) has SIGINT ignored, which ``stop_signals`` rightly keeps
    as the program's own choice, and these tests would fail there."""
    before = {signum: signal.getsignal(signum) for signum in (signal.SIGINT, signal.SIGTERM)}
    for signum in before:
        signal.signal(signum, signal.SIG_DFL if signum == signal.SIGTERM
                      else signal.default_int_handler)
    try:
        yield
    finally:
        for signum, handler in before.items():
            signal.signal(signum, handler)


def _signalled(signum: int, monkeypatch) -> list[str]:
    """Visit a unit's children with ``signum`` sent to this process at the first one;
    the names of the files asked about (the visit goes on to its end)."""
    asked: list[str] = []

    def judged(judge):
        def of(location):
            if not asked:
                os.kill(os.getpid(), signum)
            asked.append("x")
            return True
        return of

    monkeypatch.setattr(cursors, "by_file", judged)
    cursors.children_in(cursors.root(_unit()), lambda _name: True)
    return asked


def test_ctrl_c_in_a_visit_stops_the_run_after_it(monkeypatch):
    with processes.stop_signals(), pytest.raises(KeyboardInterrupt):
        _signalled(signal.SIGINT, monkeypatch)
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler


def test_sigterm_exits_143_once(monkeypatch):
    with processes.stop_signals():
        with pytest.raises(SystemExit) as stopped:
            _signalled(signal.SIGTERM, monkeypatch)
        assert stopped.value.code == 143
        # a second one does not interrupt the unwinding
        os.kill(os.getpid(), signal.SIGTERM)
        assert signal.getsignal(signal.SIGTERM) is signal.SIG_IGN
    assert signal.getsignal(signal.SIGTERM) is signal.SIG_IGN
    signal.signal(signal.SIGTERM, signal.SIG_DFL)


def test_nothing_changes_where_the_program_has_its_own_handler():
    def own(_signum, _frame):
        pass

    previous = signal.signal(signal.SIGTERM, own)
    try:
        with processes.stop_signals():
            assert signal.getsignal(signal.SIGTERM) is own
            assert signal.getsignal(signal.SIGINT) is processes._stopped
    finally:
        signal.signal(signal.SIGTERM, previous)


def test_a_visit_of_another_thread_does_not_hold_the_main_threads_stop():
    """Python runs a signal's handler in the main thread: a visit another thread is in
    (a worker thread's, or one a test left running) neither holds the main thread's
    Ctrl-C nor has it raised in its own."""
    import threading

    inside, leave = threading.Event(), threading.Event()
    raised: list[BaseException] = []

    def visiting() -> None:
        try:
            with processes.held_signals:
                inside.set()
                leave.wait(10)
        except BaseException as error:  # what the thread would get
            raised.append(error)

    thread = threading.Thread(target=visiting)
    thread.start()
    try:
        assert inside.wait(10)
        with processes.stop_signals(), pytest.raises(KeyboardInterrupt):
            os.kill(os.getpid(), signal.SIGINT)
            for _ in range(1000):  # the handler runs between two bytecodes
                pass
    finally:
        leave.set()
        thread.join(10)
    assert raised == []


# a run with a pool of two workers, stopped by SIGTERM to its main process alone (``kill
# PID``) from its first task, each task a minute long; "stuck": each task blocks the
# stop signals first, as a worker waiting for good on a lock would never see them. It
# prints when the stop was sent and when the run ended (its start, under load, is slow)
STOPPED_POOL = """
import os, signal, sys, time
from haros_arch import processes

def task(index):
    if sys.argv[1] == "stuck":
        signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGTERM, signal.SIGINT})
    os.write(1, f"begun {index}\\n".encode())  # one write: whole lines, never mixed
    if index == 0:
        time.sleep(float(sys.argv[3]))  # 0: the stop may come while the tasks are submitted
        os.write(1, f"stop {time.time()}\\n".encode())
        os.kill(os.getppid(), signal.SIGTERM)
    time.sleep(60)
    return index

try:
    with processes.stop_signals(), processes.worker_pool(2) as pool:
        print(list(pool.map(task, range(8))))
finally:
    os.write(1, f"end {time.time()}\\n".encode())
"""


def _left(marker: str) -> list[str]:
    """The processes still running whose command line holds ``marker``."""
    found = []
    for entry in os.listdir("/proc"):
        try:
            with open(f"/proc/{entry}/cmdline", "rb") as line:
                if marker.encode() not in line.read():
                    continue
            with open(f"/proc/{entry}/stat") as status:
                if status.read().rsplit(") ", 1)[1][0] != "Z":
                    found.append(entry)
        except (FileNotFoundError, ProcessLookupError, IndexError, NotADirectoryError):
            continue
    return found


def _run_script(script: str, *args: str, timeout: float) -> tuple[int, str, str]:
    """Run ``script`` in a fresh interpreter, in a session of its own (its workers end
    with it): its exit status, stdout and stderr; a run that does not end within
    ``timeout`` is killed and fails the test."""
    import subprocess
    import sys

    run = subprocess.Popen([sys.executable, "-c", script, *args], text=True,
                           stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                           start_new_session=True)
    try:
        stdout, stderr = run.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        os.killpg(run.pid, signal.SIGKILL)
        stdout, stderr = run.communicate()
        raise AssertionError(f"the run did not end: {stdout}{stderr}") from None
    return run.returncode, stdout, stderr


def _stopped_pool(kind: str, wait: float = 1.0) -> tuple[float, list[str]]:
    """How long the run took to end after the stop, and its tasks begun."""
    import uuid

    marker = f"haros-arch-pool-test-{uuid.uuid4().hex}"
    code, stdout, stderr = _run_script(STOPPED_POOL, kind, marker, str(wait), timeout=240)
    assert code == 143, stdout + stderr
    assert _left(marker) == [], "a worker was left behind"
    times = {line.split()[0]: float(line.split()[1]) for line in stdout.splitlines()
             if line.startswith(("stop ", "end "))}
    assert set(times) == {"stop", "end"}, stdout + stderr
    return times["end"] - times["stop"], [line for line in stdout.splitlines()
                                          if line.startswith("begun")]


def test_a_stopped_pool_begins_no_queued_task_and_ends_its_running_ones():
    """A stop of the main process alone used to wait for each running task (a minute
    here) and run those the pool had queued (minutes for a stopped ``models build``);
    now it is passed on to the workers, and a queued task is not begun."""
    seconds, begun = _stopped_pool("plain")
    assert len(begun) <= 2, begun
    assert seconds < 45, seconds  # about a second on an idle machine


def test_a_stopped_pool_kills_a_worker_that_does_not_end():
    """A worker that never sees the stop (waiting for good) is killed after
    ``STOP_SECONDS``: a stopped run ends (it waited for good)."""
    seconds, begun = _stopped_pool("stuck")
    assert len(begun) <= 2, begun
    assert seconds < processes.STOP_SECONDS + 35, seconds  # about 10 s when idle


def test_a_stop_while_the_tasks_are_submitted_stops_the_run():
    """The stop comes at once, perhaps while the pool still starts its thread (the first
    submission): it is the run's stop, not an error of the pool's locks."""
    for _ in range(3):
        seconds, begun = _stopped_pool("plain", 0.0)
        assert len(begun) <= 2, begun
        assert seconds < 45, seconds


def test_a_process_forked_while_a_stop_is_held_holds_none():
    """A pool's worker is forked by a submission, which holds the stop: the worker must
    not inherit that (it then never stopped on its own SIGTERM and was killed)."""
    with processes.held_signals:
        pid = os.fork()
        if pid == 0:  # the child: its answer as its exit status
            held = processes.held_signals
            os._exit(0 if held.depth == 0 and held.requested is None else 1)
    _, status = os.waitpid(pid, 0)
    assert os.waitstatus_to_exitcode(status) == 0


def _stops_its_worker(record: str) -> None:
    """A task that makes a folder its worker removes at its end, writes its worker's pid
    and the folder, and then stops its own worker (a SIGTERM that ``_end_workers``, or
    ``timeout`` to the process group, sends)."""
    import tempfile
    import time

    folder = tempfile.mkdtemp(prefix="haros-arch-worker-test-")
    processes.remove_at_end(folder)
    with open(record, "w") as out:
        out.write(f"{os.getpid()} {folder}")
    os.kill(os.getpid(), signal.SIGTERM)
    time.sleep(30)  # the stop comes first


def _gone(pid: int) -> bool:
    try:
        with open(f"/proc/{pid}/stat") as status:
            return status.read().rsplit(") ", 1)[1][0] == "Z"
    except (FileNotFoundError, ProcessLookupError):
        return True


def test_a_worker_stopped_in_a_task_ends_and_takes_no_other(tmp_path):
    """A worker whose task the stop ended went back to the pool's queue for the next
    task (the pool's loop takes the stop for the task's error); another worker stopped
    while reading from that queue may have left half a message there, whose rest the
    first then read as one (an EOFError printed by a run stopped under load). Now it
    ends at once, its folders removed, and no later task reaches it."""
    import time
    from concurrent.futures.process import BrokenProcessPool

    record = tmp_path / "worker"
    with processes.worker_pool(1) as pool:
        stopped = pool.submit(_stops_its_worker, str(record))
        try:
            later = pool.submit(os.getpid)
        except BrokenProcessPool:  # the worker has ended already
            later = None
        assert stopped.exception(timeout=120) is not None
        if later is not None:  # never run: the pool is broken
            assert later.exception(timeout=120) is not None
        pid, folder = record.read_text().split()
        deadline = time.monotonic() + 60
        while not _gone(int(pid)) and time.monotonic() < deadline:
            time.sleep(0.05)
        assert _gone(int(pid)), "the stopped worker still waits for tasks"
        assert not os.path.exists(folder)


# a run with a pool of two workers whose stop (SIGTERM to itself) comes while its main
# thread waits for the first result, just after it took that result's lock inside the
# lock's ``__enter__`` (Python code, where a signal's handler may run): the lock was left
# taken, the pool's thread waited for it for good, and so did the run's end
STOPPED_IN_WAIT = """
import os, signal, sys, threading, time
from haros_arch import processes

enter = threading.Condition.__enter__
main = threading.get_ident()
sent = []

def entered(self):
    taken = enter(self)
    if (threading.get_ident() == main and not sent
            and sys._getframe(1).f_code.co_name == "result"):
        sent.append(True)
        os.kill(os.getpid(), signal.SIGTERM)  # its handler runs on return of the call
    return taken

def task(index):
    time.sleep(2)
    return index

with processes.stop_signals(), processes.worker_pool(2) as pool:
    threading.Condition.__enter__ = entered
    print(list(pool.map(task, range(4))))
"""


def test_a_stop_while_waiting_for_a_result_ends_the_run():
    """The run ends with the stop's status, not waiting for good at its exit."""
    code, stdout, stderr = _run_script(STOPPED_IN_WAIT, timeout=120)
    assert code == 143, stdout + stderr
    assert "Traceback" not in stderr, stderr


# a stop (SIGTERM to the run's process group, as ``timeout`` sends it) whose handler
# runs in a finaliser or a callback of C code: in the run itself, and in a pool's
# worker within a task (libclang's objects are freed all through a walk; its
# ``get_includes`` calls back). Raised there, Python printed it as an "Exception
# ignored" with its traceback and dropped it: the run went on to its end.
# With a pool, the run's own stop, held while it waited for a result, lost to the
# BrokenProcessPool its ended worker left: "internal error" instead of 143
STOPPED_IN_FINALISER = """
import ctypes, os, signal, sys, time
from haros_arch import processes

class Freed:
    def __del__(self):
        os.killpg(0, signal.SIGTERM)  # its handler runs here, before this returns
        self.after = [n for n in range(10)]

def compare(a, b):
    os.killpg(0, signal.SIGTERM)  # in a callback of C code (libc's qsort)
    return 0

def work(index):
    if sys.argv[2] == "finaliser":
        Freed()
    else:
        values = (ctypes.c_int * 2)(2, 1)
        kind = ctypes.CFUNCTYPE(ctypes.c_int, ctypes.c_void_p, ctypes.c_void_p)
        ctypes.CDLL(None).qsort(values, 2, ctypes.sizeof(ctypes.c_int), kind(compare))
    for _ in range(200):  # the stop must end this within two seconds
        time.sleep(0.01)
    return index

with processes.stop_signals():
    if sys.argv[1] == "pool":
        with processes.worker_pool(1) as pool:
            print("result", list(pool.map(work, range(2))), flush=True)
    else:
        print("result", work(0), flush=True)
"""


@pytest.mark.parametrize("where", ["run", "pool"])
@pytest.mark.parametrize("inside", ["finaliser", "callback"])
def test_a_stop_in_a_finaliser_or_callback_ends_the_run_with_no_traceback(where, inside):
    code, stdout, stderr = _run_script(STOPPED_IN_FINALISER, where, inside, timeout=120)
    assert "result" not in stdout, stdout + stderr
    assert "Traceback" not in stderr and "Exception ignored" not in stderr, stderr
    assert code == 143, stdout + stderr


# a pool worker stopped (SIGTERM) while it writes a large result back to the run: it
# ended at once, half the message in the pipe, and the pool's thread took the pool for
# broken or, when it had begun to read the message, waited for its rest for good, and so
# did the run's exit (a cause of the rare hang of the stopped two-worker run in CI)
STOPPED_IN_SEND = """
import os, signal, sys, threading
from haros_arch import processes

def task(size):
    made = b"x" * size
    # SIGTERM to this worker soon after the task returns, while its result is written
    threading.Timer(0.02, os.kill, (os.getpid(), signal.SIGTERM)).start()
    return made

with processes.stop_signals(), processes.worker_pool(1) as pool:
    future = pool.submit(task, 200_000_000)
    print("result", len(processes.result(future)), flush=True)
"""


def test_a_worker_stopped_while_it_sends_its_result_ends_after_the_message():
    _code, stdout, stderr = _run_script(STOPPED_IN_SEND, timeout=90)
    assert "result 200000000" in stdout, stdout + stderr
