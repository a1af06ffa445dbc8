"""Give a configuration's node instances without source their interface models.

A launch file starts ``amcl/amcl``; package ``amcl`` is installed (found through
``ROS_PACKAGE_PATH`` / ``AMENT_PREFIX_PATH`` with no source) or not on this machine at
all. Its node then takes the interface model of the configuration's distribution, and
is used by the graph exactly like an extracted node: its completeness is ``model`` (or
``partial`` when the model says calls may be missing), ``Node.model`` names the model
and its version, and every link made from it has ``origin: "model"``.

The distribution is the project file's ``distro:``, else ``ROS_DISTRO`` in the
configuration's environment when it is of the ROS of its launch files, else guessed from
its launch files (ROS 1: noetic, ROS 2: jazzy); humble and iron take jazzy's model of a
package they have none of (models for them are made only where their packages differ:
humble's ship for 50 packages, iron's for none). Another distribution of a known ROS
(melodic, kinetic; foxy, kilted, rolling) takes the model of the nearest release of its
ROS that has one (noetic's for a ROS 1 one), as evidence of what its node does, not of
what it lacks: such a node is ``partial`` (its release may read or name what that
model's does not), so checks that claim something absent do not decide on it. A
``MODEL_DISTRO`` diagnostic says which, and ``MODEL_USED`` which model each node took
(its label starts with the distribution it is for), and under which name when the launch
file starts it by another name its releases install (``Node.aliases``).
"""

from __future__ import annotations

import copy
from collections.abc import Collection, Mapping
from dataclasses import replace

from .. import diagnostics as diag
from ..diagnostics import Diagnostic
from ..graph.build import is_container, node_key, nodelet_plugin
from ..launch.model import LaunchModel
from ..model.location import Location
from ..model.source import Node, Package
from ..plugins.attach import class_packages, plugin_types
from ..workspace import Workspace
from .commands import command_node
from .format import InterfaceModel
from .library import Library

DEFAULT_DISTRO = {1: "noetic", 2: "jazzy"}
# a distribution whose models are made only where its packages differ from another's
FALLBACK = {"humble": "jazzy", "iron": "jazzy"}
# each ROS's distributions, oldest first (the names ROS_DISTRO takes)
RELEASES = (
    ("boxturtle", "cturtle", "diamondback", "electric", "fuerte", "groovy", "hydro",
     "indigo", "jade", "kinetic", "lunar", "melodic", "noetic"),
    ("ardent", "bouncy", "crystal", "dashing", "eloquent", "foxy", "galactic", "humble",
     "iron", "jazzy", "kilted", "rolling"),
)


def stand_ins(distro: str) -> tuple[str, ...]:
    """The other distributions of ``distro``'s ROS whose models may stand for its own,
    nearest release first (the newer of two as near): none for a name of no ROS."""
    for releases in RELEASES:
        if distro in releases:
            at = releases.index(distro)
            return tuple(sorted((r for r in releases if r != distro),
                                key=lambda r: (abs(releases.index(r) - at),
                                               releases.index(r) < at)))
    return ()


def choose_distro(setting: str | None, environment: Mapping[str, str],
                  launch: LaunchModel, guessed: tuple[str, str] | None = None
                  ) -> tuple[str, str]:
    """The distribution whose models a configuration uses, and why that one: the
    project file's, the environment's when it is one of the ROS of the launch files (or
    of no ROS known), for ROS 2 launch files the one the workspace's own files name
    (``guessed``: ``distro_guess``), else the default of their ROS."""
    if setting:
        return setting, "the project file's 'distro'"
    version = 2 if any(d.ros_version == 2 for d in launch.nodes) else 1
    environment_distro = environment.get("ROS_DISTRO")
    other = ""
    if environment_distro:
        ros = ros_of(environment_distro)
        if ros is None or ros == version:
            return environment_distro, "ROS_DISTRO in the configuration's environment"
        # a ROS 2 distribution's environment runs no roslaunch, a ROS 1 one no ros2
        # launch: the launch files say which ROS their nodes are of (a tree in the middle
        # of its port keeps ROS 1 launch files beside the ROS 2 ones)
        other = (f"; ROS_DISTRO {environment_distro} in the configuration's environment "
                 f"is a ROS {ros} distribution")
    if version == 2 and guessed is not None and not other:
        return guessed
    return DEFAULT_DISTRO[version], f"guessed: its launch files are ROS {version}{other}"


