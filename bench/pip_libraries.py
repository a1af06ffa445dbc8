"""Write ``haros_arch/extract/python/pip_libraries.yaml``: the import names of the Python
libraries that rosdep installs from PyPI, and the names of its Python keys, less the
names of released ROS packages.

    python bench/pip_libraries.py ROSDISTRO_GIT_DIR COMMIT \
        > haros_arch/extract/python/pip_libraries.yaml

ROSDISTRO_GIT_DIR is a clone (or bare mirror) of github:ros/rosdistro. Each ``pip:`` rule
of ``rosdep/python.yaml`` names PyPI distributions; a package.xml often names such a
library by its import name instead of its rosdep key (``<depend>dt_apriltags</depend>``,
the key being ``python-dt-apriltags-pip``). The import name is taken as the
distribution's name normalised as pip and Python do (``-`` and ``.`` to ``_``, lower
case, extras and version pins dropped). A name that some distribution of the same
commit releases as a ROS package (``depthai``, ``canopen``) is left out: that name may
be the ROS package's. A key ``python-X`` / ``python3-X`` (``-pip`` dropped) of the same
file names a Python library, which the system's packages install (``python3-requests``,
``python3-smbus``, ``python3-zmq``): its ``X``, normalised so, is taken as its import name
too (a name that is not one, ``opencv``, matches no module and changes nothing), unless
the key is the interpreter's own on some platform (``python3-dev``: ``_key_names``). A ROS 1
node's call into a module no list knows makes the node partial (PY_MODULE_UNSEEN), so
these libraries must be known as such.
"""

from __future__ import annotations

import re
import subprocess
import sys
from typing import Any

import yaml

# Python libraries of the rules that talk to ROS themselves, left out (a node that builds
# one of their classes may communicate through it): roslibpy (topics and services through
# rosbridge), jupyros (rospy publishers and subscribers behind notebook widgets), Isaac
# Sim's ROS bridges, pyros_setup (sets up a ROS environment for a program)
TALK_TO_ROS = frozenset({"roslibpy", "jupyros", "isaacsim_ros1", "isaacsim_ros2",
                         "isaacsim_ros", "pyros_setup"})
# the distributions whose released packages are left out (ROS 1 and ROS 2, old and new)
DISTROS = ("indigo", "kinetic", "lunar", "melodic", "noetic", "dashing", "eloquent",
           "foxy", "galactic", "humble", "iron", "jazzy", "kilted", "rolling")


def _show(git_dir: str, commit: str, path: str) -> str:
    done = subprocess.run(["git", "--git-dir", git_dir, "show", f"{commit}:{path}"],
                          capture_output=True, text=True, check=False)
    return done.stdout


def _pip_names(rules: Any) -> set[str]:
    """Every PyPI distribution named under a ``pip`` key, at any depth."""
    found: set[str] = set()
    if isinstance(rules, dict):
        for key, value in rules.items():
            if key == "pip":
                items = value.get("packages", []) if isinstance(value, dict) else value
                found.update(str(item) for item in items or ())
            else:
                found |= _pip_names(value)
    elif isinstance(rules, list):
        for value in rules:
            found |= _pip_names(value)
    return found


# a system package that is the Python interpreter itself (Arch's, Fedora's, NixOS's
# ``python`` / ``python3``, Gentoo's ``dev-lang/python`` with any version or USE flag)
_INTERPRETER = re.compile(r"python[23]?|=?dev-lang/python\b.*")


def _system_packages(rules: Any) -> set[str]:
    """The system package names of a key's rules, at any depth (not those of ``pip``)."""
    found: set[str] = set()
    if isinstance(rules, dict):
        for key, value in rules.items():
            if key != "pip":
                found |= _system_packages(value)
    elif isinstance(rules, list):
        for value in rules:
            found |= {value} if isinstance(value, str) else _system_packages(value)
    return found


def _key_names(rules: Any) -> set[str]:
    """The library each Python key names: ``python3-X`` / ``python-X``, less ``-pip``;
    not a key that some platform installs as the interpreter itself
    (``_INTERPRETER``): what it gives is part of Python (its headers, ``venv``, the
    standard library's modules and Tk binding), and its ``X`` is a Debian package's
    name, no module (``python3-dev``, ``python3-interpreter``, ``python-support``,
    ``python3-tk``: tkinter). Its ``pip`` rules still count (``importlib-metadata``)."""
    found: set[str] = set()
    for key, value in rules.items() if isinstance(rules, dict) else ():
        matched = re.fullmatch(r"python3?-(.+?)(-pip)?", str(key))
        if matched and not any(_INTERPRETER.fullmatch(name)
                               for name in _system_packages(value)):
            found.add(matched.group(1))
    return found


def _import_name(distribution: str) -> str:
    bare = re.split(r"[\[<>=!~; ]", distribution.strip(), maxsplit=1)[0]
    return re.sub(r"[-.]+", "_", bare).lower()


def main(git_dir: str, commit: str) -> None:
    rules = yaml.safe_load(_show(git_dir, commit, "rosdep/python.yaml"))
    names = {_import_name(name) for name in _pip_names(rules) | _key_names(rules)} - {""}
    released: set[str] = set()
    for distro in DISTROS:
        data = yaml.safe_load(_show(git_dir, commit, f"{distro}/distribution.yaml") or "{}")
        for repository, entry in (data.get("repositories") or {}).items():
            released.add(repository)
            release = entry.get("release") or {}
            released.update(release.get("packages") or ())
    kept = sorted(names - released - TALK_TO_ROS)
    print("# The import names of the Python libraries rosdep installs from PyPI (every pip")
    print("# rule of rosdep/python.yaml of github:ros/rosdistro at commit")
    print(f"# {commit}, each distribution's name normalised: '-' and '.' to")
    print("# '_', lower case) and of its Python keys (python3-X, python-X: X so normalised),")
    print("# less the names of the ROS packages the distributions of the")
    print("# same commit release (DISTROS), and of those that talk to ROS themselves")
    print("# (roslibpy, jupyros, ...: TALK_TO_ROS). Written by")
    print("# bench/pip_libraries.py; read by haros_arch/extract/python (NOT_CLIENTS): a")
    print("# package.xml dependency of one of these names, not in the workspace, is a Python")
    print("# library, not a ROS package whose code is not read; a module of one of these")
    print("# names is a library a ROS 1 node may call (no PY_MODULE_UNSEEN).")
    print(yaml.safe_dump({"libraries": kept}, default_flow_style=False, sort_keys=False),
          end="")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
