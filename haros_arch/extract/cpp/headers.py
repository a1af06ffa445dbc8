"""The include path of a parse: stand-in ROS headers, synthesised message headers and
empty stand-ins for headers that are nowhere to be found.

Before parsing, the ``#include`` lines of the sources (and, transitively, of the
workspace headers they include) are scanned with a regular expression. Each header is
resolved the way the preprocessor will, and:

- a message or service header (``pkg/Name.h`` whose package has ``msg/Name.msg`` or
  ``srv/Name.srv``, is a well-known message package, or is simply not found) is
  synthesised in a generated folder that comes first on the include path;
- in the default mode, ``ros/...`` and ``boost/...`` headers come from our stand-ins
  only, so the result does not depend on what is installed; one we have no stand-in for
  becomes an empty header; the C and C++ standard library is our own small stand-in
  (``standin/std``) and nothing of the system is searched (``-nostdinc``), so no compiler
  needs to be installed; the stand-ins are precompiled once per process (a PCH), which
  brings a translation unit down to a few milliseconds;
- any other header that is not found becomes an empty header and a
  ``CPP_INCLUDE_MISSING`` diagnostic, except ``<name>_export.h``, which CMake's
  generate_export_header writes at build time: it defines ``NAME_EXPORT`` and its
  siblings empty;
- the headers of ros2_control (``controller_interface/``, ``hardware_interface/``,
  ``semantic_components/``, ``joint_limits/``) and of PCL (``pcl/``, ``pcl_conversions/``,
  ``pcl_ros/``), which workspaces have installed rather than as sources, come from the
  stand-ins in ``standin/fallback`` only when the workspace does not have them
  (``FALLBACK``; a PCL header without a file there is the library's umbrella,
  ``FALLBACK_UMBRELLAS``): never in place of the package's real headers;
- a package's own headers win over the stand-ins: a unit of a package our stand-ins also
  provide (rclcpp_components, bondcpp, class_loader, ...) is parsed with the package's
  ``include`` folder first and without the precompiled stand-ins (whose classes its own
  headers define again); not a package whose API the extractor knows by its stand-ins
  (tf2_ros, image_transport, ...: the API tables name its classes); of such a package
  being extracted, a header with no stand-in file that defines none of the classes its
  stand-ins name is read from the package (``_own_extra``: image_transport's
  ``republish.hpp``, which declares the node class ``Republisher``).

The workspace's include folders (hundreds on Autoware) reach clang as one header map
(``header_map``), written before the first parse: an ``#include`` is one look-up in it,
not one failed ``stat`` per folder; the cache keys list the folders themselves.

With ``system_headers=True`` the stand-ins are left out and only headers that the system
lacks are synthesised, so the real ROS headers are used.
"""

from __future__ import annotations

import contextlib
import fcntl
import functools
import hashlib
import os
import re
import shutil
import tempfile
import threading
from collections.abc import Callable, Iterable, Iterator, Mapping, Sequence
from dataclasses import dataclass

from clang.cindex import TranslationUnitLoadError, TranslationUnitSaveError

from ... import cmake, processes, share
from ... import diagnostics as diag
from ...compile_commands import UnitFlags
from ...diagnostics import Diagnostic
from ...files import read_text, write_whole
from ...manifest import ros_version
from ...model.location import Location
from ...workspace import Workspace
from . import (
    api,
    build_macros,
    cmake_includes,
    header_map,
    interfaces,
    parameter_library,
    reconfigure,
    ros2_interfaces,
    toolchain,
    versions,
)

STANDIN = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "standin")
STD_STANDIN = os.path.join(STANDIN, "std")  # the C and C++ standard library stand-in
PRELUDE = os.path.join(STANDIN, "haros_prelude.h")  # what is precompiled
# stand-ins for the headers of packages a workspace usually has installed, not as sources
# (ros2_control's controller_interface, hardware_interface): read only where the workspace
# has no header by that name, so its real headers are never shadowed
FALLBACK = os.path.join(STANDIN, "fallback")
# a header of these libraries that FALLBACK has no file for stands in as the library's
# umbrella there (PCL's many headers: ``pcl/segmentation/extract_clusters.h``)
FALLBACK_UMBRELLAS = {"pcl/": "pcl/haros_pcl.h",
                      "pcl_conversions/": "pcl_conversions/pcl_conversions.h",
                      "pcl_ros/": "pcl_ros/haros_pcl_ros.h",
                      # the ROS package filters (its chains and filter bases)
                      "filters/": "filters/filter_chain.h",
                      # ROS 1 laser_proc (its publisher of multi-echo scans)
                      "laser_proc/": "laser_proc/LaserTransport.h",
                      # ROS 1 navigation's costmap and plugin interfaces, for the
                      # layers, planners and recoveries outside the navigation stack
                      "costmap_2d/": "costmap_2d/haros_costmap_2d.h",
                      "nav_core/": "nav_core/haros_nav_core.h",
                      # jsk_common's nodelet bases (jsk_recognition's nodelets)
                      "jsk_topic_tools/": "jsk_topic_tools/haros_jsk_topic_tools.h",
                      # rpg_vikit's parameter helpers (uzh-rpg's SVO)
                      "vikit/": "vikit/haros_vikit.h",
                      # PickNik's rosparam_shortcuts (its checked parameter reads)
                      "rosparam_shortcuts/": "rosparam_shortcuts/rosparam_shortcuts.h",
                      # navigation2's libraries, for its plugins outside navigation2
                      **{f"{p}/": f"{p}/haros_{p}.h" for p in (
                          "nav2_util", "nav2_ros_common", "nav2_core", "nav2_costmap_2d",
                          "nav2_behaviors")},
                      # Gazebo classic's plugin bases and SDFormat's Element, for the
                      # Gazebo plugins a workspace builds (ROS 2 gazebo_ros' node.hpp
                      # is a file of its own there: not every gazebo_ros header, which
                      # ROS 1's gazebo_ros has too)
                      "gazebo/": "gazebo/haros_gazebo.h", "sdf/": "sdf/haros_sdf.h",
                      # BehaviorTree.CPP, versions 4 and 3 (navigation2's behaviour trees)
                      "behaviortree_cpp/": "behaviortree_cpp/haros_behaviortree_cpp.h",
                      "behaviortree_cpp_v3/": "behaviortree_cpp/haros_behaviortree_cpp.h"}
