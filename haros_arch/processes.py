"""How a run's processes stop: the run itself on Ctrl-C or SIGTERM, and a pool of workers.

A run stopped by Ctrl-C or SIGTERM (``timeout``, a CI job cancelled) ends like one that
failed: its ``finally`` blocks and exit handlers remove its temporary folders, and a
pool's workers end instead of being left behind waiting for tasks.
"""

from __future__ import annotations

import concurrent.futures.process
import contextlib
import multiprocessing
import multiprocessing.process
import os
import shutil
import signal
import sys
import threading
import time
from collections.abc import Callable, Iterator
from concurrent.futures import Future, ProcessPoolExecutor
from concurrent.futures import TimeoutError as FutureTimeout
from types import FrameType, TracebackType
from typing import Any


class _Held:
    """``held_signals``: a stop (Ctrl-C, SIGTERM) that comes while a call into C runs
    Python callbacks (libclang's visit of a tree) waits for the call's end. Raised in
    a callback, where the interpreter mostly is during such a call, or in a hook run at
    a fork, its exception is printed and dropped, and the run would go on: the stop is
    also kept (``requested``) and raised again at the end of the next visit or at
    ``raise_if_stopped``."""

    def __init__(self) -> None:
        self.depth = 0
        self.requested: BaseException | None = None
        # the stop was raised where Python dropped it (``_unraisable``), and not raised
        # again since
        self.dropped = False

    def __enter__(self) -> None:
        # the main thread's calls only: Python runs a signal's handler there, and a call
        # of another thread (a worker thread's visit) must neither hold the main
        # thread's stop nor get it raised in its own
        if threading.current_thread() is threading.main_thread():
            self.depth += 1

    def __exit__(self, kind: type[BaseException] | None, _error: BaseException | None,
                 _trace: TracebackType | None) -> None:
        if threading.current_thread() is not threading.main_thread():
            return
        self.depth -= 1
        if self.depth == 0 and (kind is None or (issubclass(kind, Exception) and isinstance(
                self.requested, (KeyboardInterrupt, SystemExit)))):
            # a stop also wins over an error of the block, which may be its consequence
            # (a pool whose workers the same SIGTERM ended: BrokenProcessPool); else
            # that exception unwinds the run
            raise_if_stopped()


held_signals = _Held()


def _forked() -> None:
    """A forked process (a pool's worker, forked by a submission, which holds the stop)
    starts with no stop held nor asked for: its own come as they come."""
    held_signals.depth = 0
    held_signals.requested = None
    held_signals.dropped = False


os.register_at_fork(after_in_child=_forked)


def raise_if_stopped() -> None:
    """Raise the stop the run was asked for, if any (see ``_Held``)."""
    if held_signals.requested is not None:
        held_signals.dropped = False
        raise held_signals.requested


def _stop_for(signum: int) -> BaseException:
    """The exception a stop signal raises: Ctrl-C's KeyboardInterrupt, else the exit
    status 128 + the signal's number."""
    return KeyboardInterrupt() if signum == signal.SIGINT else SystemExit(128 + signum)


def _stopped(signum: int, _frame: FrameType | None) -> None:
    error = _stop_for(signum)
    if signum == signal.SIGTERM:
        # once: a second SIGTERM (``timeout`` signals the whole process group, a worker
        # may pass one on) must not interrupt the unwinding the first one started
        signal.signal(signal.SIGTERM, signal.SIG_IGN)
    _request(error)


def _request(error: BaseException) -> None:
    """Keep ``error`` as the one the run was asked for (a stop of the run over a unit's
    time limit, not the other way round) and raise it, unless a call into C runs our
    callbacks (``_Held``): then it is raised when that call ends. Raised where Python
    cannot pass it on (a finaliser, a callback of C code not held), it is raised again
    soon (``_unraisable``)."""
    held = held_signals.requested
    if held is None or (isinstance(held, OverTime) and not isinstance(error, OverTime)):
        held_signals.requested = error
    if not held_signals.depth:
        held_signals.dropped = False
        raise error


# how soon a stop that was raised where Python could not pass it on is raised again
AGAIN_SECONDS = 0.01


def _unraisable(unraisable: Any) -> None:
    """``sys.unraisablehook`` within ``stop_signals``: the stop asked for, raised in a
    finaliser (``__del__``, which the interpreter calls wherever an object's last
    reference goes: libclang's strings and translation units in a walk) or in a callback
    of C code (libclang's ``get_includes``), is raised again in ``AGAIN_SECONDS``
    (``_again``), out of where it came by then, not printed with its traceback as an
    ignored exception and dropped; anything else goes to the hook before it."""
    if unraisable.exc_value is not None and unraisable.exc_value is held_signals.requested:
        held_signals.dropped = True
        _soon(_again)
        return
    before = _UNRAISABLE_BEFORE[-1] if _UNRAISABLE_BEFORE else sys.__unraisablehook__
    before(unraisable)