def ros_of(distro: str) -> int | None:
    """1 or 2: the ROS ``distro`` is a distribution of (``RELEASES``), None for a name
    of neither."""
    return next((n for n, releases in enumerate(RELEASES, 1) if distro in releases), None)


class Attacher:
    """Interface models for the configurations of one analysis; each modelled node is
    made once and listed in ``packages`` (so the JSON model shows it)."""

    def __init__(self, library: Library, distro: str | None,
                 packages: list[Package], guessed: tuple[str, str] | None = None) -> None:
        self.library = library
        self.distro = distro
        self.guessed = guessed  # the ROS 2 distribution the workspace's files name
        self.packages = packages
        self._made: dict[tuple[str, str, str, bool], Node] = {}

    def nodes_for(self, launch: LaunchModel, workspace: Workspace, nodes: Mapping[str, Node],
                  environment: Mapping[str, str], found: list[Diagnostic]
                  ) -> dict[str, Node]:
        """``nodes`` plus a modelled node for each launched node type that no workspace
        package provides; problems and choices go to ``found``."""
        result = dict(nodes)
        chosen: tuple[str, str] | None = None
        for decl in launch.nodes:
            key = node_key(decl, result)
            package = key.partition("/")[0]
            if (key in result or package in workspace.packages or command_node(decl)
                    or "/" not in key  # a nodelet by a name no package is known to export
                    or (nodelet_plugin(decl) is None and is_container(decl))):
                continue
            if chosen is None:
                chosen = choose_distro(self.distro, environment, launch, self.guessed)
                found.append(diag.make("MODEL_DISTRO", decl.location, distro=chosen[0],
                                       why=chosen[1] + self._standing(chosen[0])))
            plugin = nodelet_plugin(decl)
            if plugin is not None and self._find(package, chosen[0]) is None:
                # a lookup name whose first part is not the exporting package
                other = next((p for p in class_packages(plugin)[1:] if p not in
                              workspace.packages and self._find(p, chosen[0])), None)
                if other is not None:
                    package, key = other, f"{other}/{plugin}"
            model = self._find(package, chosen[0])
            if model is None:
                continue
            executable = key.partition("/")[2]
            node = self._node(model, executable, chosen[0])
            if node is None:
                found.append(diag.make("MODEL_NODE_MISSING", decl.location, node=key,
                                       model=model.label,
                                       nodes=", ".join(n.executable for n in model.nodes)
                                       or "none"))
                continue
            result[key] = node
            where = workspace.find(package)
            label = model.label if node.executable == executable else (
                f"{model.label} (its node {node.executable}, which releases also install "
                f"as {executable})")
            found.append(diag.make(
                "MODEL_USED", decl.location, node=key, model=label,
                where=f"installed at {where} without source" if where else "not found"))
        found.extend(self.library.diagnostics)
        self.library.diagnostics.clear()
        return result

    def plugin_models(self, launch: LaunchModel, environment: Mapping[str, str]
                      ) -> PluginFinder:
        """For plugin attachment (``plugins.attach``): a plugin class of a package without
        source to its node in that package's model (kind ``plugin``, by lookup name or
        C++ type; or any node by ``pkg/exec``, for the nodes hosts make), for the
        configuration's distribution."""
        distro = choose_distro(self.distro, environment, launch, self.guessed)[0]
        return PluginFinder(self, distro)

    def _find(self, package: str, distro: str) -> InterfaceModel | None:
        """The package's model for ``distro``, else for the distribution whose models
        stand for it (``FALLBACK``: models are made for humble only where it differs
        from jazzy), else for the nearest release of its ROS that has one
        (``stand_ins``); the model's label names the distribution it is for."""
        fallback = (FALLBACK[distro],) if distro in FALLBACK else ()
        for candidate in (distro, *fallback, *stand_ins(distro)):
            model = self.library.find(package, candidate)
            if model is not None:
                return model
        return None

    def _standing(self, distro: str) -> str:
        """What the ``MODEL_DISTRO`` note adds on the models ``distro`` takes when it has
        none of a package: the distributions with models that stand for it."""
        if distro in FALLBACK:
            return f"; {FALLBACK[distro]}'s stand for a package it has none of"
        if not any(distro in releases for releases in RELEASES):
            return "; no ROS distribution of that name is known: no interface model is used"
        having = self.library.distributions()
        others = [d for d in stand_ins(distro) if d in having]
        if distro in having or not others:
            return ""
        names = " else ".join(d + "'s" for d in others)
        return f"; {distro} has none here: {names} stand for it, each node that takes one partial"

    def _node(self, model: InterfaceModel, executable: str, distro: str) -> Node | None:
        """The node of ``model`` run as ``executable`` in a configuration of ``distro``:
        ``partial`` when the model is another release's that does not stand for it
        whole (``FALLBACK`` does)."""
        source = model.node(executable)
        if source is None:
            return None
        other = model.distro not in (None, distro, FALLBACK.get(distro))
        key = (model.distro or "", model.package, source.executable, other)
        if key in self._made:
            return self._made[key]
        node = copy.deepcopy(source)
        node.model = model.label
        if node.completeness == "complete" and not other:
            node.completeness = "model"
        elif node.completeness in ("complete", "partial"):
            node.completeness_reasons = [f"interface model {model.label}: {r}"
                                         for r in node.completeness_reasons]
            if other:
                node.completeness = "partial"
                node.completeness_reasons.append(
                    f"interface model {model.label} is {model.distro}'s, standing for "
                    f"another release that has none of {model.package} here: what that "
                    f"release reads or names may differ")
        node.calls = [replace(c, origin="model") if c.origin != "action" else c
                      for c in node.calls]
        node.location = Location(file=model.path) if model.path else node.location
        self._made[key] = node
        owner = next((p for p in self.packages if p.name == model.package
                      and not p.path), None)
        if owner is None:
            owner = Package(model.package, "", version=model.version)
            self.packages.append(owner)
        owner.nodes.append(node)
        return node