# CXTranslationUnit_ForSerialization | Incomplete (a header, not a whole program)
_PCH_OPTIONS = 0x10 | 0x02
_DETAILED_RECORD = 0x01  # CXTranslationUnit_DetailedPreprocessingRecord
# a ``-std`` past C++17 (``c++20``, ``gnu++2a``, ``c++23``, ...)
_NEWER_STD = re.compile(r"-std=(?:c|gnu)\+\+(?:2\w)")
# a second folder of synthesised headers, for a header whose name is a folder of others
OVERFLOW = ".overflow"
HEADER_MAP = "workspace.hmap"  # the include folders as one header map (``header_map``)
# Prefixes only our stand-ins provide in the default mode; a header of one of these
# libraries we have no stand-in for includes the library's umbrella stand-in.
QT = "haros_qt.h"  # the Qt stand-in every Qt header includes
UMBRELLAS = {
    "rclcpp/": "rclcpp/rclcpp.hpp", "rclcpp_action/": "rclcpp_action/rclcpp_action.hpp",
    "rclcpp_lifecycle/": "rclcpp_lifecycle/lifecycle_node.hpp",
    "rclcpp_components/": "rclcpp_components/register_node_macro.hpp",
    "rmw/": "rmw/qos_profiles.h", "tf2/": "tf2_ros/buffer.h", "tf2_ros/": "tf2_ros/buffer.h",
    "rosidl_runtime_cpp/": "rosidl_runtime_cpp/traits.hpp",
    "rcl/": "rcl/haros_rcl.h", "rcutils/": "rcl/haros_rcl.h", "rcpputils/": "rcl/haros_rcl.h",
    "class_loader/": "class_loader/class_loader.hpp",
    "tf2_geometry_msgs/": "tf2_ros/buffer.h",
    "image_transport/": "image_transport/image_transport.h",
    "message_filters/": "message_filters/subscriber.h",
    "actionlib/": "actionlib/server/simple_action_server.h", "nodelet/": "nodelet/nodelet.h",
    "nodelet_topic_tools/": "nodelet_topic_tools/nodelet_lazy.h",
    "pluginlib/": "pluginlib/class_list_macros.hpp",
    "ament_index_cpp/": "ament_index_cpp/ament_index_cpp.hpp",
    "tf2_eigen/": "tf2_eigen/tf2_eigen.hpp",
    "dynamic_reconfigure/": "dynamic_reconfigure/server.h",
    "diagnostic_updater/": "diagnostic_updater/diagnostic_updater.h",
    "camera_info_manager/": "camera_info_manager/camera_info_manager.h",
    "bondcpp/": "bondcpp/bond.hpp",
    # roscpp's headers we have no file for (``ros/assert.h``, ``ros/advertise_options.h``,
    # ``ros/transport_hints.h``, ...): the API our ``ros/ros.h`` declares
    "ros/": "ros/ros.h",
    "xmlrpcpp/": "xmlrpcpp/XmlRpc.h",  # roscpp's XmlRpcValue, XmlRpcException
    # and its headers by their bare names, <XmlRpcValue.h>, <XmlRpc.h>: xmlrpcpp exports
    # its include/xmlrpcpp folder too (cob_bms_driver, cob_scan_unifier)
    "XmlRpc": "xmlrpcpp/XmlRpc.h",
    "realtime_tools/": "realtime_tools/realtime_publisher.h",
    "pal_statistics/": "pal_statistics/pal_statistics_macros.hpp",
    # test nodes (rostest, launch_testing): without it a TEST's body, and every ROS call
    # in it, is lost to the parse errors of its macros
    "gtest/": "gtest/gtest.h", "gmock/": "gtest/gtest.h",
    # libraries beside ROS that node classes use: minimal stand-ins keep them parsing
    "opencv2/": "opencv2/opencv.hpp", "opencv/": "opencv2/opencv.hpp",
    "gtk/": "gtk/gtk.h",  # around an OpenCV window (image_view's nodelets)
    "angles/": "angles/angles.h",
    "urdf/": "urdf/model.h", "urdf_model/": "urdf/model.h", "urdf_parser/": "urdf/model.h",
    "cv_bridge/": "cv_bridge/cv_bridge.h", "Eigen/": "Eigen/Dense", "eigen3/": "Eigen/Dense",
    "yaml-cpp/": "yaml-cpp/yaml.h", "gflags/": "gflags/gflags.h", "glog/": "glog/logging.h",
    "fmt/": "fmt/format.h",  # {fmt}: names formatted from a literal (``values.Scope``)
    # Boost.Asio's and Boost.System's headers: boost::system's error codes, which asio's
    # handlers take (the asio classes are declared permissively)
    "boost/asio/": "boost/asio.hpp", "boost/system/": "boost/system/error_code.hpp",
    "boost/filesystem/": "boost/filesystem.hpp",
    "boost/ptr_container/": "boost/ptr_container/ptr_vector.hpp",
    "boost/circular_buffer/": "boost/circular_buffer.hpp",
    "boost/heap/": "boost/heap/priority_queue.hpp",  # Boost.Heap, each heap alike
    "boost/optional/": "boost/optional.hpp",
    "boost/uuid/": "boost/uuid/uuid.hpp", "boost/type_index/": "boost/type_index.hpp",
    "boost/functional/hash/": "boost/functional/hash.hpp",
    "boost/container_hash/": "boost/functional/hash.hpp",
    "boost/program_options/": "boost/program_options.hpp",
    "boost/random/": "boost/random.hpp",  # Boost.Random, the engines of <random>
    "boost/accumulators/": "boost/accumulators/accumulators.hpp",  # sample statistics
    "boost/algorithm/string/": "boost/algorithm/string.hpp",
    **{f"Qt{m}/": QT for m in ("Core", "Gui", "Widgets", "Network", "Concurrent", "Test")},
}
SHADOWED = ("ros/", "boost/", "tf/", *UMBRELLAS)
_QT_HEADER = re.compile(r"Q[A-Z][A-Za-z]*(\.h)?|Qt[A-Z][A-Za-z]*")  # <QObject>, <QtGui>
_ROS2_HEADER = re.compile(r"([A-Za-z_]\w*)/(msg|srv|action)/([a-z0-9_]+)\.hpp")

_INCLUDE = re.compile(r'^[ \t]*#[ \t]*include[ \t]*([<"])([^>"\n]+)[>"]', re.MULTILINE)
_SERVICE_PART = re.compile(r"(\w+)(?:Request|Response)")
_MESSAGE_HEADER = re.compile(r"([A-Za-z_]\w*)/([A-Z]\w*)\.h")
# dynamic_reconfigure's generated header: ``<name>Config.h``, the name as the .cfg's
# ``gen.generate(PACKAGE, node, name)`` writes it, lowercase too
_CONFIG_HEADER = re.compile(r"([A-Za-z_]\w*)/([A-Za-z_]\w*Config)\.h")
# a header that is a message when the package defines one by that name (tf's tfMessage)
_DEFINED_HEADER = re.compile(r"([A-Za-z_]\w*)/([A-Za-z]\w*)\.h")
_NOT_FOUND = re.compile(r"^'([^']+)' file not found")


# the top names (packages, namespaces) whose headers our stand-ins give in place of any
# of the workspace (``SHADOWED``, a folder of ``standin/``; not ``standin/fallback``'s,
# which a workspace package's own headers win over): a package of them being modelled
# has its own code read against these, and its definitions of the API the rows model are
# its implementation (``visitor._implements_row``)
REPLACED = frozenset({p.rstrip("/") for p in SHADOWED} | {
    f for f in os.listdir(STANDIN) if os.path.isdir(os.path.join(STANDIN, f))}) - {
    "std", os.path.basename(FALLBACK)}
# the packages whose headers the stand-ins provide (rclcpp_components, bondcpp, ...) and
# whose own headers win when they are modelled; not those whose classes the API tables
# name (tf2_ros, image_transport, ...): their stand-ins are the API the extractor knows,
# and their own sources are modelled against them (a row that describes only our
# stand-in, rclcpp_components' ComponentManager, does not count)
_STANDIN_PACKAGES = frozenset({p.rstrip("/") for p in SHADOWED} | {
    f for f in os.listdir(STANDIN) if os.path.isdir(os.path.join(STANDIN, f))}) - {
    "std", os.path.basename(FALLBACK), *(
        key[0].split("::")[0] for table in (api.ROSCPP, api.LIBRARIES, api.RCLCPP,
                                            api.RCLCPP_LIBRARIES)
        for key, row in table.items() if not row.standin_only)}

# ``<name>_export.h`` from CMake's generate_export_header (not in the source tree): its
# macros, defined empty, as for a static build
_EXPORT_HEADER = re.compile(r"([A-Za-z_]\w*)_export\.hp?p?")
_EXPORT_MACROS = ("EXPORT", "NO_EXPORT", "DEPRECATED", "DEPRECATED_EXPORT",
                  "DEPRECATED_NO_EXPORT")

_ROS_PREFIXES = ("ros/", "boost/", "tf/", "rclcpp", "rmw/", "tf2", "image_transport/",
                 "message_filters/", "actionlib/", "nodelet/", "pluginlib/")
_LIBRARY_UMBRELLAS = frozenset({"opencv2/opencv.hpp", "cv_bridge/cv_bridge.h", "Eigen/Dense",
                                QT})
_LIBRARY_HEADERS = ("sensor_msgs/image_encodings.", "sensor_msgs/point_cloud2_iterator.",
                    "sensor_msgs/distortion_models.", "sensor_msgs/point_cloud_conversion.",
                    "sensor_msgs/fill_image.")


# a class or struct defined (not only declared): ``class VISIBILITY Name final : ...{``
_CLASS_DEFINITION = re.compile(
    r"\b(?:class|struct)\s+(?:[A-Z][A-Z0-9_]*\s+)*([A-Za-z_]\w*)\s*(?:final\s*)?[:{]")
# a class or struct the stand-ins name, declared or defined
_CLASS_NAMED = re.compile(r"\b(?:class|struct)\s+(?:[A-Z][A-Z0-9_]*\s+)*([A-Za-z_]\w*)\s*[:{;]")
_COMMENT = re.compile(r"//[^\n]*|/\*.*?\*/", re.DOTALL)


def _strip_comments(text: str) -> str:
    return _COMMENT.sub(" ", text)


_STANDIN_CLASSES: dict[str, frozenset[str]] = {}


def _standin_classes(package: str) -> frozenset[str]:
    """The classes and structs the stand-ins of ``package`` name: its stand-in files
    and the stand-ins its umbrella includes, transitively (``tf2/``'s umbrella is
    ``tf2_ros/buffer.h``)."""
    if package not in _STANDIN_CLASSES:
        paths = [os.path.join(folder, name)
                 for folder, _, files in os.walk(os.path.join(STANDIN, package))
                 for name in files]
        umbrella = UMBRELLAS.get(f"{package}/")
        if umbrella is not None:
            paths.append(os.path.join(STANDIN, umbrella))
        names: set[str] = set()
        seen: set[str] = set()
        while paths:
            path = paths.pop()
            if path in seen or not os.path.isfile(path):
                continue
            seen.add(path)
            with open(path, encoding="utf-8") as f:
                text = _strip_comments(f.read())
            names.update(m.group(1) for m in _CLASS_NAMED.finditer(text))
            paths += [os.path.join(STANDIN, m.group(2)) for m in _INCLUDE.finditer(text)]
        _STANDIN_CLASSES[package] = frozenset(names)
    return _STANDIN_CLASSES[package]


def _library_include_dirs(workspace: Workspace) -> list[str]:
    """``<package>/<folder>/include`` of every workspace package, sorted. Not those one
    level deeper (slam_toolbox's ``lib/karto_sdk/include``, a library the package
    builds with add_subdirectory): read for real, such a library's inline code is
    walked in every unit (slam_toolbox: 4-5x the cost per unit for the same calls);
    its headers are synthesised like those of a missing package until the walk visits
    only functions that can hold a call."""
    found = []
    for package in workspace.packages.values():
        if not package.root:
            continue
        for entry in _folders(package.root):
            if entry != "include" and os.path.isdir(os.path.join(package.root, entry, "include")):
                found.append(os.path.join(package.root, entry, "include"))
    return found