# the hooks ``_unraisable`` stands in for (``stop_signals``)
_UNRAISABLE_BEFORE: list[Callable[[Any], None]] = []


def _again(_frame: FrameType | None) -> None:
    """Raise the stop dropped (``_unraisable``) unless it was raised again meanwhile
    (where the run holds it: the end of a visit, a wait's poll): twice, the second would
    interrupt the unwinding of the first (a pool's workers left)."""
    stop = held_signals.requested
    if stop is not None and held_signals.dropped:  # not raised again since it was dropped
        _request(stop)


def _soon(then: Callable[[FrameType | None], None]) -> None:
    """Call ``then`` with the frame the interpreter is in ``AGAIN_SECONDS`` from now
    (SIGALRM, whose handler is put back first); nothing more when it is on its way."""
    if signal.getsignal(signal.SIGALRM) is _alarm:
        _SOON[-1] = then
        return
    _SOON[:] = [signal.getsignal(signal.SIGALRM) or signal.SIG_DFL, then]
    signal.signal(signal.SIGALRM, _alarm)
    signal.setitimer(signal.ITIMER_REAL, AGAIN_SECONDS)


# while ``_alarm`` is SIGALRM's handler: the handler it stands in for, then what it calls
_SOON: list[Any] = []


def _alarm(_signum: int, frame: FrameType | None) -> None:
    before, then = _SOON
    _SOON.clear()
    signal.signal(signal.SIGALRM, before)
    then(frame)