class PluginFinder:
    """A plugin class of a package without source to its node in that package's model
    (``Attacher.plugin_models``), and a package's model itself (``package``: a tree
    host's BT libraries and default trees, ``plugins.behavior_trees``), for one
    distribution."""

    def __init__(self, attacher: Attacher, distro: str) -> None:
        self.attacher = attacher
        self.distro = distro

    def __call__(self, cls: str) -> Node | None:
        for package in class_packages(cls):
            model = self.attacher._find(package, self.distro)
            source = None if model is None else next(
                (n for n in model.nodes if n.name == cls or (n.kind == "plugin" and (
                    cls == n.executable or cls in plugin_types(n)))), None)
            if model is not None and source is not None:
                return self.attacher._node(model, source.executable, self.distro)
        return None

    def package(self, name: str) -> InterfaceModel | None:
        return self.attacher._find(name, self.distro)

    def exported(self, package: str, bases: Collection[str]) -> list[Node] | None:
        """The plugin classes of ``package``'s model whose base is one of ``bases``, each
        as hosts take it; None when there is no model of the package."""
        model = self.attacher._find(package, self.distro)
        if model is None:
            return None
        found = (self.attacher._node(model, n.executable, self.distro) for n in model.nodes
                 if n.kind == "plugin" and n.plugin_base in bases)
        return [n for n in found if n is not None]