def _built_include_dirs(sources: Sequence[str], workspace: Workspace) -> list[str]:
    """The include folders the compile lines of ``sources`` get from their packages'
    CMake files as the interpreter reads them (``cmake.source_include_dirs``), in order:
    folders of a workspace package's own project (``cmake_includes.own_folder``) and
    folders of the workspace outside every package (``cmake_includes.shared_folder``)."""
    found: list[str] = []
    for source in dict.fromkeys(map(os.path.abspath, sources)):
        package = workspace.package_of(source)
        if package is None or not package.root:
            continue
        given = cmake.source_include_dirs(package, workspace).get(workspace.relpath(source), ())
        found += [folder for folder in given if folder not in found
                  and (cmake_includes.own_folder(folder, workspace)
                       or cmake_includes.shared_folder(folder, workspace))]
    return found


MAX_DEPENDED = 64  # packages whose exported include folders one extraction reads


def _depended_roots(roots: Iterable[str], workspace: Workspace) -> list[str]:
    """The roots of the workspace packages that the packages at ``roots`` build on
    (package.xml's ``depend`` / ``build_depend``), and those they build on in turn, in
    the order met; not ``roots`` themselves, at most ``MAX_DEPENDED``."""
    seen = set(roots)
    todo = [p for p in (workspace.package_of(root) for root in roots) if p is not None]
    found: list[str] = []
    while todo and len(found) < MAX_DEPENDED:
        for name in cmake.build_depends(todo.pop(0)):
            package = workspace.packages.get(name)
            if package is None or not package.root or package.root in seen:
                continue
            seen.add(package.root)
            found.append(package.root)
            todo.append(package)
    return found[:MAX_DEPENDED]


def _headers_beside_sources(workspace: Workspace) -> list[str]:
    """The roots of the packages that keep their headers beside their sources in a folder
    named as the package, included from the package root (cartographer_ros:
    ``cartographer_ros/node.h`` next to ``node.cc``, ``#include "cartographer_ros/node.h"``,
    the root being the include folder its CMakeLists gives with ``${PROJECT_SOURCE_DIR}``),
    sorted."""
    found = []
    for package in sorted(workspace.packages.values(), key=lambda p: p.name):
        if not package.root:
            continue
        try:
            entries = os.listdir(os.path.join(package.root, package.name))
        except OSError:
            continue
        if any(entry.endswith((".h", ".hh", ".hpp", ".hxx")) for entry in entries):
            found.append(package.root)
    return found


def _folders(path: str) -> list[str]:
    """The folders in ``path`` (no hidden ones, no symbolic links), sorted."""
    try:
        entries = sorted(os.listdir(path))
    except OSError:
        return []
    return [e for e in entries if not e.startswith(".") and not os.path.islink(
        os.path.join(path, e)) and os.path.isdir(os.path.join(path, e))]


_PACKAGE_NAME = re.compile(r"[A-Za-z0-9_]+")


def is_ros2_header(header: str) -> bool:
    return header.startswith("rclcpp") or _ROS2_HEADER.fullmatch(header) is not None


def is_ros1_header(header: str) -> bool:
    """roscpp's headers (``ros/ros.h``, ``ros/node_handle.h``, ...): ROS 2 has none."""
    return header.startswith("ros/")


@dataclass(frozen=True)
class Evidence:
    """What a file's includes (and the workspace headers they include) say of its ROS:
    a ROS 2 header included under no preprocessor condition (include guards aside), one
    included only under a condition, a ROS 1 header under none."""
    ros2_firm: bool = False
    ros2_conditional: bool = False
    ros1_firm: bool = False

    @property
    def ros2(self) -> bool:
        return self.ros2_firm or (self.ros2_conditional and not self.ros1_firm)

    def join(self, other: Evidence) -> Evidence:
        return Evidence(self.ros2_firm or other.ros2_firm,
                        self.ros2_conditional or other.ros2_conditional,
                        self.ros1_firm or other.ros1_firm)

    def conditional(self) -> Evidence:
        """As seen through an include made under a condition: nothing firm."""
        return Evidence(ros2_conditional=self.ros2_firm or self.ros2_conditional)


NO_EVIDENCE = Evidence()
_DIRECTIVE = re.compile(r"^[ \t]*#[ \t]*(if|ifdef|ifndef|elif|else|endif|define)\b[ \t]*(\w*)",
                        re.MULTILINE)


def _conditional_spans(text: str) -> list[tuple[int, int]]:
    """The spans of ``text`` inside ``#if``/``#ifdef``/``#ifndef`` blocks, an include
    guard's (``#ifndef X`` at the top level followed by ``#define X``) not counted; an
    unclosed block runs to the end."""
    spans: list[tuple[int, int]] = []
    stack: list[tuple[int, bool]] = []  # (start, is a guard)
    pending: tuple[int, str] | None = None  # an ``#ifndef`` at the top level: a guard?
    for match in _DIRECTIVE.finditer(text):
        word, name = match.group(1), match.group(2)
        if pending is not None:
            stack.append((pending[0], word == "define" and name == pending[1]))
            pending = None
        if word in ("if", "ifdef"):
            stack.append((match.start(), False))
        elif word == "ifndef":
            if not stack:
                pending = (match.start(), name)
            else:
                stack.append((match.start(), False))
        elif word == "endif" and stack:
            start, is_guard = stack.pop()
            if not is_guard:
                spans.append((start, match.end()))
    if pending is not None:
        stack.append((pending[0], False))
    spans.extend((start, len(text)) for start, is_guard in stack if not is_guard)
    return spans


# ``package::kind::Name``, an interface written in full (spaces allowed around ``::``)
_INTERFACE_NAME = re.compile(r"\b([A-Za-z_]\w*)\s*::\s*(msg|srv|action)\s*::\s*([A-Za-z_]\w*)")


@functools.lru_cache(maxsize=64)
def _interface_names(text: str) -> dict[tuple[str, str], list[str]]:
    """The names ``package::kind::Name`` of a file's text write, by package and kind, in
    order (one scan of a text for every interface header its includes make, not one
    each: a source of navigation2 includes dozens)."""
    found: dict[tuple[str, str], list[str]] = {}
    for match in _INTERFACE_NAME.finditer(text):
        found.setdefault((match.group(1), match.group(2)), []).append(match.group(3))
    return found


# a missing header's stand-in: these words around its name (``stood_in`` reads it back)
_EMPTY_MARK, _EMPTY_END = "// empty stand-in for ", ", created by haros_arch\n"