@contextlib.contextmanager
def stop_signals() -> Iterator[None]:
    """Within the block Ctrl-C raises KeyboardInterrupt and the first SIGTERM
    ``SystemExit(143)`` (later ones are ignored), held while ``held_signals`` is and
    raised again where one was dropped (``_Held``, ``_unraisable``): the run unwinds.
    By default Python ends at once on SIGTERM and leaves its temporary folders (and,
    with a pool, the workers). Nothing is changed off the main thread, nor a handler
    of the program's own."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    defaults = {signal.SIGINT: signal.default_int_handler, signal.SIGTERM: signal.SIG_DFL}
    previous = {signum: signal.getsignal(signum) for signum in defaults}
    ours = [signum for signum, handler in defaults.items() if previous[signum] is handler]
    for signum in ours:
        signal.signal(signum, _stopped)
    _UNRAISABLE_BEFORE.append(sys.unraisablehook)
    sys.unraisablehook = _unraisable
    try:
        yield
    finally:  # not SIGTERM's once it came: it stays ignored while the process ends
        held_signals.requested = None
        held_signals.dropped = False
        for signum in ours:
            if signal.getsignal(signum) is _stopped:
                signal.signal(signum, previous[signum])
        before = _UNRAISABLE_BEFORE.pop()
        if sys.unraisablehook is _unraisable:
            sys.unraisablehook = before


# how long a stopped run waits for its workers to end after passing the stop on to
# them (a worker ends at its next Python step, or when a call into C it is in returns:
# a parse of one unit) before it kills those left (one whose code waits for good)
STOP_SECONDS = 10.0


# folders a process removes when it ends (``remove_at_end``), each with the process
# that made it: a process forked from it may have inherited the list, not the folders
_REMOVED_AT_END: list[tuple[int, str]] = []


def remove_at_end(folder: str) -> None:
    """Remove ``folder`` when this process ends: at its exit (a pool's worker too, where
    ``atexit`` handlers do not run) or when a stop ends a worker (``_end_worker``).
    Never by a process forked from this one, which may have inherited the path."""
    multiprocessing.util.Finalize(None, shutil.rmtree, args=(folder, True), exitpriority=0)
    _REMOVED_AT_END.append((os.getpid(), folder))


def _end_worker(error: BaseException) -> None:
    """End a stopped worker at once, its folders removed, with the stop's exit status.
    Not through the pool's loop: that catches the stop as a task's error and reads the
    next task, from a queue another worker stopped while reading may have left in the
    middle of a message (its bytes then taken for one: an EOFError printed as the run
    ended)."""
    for pid, folder in _REMOVED_AT_END:
        if pid == os.getpid():
            shutil.rmtree(folder, True)
    for stream in (sys.stdout, sys.stderr):
        with contextlib.suppress(Exception):
            stream.flush()
    os._exit(error.code if isinstance(error, SystemExit) and isinstance(error.code, int)
             else 128 + signal.SIGINT)


def _end_if_stopped() -> None:
    """End this worker if it was told to stop (not for a unit's time limit)."""
    stop = held_signals.requested
    if isinstance(stop, (KeyboardInterrupt, SystemExit)):
        _end_worker(stop)


# whether this worker runs a task (else it waits for one, in the pool's queue)
_in_task = False


def _worker_stopped(signum: int, frame: Any) -> None:
    """A worker's Ctrl-C or SIGTERM: within a task, the run's stop (``_stopped``), which
    ends the task and then the worker; between tasks, the worker ends at once, but not
    while it writes a task's result to the run (``_sending``): then when that is done."""
    if _in_task:
        _stopped(signum, frame)
        return
    stop = _stop_for(signum)
    if _sending(frame):
        held_signals.requested = stop
        _soon(_sent)
        return
    _end_worker(stop)


# the modules whose code writes a worker's result to the run, and their functions that
# do (concurrent.futures' ``_sendback_result``, the queue's ``put``, the connection's
# ``send_bytes``)
_SENDERS = {"concurrent.futures.process": ("_sendback_result",),
            "multiprocessing.queues": ("put",),
            "multiprocessing.connection": ("send_bytes", "_send_bytes", "_send")}


def _sending(frame: FrameType | None) -> bool:
    """Whether the worker is writing a message to the run: a worker ended there leaves
    half a message in the pipe, and the pool's thread in the run waits for its rest for
    good (the run's exit, which joins that thread, too), or takes the pool for broken."""
    while frame is not None:
        names = _SENDERS.get(frame.f_globals.get("__name__", ""))
        if names is not None and frame.f_code.co_name in names:
            return True
        frame = frame.f_back
    return False


def _sent(frame: FrameType | None) -> None:
    """End the worker once it is no longer writing a message (``_sending``): looked at
    again every ``AGAIN_SECONDS``."""
    stop = held_signals.requested
    if stop is None:
        return
    if _sending(frame):
        _soon(_sent)
    else:
        _end_worker(stop)


def _start_worker(initializer: Callable[..., Any] | None, *initargs: Any) -> None:
    """A pool worker's start: its stop signals, then the pool's own initialiser. A stop
    that comes before they are set (the handler the worker was forked with raises it)
    ends the worker as one between tasks does: raised out of an initialiser, the pool
    prints it with its traceback."""
    global _in_task
    _in_task = False
    try:
        for signum in (signal.SIGINT, signal.SIGTERM):
            if signal.getsignal(signum) is not signal.SIG_IGN:
                signal.signal(signum, _worker_stopped)
        if initializer is not None:
            initializer(*initargs)
    except (KeyboardInterrupt, SystemExit) as stop:
        _end_worker(stop)


def _unless_stopped(function: Callable[..., Any], *args: Any, **kwargs: Any) -> Any:
    """A worker's task: not begun once the worker was told to stop (a task the pool had
    already queued for it would else run whole after the stop), and a task the stop
    ended ends its worker (``_end_worker``)."""
    global _in_task
    _end_if_stopped()
    _in_task = True
    try:
        return function(*args, **kwargs)
    finally:
        _in_task = False
        _end_if_stopped()


class _Pool(ProcessPoolExecutor):
    """``worker_pool``'s: each task checks first that its worker was not stopped, and a
    stopped worker ends. A stop that comes while a task is submitted waits for the
    submission's end (``held_signals``): raised inside it, in the lock of a thread the
    pool starts (its first submission), it left that lock released twice, a RuntimeError
    in place of the stop."""

    def __init__(self, max_workers: int | None = None, *,
                 initializer: Callable[..., Any] | None = None,
                 initargs: tuple[Any, ...] = (), **options: Any) -> None:
        super().__init__(max_workers, initializer=_start_worker,
                         initargs=(initializer, *initargs), **options)

    def submit(self, fn: Callable[..., Any], /, *args: Any, **kwargs: Any) -> Future[Any]:
        with held_signals:
            return super().submit(_unless_stopped, fn, *args, **kwargs)

    def map(self, fn: Callable[..., Any], *iterables: Any, timeout: float | None = None,
            chunksize: int = 1) -> Iterator[Any]:
        """Each task's result, in the order of the items, each waited for by ``result``."""
        futures = [self.submit(fn, *items) for items in zip(*iterables, strict=False)]
        return _in_order(futures, timeout)


# how often a wait for a task's result (``result``) looks whether the run was stopped
RESULT_POLL_SECONDS = 0.2


def result(future: Future[Any], timeout: float | None = None) -> Any:
    """``future.result(timeout)`` with a stop that comes meanwhile held until the wait
    is out of the future's lock (``held_signals``), then raised. A stop raised in the
    wait itself could come just after the lock was taken inside its Python
    ``__enter__``: the lock stayed taken, the pool's thread waited for it for good to
    set a result, and so did the run's end, which joins that thread."""
    deadline = None if timeout is None else time.monotonic() + timeout
    while True:
        left = RESULT_POLL_SECONDS if deadline is None else min(
            RESULT_POLL_SECONDS, max(0.0, deadline - time.monotonic()))
        with held_signals, contextlib.suppress(FutureTimeout):
            return future.result(left)
        if deadline is not None and time.monotonic() >= deadline:
            raise FutureTimeout()


def _in_order(futures: list[Future[Any]], timeout: float | None) -> Iterator[Any]:
    """The futures' results in order (``_Pool.map``); the ones not waited for are
    cancelled when the caller stops reading."""
    try:
        for future in futures:
            yield result(future, timeout)
    finally:
        for future in futures:
            future.cancel()


def _end_workers(workers: list[multiprocessing.process.BaseProcess]) -> None:
    """Pass a stop on to the pool's workers (SIGTERM: each ends as the run does, its own
    temporary folders removed), wait ``STOP_SECONDS`` for them, kill those left."""
    for worker in workers:
        if worker.is_alive():
            worker.terminate()
    deadline = time.monotonic() + STOP_SECONDS
    for worker in workers:
        worker.join(max(0.0, deadline - time.monotonic()))
    for worker in workers:
        if worker.is_alive():
            worker.kill()
            worker.join()


@contextlib.contextmanager
def worker_pool(workers: int | None, **options: Any) -> Iterator[ProcessPoolExecutor]:
    """A ``ProcessPoolExecutor`` whose workers end soon when the block is left by an
    exception (Ctrl-C, SIGTERM, an error): the tasks not begun are dropped, the running
    ones stopped, a worker that does not end within ``STOP_SECONDS`` killed. A plain
    pool runs every task submitted before it lets go, and waits for good for a worker
    that never ends."""
    pool = _Pool(max_workers=workers, **options)
    try:
        yield pool
    except BaseException:
        # the pool's processes: its workers are this process's only children
        children = multiprocessing.active_children()
        thread = getattr(pool, "_executor_manager_thread", None)  # shutdown drops it
        pool.shutdown(wait=False, cancel_futures=True)
        _end_workers(children)
        _ended(thread)
        raise
    thread = getattr(pool, "_executor_manager_thread", None)
    pool.shutdown(wait=True)
    _ended(thread)


def _ended(thread: object) -> None:
    """Wait (``STOP_SECONDS``) for a pool's own thread to end, then take it off the
    threads the interpreter's exit wakes (``concurrent.futures.process``): a thread that
    ended needs no waking, and a stopped run's exit wrote to a wake-up pipe whose file
    was closed by then, now and then, and printed an OSError (Bad file descriptor) with
    its traceback."""
    if not isinstance(thread, threading.Thread):
        return
    thread.join(STOP_SECONDS)
    woken = getattr(concurrent.futures.process, "_threads_wakeups", None)
    if not thread.is_alive() and woken is not None:
        woken.pop(thread, None)


class OverTime(BaseException):
    """``cpu_limit``'s: the block used more processor time than it may. Not an
    ``Exception``: a handler of errors the block has must not take it for one of them
    and go on."""

    def __init__(self, seconds: float) -> None:
        super().__init__(f"{seconds:g} s of processor time")
        self.seconds = seconds


@contextlib.contextmanager
def cpu_limit(seconds: float) -> Iterator[None]:
    """Within the block, ``OverTime`` is raised once the process has used ``seconds``
    of processor time in it: a bound on work whose length the input decides (one C++
    unit's analysis), so that a case the analysis loops on, or a hostile file, ends
    with a diagnostic instead of stalling the run. Raised where the interpreter is, or,
    in a callback of a call into C, when that call ends (``held_signals``). Off the main
    thread, where Python runs no handler, there is no limit."""
    if threading.current_thread() is not threading.main_thread() or seconds <= 0:
        yield
        return

    def over(_signum: int, _frame: FrameType | None) -> None:
        _request(OverTime(seconds))

    previous = signal.signal(signal.SIGPROF, over)
    signal.setitimer(signal.ITIMER_PROF, seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_PROF, 0)
        signal.signal(signal.SIGPROF, previous)
        if isinstance(held_signals.requested, OverTime):
            held_signals.requested = None  # this limit's: not a stop of the run
