"""How much of a big ROS 2 system ``capture --ros2`` sees, by listening time.

Starts PARTICIPANTS processes of tests/ros2_system.py (Cyclone DDS only, no ROS 2; one
participant per process, as rmw makes one per process), each with NODES nodes of ENDPOINTS
endpoints (half writers, half readers, on 50 shared topics), on a random domain
restricted to loopback, then captures it for each listening time and prints the nodes
and endpoints seen out of those started, and the wall time. Run:

    .venv/bin/python bench/live_dds.py [PARTICIPANTS NODES ENDPOINTS]   (default 20 5 10)
"""

from __future__ import annotations

import json
import os
import random
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from haros_arch.live import capture_ros2

ROOT = Path(__file__).resolve().parents[1]
LOOPBACK = (
    "<CycloneDDS><Domain id='any'><General><Interfaces><NetworkInterface address='127.0.0.1'/>"
    "</Interfaces><AllowMulticast>false</AllowMulticast></General><Discovery>"
    "<ParticipantIndex>auto</ParticipantIndex><MaxAutoParticipantIndex>120"
    "</MaxAutoParticipantIndex><Peers><Peer address='127.0.0.1'/></Peers></Discovery>"
    "</Domain></CycloneDDS>")
STRING = "std_msgs::msg::dds_::String_"


def spec(participants: int, nodes: int, endpoints: int) -> list[dict]:
    return [{"nodes": [{"namespace": f"/p{p}", "name": f"n{n}", "endpoints": [
        {"topic": f"rt/t{(p * nodes + n + e) % 50}", "type": STRING, "writes": e % 2 == 0}
        for e in range(endpoints)]} for n in range(nodes)]} for p in range(participants)]


def main(argv: list[str]) -> int:
    participants, nodes, endpoints = (int(a) for a in argv) if argv else (20, 5, 10)
    os.environ["CYCLONEDDS_URI"] = LOOPBACK
    domain = random.randint(1, 200)
    with tempfile.TemporaryDirectory() as folder:
        env = {**os.environ, "PYTHONPATH": os.pathsep.join([str(ROOT), str(ROOT / "tests")])}
        started = time.monotonic()
        children = []
        for index, participant in enumerate(spec(participants, nodes, endpoints)):
            path = Path(folder) / f"system{index}.json"
            path.write_text(json.dumps([participant]))
            children.append(subprocess.Popen(
                [sys.executable, str(ROOT / "tests/ros2_system.py"), str(domain), str(path)],
                stdin=subprocess.PIPE, stdout=subprocess.PIPE, env=env, text=True))
        try:
            for child in children:
                assert child.stdout is not None and child.stdout.readline().strip() == "ready"
            print(f"system of {participants * nodes} nodes, "
                  f"{participants * nodes * endpoints} endpoints in {participants} processes "
                  f"up in {time.monotonic() - started:.1f} s")
            for seconds in (0.5, 1.0, 3.0):
                began = time.monotonic()
                live = capture_ros2(domain, seconds)
                spent = time.monotonic() - began
                ends = sum(len(t["endpoints"]) for t in live["topics"])
                owned = ends - live["unowned_endpoints"]
                print(f"listening {seconds:.1f} s: {len(live['nodes'])}/{participants * nodes} "
                      f"nodes, {ends}/{participants * nodes * endpoints} endpoints "
                      f"({owned} with their node), {spent:.2f} s wall")
        finally:
            for child in children:
                assert child.stdin is not None
                child.stdin.close()
            for child in children:
                child.wait(timeout=60)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