class IncludeSetup:
    """The folders and flags of one extraction; call ``close`` when done."""

    def __init__(self, workspace: Workspace, include_dirs: Sequence[str],
                 system_headers: bool, units: Mapping[str, UnitFlags] | None = None,
                 sources: Sequence[str] = (), distro: str | None = None,
                 kept_in: str | None = None) -> None:
        self.workspace = workspace
        # the distribution whose client libraries the stand-ins announce (``versions``);
        # not with the system's headers, which say it
        self.distro = distro
        self._versions = [] if system_headers else versions.flags(distro)
        self.units = dict(units or {})  # real source path -> its compile command's flags
        self.system_headers = system_headers
        # the synthesised headers' folder: the workspace's own in the cache folder
        # ``kept_in``, kept from run to run, when no other run holds it (``_kept``);
        # else a temporary one
        self._lock: int | None = None
        self._released = False  # the kept folder let go of between two uses (``release``)
        kept = self._kept(workspace.root, kept_in) if kept_in else None
        self.generated = kept or tempfile.mkdtemp(prefix="haros-arch-cpp-")
        # where what a parse with another release's version read in a header's branch is
        # kept from run to run (``extract.cpp._other_version``), with the cache folder
        self.other_folder = os.path.join(kept_in, "cpp-other") if kept and kept_in else None
        self.user_dirs = [os.path.abspath(d) for d in include_dirs]
        # first the folders the interpreted CMake files give the targets that compile
        # the sources: where a package keeps variants of the same headers (foxglove_bridge:
        # ros1_foxglove_bridge/include, ros2_foxglove_bridge/include and the SDK's,
        # each with ``foxglove_bridge/param_utils.hpp``), the build's are the ones read
        self.user_dirs += [inc for inc in _built_include_dirs(sources, workspace)
                           if inc not in self.user_dirs]
        self.user_dirs += [inc for inc in (os.path.join(p.root, "include")
                                           for p in workspace.packages.values() if p.root)
                           if os.path.isdir(inc) and inc not in self.user_dirs]
        # then the include folders one level down: a package that builds several
        # libraries keeps each one's headers in its folder (MoveIt's moveit_core and
        # moveit_ros_planning: ``moveit_cpp/include/moveit/moveit_cpp/moveit_cpp.hpp``,
        # listed in their CMakeLists, which only the analysed package's is read)
        self.user_dirs += [inc for inc in _library_include_dirs(workspace)
                           if inc not in self.user_dirs]
        self.user_dirs += [root for root in _headers_beside_sources(workspace)
                           if root not in self.user_dirs]
        # and the folders deeper that the CMake files of the packages being extracted
        # give (zed_components' src/zed_camera/include), not those of a sub-project
        roots = dict.fromkeys(package.root for package in (
            workspace.package_of(source) for source in sources)
            if package is not None and package.root)
        for root in roots:
            self.user_dirs += [inc for inc in cmake_includes.cmake_include_dirs(root, workspace)
                               if inc not in self.user_dirs]
        # then what the workspace packages they build on export to catkin
        # (``${catkin_INCLUDE_DIRS}``), after their own folders as CMake orders them
        depended = _depended_roots(roots, workspace)
        for root in depended:
            self.user_dirs += [inc for inc in cmake_includes.exported_include_dirs(
                root, workspace) if inc not in self.user_dirs]
        # the headers those packages install under names their folders do not hold
        # (``_installed_header``), the first package's where two install one name; not
        # those of a sub-project the package vendors, whose include folders are not
        # given either (ouster-ros installs ouster-sdk's ``ouster/`` and ``nonstd/``:
        # read, the SDK's Eigen tensors and optional-lite broke the node classes that
        # hold its types)
        self._installed: dict[str, str] = {}
        for root in (*roots, *depended):
            package = workspace.package_of(root)
            if package is not None and package.root == root:
                for name, path in share.include_map(package, workspace).items():
                    if cmake_includes.in_own_project(path, root):
                        self._installed.setdefault(name, path)
        for unit in self.units.values():  # so that the scan before parsing finds them
            self.user_dirs += [d for d in unit.include_dirs if d not in self.user_dirs]
        # the packages being extracted that our stand-ins also provide, with their
        # include folders: their own headers win (``_own_header``, ``arguments``)
        self.own: dict[str, list[str]] = {}
        self.own_extra: dict[str, list[str]] = {}
        for source in sources:
            package = workspace.package_of(source)
            if package is not None and package.root and package.name in _STANDIN_PACKAGES:
                folder = os.path.join(package.root, "include")
                nested = os.path.join(folder, package.name)
                self.own[package.name] = [f for f in (folder, nested) if os.path.isdir(
                    os.path.join(f, package.name))]
            elif package is not None and package.root and f"{package.name}/" in UMBRELLAS:
                # a package whose API our stand-ins give (image_transport): its headers
                # that define none of the stand-ins' classes are read (``_own_extra``)
                folder = os.path.join(package.root, "include")
                nested = os.path.join(folder, package.name)
                self.own_extra[package.name] = [f for f in (folder, nested) if os.path.isdir(
                    os.path.join(f, package.name))]
        self.diagnostics: list[Diagnostic] = []
        # the headers synthesised and the diagnostics said once the sources' headers
        # are prepared (``prepared_now``), before any parse: what a parse adds (a header
        # clang still missed) is the unit's own, counted for each unit that includes it
        # (``stood_in``), not for the units its process happens to parse next
        self.prepared: frozenset[str] | None = None
        self.prepared_said = 0
        # the headers the unit being parsed includes that parses stood in for
        # (``stood_in``), said missing by it
        self.unit_missing: list[Diagnostic] = []
        self._handled: set[str] = set()
        self._scanned: dict[str, Evidence] = {}  # file -> its ROS (see ``scan``)
        # the texts of the files being scanned, the unit's source first, each including the
        # next: where a ROS 2 interface header is included, they write its type's name
        self._including: list[str] = []
        self._fallbacks: dict[str, bool] = {}  # header read from FALLBACK -> ROS 2 code
        # (header, folder of a quoted include) -> what ``_prepare`` found, when it
        # changed nothing
        self._looked_up: dict[tuple[str, str], str | None] = {}
        self._unit_dirs: dict[str, list[str]] = {}  # see ``_unit_folders``
        self.written: dict[str, str] = {}  # synthesised header path -> its text
        self.overflow = os.path.join(self.generated, OVERFLOW)
        self._folders: set[str] = set()  # the folders of the written headers
        self._on_disk = False
        # the include folders as the parse searches them (``header_map``), once written
        self.search: list[str] | None = None
        self._tops: dict[str, list[str]] | None = None  # see ``_resolve``
        # a name written with ``.`` or ``..`` parts that an include folder resolves
        # (``"../src/publishers/basic.hpp"`` through ``include``) -> that folder
        self._dotted: dict[str, str] = {}
        self._defined: dict[str, dict[str, str]] = {}  # see ``_definitions``
        self._roots: frozenset[str] | None = None  # see ``_inside``
        self._inside_of: dict[str, bool] = {}
        self._listed: dict[tuple[str, str], frozenset[str]] = {}  # see ``_entries``
        # each source's -D flags from its package's CMake files (``package_macros``),
        # found before the workers start, which take a copy
        self._cmake_flags: dict[str, list[str]] = {}
        # and the C++ standard they ask, when newer than the default (``cmake_standard``)
        self._cmake_std: dict[str, str | None] = {}
        for source in dict.fromkeys(map(os.path.abspath, sources)):
            if os.path.realpath(source) not in self.units:
                self._cmake_flags[source] = build_macros.cmake_flags(source, workspace)
                self._cmake_std[source] = build_macros.cmake_standard(source, workspace)
        # generate_parameter_library's targets (``_parameter_header``), read when needed
        self._parameter_targets: list[parameter_library.Target] | None = None
        # the dynamic_reconfigure configs of each package read so far (``_reconfigure``)
        self._configs: dict[str, dict[str, reconfigure.Config]] = {}

    @contextlib.contextmanager
    def announcing(self, library: versions.Library, version: tuple[int, int, int]
                   ) -> Iterator[None]:
        """The parses made inside take ``library`` to be ``version`` (a unit parsed
        again for a branch on a version not known: ``versions``); the diagnostics and
        missing headers they add are dropped after."""
        kept = self._versions, self.unit_missing, len(self.diagnostics)
        self._versions = library.announce(version)
        try:
            yield
        finally:
            self._versions, self.unit_missing = kept[0], kept[1]
            del self.diagnostics[kept[2]:]

    def arguments(self, pch: bool = True, source: str | None = None) -> list[str]:
        """The parse flags (of translation unit ``source``: its compile command's include
        folders, macros and standard, after our stand-ins); without ``pch`` the
        precompiled stand-ins and the header map are left out (the flags that key the
        cache, which must not name this process's files): the folders are listed."""
        unit = self.units.get(os.path.realpath(source)) if source and self.units else None
        std = unit.std if unit is not None else self.cmake_standard(source)
        # the version macros are language flags: the precompiled stand-ins are keyed by
        # them, and so is the cache (``arguments(False)``)
        flags = [*toolchain.base_arguments(self.system_headers, std), *self._versions]
        args = ["-I", self.generated, "-I", self.overflow]
        own = self._own_folders(source)
        if own:  # before everything, and no precompiled stand-ins that would redefine
            args = [*(a for f in own for a in ("-I", f)), *args]  # its classes
            pch = False
        if not self.system_headers:
            args += ["-I", STANDIN]
        if unit is not None:
            args += unit.arguments()
        args += self.package_macros(source, unit)
        if unit is None:  # its own target's folders first, as its compile line has them
            args += [a for f in self._unit_folders(source) for a in ("-I", f)]
        for folder in (self.search if pch and self.search is not None else self.user_dirs):
            args += ["-I", folder]
        if self.system_headers:
            return args + flags
        args += ["-isystem", STD_STANDIN, *flags]
        made = precompiled_prelude(flags) if pch else None
        return [*args, "-include-pch", made] if made is not None else args

    def cmake_standard(self, source: str | None) -> str | None:
        """The C++ standard the CMake targets of a unit that no compile command gives
        ask, when newer than the default (``build_macros.cmake_standard``)."""
        if source is None:
            return None
        if source not in self._cmake_std:
            self._cmake_std[source] = build_macros.cmake_standard(source, self.workspace)
        return self._cmake_std[source]

    def package_macros(self, source: str | None, unit: UnitFlags | None = None) -> list[str]:
        """The macros the build defines for a unit that no compile command gives: those
        of its package's CMake files (``build_macros.cmake_flags``), and
        ``-DROS_PACKAGE_NAME="<package>"`` for a unit of a package whose build defines
        it: every ROS 1 package (rosconsole's CMake extras, which catkin's roscpp brings,
        ``add_definitions`` it with the project's name) and a ROS 2 package built with
        ament_cmake_ros (its extras do the same; plain ament_cmake defines nothing).
        Not where the unit's compile command defines it already, nor for a package
        name no build would accept."""
        package = self.workspace.package_of(source) if source else None
        own: list[str] = []
        if unit is None and source is not None:
            if source not in self._cmake_flags:
                self._cmake_flags[source] = build_macros.cmake_flags(source, self.workspace)
            own = self._cmake_flags[source]
        given = {m[2:].partition("=")[0] for m in (unit.macros if unit is not None else own)}
        if package is None or not _PACKAGE_NAME.fullmatch(package.name) or (
                "ROS_PACKAGE_NAME" in given):
            return own
        version = ros_version(package)
        if version == 1 or (version == 2 and any(
                d.name == "ament_cmake_ros" for d in package.dependencies)):
            return [*own, f'-DROS_PACKAGE_NAME="{package.name}"']
        return own

    def _unit_folders(self, source: str | None) -> list[str]:
        """The include folders the CMake files give the target that compiles ``source``
        (``_built_include_dirs``), searched before the batch's shared ones: in a batch of
        several packages the shared order is the first package's, and a header name two
        packages hold (spencer's rwth_ground_plane and rwth_upper_body_detector, each
        with its ``Globals.h``) was the first package's for every unit. Empty when the
        shared search begins with them anyway."""
        if source is None:
            return []
        found = self._unit_dirs.get(source)
        if found is None:
            found = [f for f in _built_include_dirs([source], self.workspace)
                     if os.path.isdir(f)]
            if self.user_dirs[:len(found)] == found:
                found = []
            self._unit_dirs[source] = found
        return found

    def _own_folders(self, source: str | None) -> list[str]:
        """The include folders of ``source``'s package when it is one our stand-ins also
        provide (its own headers, not the stand-ins, are what it is built with)."""
        if not self.own or source is None or self.system_headers:
            return []
        package = self.workspace.package_of(source)
        return self.own.get(package.name, []) if package is not None else []

    def prepared_now(self) -> None:
        """Every source's headers are prepared (``scan``): what the batch's parses all
        start from, and the batch's own diagnostics (``diagnostics[:prepared_said]``)."""
        self.prepared = frozenset(self.written)
        self.prepared_said = len(self.diagnostics)

    def release(self) -> None:
        """Let another run take the kept folder (``_kept``) while this setup waits to be
        used again in this run (``extract.one_run``); ``hold`` takes it back."""
        if self._lock is not None:
            os.close(self._lock)
            self._lock = None
            self._released = True

    def hold(self) -> bool:
        """Take the kept folder back after ``release``; False when another run holds it
        now. Another run may have made the folder hold its own headers meanwhile: they
        are written again before a parse (``materialise``)."""
        if not self._released:
            return True
        lock = _locked(self.generated)
        if lock is None:
            return False
        self._lock, self._released, self._on_disk = lock, False, False
        return True

    def close(self) -> None:
        if self._released:  # the kept folder, let go of already
            return
        if self._lock is not None:  # kept for the next run, which makes it what it needs
            os.close(self._lock)
            self._lock = None
        elif self._on_disk:
            shutil.rmtree(self.generated, ignore_errors=True)
        else:
            os.rmdir(self.generated)

    def _kept(self, root: str, folder: str) -> str | None:
        """The workspace's folder of synthesised headers in the cache ``folder``, locked
        for this run; None when it cannot be made or another run holds it. Writing the
        headers of a large workspace and removing them again cost a run that parses
        one changed source more than its parse (hundreds of folders of message
        headers); ``materialise`` brings the kept folder to exactly this run's set."""
        name = hashlib.sha256(os.fsencode(root)).hexdigest()[:16]
        path = os.path.join(folder, "generated", name)
        try:
            os.makedirs(path, exist_ok=True)
        except OSError:
            return None
        self._lock = _locked(path)
        return path if self._lock is not None else None

    # -- before parsing ---------------------------------------------------------------

    def scan(self, path: str, text: str) -> bool:
        """Prepare every header that ``path`` (with contents ``text``) includes; True when
        it or a workspace header it includes is ROS 2 code (includes rclcpp or a ROS 2
        message header). Code kept for both ROS versions includes each one's headers
        under a preprocessor condition (open_vins' ``#if ROS_AVAILABLE == 1`` roscpp's,
        ``#elif ROS_AVAILABLE == 2`` rclcpp's): a ROS 2 header included only under a
        condition does not make ROS 2 code of a unit that includes a ROS 1 header
        (``ros/...``) under none (``Evidence``)."""
        return self._scan(path, text).ros2

    def _scan(self, path: str, text: str) -> Evidence:
        if path in self._scanned:
            return self._scanned[path]
        self._scanned[path] = NO_EVIDENCE  # a header that includes itself back
        self._including.append(text)
        try:
            found = self._scan_includes(text, self.workspace.location(path),
                                        os.path.dirname(path))
        finally:
            self._including.pop()
        self._scanned[path] = found
        return found

    def _scan_includes(self, text: str, file: Location, folder: str) -> Evidence:
        found = NO_EVIDENCE
        conditional = _conditional_spans(text)
        line, counted = 1, 0  # the line of the include, counted on from the last one
        for match in _INCLUDE.finditer(text):
            header = match.group(2).strip()
            under = any(start <= match.start() < end for start, end in conditional)
            line += text.count("\n", counted, match.start())
            counted = match.start()
            where = Location(file.package, file.file, line, match.start(2) - match.start() + 1)
            real = self._prepare(header, folder, match.group(1) == '"', where)
            here = Evidence(ros2_firm=is_ros2_header(header) or self._fallbacks.get(
                header, False), ros1_firm=is_ros1_header(header))
            if real and self._inside(real):
                if real in self._scanned:  # a header scanned before: not read again
                    here = here.join(self._scanned[real])
                else:
                    more, _ = read_text(real, self.workspace.location(real))
                    if more is not None:
                        here = here.join(self._scan(real, more))
            found = found.join(here.conditional() if under else here)
        return found

    def _prepare(self, header: str, folder: str, quoted: bool, where: Location) -> str | None:
        """Make ``header`` resolvable; return the real file it resolves to, if any. An
        include that changed nothing (a workspace header, a stand-in's) is answered the
        same way again without the look-ups: every unit includes them."""
        if header in self._handled:
            return None
        key = (header, folder if quoted else "")
        if key in self._looked_up:
            return self._looked_up[key]
        marks = (len(self.diagnostics), len(self.written), len(self._handled))
        found = self._look_up(header, folder, quoted, where)
        if marks == (len(self.diagnostics), len(self.written), len(self._handled)):
            self._looked_up[key] = found
        return found

    def _look_up(self, header: str, folder: str, quoted: bool, where: Location) -> str | None:
        # a file once, whatever path reaches it: RxCpp's schedulers/rx-currentthread.hpp
        # includes "../rx-includes.hpp", which includes it back, so its path would grow
        # ("schedulers/../schedulers/../...") and the scan recurse until Python stopped it
        if quoted and os.path.isfile(nearby := os.path.normpath(os.path.join(folder, header))):
            return nearby
        ros2 = _ROS2_HEADER.fullmatch(header)
        if ros2 is not None and not self.system_headers and (
                real := self._own_interface_like(header, ros2)) is not None:
            return real
        if ros2 is not None and (not self.system_headers or self._resolve(header) is None):
            self._ros2_interface(header, ros2.group(1), ros2.group(2), ros2.group(3), where)
            return None
        qt = _QT_HEADER.fullmatch(header) is not None
        own = self._own_header(header) or self._own_extra(header)
        if own is not None:
            return own
        if not self.system_headers and (header.startswith(SHADOWED) or qt):
            standin = os.path.join(STANDIN, header)
            if is_ros1_header(header) and not os.path.isfile(standin) and (
                    real := self._resolve(header)) is not None and self.workspace.holds(real):
                # a workspace header in a ``ros/`` folder of an include folder, which
                # roscpp's installed ``ros/`` does not hold, as a compiler finds it
                # (quadruped-robot's ``"ros/qr_cmd_vel_receiver.h"`` from include/quadruped)
                return real
            if os.path.isfile(standin) and not header.startswith(_ROS_PREFIXES):
                self._handled.add(header)
                self._scan_standin(standin)  # what it includes (a message header) is ready
            elif not os.path.isfile(standin) and (message := _DEFINED_HEADER.fullmatch(
                    header)) and not header.startswith(("ros/", "boost/")) and self._definition(
                    message.group(1), message.group(2)) is not None:
                # a message of a package whose headers are ours (tf/tfMessage.h)
                self._message(header, message.group(1), message.group(2), where)
            elif not os.path.isfile(standin):
                umbrella = QT if qt else next(
                    (u for p, u in UMBRELLAS.items() if header.startswith(p)), None)
                if umbrella is None:
                    self._empty(header, where)
                else:
                    self._handled.add(header)
                    self._write(header, f"// haros_arch: stands in for {header}\n"
                                        f"#include <{umbrella}>\n")
                    if umbrella in _LIBRARY_UMBRELLAS:
                        self._scan_standin(os.path.join(STANDIN, umbrella))
            return None
        if not self.system_headers and os.path.isfile(os.path.join(STANDIN, header)) and (
            header.startswith(_LIBRARY_HEADERS)
        ):
            self._handled.add(header)  # sensor_msgs/image_encodings.h
            self._scan_standin(os.path.join(STANDIN, header))  # the messages it includes
            return None
        if _EXPORT_HEADER.fullmatch(os.path.basename(header)) and self._resolve(header) is None:
            self._empty(header, where)  # CMake's export header, not a message's
            return None
        message = self._message_header(header)
        if message is not None and self._message(
            header, message.group(1), message.group(2), where
        ):
            return None
        config = _CONFIG_HEADER.fullmatch(header)
        if message is None and config is not None and self._reconfigure(
            header, config.group(1), config.group(2), where
        ):
            return None  # a config named in lowercase: yocs_cmd_vel_mux's reloadConfig.h
        found = self._resolve(header)
        if found is None and _fallback_file(header) is not None:
            self._fallback(header)
            return None
        if found is None and self.system_headers and os.path.isfile(os.path.join(STANDIN, header)):
            # an API header the system lacks (Debian ships pluginlib's macros only as .hpp)
            self._handled.add(header)
            self._write(header, f'#include "{os.path.join(STANDIN, header)}"\n')
            return None
        if found is None and (installed := self._installed_header(header)) is not None:
            return installed
        if found is None and not self._parameter_header(header, where):
            self._empty(header, where)
        return found

    def _installed_header(self, header: str) -> str | None:
        """The workspace file a package being extracted, or one it builds on, installs
        as ``header`` under its prefix's ``include`` folder, when no include folder holds
        that name: a synthesised header that includes it, first on the include path
        (zed_debug's ``<zed_components/zed_camera_component.hpp>``, installed from
        zed_components' ``src/zed_camera/include/``; the stand-in left ``stereolabs::
        ZedCamera`` unknown where the program builds it). None otherwise."""
        path = self._installed.get(header.replace("\\", "/"))
        if path is None or not os.path.isfile(path):
            return None
        self._handled.add(header)
        self._write(header, f"// haros_arch: {header} as its package installs it\n"
                            f'#include "{path}"\n')
        return path

    def _reconfigure(self, header: str, package: str, name: str, where: Location) -> bool:
        """Synthesise the ``<Name>Config.h`` a ``cfg/<file>.cfg`` of the package makes
        dynamic_reconfigure generate (``reconfigure``); False when none does."""
        if self.system_headers and self._resolve(header) is not None:
            return False  # the real generated header
        found = self._configs.get(package)
        if found is None:
            folder = self.workspace.find(package)
            found, problems = ({}, []) if folder is None else reconfigure.configs(
                folder, package, reconfigure.workspace_modules(self.workspace))
            self._configs[package] = found
            self.diagnostics.extend(problems)
        config = found.get(name)
        if config is None:
            return False
        self._handled.add(header)
        source = self.workspace.relpath(config.path)
        self._write(header, reconfigure.render(config, source))
        if config.partial:
            self.diagnostics.append(diag.make(
                "CPP_RECONFIGURE_PARTIAL", self.workspace.location(config.path),
                name=f"{package}/{name}", count=len(config.parameters)))
        for message in reconfigure.MESSAGES:
            self._prepare(message, "", False, where)
        return True

    def _parameter_header(self, header: str, where: Location) -> bool:
        """Synthesise the header generate_parameter_library writes at build time
        (``<project>/<target>.hpp``) from the target's YAML; False when ``header`` is not
        one, or its YAML cannot be read (a diagnostic at the YAML says why)."""
        if self._parameter_targets is None:
            self._parameter_targets = parameter_library.targets(self.workspace)
        target = parameter_library.header_target(header, self._parameter_targets,
                                                 where.package or "")
        if target is None:
            return False
        read, found = parameter_library.load(target, self.workspace)
        self.diagnostics.extend(found)
        if read is None:
            return False
        self._handled.add(header)
        self._write(header, parameter_library.render(
            target, *read, self.workspace.relpath(target.yaml)))
        return True

    def _own_header(self, header: str) -> str | None:
        """The real file of ``header`` when it is a header of a package being extracted
        that our stand-ins would otherwise shadow (``rclcpp_components/
        component_manager.hpp`` while modelling rclcpp_components); None otherwise."""
        prefix, _, rest = header.partition("/")
        if not rest or self.system_headers:
            return None
        return next((os.path.join(f, header) for f in self.own.get(prefix, ())
                     if os.path.isfile(os.path.join(f, header))), None)

    def _own_extra(self, header: str) -> str | None:
        """The real file of ``header`` when it is a header of a package being extracted
        whose API our stand-ins give, that has no stand-in file and defines no class the
        stand-ins of that package name (image_transport's ``republish.hpp``, which
        declares its node class): the umbrella stand-in would leave that class
        undeclared. A header that defines one of the stand-ins' classes
        (``publisher.hpp``) keeps the umbrella: both would define it. None otherwise."""
        prefix, _, rest = header.partition("/")
        if not rest or self.system_headers or prefix not in self.own_extra or (
                os.path.isfile(os.path.join(STANDIN, header))):
            return None
        path = next((os.path.join(f, header) for f in self.own_extra[prefix]
                     if os.path.isfile(os.path.join(f, header))), None)
        if path is None:
            return None
        text, _ = read_text(path, self.workspace.location(path))
        if text is None:
            return None
        defined = {m.group(1) for m in _CLASS_DEFINITION.finditer(_strip_comments(text))}
        return path if not defined & _standin_classes(prefix) else None

    def _fallback(self, header: str) -> None:
        """``header`` from the stand-ins of ``FALLBACK`` (the workspace has none by that
        name): a synthesised header that includes it, first on the include path."""
        path = _fallback_file(header)
        assert path is not None
        self._handled.add(header)
        self._write(header, f"// haros_arch: the stand-in of {header}, which the workspace "
                            f'does not have\n#include "{path}"\n')
        self._scan_standin(path)  # what it includes, from the workspace or FALLBACK
        self._fallbacks[header] = self._scanned.get(path, NO_EVIDENCE).ros2

    def _scan_standin(self, path: str) -> None:
        """Prepare what a library stand-in includes (cv_bridge: ``sensor_msgs/Image.h``)."""
        if path not in self._scanned:
            text, _ = read_text(path, Location(file=path))
            before = len(self.diagnostics)
            if text is not None:
                self.scan(path, text)
            del self.diagnostics[before:]  # nothing to report about our own headers

    def _message_header(self, header: str) -> re.Match[str] | None:
        """The package and name of ``header`` when it may be a message's or service's
        generated header: a capitalised name, or one in lowercase that the package (or
        the catalogue) defines and no real file of that name is (ROS 1 allows message
        names in lowercase: LIO-SAM's ``msg/cloud_info.msg`` and ``srv/save_map.srv``
        generate ``<lio_sam/cloud_info.h>`` and ``<lio_sam/save_map.h>``), or a part of
        an action the package's ``action/`` folder defines."""
        found = _MESSAGE_HEADER.fullmatch(header)
        if found is not None and (
            # no ROS package is named so (REP 144: lowercase letters, digits and
            # underscores): a library's header (CGAL's
            # <CGAL/Exact_predicates_inexact_constructions_kernel.h>, X11's <X11/Xlib.h>)
            not found.group(1).islower()
            # a ROS 2 distribution generates ``<pkg/msg/name.hpp>``, never ``<pkg/Name.h>``:
            # such a header of a package not in the workspace is a library's (lanelet2's
            # <lanelet2_core/LaneletMap.h>, <lanelet2_routing/RoutingGraph.h> in Autoware)
            or (versions.RCLCPP.version(self.distro) is not None
                and self.workspace.find(found.group(1)) is None)
        ) and self._definition(found.group(1), found.group(2)) is None:
            return None  # missing, not a message without fields of a package we have no
            # definition of
        if found is not None:
            return found
        found = _DEFINED_HEADER.fullmatch(header)
        if found is None or found.group(2).endswith("Config") or (
                self._resolve(header) is not None):
            return None
        # a lowercase action's parts too (industrial_calibration's
        # ``action/manual_trigger.action`` makes <pkg/manual_triggerAction.h>, ...Goal.h)
        return found if self._definition(found.group(1), found.group(2)) or (
            self._action_file(found.group(1), found.group(2))) else None

    def _message(self, header: str, package: str, name: str, where: Location) -> bool:
        """Synthesise a message / service header when that is what ``header`` is."""
        if name.endswith("Config") and self._reconfigure(header, package, name, where):
            return True
        real = self._resolve(header)
        if real is None and self._action_file(package, name) and (
            self._action(package, name, where)
        ):
            # an action of the package's ``action/`` folder: genaction makes its parts'
            # headers, whatever stale copies of its generated .msg files ``msg/`` holds
            # (industrial_training's object_manipulation_msgs keeps
            # GraspHandPostureExecutionAction.msg there, outside add_message_files: read
            # as a plain message, the action had none of actionlib's nested types)
            return True
        definition = self._definition(package, name)
        if definition is None and (real is None or not self.system_headers) and (
            self._action(package, name, where)
        ):
            return True
        if definition is None and real is not None and (
            not interfaces.interface_package(package, distro=self.distro) or self.system_headers
        ):
            return False  # an ordinary header of a package, or the real generated one
        if self.system_headers and real is not None:
            return False
        part = _SERVICE_PART.fullmatch(name) if definition is None and real is None else None
        service = self._definition(package, part.group(1)) if part is not None else None
        if part is not None and service is not None and len(service.sections) == 2:
            # gencpp's header of one part of a service (<pkg/SrvRequest.h>): the part is
            # in the service's header, which is made ready in its turn
            whole = f"{package}/{part.group(1)}.h"
            self._handled.add(header)
            self._write(header, f"// {header}, created by haros_arch\n#include <{whole}>\n")
            self._prepare(whole, "", False, where)
            return True
        if definition is None and real is None and _fallback_file(header) is not None:
            return False  # a library's capitalised header we stand in for, not a message
            # (laser_proc's <laser_proc/LaserTransport.h>)
        if definition is None:
            definition = interfaces.Interface(package, name, [[], []], known=False)
            self.diagnostics.append(diag.make(
                "CPP_MESSAGE_UNKNOWN", where, header=header))
        self._handled.add(header)
        self._write(header, interfaces.render(definition))
        for dep in interfaces.dependencies(definition):
            self._prepare(f"{dep}.h", "", False, where)
        return True

    def _definition(self, package: str, name: str) -> interfaces.Interface | None:
        folder = self.workspace.find(package)
        if folder is not None:
            for sub, ext in (("msg", ".msg"), ("srv", ".srv")):
                path = self._definitions(folder, sub).get(name + ext)
                if path is not None:
                    text, found = read_text(path, self.workspace.location(path))
                    self.diagnostics.extend(found)
                    if text is not None:
                        parsed = interfaces.parse_definition(package, name, text)
                        if ext == ".srv" and len(parsed.sections) == 1:
                            parsed.sections.append([])
                        return parsed
        text = interfaces.known(package, name, distro=self.distro)
        if text is None:
            return None
        return interfaces.parse_definition(package, name, text)

    def _definitions(self, folder: str, kind: str) -> dict[str, str]:
        """The ``kind`` (msg, srv, action) definition files of a package folder, by file
        name (``interfaces.definition_files``; the folder walked once)."""
        found = self._defined.get(folder)
        if found is None:
            found = self._defined[folder] = interfaces.definition_walk(folder)
        return interfaces.definition_files(folder, kind, found)

    def _action_file(self, package: str, name: str) -> bool:
        """Whether ``name`` is a part of an action whose ``action/<base>.action`` the
        workspace's package ``package`` holds."""
        folder = self.workspace.find(package)
        return folder is not None and any(
            os.path.isfile(_action_path(folder, base)) for _part, base in _action_bases(name))

    def _action(self, package: str, name: str, where: Location) -> bool:
        """``pkg/DoAction.h``, ``pkg/DoGoal.h``, ...: the headers of ``action/Do.action``.
        ``pkg/DoAction.h`` of a package neither in the workspace nor in the catalogue is
        still an action's (genaction names it so): its parts are declared without
        fields, as an unknown message is, so that an actionlib server or client of it
        (``SimpleActionServer<pkg::DoAction>``, which reads the action's nested types)
        is still a call (kobuki_auto_docking's ``as_(nh_, name_ + "_action", false)``
        was lost with kobuki_msgs absent, and its node said complete)."""
        folder = self.workspace.find(package)
        for part, base in _action_bases(name):
            path = "" if folder is None else _action_path(folder, base)
            if path and os.path.isfile(path):
                text, found = read_text(path, self.workspace.location(path))
                self.diagnostics.extend(found)
            elif folder is None:  # an installed package's: the shipped catalogue's
                text = interfaces.known(package, base, kinds=("action",),
                                        distro=self.distro)
                if text is None and part == "Action" and (
                        interfaces.known(package, name, distro=self.distro) is None):
                    text = ""
                    self.diagnostics.append(diag.make(
                        "CPP_MESSAGE_UNKNOWN", where, header=f"{package}/{name}.h"))
                if text is None:
                    continue
            else:
                continue
            definition = interfaces.parse_definition(package, base, text or "")
            source = interfaces.render_action(definition)
            for each in interfaces.ACTION_PARTS:
                self._handled.add(f"{package}/{base}{each}.h")
                self._write(f"{package}/{base}{each}.h", source)
            for dep in interfaces.dependencies(definition):
                self._prepare(f"{dep}.h", "", False, where)
            return True
        return False

    def _own_interface_like(self, header: str, ros2: re.Match[str]) -> str | None:
        """A header of the workspace at the path of a ROS 2 interface's
        (``pkg/action/name.hpp``) that ``pkg`` defines no interface for: the header
        itself, not a synthesised message (aerostack2's
        ``as2_behavior_tree/action/arm_service.hpp``, a behavior tree node's class; the
        empty action in its place left every tree node's class undeclared)."""
        real = self._resolve(header)
        if real is None or not self.workspace.holds(real):
            return None
        package, kind, snake = ros2.group(1), ros2.group(2), ros2.group(3)
        folder = self.workspace.find(package)
        if folder is None:
            return None
        names = [f[: -len(kind) - 1] for f in self._definitions(folder, kind)]
        if any(ros2_interfaces.snake_case(name) == snake for name in names):
            return None
        return real

    def _ros2_interface(self, header: str, package: str, kind: str, snake: str,
                        where: Location) -> None:
        """Synthesise ``pkg/msg/name.hpp`` (or srv, action) from its definition file."""
        self._handled.add(header)
        folder = self.workspace.find(package)
        extension = {"msg": ".msg", "srv": ".srv", "action": ".action"}[kind]
        # ``srvs/Pause.srv`` is still ``pkg/srv/Pause``
        files = {} if folder is None else self._definitions(folder, kind)
        names = [f[: -len(extension)] for f in sorted(files)]
        names += interfaces.catalogue_names(True, self.distro).get(package, [])
        names += [key.split("/")[1] for key in interfaces.WELL_KNOWN
                  if key.startswith(package + "/")]
        names += self._written_names(package, kind)
        name = ros2_interfaces.camel_case(snake, names)
        definition: interfaces.Interface | None = None
        path = files.get(name + extension, "")
        if path and os.path.isfile(path):
            text, found = read_text(path, self.workspace.location(path))
            self.diagnostics.extend(found)
            definition = interfaces.parse_definition(package, name, text or "")
        elif (text := interfaces.known(package, name, True, (kind,), self.distro)) is not None:
            definition = interfaces.parse_definition(package, name, text)
        elif not interfaces.interface_package(package, True, self.distro):
            self.diagnostics.append(diag.make("CPP_MESSAGE_UNKNOWN", where, header=header))
        if definition is None:
            definition = interfaces.Interface(package, name, [[]], known=False)
        self._write(header, ros2_interfaces.render(definition, kind))
        for dep in ros2_interfaces.dependencies(definition, kind):
            if dep not in self._handled:
                self._prepare(dep, "", False, where)

    def _written_names(self, package: str, kind: str) -> list[str]:
        """The names ``package::kind::Name`` that the files including the header being
        synthesised write: a name with capitals together (``GetPositionIK``) has a file
        name (``get_position_ik.hpp``) that capitalising each word would not give back."""
        return [name for text in reversed(self._including)
                for name in _interface_names(text).get((package, kind), ())]

    def _resolve(self, header: str) -> str | None:
        system = toolchain.system_include_dirs() if self.system_headers else (STD_STANDIN,)
        if self._tops is None:  # the include folders by their entries: few stat calls
            self._tops = {}
            for folder in self.user_dirs:
                try:
                    entries = os.listdir(folder)
                except OSError:
                    continue
                for entry in entries:
                    self._tops.setdefault(entry, []).append(folder)
        parts = header.replace("\\", "/").split("/", 2)
        top = parts[0]
        near = self.user_dirs if top in (".", "..") else self._tops.get(top, ())
        if len(parts) > 2 and parts[1] not in (".", "..", "") and len(near) > 1:
            # ``autoware/<package>/x.hpp``: hundreds of folders hold ``autoware``; only
            # those whose ``autoware`` holds ``<package>`` can hold the header
            near = [folder for folder in near if parts[1] in self._entries(folder, top)]
        folders = [*near, *system]
        for folder in folders:
            candidate = os.path.normpath(os.path.join(folder, header))
            if os.path.isfile(candidate):
                if top in (".", "..") and folder in self.user_dirs:
                    self._dotted.setdefault(header, folder)  # see ``materialise``
                return candidate
        return None

    def _entries(self, folder: str, top: str) -> frozenset[str]:
        """The names in ``folder/top`` (listed once per run)."""
        key = (folder, top)
        found = self._listed.get(key)
        if found is None:
            try:
                found = frozenset(os.listdir(os.path.join(folder, top)))
            except OSError:
                found = frozenset()
            self._listed[key] = found
        return found

    def _inside(self, path: str) -> bool:
        """``path`` is under one of the workspace folders or of the include folders: one
        of them is ``path`` up to one of its separators (asked once per file)."""
        inside = self._inside_of.get(path)
        if inside is None:
            if self._roots is None:
                self._roots = frozenset((*(os.path.abspath(folder).rstrip(os.sep) for folder
                                           in self.workspace.folders), *self.user_dirs))
            inside, end = False, path.find(os.sep)
            while end != -1 and not inside:
                inside = path[:end] in self._roots
                end = path.find(os.sep, end + 1)
            self._inside_of[path] = inside
        return inside

    def _empty(self, header: str, where: Location) -> None:
        self._handled.add(header)
        export = _EXPORT_HEADER.fullmatch(os.path.basename(header))
        if export is not None:  # CMake's generate_export_header writes it at build time
            name = export.group(1).upper()
            self._write(header, f"// {header}, as CMake's generate_export_header writes "
                                "it, created by haros_arch\n" + "".join(
                                    f"#define {name}_{macro}\n" for macro in _EXPORT_MACROS))
            return
        self._write(header, f"{_EMPTY_MARK}{header}{_EMPTY_END}")
        self.diagnostics.append(diag.make("CPP_INCLUDE_MISSING", where, header=header))

    def _write(self, header: str, text: str) -> None:
        """Synthesise ``header``; in the overflow folder when its name is a folder of
        headers already written, or under a name written as a file (``<QtGui>`` beside
        ``<QtGui/QImage>``)."""
        for root in (self.generated, self.overflow):
            path = os.path.normpath(os.path.join(root, header))
            if not path.startswith(root + os.sep):
                return  # "../" in a header name: nothing to create
            if not self._clashes(path, root):
                break
        else:
            return  # clashes in both folders: clang reports the header as not found
        self.written[path] = text
        self._folders.update(_parents(path, root))
        if self._on_disk:
            write_whole(path, text)

    def _clashes(self, path: str, root: str) -> bool:
        return path in self._folders or any(p in self.written for p in _parents(path, root))

    def materialise(self) -> None:
        """Write the synthesised headers, before the first parse (until then they are
        only in memory: a run answered from the cache writes none)."""
        if not self._on_disk:
            self._on_disk = True
            if self._lock is not None:
                _sync(self.generated, self.written, {os.path.join(self.generated, HEADER_MAP)})
            else:
                for path, text in self.written.items():
                    write_whole(path, text)
            # with the names written with ``..`` the scan resolved through a folder: the
            # map has each file's name below its folder only (naoqi_driver2's
            # ``src/event/audio.hpp`` includes ``"../src/publishers/basic.hpp"``, found
            # through ``include`` as its CMakeLists says)
            self.search = header_map.search_path(
                os.path.join(self.generated, HEADER_MAP), self.user_dirs, self._dotted)

    # -- after parsing ----------------------------------------------------------------

    def message_header(self, header: str) -> bool:
        """Whether ``header`` is the generated header of a message or service the
        workspace or the catalogue defines, made ready to include (a unit that uses the
        type with no include of its own: ``_unincluded_messages``)."""
        if self.system_headers:
            return False
        ros2 = _ROS2_HEADER.fullmatch(header)
        if ros2 is not None:
            if header not in self._handled:
                if self._resolve(header) is not None or not (
                        self.workspace.find(ros2.group(1)) is not None
                        or interfaces.interface_package(ros2.group(1), True, self.distro)):
                    return False
                self._ros2_interface(header, ros2.group(1), ros2.group(2), ros2.group(3),
                                     Location())
            return True
        spec = self._message_header(header)
        if spec is None or self._definition(spec.group(1), spec.group(2)) is None:
            return False
        if header in self._handled:
            return True
        return self._message(header, spec.group(1), spec.group(2), Location())

    def remade(self, path: str) -> str | None:
        """The text of the synthesised header at ``path`` when this run makes it, made
        now if it is a message header that a parse makes on demand (``message_header``):
        a unit kept in the cache that used one is then as it was, though no scan of this
        run made it. None for any other (a header repaired after a parse is not made
        again: where clang would now find it, the repair is what the parse says)."""
        if path not in self.written:
            header = os.path.relpath(path, self.generated)
            if header.startswith((os.pardir, OVERFLOW + os.sep)) or not (
                    self.message_header(header.replace(os.sep, "/"))):
                return None
        return self.written.get(path)

    def stood_in(self, includes: Iterable[tuple[str, Callable[[], Location]]]
                 ) -> list[Diagnostic]:
        """``CPP_INCLUDE_MISSING`` of each header a parse included (``includes``: the
        file and a function that gives where it is included, in order) that is an
        empty stand-in a parse made (``repair``), this process's or another's: each unit
        that includes it says so where it includes it, whichever unit's parse made it
        first."""
        found: list[Diagnostic] = []
        seen: set[str] = set()
        for path, where in includes:
            if path in seen or (self.prepared is not None and path in self.prepared):
                continue
            seen.add(path)
            header = self.empty_stand_in(path)
            if header is not None:
                found.append(diag.make("CPP_INCLUDE_MISSING", where(), header=header))
        return found

    def empty_stand_in(self, path: str) -> str | None:
        """The header as included (``moveit/robot_model_loader/robot_model_loader.h``)
        when ``path`` is an empty stand-in a parse made for it (``repair``), else None."""
        if not path.startswith((self.generated + os.sep, self.overflow + os.sep)):
            return None
        text = self.written.get(path)
        if text is None:
            try:
                with open(path, encoding="utf-8", errors="replace") as handle:
                    text = handle.read(len(_EMPTY_MARK) + 512)
            except OSError:
                return None
        if not text.startswith(_EMPTY_MARK):
            return None
        return text[len(_EMPTY_MARK):].partition(_EMPTY_END)[0]

    def repair(self, messages: list[tuple[str, Location]]) -> bool:
        """Create what clang reported as not found; True when a new parse may help."""
        changed = False
        for message, where in messages:
            match = _NOT_FOUND.match(message)
            if match is None or match.group(1) in self._handled:
                continue
            header = match.group(1)
            if _ROS2_HEADER.fullmatch(header) is not None and self.message_header(header):
                changed = True  # made as a parse asks it on demand (``message_header``):
                continue  # a header is the same whichever question of which process made it
            self._handled.add(header)
            spec = self._message_header(header)
            if spec is None or not self._message(header, spec.group(1), spec.group(2), where):
                self._empty(header, where)
            changed = True
        return changed


