"""Our query engine against pyflwor-ext on the same queries and models, in one run.

    .venv/bin/python bench/query_speed.py [--skip-pyflwor-above N]

Models have 100, 1,000 and 10,000 links (half publishers, half subscribers, one topic
per two publisher/subscriber pairs, one link in ten of another type). Prints seconds
and the ratio pyflwor / ours for each query and size. pyflwor-ext needs
``collections.MutableSet`` on Python >= 3.10, which is patched in here. Then the time of
each shipped catalogue query on an Autoware-size configuration (bench/catalogue_speed.py).
"""

from __future__ import annotations

import argparse
import collections
import collections.abc
import sys
import time

import checkout  # bench/checkout.py: says which haros_arch is measured

from haros_arch import query
from haros_arch.model.load import from_data

QUERIES = {
    "type mismatch (paper Fig. 5)":
        "for p in <configs/nodes/publishers>, s in <configs/nodes/subscribers> "
        "where p.topic_name == s.topic_name and p.type != s.type return p, s",
    "HAROS type_check_topics":
        "for p in <configs/nodes/publishers | configs/nodes/subscribers>, "
        "s in <configs/nodes/publishers | configs/nodes/subscribers> "
        "where p.topic_name == s.topic_name and p.type != s.type return p, s",
    "multiple publishers (path)": "configs/topics[len(self.publishers) > 1]",
}


def model(links: int):  # type: ignore[no-untyped-def]
    topics = max(1, links // 4)
    return from_data({"configurations": [{"name": "c", "links": [
        {"kind": "publish" if i % 2 == 0 else "subscribe", "node": f"/n{i % 97}",
         "name": f"/t{(i // 2) % topics}",
         "type": "std_msgs/String" if i % 10 else "std_msgs/Int32"}
        for i in range(links)]}]})


def timed(run) -> tuple[float, int]:  # type: ignore[no-untyped-def]
    start = time.perf_counter()
    result = run()
    return time.perf_counter() - start, len(result)


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--skip-pyflwor-above", type=int, default=10_000,
                        help="run pyflwor only on models up to this many links")
    parser.add_argument("--pyflwor-max-pairs", type=int, default=30_000_000,
                        help="skip pyflwor where its nested loops would visit more pairs")
    args = parser.parse_args()
    if not hasattr(collections, "MutableSet"):
        collections.MutableSet = collections.abc.MutableSet  # type: ignore[attr-defined]
    try:
        import pyflwor  # type: ignore[import-not-found]
    except ImportError:
        pyflwor = None
        print("pyflwor-ext is not installed: only our times are shown")
    print(f"{'query':32} {'links':>6} {'ours (s)':>10} {'pyflwor (s)':>12} {'ratio':>8}")
    for name, text in QUERIES.items():
        compiled = query.compile(text)
        for links in (100, 1_000, 10_000):
            # evaluation only: the model is built outside the timed part
            m = model(links)
            ours, n_ours = timed(lambda m=m, q=compiled: q.run(query.model_scope(m)))
            theirs_text, ratio = "-", "-"
            pairs = 0 if not text.startswith("for") else \
                links * links * (1 if "Fig. 5" in name else 4) // 4
            if pyflwor is not None and pairs > args.pyflwor_max_pairs:
                theirs_text, ratio = "skipped", f"({pairs:,} pairs)"
            elif pyflwor is not None and links <= args.skip_pyflwor_above:
                fresh = model(links)  # pyflwor writes attributes onto what it walks
                theirs, n_theirs = timed(lambda f=fresh, t=text: pyflwor.execute(
                    t, {"configs": f.configs, "len": len}))
                theirs_text, ratio = f"{theirs:.4f}", f"{theirs / ours:.0f}x"
                if n_theirs != n_ours:
                    ratio += f" (results differ: {n_ours} vs {n_theirs})"
            print(f"{name:32} {links:>6} {ours:>10.4f} {theirs_text:>12} {ratio:>8}",
                  flush=True)
    print()
    sys.argv = sys.argv[:1]
    from catalogue_speed import main as catalogue

    catalogue()


if __name__ == "__main__":
    checkout.announce()
    main()
