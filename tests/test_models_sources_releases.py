"""Each pin of the shipped models' list says whether it is the release its distribution ships.

A model of a branch's later commit reads names the released node does not (noetic usb_cam's
develop, slam_toolbox's ``~reset``, teleop_twist_keyboard's ``~stamped``), and a model of an
earlier one misses what the release added (rosbridge 2.1.0 before ``default_call_service_timeout``).
So each entry of ``haros_arch/models/sources.yaml`` pins either the commit of the release tag
of the version the distribution's ``distribution.yaml`` releases, said on its ``commit:`` line
as ``# release VERSION``, or says why not: ``# not the release: REASON``. A pin said to be a
release is the tree of that version: its models carry the version its package.xml gives."""

from __future__ import annotations

import json
import os
import re

import yaml

from haros_arch.models import metapackages

HERE = os.path.dirname(metapackages.TABLE)
SOURCES = os.path.join(HERE, "sources.yaml")
DATA = os.path.join(HERE, "data")

RELEASE = re.compile(r"#\s*release (\S+)")
NOT_RELEASE = re.compile(r"#\s*not the release: \S")


def _commit_lines() -> list[tuple[int, str]]:
    """The ``commit:`` line of each entry (not of its ``with`` trees), with its number."""
    with open(SOURCES, encoding="utf-8") as handle:
        lines = handle.read().splitlines()
    found = []
    for number, line in enumerate(lines, 1):
        if line.startswith("  commit:"):
            found.append((number, line))
    return found


def test_every_pin_says_whether_it_is_the_release() -> None:
    with open(SOURCES, encoding="utf-8") as handle:
        entries = yaml.safe_load(handle)
    lines = _commit_lines()
    assert len(lines) == len(entries)
    unsaid = [f"sources.yaml:{number}" for number, line in lines
              if not RELEASE.search(line) and not NOT_RELEASE.search(line)]
    assert unsaid == []


def test_a_pin_said_to_be_a_release_is_the_tree_of_that_version() -> None:
    with open(SOURCES, encoding="utf-8") as handle:
        entries = yaml.safe_load(handle)
    wrong = []
    for entry, (number, line) in zip(entries, _commit_lines(), strict=True):
        said = RELEASE.search(line)
        assert entry["commit"] in line
        if said is None or NOT_RELEASE.search(line):
            continue
        for package in entry["packages"]:
            path = os.path.join(DATA, entry["distro"], f"{package}.json")
            if not os.path.exists(path):
                continue
            with open(path, encoding="utf-8") as handle:
                model = json.load(handle)
            if model["source"]["commit"] != entry["commit"]:
                continue
            if model["version"] != said.group(1):
                wrong.append((number, package, model["version"], said.group(1)))
    assert wrong == []