# -- the precompiled prelude -----------------------------------------------------------

_PCH: dict[tuple[str, ...], str | None] = {}
_PCH_LOCK = threading.Lock()


def precompiled_prelude(flags: Sequence[str]) -> str | None:
    """A PCH of the stand-in headers for these language ``flags``, built once per process.

    None when libclang cannot build it; parsing then reads the headers every time.
    """
    key = tuple(flags)
    with _PCH_LOCK:
        if key in _PCH:
            made = _PCH[key]
            # a file gone since (a cleaner of the temporary folder, the run still going)
            # is made again: libclang refuses every unit that names it
            if made is None or os.path.isfile(made):
                return made
        folder = tempfile.mkdtemp(prefix="haros-arch-pch-")
        # removed when this process ends, a pool's worker too (``atexit`` handlers do
        # not run there: ``models build --jobs`` left one folder per worker)
        processes.remove_at_end(folder)
        path: str | None = os.path.join(folder, "prelude.pch")
        args = ["-I", STANDIN, "-isystem", STD_STANDIN, *flags, "-x", "c++-header"]
        # from C++20 on, libclang refuses (``Error parsing translation unit``) a PCH made
        # without the detailed preprocessing record to a unit parsed with it
        # (``PARSE_OPTIONS``); before, the PCH stays as it was
        options = _PCH_OPTIONS | (_DETAILED_RECORD if any(
            _NEWER_STD.fullmatch(flag) for flag in flags) else 0)
        try:
            tu = toolchain.index().parse(PRELUDE, args=args, options=options)
            if any(d.severity >= 3 for d in tu.diagnostics):
                path = None
            else:
                tu.save(path)
        except (TranslationUnitLoadError, TranslationUnitSaveError):
            path = None
        _PCH[key] = path
        return path


