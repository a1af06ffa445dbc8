"""Fidelity of ``capture --bag`` on real recorded bags, against independent readers.

- ROS 1 ``.bag``: Debian's ``rosbag`` (python3-rosbag, run with the system Python) lists
  each connection's topic, type and ``callerid``; we must give the same topics, types
  (``pkg/Name``) and publishers.
- ROS 2 bag folders: the ``metadata.yaml`` read here with PyYAML, the QoS decoded with
  rmw's enum values (``rmw/types.h``: history 1 keep_last / 2 keep_all, reliability
  1 reliable / 2 best_effort, durability 1 transient_local / 2 volatile, liveliness
  1 automatic / 3 manual_by_topic; newer bags write the words); we must give the same
  topics, types and, per offered profile, the same reliability, durability, history and
  liveliness; a recorded service-event topic (``/x/_service_event``, Jazzy's service
  introspection) must be service ``/x`` of its type.

Prints one line per bag (agreeing facts / facts) and the totals. Run:

    .venv/bin/python bench/live_bags.py BAG_OR_FOLDER...  (folders are searched for bags)
"""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path
from typing import Any

import yaml

from haros_arch.live import CaptureError, capture_bag

SYSTEM_PYTHON = "/usr/bin/python3"
ROSBAG_LIST = """
import json, sys, rosbag
with rosbag.Bag(sys.argv[1]) as bag:
    rows = sorted({(c.topic, c.datatype, c.header.get('callerid', b'').decode() or None)
                   for c in bag._connections.values()}, key=str)
print(json.dumps(rows))
"""
WORDS = {
    "history": {1: "keep_last", 2: "keep_all"},
    "reliability": {1: "reliable", 2: "best_effort"},
    "durability": {1: "transient_local", 2: "volatile"},
    "liveliness": {1: "automatic", 3: "manual_by_topic"},
}


def ros1_facts(path: Path) -> set[tuple[Any, ...]]:
    out = subprocess.run([SYSTEM_PYTHON, "-c", ROSBAG_LIST, str(path)], capture_output=True,
                         text=True, check=True, timeout=120).stdout
    facts: set[tuple[Any, ...]] = set()
    for topic, datatype, callerid in json.loads(out):
        facts |= {("topic", topic), ("type", topic, datatype)}
        if callerid:
            facts.add(("publisher", topic, callerid))
    return facts


def ros1_ours(live: dict[str, Any]) -> set[tuple[Any, ...]]:
    facts: set[tuple[Any, ...]] = set()
    for topic in live["topics"]:
        facts.add(("topic", topic["name"]))
        facts |= {("type", topic["name"], t) for t in topic["types"]}
        facts |= {("publisher", topic["name"], n) for n in topic["publishers"]}
    return facts


def _word(policy: str, value: Any) -> str | None:
    if isinstance(value, str):
        word = value.lower()
        return None if word in ("system_default", "unknown", "best_available") else word
    return WORDS[policy].get(value)


def ros2_facts(folder: Path) -> set[tuple[Any, ...]]:
    meta = yaml.safe_load((folder / "metadata.yaml").read_text())["rosbag2_bagfile_information"]
    facts: set[tuple[Any, ...]] = set()
    for entry in meta["topics_with_message_count"]:
        topic = entry["topic_metadata"]
        name = topic["name"]
        if name.endswith("/_service_event") and topic["type"].endswith("_Event"):
            # service introspection: the topic says that the service exists
            service = name[:-len("/_service_event")]
            facts |= {("service", service), ("type", service, topic["type"][:-len("_Event")])}
            continue
        facts |= {("topic", name), ("type", name, topic["type"])}
        profiles = topic.get("offered_qos_profiles") or []
        if isinstance(profiles, str):
            profiles = yaml.safe_load(profiles) or []
        for profile in profiles:
            for policy in WORDS:
                word = _word(policy, profile.get(policy))
                if word:
                    facts.add(("qos", name, policy, word))
    return facts


def ros2_ours(live: dict[str, Any]) -> set[tuple[Any, ...]]:
    facts: set[tuple[Any, ...]] = set()
    for topic in live["topics"]:
        facts.add(("topic", topic["name"]))
        facts |= {("type", topic["name"], t) for t in topic["types"]}
        for end in topic.get("endpoints") or ():
            for policy in WORDS:
                if (end.get("qos") or {}).get(policy):
                    facts.add(("qos", topic["name"], policy, end["qos"][policy]))
    for service in live["services"]:
        facts.add(("service", service["name"]))
        facts |= {("type", service["name"], t) for t in service["types"]}
    return facts


def bags(paths: list[str]) -> list[Path]:
    found: list[Path] = []
    for given in map(Path, paths):
        if given.is_file() and given.suffix == ".bag":
            found.append(given)
        elif given.is_dir():
            found += sorted(given.rglob("*.bag"))
            found += sorted(p.parent for p in given.rglob("metadata.yaml")
                            if any(p.parent.glob("*.db3")) or any(p.parent.glob("*.mcap")))
    return found


def main(paths: list[str]) -> int:
    agree = total = failed = 0
    for bag in bags(paths):
        try:
            live = capture_bag(str(bag))
        except CaptureError as error:
            print(f"{bag}: capture failed: {error}")
            failed += 1
            continue
        if bag.suffix == ".bag":
            theirs, ours = ros1_facts(bag), ros1_ours(live)
        else:
            theirs, ours = ros2_facts(bag), ros2_ours(live)
        agree += len(theirs & ours)
        total += len(theirs | ours)
        note = "" if theirs == ours else (f"  only theirs {sorted(theirs - ours)[:3]}"
                                          f"  only ours {sorted(ours - theirs)[:3]}")
        print(f"{bag}: {len(theirs & ours)}/{len(theirs | ours)}{note}")
    print(f"total: {agree}/{total} facts agree"
          + (f" ({100 * agree / total:.1f}%)" if total else "") + f"; {failed} failed")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
