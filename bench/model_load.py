"""How loading a saved model grows with its links: 10k, 100k and 300k links, half of them
naming resources the document does not list and a tenth with '?' names (each its own
resource, as extract writes them). Prints seconds per size and the ratio to linear.

    PYTHONPATH=. .venv/bin/python bench/model_load.py [--sizes 10000,100000,300000]
"""

from __future__ import annotations

import argparse
import time

from haros_arch.model.load import from_data


def document(links: int) -> dict:
    nodes = [{"name": f"/n{i}", "node": None} for i in range(max(1, links // 100))]
    listed = [{"name": f"/t{i}", "id": f"topic:/t{i}", "types": ["std_msgs/String"]}
              for i in range(links // 4)]
    items = []
    for i in range(links):
        node = f"/n{i % len(nodes)}"
        if i % 10 == 0:
            name = "/?"
        elif i % 2 == 0:
            name = f"/t{i % max(1, links // 4)}"
        else:
            name = f"/unlisted{i}"
        items.append({"kind": "publish" if i % 3 else "subscribe", "node": node,
                      "name": name, "type": "std_msgs/String"})
    return {"schema": "haros-arch/1", "project": "bench",
            "configurations": [{"name": "c", "nodes": nodes, "topics": listed,
                                "links": items}]}


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--sizes", default="10000,100000,300000")
    sizes = [int(s) for s in parser.parse_args().sizes.split(",")]
    first: float | None = None
    for size in sizes:
        data = document(size)
        started, cpu = time.perf_counter(), time.process_time()
        model = from_data(data)
        took = time.perf_counter() - started
        cpu = time.process_time() - cpu
        config = model.configurations[0]
        per = took / size
        first = first or per
        print(f"{size:>8} links: {took:7.2f} s load ({cpu:.2f} s CPU: on a busy machine "
              f"the wall time waits), {len(config.topics):>7} topics, "
              f"per link {per * 1e6:6.1f} us ({per / first:4.2f}x the smallest)")


if __name__ == "__main__":
    main()