def without_pch(args: list[str]) -> list[str] | None:
    """``args`` with the precompiled prelude they name (``-include-pch``) read from its
    header instead, the same declarations, for a parse libclang refused: a precompiled
    file cut short (a full disk) or removed while the run goes on, which is forgotten so
    that the next unit's is made again; None when they name none."""
    if "-include-pch" not in args[:-1]:
        return None
    at = args.index("-include-pch")
    with _PCH_LOCK:
        for key in [k for k, made in _PCH.items() if made == args[at + 1]]:
            del _PCH[key]
    return [*args[:at], "-include", PRELUDE, *args[at + 2:]]


def _fallback_file(header: str) -> str | None:
    """The stand-in of ``FALLBACK`` for ``header``, if there is one (not a name that leads
    out of the folder: ``../rclcpp/rclcpp.hpp``)."""
    name = os.path.normpath(header)
    if os.path.isabs(name) or name.startswith(os.pardir):
        return None
    path = os.path.join(FALLBACK, name)
    if os.path.isfile(path):
        return path
    umbrella = next((u for p, u in FALLBACK_UMBRELLAS.items() if name.startswith(p)), None)
    return os.path.join(FALLBACK, umbrella) if umbrella is not None else None


def _parents(path: str, root: str) -> list[str]:
    """The folders between ``root`` (excluded) and ``path``."""
    found = []
    folder = os.path.dirname(path)
    while folder.startswith(root + os.sep):
        found.append(folder)
        folder = os.path.dirname(folder)
    return found


