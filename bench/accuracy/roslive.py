"""Run one launch configuration against a fresh roscore on loopback and capture its graph.

Every process we start gets its own session; before shutting down we record the whole
process tree (roslaunch gives each node a session of its own, so a process-group signal
alone would miss them) and end every recorded PID: SIGINT, then SIGTERM, then SIGKILL.
"""

from __future__ import annotations

import contextlib
import json
import os
import shutil
import signal
import socket
import subprocess
import tempfile
import time
import xmlrpc.client
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

CALLER = "/accuracy_bench"



def free_port() -> int:
    with socket.socket() as sock:
        sock.bind(("127.0.0.1", 0))
        return int(sock.getsockname()[1])


def _children_map() -> dict[int, list[int]]:
    children: dict[int, list[int]] = {}
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open(f"/proc/{entry}/stat") as handle:
                stat = handle.read()
        except OSError:
            continue
        # pid (comm) state ppid ...: comm may hold spaces, so split after the last ')'
        ppid = int(stat[stat.rfind(")") + 2:].split()[1])
        children.setdefault(ppid, []).append(int(entry))
    return children


def process_tree(root: int) -> list[int]:
    """``root`` and all its descendants alive now."""
    children = _children_map()
    found, todo = [], [root]
    while todo:
        pid = todo.pop()
        found.append(pid)
        todo.extend(children.get(pid, []))
    return found


def _alive(pid: int) -> bool:
    try:
        with open(f"/proc/{pid}/stat") as handle:
            stat = handle.read()
    except OSError:
        return False
    return stat[stat.rfind(")") + 2] != "Z"


def _signal_all(pids: list[int], sig: int) -> None:
    for pid in pids:
        if _alive(pid):
            with contextlib.suppress(ProcessLookupError):
                os.kill(pid, sig)


def _wait_gone(pids: list[int], popen: subprocess.Popen[bytes], seconds: float) -> bool:
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        popen.poll()  # reap our direct child so it does not linger as a zombie
        if not any(_alive(pid) for pid in pids):
            return True
        time.sleep(0.2)
    return False


def stop(popen: subprocess.Popen[bytes], grace: float = 15.0) -> list[int]:
    """End ``popen`` and everything it started; returns the PIDs that needed SIGKILL."""
    pids = process_tree(popen.pid)
    _signal_all(pids, signal.SIGINT)
    if _wait_gone(pids, popen, grace):
        return []
    pids = [pid for pid in {*pids, *process_tree(popen.pid)} if _alive(pid)]
    _signal_all(pids, signal.SIGTERM)
    if _wait_gone(pids, popen, 5.0):
        return []
    stubborn = [pid for pid in pids if _alive(pid)]
    _signal_all(stubborn, signal.SIGKILL)
    _wait_gone(stubborn, popen, 5.0)
    return stubborn


def signature(uri: str, timeout: float = 5.0) -> str:
    """What must stay unchanged for the graph to count as settled: nodes, topics, types,
    services and parameter names (not values), read straight from the master."""
    master = xmlrpc.client.ServerProxy(uri, transport=_Transport(timeout))
    state = [master.getSystemState(CALLER), master.getTopicTypes(CALLER),
             master.getParamNames(CALLER)]
    return json.dumps(state, sort_keys=True)


class _Transport(xmlrpc.client.Transport):
    def __init__(self, timeout: float) -> None:
        super().__init__()
        self.timeout = timeout

    def make_connection(self, host: Any) -> Any:
        connection = super().make_connection(host)
        connection.timeout = self.timeout
        return connection


@dataclass
class RunRecord:
    name: str
    launch: str
    args: dict[str, str]
    settled: bool = False
    seconds: float = 0.0
    launch_exit: int | None = None
    killed: list[int] = field(default_factory=list)
    error: str = ""

    def to_data(self) -> dict[str, Any]:
        return dict(self.__dict__)


def _wait_for_master(uri: str, core: subprocess.Popen[bytes], seconds: float) -> None:
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        if core.poll() is not None:
            raise RuntimeError(f"roscore exited with {core.returncode}")
        try:
            signature(uri, 2.0)
            return
        except (OSError, xmlrpc.client.Error):
            time.sleep(0.3)
    raise RuntimeError("roscore did not answer in time")


def run_configuration(
    name: str, launch_file: Path, launch_label: str, args: dict[str, str],
    env: dict[str, str], out: Path, capture_cmd: list[str], settle: float = 3.0,
    min_wait: float = 4.0, timeout: float = 60.0, log_dir: Path | None = None,
) -> RunRecord:
    """roscore + roslaunch on a fresh port; wait until the graph settles; capture to ``out``."""
    record = RunRecord(name, launch_label, args)
    port = free_port()
    uri = f"http://127.0.0.1:{port}"
    home = Path(tempfile.mkdtemp(prefix=f"accuracy_{name}_"))
    run_env = {**env, "ROS_MASTER_URI": uri, "ROS_HOSTNAME": "127.0.0.1",
               "ROS_HOME": str(home), "ROS_LOG_DIR": str(home / "log"),
               "QT_QPA_PLATFORM": "offscreen", "PYTHONUNBUFFERED": "1"}
    logs = log_dir or home
    logs.mkdir(parents=True, exist_ok=True)
    started = time.monotonic()
    core = launch = None
    with open(logs / f"{name}.roscore.log", "wb") as core_log, \
            open(logs / f"{name}.roslaunch.log", "wb") as launch_log:
        try:
            core = subprocess.Popen(["roscore", "-p", str(port)], env=run_env,
                                    stdin=subprocess.DEVNULL, stdout=core_log,
                                    stderr=subprocess.STDOUT, start_new_session=True)
            _wait_for_master(uri, core, 30.0)
            launch_args = [f"{key}:={value}" for key, value in args.items()]
            launch = subprocess.Popen(["roslaunch", "-p", str(port), str(launch_file),
                                       *launch_args], env=run_env,
                                      stdin=subprocess.DEVNULL, stdout=launch_log,
                                      stderr=subprocess.STDOUT, start_new_session=True)
            record.settled = _settle(uri, settle, min_wait, timeout)
            record.launch_exit = launch.poll()
            subprocess.run([*capture_cmd, "--master", uri, "-o", str(out)], env=run_env,
                           check=True, timeout=60, stdout=subprocess.DEVNULL)
        except (RuntimeError, subprocess.SubprocessError, OSError) as err:
            record.error = str(err)
        finally:
            for popen in (launch, core):
                if popen is not None:
                    record.killed += stop(popen)
    record.seconds = round(time.monotonic() - started, 1)
    shutil.rmtree(home, ignore_errors=True)
    return record


def _settle(uri: str, settle: float, min_wait: float, timeout: float) -> bool:
    """Poll the master until its graph has not changed for ``settle`` seconds."""
    started = time.monotonic()
    last, since = "", started
    while time.monotonic() - started < timeout:
        time.sleep(0.5)
        try:
            now = signature(uri)
        except (OSError, xmlrpc.client.Error):
            continue
        if now != last:
            last, since = now, time.monotonic()
        elif time.monotonic() - since >= settle and time.monotonic() - started >= min_wait:
            return True
    return False
