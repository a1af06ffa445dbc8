"""Python extractor: is the work linear in the size of a node's source?

Writes a generated rospy node at two sizes (10x apart) into a temporary workspace and
prints the ratio of their extraction times (about 10 when linear), plus calls per
second. Run: .venv/bin/python bench/python_extract.py
"""

from __future__ import annotations

import os
import tempfile
import time

from haros_arch.extract.python import extract_python
from haros_arch.workspace import scan

PACKAGE = ('<?xml version="1.0"?><package format="2"><name>gen</name><version>0.0.0</version>'
           '<description>d</description><maintainer email="a@b.c">m</maintainer>'
           '<license>MIT</license></package>')


def node(functions: int) -> str:
    parts = ["import rospy\nfrom std_msgs.msg import String\nPREFIX = 'robot'\n"]
    for i in range(functions):
        parts.append(
            f"def setup_{i}(name):\n"
            f"    if rospy.get_param('~enable_{i}', True):\n"
            f"        rospy.Publisher(PREFIX + '/' + name, String, queue_size={i % 10 + 1})\n"
            f"    rospy.Subscriber(f'{{PREFIX}}/in_{i}', String, None)\n"
            f"setup_{i}('out_{i}')\n")
    return "".join(parts)


def measure(root: str, functions: int) -> tuple[float, int]:
    path = os.path.join(root, "gen", "scripts", f"node_{functions}.py")
    with open(path, "w") as handle:
        handle.write(node(functions))
    ws = scan([root])
    start = time.perf_counter()
    result = extract_python([path], ws, package="gen")
    return time.perf_counter() - start, len(result.calls)


def main() -> None:
    with tempfile.TemporaryDirectory() as root:
        os.makedirs(os.path.join(root, "gen", "scripts"))
        with open(os.path.join(root, "gen", "package.xml"), "w") as handle:
            handle.write(PACKAGE)
        small, small_calls = measure(root, 200)
        large, large_calls = measure(root, 2000)
    print(f"small: {small_calls} calls in {small:.3f}s; large: {large_calls} calls in {large:.3f}s")
    print(f"time ratio large/small: {large / small:.1f} (10x the code; ~10 means linear)")
    print(f"calls per second (large): {large_calls / large:.0f}")


if __name__ == "__main__":
    main()