def _sync(folder: str, wanted: Mapping[str, str], spared: set[str]) -> None:
    """Make ``folder`` hold exactly the files ``wanted`` (path -> text), and those
    ``spared``: a file of an earlier run that this one does not write is removed (a
    header clang would find where this run's repair says it is missing), one whose
    text differs is written again, one that is the same is left as it is."""
    for parent, _folders, files in os.walk(folder, topdown=False):
        for name in files:
            path = os.path.join(parent, name)
            if path not in wanted and path not in spared:
                with contextlib.suppress(OSError):
                    os.remove(path)
        if parent != folder and not os.listdir(parent):
            with contextlib.suppress(OSError):
                os.rmdir(parent)
    for path, text in wanted.items():
        data = text.encode("utf-8")
        try:
            with open(path, "rb") as handle:
                same = handle.read(len(data) + 1) == data
        except OSError:
            same = False
        if not same:
            if os.path.isdir(path):  # a folder of an earlier run where this one writes a file
                shutil.rmtree(path, ignore_errors=True)
            write_whole(path, text)


def _locked(folder: str) -> int | None:
    """The lock of a kept folder of synthesised headers (``<folder>.lock``) taken for
    this run, its descriptor; None when it cannot be opened or another run holds it."""
    try:
        lock = os.open(folder + ".lock", os.O_RDWR | os.O_CREAT, 0o644)
    except OSError:
        return None
    try:
        fcntl.flock(lock, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except OSError:
        os.close(lock)
        return None
    return lock


def _action_bases(name: str) -> Iterator[tuple[str, str]]:
    """Each (part, action) ``name`` may be the header of a part of (``DoActionGoal``:
    ``("ActionGoal", "Do")``, and ``("Goal", "DoAction")``)."""
    for part in interfaces.ACTION_PARTS:
        base = name.removesuffix(part)
        if base != name and base:
            yield part, base


def _action_path(folder: str, base: str) -> str:
    """Where the package in ``folder`` defines action ``base``."""
    return os.path.join(folder, "action", base + ".action")
