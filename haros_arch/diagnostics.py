"""The catalogue of diagnostic codes and the ``Diagnostic`` value.

Every problem found in the analysed workspace (a file that cannot be parsed, a launch
file that names a missing package, ...) becomes a ``Diagnostic`` with a stable code from
``CATALOGUE``; the run goes on with everything else. Tests assert on codes and
locations, never on prose.
"""

from __future__ import annotations

import os
import traceback
from collections.abc import Callable
from dataclasses import dataclass
from typing import TypeVar

from .model.diagnostic import SEVERITY_RANK, Diagnostic, Severity
from .model.location import NOWHERE, Location

__all__ = ["CATALOGUE", "SEVERITY_RANK", "Diagnostic", "Entry", "Severity", "make", "per_file"]

T = TypeVar("T")


@dataclass(frozen=True)
class Entry:
    severity: Severity
    template: str
    explanation: str


CATALOGUE: dict[str, Entry] = {
    # project file and workspace
    "PROJECT_YAML": Entry(
        "error", "project file is not valid YAML: {detail}",
        "The project file could not be read as YAML. Fix the syntax at the given line."),
    "PROJECT_SCHEMA": Entry(
        "error", "{detail}",
        "The project file is valid YAML but a key is unknown or a value has the wrong type."),
    "WORKSPACE_MISSING": Entry(
        "error", "workspace folder {path} does not exist",
        "A folder named by the project file's 'workspace' key is not there."),
    "FILE_UNREADABLE": Entry(
        "error", "cannot read {path}: {detail}",
        "A file of the workspace could not be opened or read; it is skipped."),
    "FILE_TOO_LARGE": Entry(
        "warning", "{path} is {size} bytes, above the limit of {limit}; skipped",
        "Files above the size limit are not analysed, so a hostile or generated file "
        "cannot exhaust memory."),
    "FILE_ENCODING": Entry(
        "warning", "{path} is not valid UTF-8; undecodable bytes were replaced",
        "The file was read with replacement characters where bytes were not UTF-8; "
        "names that contain them may be wrong."),
    # package manifests
    "PACKAGE_XML_SYNTAX": Entry(
        "error", "package.xml is not well-formed XML: {detail}",
        "The package manifest could not be parsed; the package is skipped."),
    "PACKAGE_XML_INVALID": Entry(
        "error", "package.xml is not a package manifest: {detail}",
        "The manifest lacks a required element (such as <name>) or its root is not "
        "<package>; the package is skipped."),
    "PACKAGE_MANIFEST_VARIANT": Entry(
        "warning", "folder {folder} has {names} but no package.xml: a manifest its build "
        "copies to package.xml; the package is not read (copy the one for your ROS there)",
        "A package that keeps one manifest per ROS version (livox_ros_driver2's "
        "package_ROS1.xml and package_ROS2.xml; its build.sh copies one to package.xml "
        "before building) is no package until one is copied: its nodes, and those launch "
        "files name from it, are not in the workspace."),
    "PACKAGE_BUILD_BY_ROS_VERSION": Entry(
        "info", "package {name} builds with {builds} (package.xml's build_type conditions "
        "over $ROS_VERSION) and this run names no ROS version: the executables and share "
        "folder of each build are read (give distro: in a project file, or run in a "
        "sourced ROS shell, to read one)",
        "A package kept for both ROS versions (CARLA's ros-bridge: a catkin CMakeLists.txt "
        "for ROS 1, setup.py's entry points for ROS 2) is built by the one the "
        "distribution's ROS_VERSION selects. With none given, the nodes of both builds "
        "are read, so that the ROS 1 and the ROS 2 launch files each find theirs, and a "
        "share folder (ROS 2's) is what the ROS 2 build installs."),
    "PACKAGE_DUPLICATE": Entry(
        "error", "package {name} is defined twice (also at {other})",
        "Two folders of the workspace declare the same package name; the first one "
        "found is used, as colcon and catkin refuse such workspaces."),
    "PACKAGE_NOT_FOUND": Entry(
        "error", "package {name} {why}",
        "A launch file, project file or $(find) names a package that is neither in the "
        "workspace nor on ROS_PACKAGE_PATH / AMENT_PREFIX_PATH, or one the workspace "
        "holds in a folder an ignore marker (COLCON_IGNORE, CATKIN_IGNORE, AMENT_IGNORE) "
        "leaves out, as colcon and catkin do: the marker file is named. A launch file's "
        "$(find) or FindPackageShare of a package not found is an info "
        "(LAUNCH_UNKNOWN_VALUE: installed where the robot runs, perhaps), unless the name "
        "is a letter or two from a package that is here: then it is this error, with "
        "the name it most likely misspells. A ROS 2 Python launch file's "
        "get_package_share_directory (or FindPackageShare(...).find()) of such a name is "
        "this error at the call, which raises PackageNotFoundError when it runs, whatever "
        "the conditions of the actions its value goes to."),
    # build files
    "CMAKE_SYNTAX": Entry(
        "error", "CMake syntax error: {detail}",
        "The CMake file could not be tokenised from this point on; commands read before "
        "it are still used."),
    "CMAKE_SOURCE_MISSING": Entry(
        "warning", "source file {path} of target {target} does not exist",
        "A build target names a source file that is not in the package (nor one a "
        "configure_file writes by that name in the build folder, where CMake looks "
        "next)."),
    "CMAKE_SOURCE_IN_SUBMODULE": Entry(
        "warning", "sources of target {target} lie in the git submodule {submodule} "
        "(declared at {declared}), which is not checked out here (git submodule update "
        "--init); their code is not read",
        "A build target names source files under a folder a .gitmodules file declares "
        "as a git submodule, and that folder is missing or empty, as a clone without "
        "--recursive leaves it (microstrain_inertial's driver compiles its "
        "microstrain_inertial_driver_common submodule). Not a missing file: the code is "
        "elsewhere. What it does stays unknown; check out the submodules to read it."),
    "CMAKE_SOURCE_OUTSIDE": Entry(
        "info", "sources of target {target} lie outside the workspace, in {folder}, and "
        "are not here; their code is not read",
        "A build target names source files by a path outside the workspace that does not "
        "exist on this machine: a library's sources installed where the robot is built "
        "(autonav's VectorNav SDK, /usr/local/vectornav/cpp/src). Not a missing file of "
        "the package; said once per target. Its code is read as an installed library's "
        "is: not at all, no ROS calls of its own."),
    "CMAKE_PROGRAM_NOT_IN_SOURCES": Entry(
        "info", "program {path} installed here is not in the sources; the package's "
        "{command} ({where}) may make it at build time",
        "install(PROGRAMS) names a file the source tree does not hold, in a package "
        "whose add_custom_target or add_custom_command runs commands whose outputs are "
        "not known statically (webots_ros2_driver's make builds webots/webots-controller): "
        "the file may exist once built, so it is not reported missing; if it is a node, "
        "its interface is unknown."),
    "CMAKE_PROGRAM_FROM_BUILD": Entry(
        "info", "program {path} is installed from the build folder; the build makes it, "
        "its code is not read",
        "install(PROGRAMS) names a file in the build folder (``${CMAKE_BINARY_DIR}``, "
        "``${CMAKE_CURRENT_BINARY_DIR}``), which a configure_file, a file(DOWNLOAD) or a "
        "custom command writes when the package is built (tucan_ros2's "
        "QGroundControl.AppImage): not a missing source; if it is a node, its interface "
        "is unknown."),
    "CMAKE_GUESSED_EXECUTABLE": Entry(
        "info", "{command}() is defined outside the workspace; {target} is taken as an "
        "executable built from {sources}, one of which defines main()",
        "A command the workspace does not define (a function of a package outside it, "
        "such as cartographer's google_binary) names a new target and C/C++ sources of "
        "the package, one of which defines main(): that executable is taken as built, "
        "linking the package's libraries its code names, so launch files that run it "
        "find it."),
    "CMAKE_GUESSED_LIBRARY": Entry(
        "info", "{command}() is defined outside the workspace; {target} is taken as a "
        "library built from {sources}",
        "A command the workspace does not define whose name says it makes a library "
        "(MOLA's mola_add_library, cartographer's google_library) names a new target and "
        "C/C++ sources of the package, none of which defines main(): that library is "
        "taken as built, so the package's executables made after it link it, as they do "
        "an add_library's (of which they run what their code names)."),
    "CMAKE_SUPERBUILD": Entry(
        "info", "ExternalProject_Add({name}) configures the package's own folder again "
        "with {values}; its targets are read from that configuration",
        "A superbuild: the package's CMakeLists.txt, as configured first, builds "
        "dependencies and then itself as an external project with other cache entries "
        "(USE_SUPERBUILD=OFF). The executables and libraries the package installs are "
        "those of the second configuration, which is read in place of the first."),
    "CMAKE_EXTERNAL_PROJECT": Entry(
        "warning", "ExternalProject_Add({name}) builds {folder} as a project of its own, "
        "whose executables are not read; the nodes it builds are unknown",
        "CMake configures and builds an external project's folder separately at build "
        "time; the executables its CMakeLists.txt builds (and the package installs) are "
        "not in the model, so launch files that run them and their interfaces are not "
        "known."),
    "CMAKE_LIMIT": Entry(
        "warning", "CMake evaluation bounded: {detail}",
        "The CMake interpreter bounds its work (commands evaluated, loop iterations, "
        "nesting of calls, includes and subdirectories) so a hostile or runaway build "
        "file cannot hang the analysis; targets declared past the bound are not seen."),
    "PYSETUP_SYNTAX": Entry(
        "error", "setup file cannot be parsed: {detail}",
        "setup.py or setup.cfg is read statically (never run); this one is not valid "
        "Python / INI, so its entry points are unknown."),
    "PYSETUP_DYNAMIC": Entry(
        "info", "{detail} in setup.py is computed in a way not evaluated statically",
        "setup.py goes through the safe evaluator (literals, module-level names, "
        "operators, f-strings, str methods, os.path, glob inside the package) under a "
        "work bound; an entry point built otherwise, or after the bound, is not found."),
    "PYSETUP_MODULE_MISSING": Entry(
        "warning", "module {module} of entry point {name} not found in the package",
        "A console_scripts entry point names a module with no .py file (or package "
        "__init__.py) in the package; the node is kept without sources."),
    "PLUGIN_XML_SYNTAX": Entry(
        "error", "plugin description is not well-formed XML: {detail}",
        "A plugin description file exported in package.xml could not be parsed; its "
        "nodelets and plugin classes are unknown."),
    "PLUGIN_LIBRARY_UNKNOWN": Entry(
        "warning", "no target of the package builds library {library} of plugin {plugin}",
        "The plugin description names a library that no add_library of the package "
        "builds and no PLUGINLIB_EXPORT_CLASS in a library names the class; the nodelet or "
        "plugin is kept without sources."),
    "PLUGIN_CLASS_NOT_BUILT": Entry(
        "warning", "no source that library {library} builds exports {cls} (plugin {plugin})",
        "The library's sources export other plugin classes (PLUGINLIB_EXPORT_CLASS and "
        "the like) but not this one: the file that does is not built by default (added "
        "under a CMake option or condition that is off), or exports it in a way not read. "
        "The nodelet or plugin is kept without sources: its interface is unknown."),
    "PLUGIN_NOT_FOUND": Entry(
        "warning", "plugin class {plugin} loaded by {host} is not exported by an analysed "
        "package",
        "A host node (controller manager, nav2 server or costmap, move_base) is told to "
        "load a plugin class that no analysed package exports in a plugin description (it "
        "comes from an installed package, its package is not among the project file's "
        "packages, or the name is wrong); the host instance is partial: the plugin's "
        "calls are unknown."),
    "HARDWARE_UNKNOWN": Entry(
        "info", "the hardware plugins of controller manager {host} are not known: {detail}",
        "A ROS 2 controller manager (ros2_control_node) loads the hardware plugins that the "
        "``<ros2_control><hardware><plugin>`` elements of its robot description name, and "
        "the description it reads (its ``robot_description`` parameter, or the topic of "
        "that name robot_state_publisher publishes) is not given by a xacro or cat command "
        "whose file is known, or parts of it are not; what its hardware code does with ROS "
        "is not known and the manager instance is partial."),
    "PLUGIN_CLASS_UNKNOWN": Entry(
        "warning", "the class of plugin {plugin} loaded by {host} is not known",
        "The parameter that gives the plugin's class (``<name>.plugin``, ``<name>.type``, "
        "``base_global_planner``, a spawner's parameter file) is not set or its value is "
        "not known statically; the host instance is partial (not for a ROS 1 controller "
        "whose type nothing may set: the manager refuses to load it)."),
    "BT_XML_SYNTAX": Entry(
        "error", "behavior tree file is not well-formed XML: {detail}",
        "A BehaviorTree.CPP tree file that a tree host (nav2's bt_navigator) runs could "
        "not be parsed; the calls of its nodes are unknown and the host instance is "
        "partial."),
    "BT_NODE_UNKNOWN": Entry(
        "warning", "behavior tree node {id} run by {host} has no registered class found",
        "No BT plugin library the host loads (BT_REGISTER_NODES in the libraries of the "
        "analysed packages) registers this tree ID: its calls are unknown and the host "
        "instance is partial."),
    "BT_LIBRARY_NOT_FOUND": Entry(
        "warning", "behavior tree library {library} loaded by {host} is not built by an "
        "analysed package",
        "The host's plugin library list names a library that no library target of an "
        "analysed package depending on BehaviorTree.CPP builds with BT_REGISTER_NODES; "
        "the nodes it registers are unknown and the host instance is partial."),
    "BT_TREE_NOT_FOUND": Entry(
        "warning", "behavior tree file {path} run by {host} cannot be found",
        "The parameter naming the tree file gives a path that is neither in the "
        "workspace nor in an installed package; its nodes' calls are unknown and the "
        "host instance is partial."),
    "PLUGIN_PARAM_FILE": Entry(
        "warning", "parameter file {path} of a controller spawner cannot be read",
        "A controller_manager spawner's --param-file names a file that does not exist, "
        "lies outside the workspace and installed packages, is not YAML, or is too big "
        "once its YAML aliases are expanded; the "
        "controllers it configures keep no parameters from it."),
    "ROBOT_DESCRIPTION_XACRO": Entry(
        "warning", "xacro: {detail}",
        "A xacro construct of a robot description is wrong (an unknown macro or block, a "
        "parameter not given, an expression Python would reject) or outside what is read "
        "statically; the part it makes is left out or written ?, and the description is "
        "partial."),
    "ROBOT_DESCRIPTION_FILE": Entry(
        "warning", "robot description file {path} cannot be read: {detail}",
        "A file of a robot description (the top file or a xacro:include) does not exist "
        "or is not well-formed XML; what it holds is unknown and the description is "
        "partial. A file the package's CMake writes into its folder with configure_file "
        "is read as written, from its template; the message names the command when a "
        "value it writes is not known here."),
    "ROBOT_DESCRIPTION_COMMAND_FAILS": Entry(
        "error", "robot description file {path} cannot be read: {detail}; the launch "
        "cannot load the parameter made of it and stops there",
        "A robot description file that the launch reads to set a parameter (ROS 1 "
        "``<param command=\"xacro FILE\">`` or ``textfile=\"FILE\"``, ROS 2 "
        "``Command(['xacro ', FILE])``) does not exist, nor a file it includes, or is "
        "not well-formed XML: xacro (``cat``, roslaunch's own read of a text file, for a "
        "missing file) fails, so roslaunch stops loading the launch (\"Cannot load "
        "command parameter\") and ros2 launch stops with a SubstitutionFailure, whether "
        "or not a node reads the description. Under a condition not known statically it "
        "is ROBOT_DESCRIPTION_FILE, a warning."),
    "ROBOT_DESCRIPTION_LIMIT": Entry(
        "warning", "robot description is too big to read: {detail}",
        "Reading a robot description stopped at a bound (files read, include and macro "
        "nesting, elements made, the length of a value); its plugins are unknown."),
    "ROBOT_DESCRIPTION_UNKNOWN": Entry(
        "info", "the robot description a spawner hands to Gazebo is not known: {detail}",
        "A Gazebo spawner names a description that is not read statically (a parameter "
        "no launch file sets with a xacro command, a -topic or -database source, a path "
        "with unknown parts); the Gazebo node instance is partial."),
    "GAZEBO_PLUGIN_UNKNOWN": Entry(
        "warning", "Gazebo plugin {filename} loaded by {host} is not known",
        "A <plugin> of a robot description names a library that is not in the table of "
        "Gazebo plugins (haros_arch/robot/gazebo_plugins.py), nor a Gazebo classic "
        "plugin a workspace package builds (a library registered with "
        "GZ_REGISTER_<KIND>_PLUGIN, whose calls are read from its C++), nor a gz sim "
        "system one builds (a library registered with GZ_ADD_PLUGIN or "
        "IGNITION_ADD_PLUGIN); its topics and services are unknown and the Gazebo node "
        "instance is partial."),
    "GAZEBO_PLUGIN_ARGUMENT": Entry(
        "warning", "<argument> {argument} of Gazebo plugin {name}: {detail}",
        "gazebo_ros hands a ROS 2 plugin's <ros><argument> texts to its node, each as one "
        "command-line word, ahead of the --ros-args of its <remapping> rules. rcl applies a "
        "from:=to word as a remap (a deprecated form, with a warning), and, after a "
        "--ros-args word, reads -r/--remap rules and its other flags. This argument is "
        "either ignored by rcl (one word with spaces, a word that is not a ROS argument "
        "where a ROS argument was meant) or rejected (the plugin's node cannot be made): it "
        "is not applied."),
    "GAZEBO_PLUGIN_ARGUMENT_UNKNOWN": Entry(
        "info", "<argument> {argument} of Gazebo plugin {name} is not known: {detail}",
        "A ROS 2 plugin's <ros><argument> has parts that are not known statically, or a "
        "form the tool does not model; its effect on the plugin node's names is unknown "
        "and the plugin's node instance is partial."),
    "BRIDGE_CONFIG_FILE": Entry(
        "warning", "config file {path} of a ros_gz bridge cannot be read",
        "A ros_gz_bridge parameter_bridge's config_file does not exist, lies outside the "
        "workspace and installed packages, or is not a YAML list of bridge entries; the "
        "topics it would bridge are unknown and the bridge's node is partial."),
    "GAZEBO_NOT_STARTED": Entry(
        "info", "no launch file of the configuration starts Gazebo; its node is taken as "
        "{name}",
        "A spawner hands a robot description to Gazebo, but Gazebo is started from a "
        "launch file outside the analysed packages; a node instance of that name stands "
        "for it, with the calls of the description's plugins and an unknown interface "
        "otherwise; when that launch file is gazebo_ros' own (one include of "
        "$(find gazebo_ros)/... not read), the interface of its gazebo node, gazebo_ros' "
        "gzserver, from the distribution's interface model."),
    # launch files
    "LAUNCH_FILE_MISSING": Entry(
        "error", "launch file {path} does not exist",
        "A configuration or an <include> names a launch file that is not there."),
    "LAUNCH_XML_SYNTAX": Entry(
        "error", "launch file is not well-formed XML: {detail}",
        "The launch file could not be parsed; nothing from it is used."),
    "LAUNCH_UNKNOWN_TAG": Entry(
        "warning", "unknown tag <{tag}> is ignored",
        "roslaunch ignores tags it does not know, with a warning; so do we. In a ROS 2 "
        "launch file an action tag comes from a launch extension an installed package "
        "exposes (ros_gz_bridge's <ros_gz_bridge>), else ros2 launch fails: it is kept "
        "as an action not interpreted, which may start anything."),
    "LAUNCH_UNKNOWN_ATTRIBUTE": Entry(
        "warning", "unknown attribute {attribute}= on <{tag}> is ignored",
        "The attribute is not part of the launch format for this tag."),
    "LAUNCH_UNEXPECTED_ATTRIBUTE": Entry(
        "error", "ros2 launch refuses <{tag}> with attribute {attribute}= (Unexpected "
        "attribute): the launch fails",
        "A ROS 2 XML / YAML action has an attribute launch does not read for it (ROS 1's "
        "required=, an arg's help=, a misspelling): launch checks an action's attributes "
        "after parsing it and stops with \"Unexpected attribute(s) found\". The rest of "
        "the file is still read here, for the other findings."),
    "LAUNCH_MISSING_ATTRIBUTE": Entry(
        "error", "<{tag}> needs attribute {attribute}=; the element is skipped",
        "A required attribute of a launch tag is missing."),
    "LAUNCH_DASHING_KEYWORD": Entry(
        "warning", "{action} is given {words} of Dashing's launch_ros that "
        "Foxy deprecated and Galactic removed: from Galactic on the launch file does "
        "not load (TypeError); the distribution here is {distro}; read as the newer "
        "keyword",
        "A Python launch file gives launch_ros' Node, ComposableNodeContainer or "
        "ComposableNode a keyword of its Dashing API (node_executable, node_name, "
        "node_namespace, node_plugin). Foxy accepts them with a deprecation warning; "
        "Galactic and every later distribution raise TypeError (unexpected keyword "
        "argument) and the whole launch file fails to load (urg_node 369ee4d's "
        "urg_node_launch.py). The tool reads them as the newer keywords, as Dashing to "
        "Foxy do; with the project's distro: (ROS_DISTRO) Galactic or later this is "
        "LAUNCH_DASHING_KEYWORD_REMOVED, an error, unless the call is made only under a "
        "Python test not known statically (a file that chooses the keywords by the "
        "release it runs on): then this warning, naming the test; Dashing or Eloquent, "
        "nothing."),
    "LAUNCH_DASHING_KEYWORD_REMOVED": Entry(
        "error", "{action} is given {words} of Dashing's launch_ros that "
        "{distro}'s does not take: the launch file does not load there (TypeError: "
        "unexpected keyword argument); read as the newer keyword",
        "A Python launch file gives launch_ros' Node, ComposableNodeContainer or "
        "ComposableNode a keyword of its Dashing API that the configuration's "
        "distribution (ROS_DISTRO, a project's distro:) no longer has: Galactic removed "
        "them, so the launch file fails to load there. The tool reads them as the newer "
        "keywords, to show what the file means."),
    "LAUNCH_BAD_VALUE": Entry(
        "error", "{detail}",
        "An attribute value of a launch tag cannot be used as written."),
    "LAUNCH_ARG_UNSET": Entry(
        "warning", "launch argument {name} has no value; names that use it keep '?'",
        "An $(arg) refers to an argument that was declared without a value and not "
        "given one (in a ROS 1 top-level file, or one it includes with pass_all_args, "
        "also an argument not declared at all: roslaunch takes every name:=value of "
        "its command line as an argument); what depends on it is kept with an unknown "
        "part. It is said once per configuration, at the first use, the other uses "
        "listed as its other places (also at). A ROS 2 configuration not seen "
        "declared after an action the reader could not see (a value not known among "
        "a launch description's entities, an include not read) may be declared there: "
        "LAUNCH_UNKNOWN_VALUE, undecided."),
    "LAUNCH_CONDITION_UNSET": Entry(
        "warning", "a condition tests launch configuration {name}, which nothing "
        "declares or sets here: launch takes it as unequal to any value, so what "
        "LaunchConfigurationEquals guards never runs (and what NotEquals guards always "
        "does)",
        "LaunchConfigurationEquals / LaunchConfigurationNotEquals of a configuration "
        "that no DeclareLaunchArgument, SetLaunchConfiguration or include argument gives "
        "a value: launch raises no error, it compares as unequal. Usually the name "
        "differs from the one declared (slam_toolbox_mode for slam_mode). Where an "
        "action the reader could not see may declare it, the condition is undecided "
        "instead (LAUNCH_UNKNOWN_VALUE)."),
    "LAUNCH_ARG_UNUSED": Entry(
        "info", "launch argument {name} is declared but nothing in the launch reads it: "
        "its value changes nothing",
        "A ROS 2 DeclareLaunchArgument (or <arg>) whose configuration no substitution, "
        "condition, include or function of the whole launch reads by name: the value "
        "given on the command line or its default is ignored, and ros2 launch -s offers "
        "an argument that does nothing. Mostly a leftover of a copied launch file, "
        "harmless; where a configuration of a near name is read where nothing has set it, it is "
        "most likely a misspelling, LAUNCH_ARG_MISSPELT. Not said when part of the launch "
        "was not seen (an include not read, a function not interpreted), when the name "
        "is written anywhere else in the launch files performed (an action the reader "
        "does not interpret may read it), nor for an argument a library's launch helper "
        "declares (moveit_configs_utils'), which the file calling it does not write. "
        "A ROS 1 <arg> is its file's own: said when nothing else in that file names it "
        "($(arg), $(eval), an include's value; comments aside, conditions or not), not "
        "for a file with <include pass_all_args> or an arg() of a name made in $(eval), "
        "nor for an installed package's file."),
    "LAUNCH_ARG_MISSPELT": Entry(
        "warning", "launch argument {name} is declared but nothing in the launch reads it, "
        "and a configuration of a near name is read where nothing has set it: {near}",
        "A ROS 2 DeclareLaunchArgument (or <arg>) nothing reads, beside a launch "
        "configuration of a near name that is read where nothing has declared or set it "
        "(a declaration in a file included later, navigation2's bringup declaring "
        "use_sim_time, comes too late for that read): one of the "
        "two names is most likely misspelt, so the declared default and any value given "
        "on the command line never reach what reads the other "
        "(raspimouse_slam_navigation_ros2 declared use_sim_tim and read "
        "LaunchConfiguration('use_sim_time', default='False'), so its default True never "
        "applied and nav2 ran on wall time)."),
    "LAUNCH_NODE_ARG_PATH_MISSING": Entry(
        "warning", "node {name} is given the path {path} on its command line, which is "
        "not there",
        "A node's command line (a ROS 1 node's args, a ROS 2 node's arguments) holds an "
        "absolute path into the workspace that does not exist: ROS 1's $(find pkg)/... is "
        "the package's own folder, ROS 2's share folder holds what the package's build "
        "installs, so the program is started with a file it cannot open (gazebo_ros' "
        "range_world.launch gave gzserver the world $(find gazebo_plugins)/test/"
        "test_worlds/gazebo_ros_range.W()orld; mycobot_ros2's detect_marker.launch.py "
        "gave rviz2 -d its package's config/mypal_260.rviz). A path with a part not "
        "known statically, a file the build makes, (ROS 1) a file another node of the "
        "launch writes (xacro -o), or (ROS 2) one the launch file writes as it runs "
        "(open(path, 'w'), xacro.open_output) is not judged; a search path, paths joined "
        "by ':', is judged path by path."),
    "LAUNCH_PARAM_PATH_MISSING": Entry(
        "warning", "parameter {name} is given the path {path}, which is not there",
        "A ROS 1 <param> sets a text value that is an absolute path into a package of the "
        "workspace, $(find pkg)/..., the package's own folder, and nothing is there: the "
        "node that reads it is handed a file it cannot open, as LAUNCH_NODE_ARG_PATH_MISSING "
        "says of a command line (mas_domestic_robotics' recognize_gesture_action.launch "
        "gave its detection server kwargs_file = $(find mdr_recognize_gesture_action)/"
        "object_detection_kwargs.yml, a file of the package's config/ folder). A path with "
        "a part not known statically, in a git submodule not checked out, under a name of "
        "output (a log, save or record path), or with no file extension (a folder the "
        "node may make) is not judged."),
    "LAUNCH_PROCESS_ARG_PATH_MISSING": Entry(
        "warning", "process {command} is given the path {path} on its command line, which "
        "is not there",
        "A ROS 2 launch file's ExecuteProcess (an <executable cmd=...>) that starts no node "
        "the reader can name holds, among its arguments, an absolute path into the "
        "workspace that does not exist (rviz2 -d of a package's share folder, python3 of "
        "a script there): the share folder holds what the package's build installs, so "
        "the program is started with a file it cannot open, as LAUNCH_NODE_ARG_PATH_MISSING "
        "says of a node's arguments. A path with a part not known statically, a file the "
        "build makes, one in a folder the package does not hold (the launch file may make "
        "it), one the launch file writes as it runs (open(path, 'w'), xacro.open_output) "
        "or given to an option of output is not judged."),
    "LAUNCH_INCLUDE_ABSOLUTE": Entry(
        "warning", "launch file {path} is included by an absolute path this file writes "
        "out; it is there only on the machine that wrote it",
        "An include names its file by a path into one machine's folders (/home/<user>/..., "
        "/Users/..., /root/..., a mount), written in the launch file itself: another "
        "checkout, a container or the robot has other folders, and the include fails "
        "there (ros2_kortex's gen3_dual.launch.py included kortex_control.launch.py from "
        "/home/<developer>/.../install/kortex_bringup/share/...). The file is not read "
        "(LAUNCH_UNKNOWN_VALUE). Fix: $(find pkg)/... (ROS 1), FindPackageShare or "
        "$(find-pkg-share pkg) (ROS 2)."),
    "LAUNCH_PATH_JOIN_ABSOLUTE": Entry(
        "warning", "path join part {part} starts with '/': it drops the parts before it, "
        "the path is {path}",
        "os.path.join, launch's PathJoinSubstitution and a pathlib path start again at a "
        "part that is an absolute path: [FindPackageShare('gazebo_ros'), 'launch', "
        "'/gazebo.launch.py'] is /gazebo.launch.py, not the file in the package's launch "
        "folder (a leading slash written as for a list joined by concatenation). The "
        "path is kept as launch makes it."),
    "LAUNCH_UNSUPPORTED": Entry(
        "warning", "{detail}",
        "A launch construct that the static interpreter does not evaluate; what it "
        "would produce is unknown."),
    "LAUNCH_IF_AND_UNLESS": Entry(
        "error", "<{tag}> has both if= and unless=",
        "roslaunch refuses an element with both attributes; the element is skipped."),
    "LAUNCH_INCLUDE_CYCLE": Entry(
        "error", "include cycle: {path} is already being included",
        "A launch file includes itself, directly or through other files; roslaunch would "
        "recurse until it fails. The repeated include is skipped."),
    "LAUNCH_REMAP_ILLEGAL": Entry(
        "error", "remap {rule} given to {node}: {side} is not a legal ROS 2 name "
                 "({why}){more}; rcl refuses the rule, so the node does not start",
        "A ROS 2 launch file gives a node (or a component) a remap rule whose source or "
        "target, as the launch values make it, is not a name rcl accepts: a character "
        "other than letters, digits, '_', '/', '~' and {substitutions} (a '-', a "
        "backquote), a part starting with a digit, '//', a '/' at the end. rcl fails to "
        "parse the node's arguments, and the node exits at start (a container refuses to "
        "load the component). Rules with parts not known statically are judged on what "
        "is known."),
    "LAUNCH_NODE_NAME_ILLEGAL": Entry(
        "warning", "node name {name} is not a legal ROS name: roslaunch warns, a roscpp "
                   "node refuses it when it starts, rospy warns",
        "A ROS 1 <node> is named with a character a ROS name may not hold (a '-' of a "
        "host name an argument gives, a '.'): roslaunch starts it with a warning, "
        "roscpp's ros::init throws InvalidNameException and the node exits, rospy warns "
        "and runs. Tools that list the graph may not find it by name."),
    "LAUNCH_NODE_NAME_REFUSED": Entry(
        "error", "node name {name} is not one rmw takes (letters, digits and '_', not "
                 "starting with a digit): the node does not start",
        "A ROS 2 launch file names a node (name=, __node:=) with a character a node name "
        "may not hold, a '-' or a '.' most often: rcl_node_init fails with an invalid "
        "node name and the process exits; a container refuses to load the component."),
    "LAUNCH_NODE_DUPLICATE": Entry(
        "error", "launch starts two nodes named {name} (also at {other})",
        "roslaunch refuses a launch whose node names collide (two $(anon x) of one "
        "file are one name; those of two includes of it are two). A name with unknown "
        "parts collides only where they are the same arguments or environment variables "
        "not known here: /dvrk/$(arg master)/jsp and /dvrk/$(arg slave)/jsp are one name "
        "only when both are given one value, which is not said. When both start at one "
        "place (one file included twice), the message names the include of each."),
    "LAUNCH_ARG_UNDEFINED": Entry(
        "error", "argument {name} is not defined here",
        "$(arg) names an argument that is neither declared in this scope nor passed "
        "(in an included file; the top-level file may get it from the command line, "
        "LAUNCH_ARG_UNSET); roslaunch refuses the file. The value is kept unknown."),
    "LAUNCH_ARG_REQUIRED": Entry(
        "error", "{path} requires argument {name}, which the include does not pass",
        "An included file uses an argument it declares without a value, and the <include> "
        "gives none; roslaunch refuses this. The value is kept unknown."),
    "LAUNCH_TEST_LEFT_OUT": Entry(
        "info", "<test> {name} is started by rostest only; left out of this configuration",
        "roslaunch does not start <test> nodes, rostest does. A configuration that is a "
        "rostest run says so in the project file (rostest: true) and keeps them."),
    "LAUNCH_UNKNOWN_VALUE": Entry(
        "info", "{detail}; what depends on it keeps '?'",
        "A substitution's value cannot be known statically (an unset environment "
        "variable, a package that is not found, a command that is never run, a ROS 2 "
        "launch configuration not seen declared where actions the reader could not see "
        "may declare it: the message names their places)."),
    "LAUNCH_YAML": Entry(
        "error", "{detail}",
        "The YAML of a <rosparam> or a type=\"yaml\" parameter cannot be used."),
    # ROS 2 launch files
    "LAUNCH_YAML_SYNTAX": Entry(
        "error", "YAML file cannot be read: {detail}",
        "A YAML launch file or parameter file is not valid YAML (or not shaped as one); "
        "nothing from it is used."),
    "LAUNCH_PY_SYNTAX": Entry(
        "error", "Python launch file cannot be parsed: {detail}",
        "The file is not valid Python (or too deeply nested to parse safely); nothing "
        "from it is used. It is never imported nor run."),
    "LAUNCH_PY_UNSUPPORTED": Entry(
        "warning", "{detail}",
        "A Python launch file uses a construct outside the subset the static "
        "interpreter evaluates (an unknown call, a while loop, an import of the "
        "workspace's own modules, ...). It is not run: its result is unknown, and what "
        "depends on it keeps '?' parts or a condition. Said once, where the construct "
        "is, not again where its value is used."),
    "LAUNCH_PY_EXIT": Entry(
        "warning", "{detail}: the launch file stops here, ros2 launch starts nothing of it",
        "A Python launch file calls sys.exit() / exit() / quit() / os._exit(), or raises "
        "an exception that no try around it catches, where it runs whatever the "
        "arguments: generate_launch_description() never returns, and ros2 launch ends "
        "with an error. Nothing of the file is read (what it would start is not known). "
        "Where it stops only under a test not known statically (an else after the "
        "releases it knows), that branch ends there and the rest of the file runs "
        "under the other branch's test, as after a return; that is not said."),
    "LAUNCH_PY_FILE_UNKNOWN": Entry(
        "warning", "{detail}",
        "A Python launch file reads a file (open(), yaml.safe_load, a pathlib path's "
        "read_text) that is not in the workspace, lies outside it, or whose path is not "
        "known statically. Its content is unknown, and what the code makes of it keeps "
        "'?' parts. A file's content reads no launch configuration by itself, so the "
        "arguments an include passes are still judged on the rest of the included "
        "files."),
    "LAUNCH_PROCESS": Entry(
        "info", "process {command} started here is no node the reader can name",
        "A launch file runs a process (ExecuteProcess, <executable>) whose command line is "
        "not 'ros2 run PKG EXE ...', 'ros2 topic pub ...', 'ros2 service call ...' nor "
        "'ros2 control load_controller ...', read as nodes, nor "
        "'ros2 launch PKG FILE ...', read as that launch file: a "
        "simulator, a converter, a test binary, a script. If it starts ROS nodes, they "
        "are not in the graph: a finding that claims an absence (nobody publishes, "
        "nobody reads) may be contradicted by them. A ROS 2 command not interpreted "
        "(ros2 bag play, which publishes what was recorded) is such a node for the "
        "queries: an absence it may be the missing side of is undecided, named in the "
        "-undecided info."),
    "LAUNCH_MOVEIT_DESCRIPTION_TOPIC": Entry(
        "info", "{detail}",
        "A MoveItConfigsBuilder loads the robot description from a file of a workspace "
        "package that is not there, with no substitution among its xacro arguments: "
        "moveit_configs_utils catches the error, warns and leaves the description out "
        "of the configs it builds (MoveIt then reads the one published on "
        "/robot_description). The nodes given those configs get no robot_description "
        "parameter from them."),
    "LAUNCH_PY_LIFECYCLE": Entry(
        "info", "lifecycle transitions requested here are read as changing nothing in "
        "the graph",
        "A Python launch file emits lifecycle events (ChangeState) or handles a managed "
        "node's transitions (OnStateTransition). A transition changes no node of the "
        "graph: each managed node is taken with the whole interface its code makes, as "
        "once configured, whatever state the launch file drives it to. The actions an "
        "OnStateTransition handler runs are read, under that event. Said once per file."),
    "LAUNCH_PY_ALWAYS_TRUE": Entry(
        "warning", "the Python test '{test}' is always true: a launch object is not "
        "evaluated by Python",
        "A Python 'if' of a launch file tests a launch object itself (a condition such as "
        "LaunchConfigurationEquals(...), a substitution, an action). Python takes such an "
        "object as true, whatever the launch arguments: launch evaluates a condition "
        "only when it is an action's condition=. The 'if' branch is the one read, as it "
        "is the one that runs; the file probably meant condition=IfCondition(...) or "
        "the configuration's value performed in an OpaqueFunction. A launch object "
        "compared with '!=' or 'is not' is always unequal too (launch's classes define no "
        "__eq__: Python compares them by identity). A warning, as LAUNCH_PY_BOOLEAN_OBJECT "
        "is: the launch argument the test reads changes nothing of what starts."),
    "LAUNCH_PY_BOOLEAN_OBJECT": Entry(
        "warning", "Python's '{op}' takes the launch object '{test}' as true without "
        "evaluating it: the '{op}' {result}",
        "An 'and' / 'or' of a launch file's Python has a condition or a substitution as "
        "an operand before its last (condition=IfCondition(a) and IfCondition(b), "
        "LaunchConfiguration('ns') or 'robot'). Launch's classes define no __bool__: "
        "Python takes the object as true whatever the launch arguments, so the 'and' "
        "gives its last operand whole (IfCondition(b) alone decides) and the 'or' the "
        "object itself (the fallback is never used). Fix: AndSubstitution / "
        "OrSubstitution, one PythonExpression, or the value performed in an "
        "OpaqueFunction."),
    "LAUNCH_PY_ALWAYS_FALSE": Entry(
        "warning", "the Python test '{test}' is always false: a launch object is not "
        "evaluated by Python",
        "A Python 'if' of a launch file compares a launch object itself with a value "
        "(LaunchConfiguration('sim') == 'true') or tests 'not' of one. Python "
        "compares such an object by identity and takes it as true, whatever the launch "
        "arguments, so the test is always false: the 'else' branch is the one read, as "
        "it is the one that runs. The file probably meant a condition= "
        "(LaunchConfigurationEquals, IfCondition(PythonExpression(...))) or the "
        "configuration's value performed in an OpaqueFunction. A warning: the branch the "
        "test guards never runs, whatever the launch arguments (sjtu_drone's "
        "controller == 'joystick' never started the joystick teleop)."),
    "LAUNCH_PY_BUDGET": Entry(
        "warning", "interpretation stopped: {detail}",
        "A launch file exceeded a bound of the static interpreter (steps, call depth, "
        "size of a value, number of actions). What was computed before is kept."),
    "LAUNCH_CONTAINER_EXTERNAL": Entry(
        "info", "components are loaded into the container {container}, which this "
        "configuration does not start: it runs elsewhere, with components not seen here",
        "A launch file loads components into a container that no launch file of the "
        "configuration starts (another launch file runs it); what else runs in that "
        "container is not seen, so checks that claim an absence do not decide."),
    "LAUNCH_PARAM_FILE": Entry(
        "warning", "{detail}",
        "A parameter file given to a node cannot be read or matched statically; the "
        "parameters it would set are unknown."),
    "LAUNCH_PARAMS_OUTSIDE": Entry(
        "error", "parameter file {file}: {keys} hold a value outside ros__parameters, "
        "a parameter of no node",
        "In a ROS 2 parameter file, the keys above ros__parameters spell a node's name "
        "(node: ros__parameters: name: value); a value written there (a section that "
        "lacks its ros__parameters level) belongs to no node. rcl refuses the whole file "
        "(\"Cannot have a value before ros__parameters\"), so a node given it on its "
        "command line does not start. Fix: put the values under the node's "
        "ros__parameters."),
    "LAUNCH_PARAMS_MIXED_SEQUENCE": Entry(
        "error", "parameter file {file}: {keys}: a sequence of elements of more than one "
        "type, which rcl refuses",
        "rcl reads a ROS 2 parameter file's sequence as an array of one type (bool, "
        "integer, double or string), taken from its first element; an element of "
        "another type (0 among doubles: write 0.0) makes it refuse the whole file "
        "(\"Sequence should be of same type\"), so a node given it on its command line "
        "does not start. launch_ros promotes such a list to doubles only in a launch "
        "file's own dictionaries. clearpath_sensors' microstrain_imu.yaml (a0f07cfb^) "
        "wrote imu_orientation_cov: [0.01, 0, 0, ...]."),
    "LAUNCH_PARAMS_SET": Entry(
        "warning", "parameters holds the set {text}, not a dictionary: launch_ros takes "
        "it for a parameter file's path, which is no file, and the node gets none of it",
        "A Python launch file writes an item of a node's parameters as {\"name\", "
        "value} (a set, a comma where the dictionary {\"name\": value} has a colon). "
        "launch_ros takes an item that is no mapping for the path of a parameter file, "
        "made of the set's items in an order Python does not fix; no such file exists, "
        "so it warns \"Parameter file path is not a file\" and the node starts without "
        "those parameters. yolo_ros' yolov8_3d.launch.py (7d3292d^) gave detect_3d_node "
        "its maximum_detection_threshold so."),
    "LAUNCH_SUBST_UNCLOSED": Entry(
        "warning", "the substitution \"{text}\" is never closed: roslaunch keeps it as "
        "plain text",
        "A ROS 1 launch attribute holds $( without its closing parenthesis. roslaunch "
        "substitutes only what it finds closed and says nothing of the rest, so the value "
        "is the text as written: a parameter \"$(arg flag\" (a string, not the "
        "argument's value), an include or file path that does not exist. Fix: add the "
        "missing ')'."),
    "LAUNCH_PARAM_SET_TWICE": Entry(
        "warning", "parameter {name} is set again here (first at line {line}): roslaunch "
        "keeps the last value, the first is never used",
        "Two <param> tags of one element (a node, group or launch file) set the same "
        "name under the same conditions. roslaunch does not complain: it keeps the value "
        "of the later tag, so the earlier one is dead, which usually means that one of "
        "the two names is a typo of a parameter never set (diffbot's amcl.launch sets "
        "kld_err twice, kld_z never). Not said for tags with an if / unless of their "
        "own, nor across files (an including file overriding an included one's value). "
        "Fix: correct the name of one of them, or delete the one that is not meant."),
    "LAUNCH_PARAM_LOADED_OVER": Entry(
        "warning", "parameter {name} set here is loaded again by a later <rosparam> "
        "({other}): roslaunch keeps the later value, this one is never used",
        "A <param> outside a node sets a name that a later <rosparam> of the same element "
        "(a group or launch file) loads again, under the same conditions: <param "
        "name=\"arm/speed\"> then <rosparam ns=\"arm\" file=...> whose file has speed. "
        "roslaunch adds both to its parameters in document order and keeps the later "
        "value without a word, so the <param> is dead though it reads as the override "
        "of the file. Not said for tags with an if / unless of their own, nor for a "
        "<rosparam> before the <param> (the usual override, which wins). Fix: move the "
        "<param> after the <rosparam>, or delete it."),
    "LAUNCH_PARAM_FILE_KEY_TWICE": Entry(
        "warning", "key {key} is written again here (first at line {line}) in the same "
        "mapping of this parameter file: {reader} keeps the later value, the first is "
        "never used",
        "One mapping of a parameter file (a ROS 2 file a node is given, a ROS 1 "
        "<rosparam file>) writes a key twice. YAML says keys are unique, but rcl's "
        "parameter file parser and PyYAML (roslaunch) accept the file and keep the "
        "later value without a word, so the earlier one is dead, which usually means "
        "one of the two is a parameter written under the wrong name (wato_monorepo's "
        "nuscenes_config.yaml wrote publish_clusters_topic twice, the second for the "
        "points in a box, so the node's two publishers took one topic and the clusters' "
        "topic lost its publisher). Not said of a key written twice with a mapping both "
        "times in a ROS 2 file (rcl merges them); said in a ROS 1 <rosparam> file, whose "
        "PyYAML reading keeps the later mapping whole and drops the first one's keys. "
        "Fix: rename the one meant for another parameter, or "
        "delete the one that is not meant."),
    "LAUNCH_PARAM_OVERRIDDEN": Entry(
        "warning", "parameter {name} given to {node} {given} is set again to {kept} by "
        "{file}, later in its parameters: the later value is the one kept, so this one is "
        "never used",
        "A dictionary among a ROS 2 Node's or ComposableNode's parameters gives a "
        "parameter that a parameter file later in the same list sets again for that node. "
        "launch_ros hands a node's list to rcl in order, each dictionary as a file of its "
        "own (a component's as one list of overrides in order, which rclcpp reads the "
        "same way), and the last value of a name wins without a word, so the "
        "dictionary's value is dead: where it is a launch argument's, that argument "
        "changes nothing (roverrobotics_ros2's robot_localizer_outdoor.launch.py gave its "
        "EKFs [{'use_sim_time': use_sim_time}, localization_outdoor_ekf.yaml], whose "
        "sections say use_sim_time: false, so use_sim_time:=true never reached them). "
        "Said when the dictionary's value comes from substitutions or differs from the "
        "file's. Also said, at the SetParameter, for a SetParameter in scope whose value "
        "comes from substitutions and which the node's own parameter file sets again with "
        "a value written in it: launch_ros gives the node the SetParameter values first, "
        "so that its own win, and the launch argument reaches every node but this one (a "
        "SetParameter of a written-out value is a default a node's file may mean to "
        "change, and a rewritten file, nav2's RewrittenYaml of the same argument, is not "
        "judged). Fix: put the dictionary after the file, or delete the key from one of "
        "them."),
    "LAUNCH_PARAMS_NO_NODE": Entry(
        "warning", "parameter file {file} is given to {nodes}, but its sections are for "
        "{patterns}: rcl gives their parameters to none of them",
        "A ROS 2 parameter file applies a section (the keys above ros__parameters) only to "
        "a node whose full name it matches. Every section of this file is for a name that "
        "none of the nodes it is given to has, nor a node their processes make (a file "
        "written for another node name, imu_filter: for a node launched as "
        "imu_filter_node), so none of its parameters is set and the node runs on its "
        "defaults. Also said for a file shared by several nodes for one of them that no "
        "section is for, naming only the sections no node has that are named after that "
        "node's executable or the name its code gives it (go2_ros2_sdk's /teleop_node: "
        "for teleop_twist_joy's teleop_node launched as go2_teleop_node): the section "
        "written before the launch file renamed the node, or, with no wildcard, after "
        "the node's launch name in another namespace (/cabot/people_speed_control_node "
        "for the node started without namespace /cabot), or, for a component, after the "
        "executable its package registers to run it alone (pointcloud_to_laserscan_node: "
        "for the component loaded as pointcloud_to_laserscan). Not said when a node it is "
        "given to may make nodes unseen (code not known, plugins loaded by name). Fix: "
        "key the section by the node's name (or /**), or launch the node under the "
        "name and namespace the file uses."),
    # sources
    "CPP_PARSE_ERROR": Entry(
        "info", "C++ error: {detail}",
        "libclang reported an error in this translation unit; calls in the parts it "
        "could parse are still extracted. Sources are parsed against our stand-in headers "
        "(no ROS install needed), so in code that builds with the real headers this "
        "usually marks an API our stand-ins do not declare, not a mistake in the code; "
        "it is information, and does not fail `check --fail-on warning`."),
    "CPP_PARSE_FAILED": Entry(
        "error", "C++ file could not be parsed: {detail}",
        "libclang could not produce a translation unit; the file gives no calls."),
    "CPP_TIME_LIMIT": Entry(
        "error", "C++ file not analysed: its analysis passed {detail}",
        "The parses and the walk of this translation unit used more processor time "
        "than one unit may (real units take a few seconds), so it was stopped and gives "
        "no calls: the nodes built from it are partial. Most likely a case the analysis "
        "loops on; please report it with the file. The run goes on with the other units."),
    "CPP_CALL_MISSED": Entry(
        "info", "{text} calls the ROS API, but no call was extracted there",
        "A grep finds a call of a ROS API function (or of one of the unit's own wrappers "
        "of it) on this line, and the extraction has no call within two lines of it: an "
        "error made the code around it unreadable to the parse (a class made invalid), "
        "or the walk does not reach it. The node is 'partial'."),
    "CPP_ERROR_NEAR_CALL": Entry(
        "info", "C++ error in {function} (lines {start}-{end}), which calls the ROS API: "
        "{detail}",
        "An error the parse could not get past is inside a function that calls the ROS "
        "API, so a call there may be missing or read with a wrong name or type. The node "
        "is 'partial'. Errors in code that calls no ROS API cannot hide a call and leave "
        "the node complete, as does an unqualified call of a standard function clang "
        "could not find through its arguments' types (make_pair(x->name(), x) with x of "
        "a header the parse lacks) outside the statement of a ROS call, or a reinterpret_cast "
        "clang refuses there (a value of code the parse does not read cast to a pointer: "
        "reinterpret_cast<QGLMap*>(centralWidget()) with Qt's header a stand-in)."),
    "CPP_PLUGINS_LOADED": Entry(
        "info", "{text}: loads plugin classes through {loader}",
        "The code creates instances of plugin classes by name (pluginlib's "
        "createSharedInstance / createUniqueInstance / createUnmanagedInstance / "
        "createInstance), or loads nodelets by name in its own process (nodelet::Loader's "
        "load(name, type, ...), as image_view's wrapper executable does; not when a "
        "source of the node exports a plugin class: it links the nodelet's library, "
        "whose code is read with it), or registers the behavior tree node classes of a "
        "library it opens by name (BehaviorTree.CPP's registerFromPlugin: the trees it "
        "builds make their calls; a tree host of the table, nav2's bt_navigator or "
        "PlanSys2's bt_action_node, has its trees read instead). "
        "Their calls are made on this node but are not in its code: "
        "unless the node is a plugin host whose plugins are attached ([Plugins] in the "
        "README: nav2 servers, costmaps, move_base, controller managers, ...), each "
        "instance of it is 'partial', so checks that claim something is absent do not "
        "decide on it."),
    "CPP_NODELET_IN_PROCESS": Entry(
        "info", "runs the nodelet {cls} in its own process, under the node's own name",
        "The program loads a nodelet through nodelet::Loader's load(name, type, ...) with "
        "its own node name (ros::this_node::getName()) and a class written as a literal, "
        "not under a condition (image_view's, image_rotate's and image_publisher's wrapper "
        "executables): the nodelet's onInit runs as this node, with the node's namespace, "
        "private namespace and remaps, so each instance of the node makes the calls of "
        "the nodelet class (found as a launch file's 'nodelet standalone' finds it: in "
        "the package that exports it, else the interface models). A class found nowhere "
        "leaves the instance partial."),
    "CPP_PLUGIN_IN_PROCESS": Entry(
        "info", "creates the plugin class {cls} by its name written in the code",
        "The program creates a plugin instance through a pluginlib ClassLoader "
        "(createSharedInstance, createUniqueInstance, createInstance, ...) of a class "
        "written as a literal, not under a condition (cyberdog's sensor manager's "
        "createSharedInstance(\"cyberdog::sensor::GpsCarpo\")): the class is known, so "
        "each instance of the node makes its calls (the plugin class found by its lookup "
        "name or C++ type in the package that exports it, else the interface models), and "
        "the load is no cause of 'partial'. A class found nowhere, or partial, leaves the "
        "instance partial."),
    "CPP_LIBRARY_LOADED": Entry(
        "info", "{text}: loads a shared library chosen at run time",
        "The code opens a shared library by name (POSIX dlopen, Windows LoadLibrary): "
        "MOLA's mola-cli loads the modules its YAML file lists, its ROS 2 bridge among "
        "them. What that library does on the node is not in the node's code: the node "
        "is partial, so checks that claim something is absent do not decide on it."),
    "CPP_NODE_PASSED": Entry(
        "info", "{cls} of package {package} is built with the node ({given}) in code that "
        "is not read with this node",
        "The node constructs a class of another package, giving it the node (or its "
        "handle), and that class's constructor is defined in a source of the other "
        "package: the ROS calls it makes on the node are not read. The node is "
        "'partial', so checks that claim something is absent do not decide on it."),
    "CPP_MACRO_DEMANDED": Entry(
        "info", "{macro} is defined for this unit's parse: the #error at {where} says every "
        "build that compiles it defines {macro}",
        "A header the unit includes stops the compiler unless a macro is defined "
        "(#ifndef X / #error, or #ifdef X ... #else / #error: beluga's NDT sensor model "
        "needs BELUGA_HAS_HDF5, which its CMake gives only where HDF5 is found). Any "
        "build that makes the node defines it, so the unit is parsed with it; without it "
        "the header declared nothing and the code built on it was read wrongly. Nothing "
        "to do, unless the macro is never meant to be defined."),
    "CPP_BUILD_MACRO": Entry(
        "warning", "{text}: under a condition on {macro}, which the package's CMake defines "
        "({cmake}) and the extraction does not apply",
        "The package's CMake files define a macro for the compiler (add_definitions, "
        "add_compile_definitions, target_compile_definitions: a package built for ROS 1 "
        "and ROS 2 from one tree, livox_ros_driver2's BUILDING_ROS2) and this source, or "
        "a header of the package that a node's source includes (ros_deep_learning's "
        "ros_compat.h), chooses ROS calls with it (#if / #ifdef / #elif). The extraction "
        "applies such a macro to the sources of the targets it belongs to, but not this "
        "one: it is "
        "defined under an if() the analysis cannot decide (an environment setting, a "
        "found package's version), differently for two targets that compile the source, "
        "or in a way the CMake reading does not follow. These calls may be missing or "
        "the other branch's read instead. The node is 'partial'; give the analysis the "
        "workspace's compile_commands.json (colcon build "
        "--cmake-args -DCMAKE_EXPORT_COMPILE_COMMANDS=ON) to read the build's code."),
    "CPP_TARGET_UNKNOWN": Entry(
        "warning", "{text}: under '#if {condition}', which this parse leaves out: it reads "
        "the code for the processor of the machine that runs the analysis",
        "The code chooses ROS calls by the processor it is compiled for (__arm__, "
        "__aarch64__, __x86_64__, ...: a camera driver for a Raspberry Pi builds its node "
        "only for ARM and a stub that exits on a PC). The C++ parse reads the code for the "
        "processor of the machine that runs the analysis, and which processor the robot "
        "has is not known, so this call, which the code makes on another processor, is "
        "not read. The node is 'partial', so checks that claim something is absent do "
        "not decide on it."),
    "CPP_VERSION_UNKNOWN": Entry(
        "warning", "{text}: under '#if {condition}', which this parse leaves out as it "
        "takes {library} to be {version}",
        "ROS code chooses ROS calls by its client library's version (rclcpp/version.h's "
        "RCLCPP_VERSION_GTE, RCLCPP_VERSION_MAJOR, ...; roscpp's ROS_VERSION_MINIMUM, "
        "...), and the analysis knows no distribution of that ROS: neither the project "
        "file's 'distro' nor ROS_DISTRO in the environment names one (or the "
        "configurations' ROS_DISTRO differ: the sources are read once). The stand-in "
        "headers then announce Jazzy's rclcpp (Noetic's roscpp); the unit is parsed again "
        "with the newest other version that may take a branch left out, another "
        "release's or one the chain's conditions name (RCLCPP_VERSION_GTE(29, 6, 0): "
        "29.6.0; three more parses at most), and the calls of each branch it reads are "
        "made under that branch's condition. This branch no parse read whole: no version "
        "the parses took takes it, or the parse that took it left an error in it, so "
        "this call, which "
        "another release makes, is not read. The node is 'partial', so checks that claim "
        "something is absent do not decide on it; set 'distro:' in the project file "
        "(humble, iron, jazzy, kilted, rolling; kinetic, melodic, noetic) to read the "
        "code of that release."),
    "CPP_CLASS_UNSEEN": Entry(
        "info", "{cls} of ROS package {package} is built here and its code is not read",
        "A ROS 1 node builds an object of a class of another ROS package (one that "
        "depends on roscpp, or a dependency of the node's package whose headers are "
        "missing) whose constructor's code the extraction does not have. In ROS 1 any "
        "code can make its own NodeHandle, so such a class may read parameters and make "
        "topics and services under the names it is given (costmap_2d's Costmap2DROS, a "
        "local planner) without being handed the node. The node is 'partial', so checks "
        "that claim something is absent do not decide on it. Classes whose API the "
        "extractor models (tf, image_transport, actionlib, message_filters, ...) do not "
        "count, nor a class whose members a source of the node defines (a library it links: "
        "then this is not said). ROS 2 code "
        "communicates only through a node it is given (CPP_NODE_PASSED, "
        "CPP_NODE_TO_UNKNOWN)."),
    "CPP_NODE_TO_UNKNOWN": Entry(
        "info", "the node ({given}) is given to {name}, which the parse does not know",
        "A call passes the node (or its handle or an interface of it) to a function or "
        "class whose declaration is not in the workspace (a vendor library's helper, such "
        "as a parameter getter): the ROS calls it makes on the node are not read. So does "
        "building such a class with an rclcpp::NodeOptions (a component class of a package "
        "not in the workspace): it is a node of its own in the process, whose interface is "
        "not read. The node is 'partial', so checks that claim something is absent do "
        "not decide on it. Not said when the call is also given a pointer to a member "
        "function of the node's class (a callback binding, ecl::Slot(&Node::cb, *this): "
        "the member's calls are read where it is defined)."),
    "CPP_NODE_UNREAD": Entry(
        "info", "the node is made by {name}, a library class whose own calls are read "
        "only in part",
        "The node is an object of a library class that our stand-ins declare (ros2_control's "
        "controller_manager::ControllerManager, which a node of the workspace may make "
        "itself, as ros2_control_node does): the name its constructor gives and the calls "
        "the API tables say it makes (the manager's services) are read, the rest of what "
        "its code makes on the node is not (its robot_description subscription, its "
        "parameters, the topics of newer releases). The node is 'partial', so checks that "
        "claim something is absent do not decide on it."),
    "CPP_NAMES_DECLARED": Entry(
        "info", "{count} name(s) unknown to the parse declared permissively "
        "({names}){included}; clang errors in this unit: {before} before, {after} after",
        "Names clang did not know (a type, namespace, template or base class of a library "
        "whose headers are not available) would make the classes that use them invalid "
        "and hide their calls. The extractor declared them as permissive stand-ins (a "
        "namespace; a class constructible from and convertible to anything, with any "
        "member; a template taking any arguments) and parsed the unit again. A name of "
        "a library the stand-ins provide (boost::optional reached through a missing "
        "header) is not declared permissively: the stand-in's header is included, and "
        "the name is listed apart."),
    "CPP_CALL_UNRESOLVED": Entry(
        "info", "this {function} call could not be resolved by the parse; it is kept by "
        "its name, with type {type}",
        "clang could not tell which function this call is (the object it is made on has a "
        "type that is unknown or was made invalid by an error, or an argument depends on a "
        "template's parameters). The call is kept as the "
        "ROS API function of that name, its name and values read as usual, its type as "
        "written when that names a ROS interface, else '?'."),
    "CPP_NODE_PARTIAL": Entry(
        "warning", "node {node}: its calls may be incomplete, {count} place(s) in its C++ "
        "sources where a ROS call may be missing (first: {first})",
        "Some of the node's code could not be parsed even after the names clang did not "
        "know were declared, and that code calls the ROS API (CPP_CALL_MISSED: a call "
        "site with no call extracted; CPP_ERROR_NEAR_CALL: an error inside a function "
        "that calls the API): calls there may be missing. The node model is "
        "'partial' (completeness, with the first reasons); checks that claim something "
        "is absent do not trust it."),
    "PY_NODE_UNSEEN": Entry(
        "info", "{cls} of {module}, a Python package not in the workspace, is built "
        "here and this program makes no node itself: that class makes it, its calls not "
        "read",
        "A Python program that imports rospy or rclpy makes no node in the code read "
        "(no init_node, no Node), yet builds an object of a class of a Python package "
        "the workspace does not hold and its package.xml does not name as a ROS package "
        "(pepper_sensors_py's camera.py builds PepperCam, a NaoqiCam of naoqi_sensors_py, "
        "whose module is naoqi_sensors; duckietown's DTROS). That class makes the node "
        "and may communicate and read parameters under any name: the node is 'partial' "
        "and checks that claim something is absent do not decide on it. Where the "
        "program makes its node itself, such classes are said in ROS 1, whose node is "
        "the process's (PY_MODULE_UNSEEN), and taken for libraries in ROS 2."),
    "PY_CLASS_UNSEEN": Entry(
        "info", "{cls} of ROS package {package} is built here and its code is not read",
        "A Python node builds an object of a class of a ROS package its package depends "
        "on, or one the tool has an interface model of (sound_play's SoundClient), that "
        "the workspace does not hold (an installed package), or of a module named "
        "after a package of the workspace, the node's own too, that the reader does "
        "not find in that package's sources (object_recognition_ros' setup.py puts its "
        "modules where only its build looks): such a class may be a "
        "node of its own or communicate through the node it is given (nav2_simple_"
        "commander's BasicNavigator is a node with a dozen action clients; smach_ros' "
        "IntrospectionServer publishes). Its calls are not read, so the node is "
        "'partial' and checks that claim something is absent do not decide on it. "
        "Messages, services and actions, the classes the API tables model (rospy, rclpy, "
        "actionlib, tf, tf2_ros, message_filters) and packages known to make no ROS call "
        "(tf_transformations, cv_bridge, image_geometry, ...) do not count."),
    "PY_FUNCTION_UNSEEN": Entry(
        "info", "{function} of ROS package {package} is given the node ({given}) here and "
        "its code is not read",
        "A Python node calls a function of a module named after a package of the "
        "workspace, the node's own too, that the reader does not find in that package's "
        "sources, or of a ROS package its package depends on that the workspace does not "
        "hold (an installed package), and passes it the node: an rclpy node (``self`` in "
        "a Node subclass, ``rclpy.create_node``'s), or in ROS 1, whose node is the "
        "process's, an object rospy made (a publisher, a subscriber, a service proxy). "
        "With it the function can make publishers, subscriptions, clients and parameter "
        "reads the model does not see (``setup_publishers(node)``), so the node is "
        "'partial' and checks that claim something is absent do not decide on it. The "
        "same modules count as for PY_CLASS_UNSEEN: not messages, services, actions, "
        "nor the standard library, client libraries, packages known to make no ROS call "
        "or pip libraries. A publisher an rclpy node made, passed alone, is not the "
        "node: a function given it can only publish on it."),
    "PY_MODULE_UNSEEN": Entry(
        "info", "{call} of {module}, a Python module the workspace does not hold and no "
        "list knows as a library, is called here in a ROS 1 node's process; its code is "
        "not read",
        "A ROS 1 Python node calls a function or builds a class of a module that the "
        "reader finds nowhere in the workspace and that is not the standard library "
        "(Python 2's too, tkFont, Queue, urllib2, and the modules later Python 3 releases "
        "dropped), a client library, a package known to make no ROS call, a pip library rosdep "
        "installs, nor a ROS package the tool knows of (those are PY_CLASS_UNSEEN and "
        "PY_FUNCTION_UNSEEN): mobiman's training node calls openai_ros' "
        "StartOpenAI_ROS_Environment(name), a ROS package its package.xml does not "
        "name, cloned beside the workspace, whose gym environment reads the parameters "
        "the launch file sets. rospy's node is the process's, so such code can read "
        "parameters, publish and subscribe without being given the node: the node is "
        "'partial' and checks that claim something is absent do not decide on it. "
        "Said once per module, at its first call. In ROS 2 a function must be given "
        "the node (PY_FUNCTION_UNSEEN)."),
    "PY_LAUNCHES": Entry(
        "info", "{call} starts the nodes of a launch file at run time (roslaunch's "
        "Python API); what it starts is not read",
        "A Python program runs roslaunch in its own process (``roslaunch.main(argv)``, "
        "``roslaunch.parent.ROSLaunchParent``, ``roslaunch.scriptapi.ROSLaunch``): magni's "
        "launch_core.py writes the robot's core launch file from a template and runs it. "
        "The nodes it starts, and what they communicate, are decided at run time, so "
        "the node is 'partial' and checks that claim something is absent do not decide "
        "on it, rather than take a robot's whole base for a node with no interface."),
    "PY_RUNS_ROS_TOOL": Entry(
        "info", "{call} runs rosrun, roslaunch, rosbag, rqt_bag, ros2 or a micro-ROS / "
        "XRCE-DDS agent at run time; the nodes it starts, or the topics a bag it plays or "
        "an agent bridges hold, are not read",
        "A Python program runs a command that starts ROS nodes or plays a bag "
        "(``subprocess.call(['rosrun', 'rviz', 'rviz', '-d', path])``, "
        "``os.system('roslaunch ...')``, ``rosbag play`` with the remaps the program was "
        "given), or the agent that puts a micro-ROS or XRCE-DDS client's topics on the "
        "ROS 2 graph (MicroXRCEAgent, micro-ros-agent: PX4's ``/fmu/...``), also through "
        "a terminal emulator or a shell that runs it (``gnome-terminal -- bash -c "
        "'MicroXRCEAgent udp4 -p 8888; exec bash'``): Doosan's dmodel.py writes an rviz "
        "configuration and starts rviz so, spencer_bagfile_tools' play.py plays the "
        "recorded bags, the PX4 offboard example starts the agent. What it starts or "
        "publishes is decided at run time, so the node is 'partial' and checks that "
        "claim something is absent (a remap that changes no name too) do not decide on "
        "it."),
    "PY_DYNAMIC_CLASSES": Entry(
        "info", "{call}() lists classes at run time, which the program may build; their "
        "code is not followed",
        "A Python program asks a class for its subclasses (``cls.__subclasses__()``) and "
        "builds what it gets (kalman_robot's supervisor builds every Module and State "
        "class so, each opening its own topics and reading its parameters): which "
        "classes run is decided when the program runs, so what they communicate is not "
        "read, the node is 'partial' and checks that claim something is absent do not "
        "decide on it."),
    "PY_DYNAMIC_IMPORT": Entry(
        "info", "{call} imports a module whose name is computed at run time ({name}); "
        "its code is not read",
        "A Python program imports a module by a name it computes (``__import__``, "
        "``importlib.import_module``, ``runpy.run_module`` of a variable): FlexBE's "
        "onboard engine imports each behavior it is sent and runs its state machine, "
        "which reads the engine's logging parameters and opens its topics; a plugin "
        "named by a parameter. What that code communicates is not known, so the node "
        "is 'partial' and checks that claim something is absent do not decide on it. "
        "A name ending in .msg, .srv or .action (a package's message classes) does "
        "not count, nor an import asked only where it is (``__import__(pkg).__path__``) "
        "or of a class's module (``t.__module__``), imported already."),
    "PY_CALL_DEPTH": Entry(
        "info", "the call of {call} is not followed, {depth} calls deep; ROS calls it "
        "may make are not read here",
        "The Python walk follows a node's calls into the package's own functions and "
        "methods (with the arguments given) up to a depth; a call deeper than that is "
        "not followed, its function walked alone, with its parameters and the object "
        "it is called on not known, so a publisher it makes on a node it was handed "
        "(carla's actors, built five calls down from the bridge) may be lost. Said only "
        "where the function, or one it calls by name, may reach a call of the ROS API; "
        "the node is 'partial' and checks that claim something is absent do not "
        "decide on it."),
    "PY_NODE_PARTIAL": Entry(
        "warning", "node {node}: its calls may be incomplete, {count} place(s) in its "
        "Python sources where calls may be missing or made by code not read (first: "
        "{first})",
        "A source of the node could not be read or parsed, or was too large to analyse, "
        "or the node builds a class whose code is not read (PY_CLASS_UNSEEN) or hands "
        "itself to a function whose code is not read (PY_FUNCTION_UNSEEN), runs "
        "roslaunch in its process (PY_LAUNCHES) or with a command (PY_RUNS_ROS_TOOL), "
        "or imports a module by a computed name (PY_DYNAMIC_IMPORT), or calls "
        "deeper than the walk follows (PY_CALL_DEPTH): calls may be "
        "missing. The node model is "
        "'partial' (completeness, with the first reasons); checks that claim something "
        "is absent do not trust it."),
    "CPP_PARAMETER_LIBRARY": Entry(
        "warning", "generate_parameter_library's YAML of {target} cannot be used: {detail}",
        "The header generate_parameter_library writes at build time is synthesised from "
        "the YAML its CMake call names; this YAML is not valid YAML or not shaped as the "
        "library wants (one top-level key, the namespace, over a mapping). The header is "
        "an empty stand-in: the parameters its ParamListener declares are unknown."),
    "CPP_INCLUDE_MISSING": Entry(
        "info", "header {header} not found; an empty stand-in was used",
        "The header is neither in the workspace nor on the system; declarations from "
        "it are unknown to the extractor."),
    "CPP_MESSAGE_FIELD": Entry(
        "info", "C++ error on a message known only by name: {detail}",
        "The code reads a field of a message whose definition is neither in the workspace "
        "nor installed (its header was synthesised without fields, see "
        "CPP_MESSAGE_UNKNOWN), so clang cannot check it. Not a mistake in the code; "
        "calls around it are still extracted."),
    "RECONFIGURE_CFG_INVALID": Entry(
        "warning", "dynamic_reconfigure config is not valid Python: {detail}",
        "A cfg/*.cfg file is read (never run) to know the parameters its server reads; "
        "this one does not parse, so the config header it generates is not known."),
    "CPP_RECONFIGURE_PARTIAL": Entry(
        "info", "dynamic_reconfigure config {name}: some parameters are named at run time "
        "or added by a function not read (not literal in the .cfg); only the {count} "
        "literal ones are known",
        "The server of this config reads and writes every parameter of the .cfg; those "
        "added with a computed name, or by a function the generator is handed to that "
        "is neither in the .cfg nor in a module beside it or in a workspace package's "
        "src/ folder, are not known, so the node's reads under the server's namespace "
        "stay partly unknown."),
    "CPP_MESSAGE_UNKNOWN": Entry(
        "info", "no definition found for {header}; it was synthesised without fields",
        "The header names a message or service whose .msg / .srv file is neither in the "
        "workspace nor installed; its type name is known but its fields are not, so code "
        "that reads them may give C++ errors."),
    "CPP_COMPILE_COMMANDS": Entry(
        "warning", "{path} is not used: {detail}",
        "A compile_commands.json could not be read (too large, not JSON, not a list of "
        "compile commands); sources are parsed with the default flags."),
    "CPP_DYNAMIC_NAME": Entry(
        "info", "the name of this {kind} call is computed at run time; kept as '{name}'",
        "The extractor could not resolve every part of the name statically."),
    "CPP_NAME_MEMBER_ELSEWHERE": Entry(
        "info", "the name of this {kind} call holds {member}, which nothing in this file "
        "sets (its class's constructors are in another file); kept as '{name}'",
        "The name is read from a member (often through a getter, costmap_.getName()) of "
        "a class whose constructors this translation unit does not define: what they, or "
        "an initialisation method defined with them, give the member, and which "
        "constructor built the object used here, are not followed across files, so that "
        "part of the name stays '?' (a plugin's name that its host gives, as a costmap "
        "layer's Layer::name_, is filled in by the host)."),
    "PY_PARSE_ERROR": Entry(
        "error", "Python syntax error: {detail}",
        "The Python file could not be parsed (nor read as Python 2 after repairing its "
        "print/exec/except statements, nor with Python 3.12's f-strings, whose fields "
        "may span lines or reuse the f-string's quotes, written triple-quoted, and whose "
        "strings in fields may hold escapes, written as the characters they stand for); "
        "it gives no calls."),
    "PY_PYTHON2": Entry(
        "info", "Python 2 syntax; read after a line-preserving repair",
        "The file uses Python 2 statements (print, exec, 'except E, e') or indents a "
        "block with tabs and spaces mixed (a tab to the next multiple of 8 columns); they "
        "were rewritten in memory so its ROS calls could be read. The file is never run."),
    "PY_TOO_COMPLEX": Entry(
        "warning", "Python code too large to analyse fully ({limit}); calls past it are "
        "not extracted",
        "A bound on the work per file or node was reached, so a generated or hostile "
        "file cannot stall the run. Not said for a program that imports no ROS client "
        "(nor its package's modules it imports): nothing past the cut is a ROS call."),
    "PY_DYNAMIC_NAME": Entry(
        "info", "the name of this {kind} call is computed at run time; kept as '{name}'",
        "The Python extractor could not resolve every part of the name statically."),
    "PY_SEVERAL_NODES": Entry(
        "info", "this code names several nodes ({names}); {outcome}",
        "A Python executable that creates several rclpy nodes (two Node subclasses, "
        "create_node called twice) runs them in one process: each becomes a node instance "
        "of its own with the calls made on it (a launch name= renames them all, as in ROS "
        "2). rospy.init_node called with different names on different branches is one "
        "node: the model takes the first name and gives it the calls of all."),
    # hints
    "HINT_INVALID": Entry(
        "error", "{detail}",
        "An extraction hint in the project file is malformed and was not used."),
    "HINT_UNMATCHED": Entry(
        "warning", "hint for {name} matches no node instance of configuration "
                   "{configuration}; add 'create: true' and 'node_type' to create it",
        "A configuration hint names a node instance that no launch file of the "
        "configuration starts."),
    # graph
    "NODE_NAME_GUESSED": Entry(
        "info", "{name}: launched without name= and its code is not known; named after "
        "its executable {executable}, which is a guess",
        "A ROS 2 node is named by its code (rclcpp::Node(\"name\"), rclpy's "
        "Node('name')) unless the launch file renames it. Without the code the "
        "executable's name stands in, as packages usually name the two alike; when "
        "they differ, the instance's name (and its parameters) are wrong."),
    "CONDITION_FALSE": Entry(
        "info", "{node}: no {kind} {name} in this configuration: the code makes it "
        "under {condition} ({where}), which does not hold here",
        "The call sits under a condition in the source (or its interface model) over a "
        "parameter the node reads (if (publish_acceleration_) after "
        "nh.param(\"publish_acceleration\", publish_acceleration_, false)) or over "
        "main's argc / argv, and the configuration decides it: the parameter's launch "
        "value, else the code's default, or the node's launch arguments. The link does "
        "not exist here, so no check counts it. Set the parameter (or the argument) "
        "where the node is launched if the link is wanted."),
    "NAME_PARAM_UNSET": Entry(
        "info", "{node}: the name of this {kind} is the value of the {what}, {why}; it "
        "stays unknown",
        "The code (or its interface model) takes a topic or service name from a "
        "parameter (robot_localization's imu0, twist_mux's topics list) and neither the "
        "launch files nor their parameter files set it, and the code gives no default: "
        "the link's name stays '?'. Set the parameter where the node is launched. The "
        "message says so too where the launch sets the parameter to a value not known "
        "statically (an argument nobody gives), where it sets it to a value that is not "
        "text (a float or a bool, written into a name differently by each language; an "
        "integer is written in decimal where the name has other text), and where it sets "
        "it to the empty string "
        "and what the code makes of it is no name the graph resolves: an empty name, or "
        "one with an empty segment or a trailing '/', which rcl refuses and roscpp "
        "resolves to the handle's namespace or cleans; the graph keeps '?' there."),
    "NAME_ARG_UNSET": Entry(
        "info", "{node}: the name of this {kind} holds the process's command-line "
        "argument {which}, {why}; it stays unknown",
        "The code builds a topic or service name from its command-line arguments "
        "(kinova_driver's robot_name = argv[argc-1]) and the instance's args do not "
        "tell that argument: the launch file gives too few, its args are not known "
        "statically, or the argument differs before and after ros::init (a ':=' word "
        "among the args). Give the node its args where it is launched."),
    "NODE_NOT_FOUND": Entry(
        "warning", "node type {node} is not in the workspace; its interface is unknown{hint}",
        "A launch file starts an executable that no workspace package builds; the "
        "instance is kept without publishers, subscribers or other links. When the "
        "package is in the workspace, the message lists the programs it does build "
        "(urg_node 369ee4d: its launch file runs urg_node, a name its CMakeLists.txt "
        "gave up for urg_node_driver), the nearest first."),
    "NODE_BUILT_BY_OPTION": Entry(
        "warning", "node type {node} is built only when the CMake option {option} is "
        "given a value other than its default {default} ({cmake}); its interface is unknown",
        "A launch file starts an executable that its package's CMakeLists.txt makes only "
        "in a branch an option keeps from running while the option has its default "
        "(cartographer_ros' cartographer_grpc_node under if(${BUILD_GRPC}), off by "
        "default): a default build has no such program, and the launch file fails there; "
        "a build with the option (-DBUILD_GRPC=ON) has it. Not a missing node: no "
        "launch-missing-reference. The instance is kept without publishers, "
        "subscribers or other links."),
    "NODE_EXECUTABLE_BLANK": Entry(
        "warning", "a node of package {package} is given a blank executable ({given!r}): "
        "no program of the package has that name, so the launch cannot start it; its "
        "interface is unknown",
        "A launch file starts a node whose executable (ROS 2 exec=, ROS 1 type=) is empty "
        "or white space, often a launch argument's value with the name left out; "
        "ros2 launch and roslaunch fail to find the program at that line. Reported as "
        "launch-missing-reference, like NODE_NOT_FOUND."),
    "NODE_NOT_EXECUTABLE": Entry(
        "warning", "node type {node}: {path} is there but not executable, so roslaunch "
        "cannot start it; its interface is not read",
        "A ROS 1 launch file starts a type that is a file of the package without its "
        "execute bit, and no build file installs it (catkin_install_python, "
        "install(PROGRAMS), whose copy has the bit): roslaunch finds it and refuses it "
        "(\"Found ... but it is not executable\"), so the node does not run. Set the bit "
        "(chmod +x) or install the script."),
    "NODE_TYPE_UNKNOWN": Entry(
        "warning", "node type {node} is not known statically; its interface is unknown",
        "A launch file starts a node whose package or executable it names with a value "
        "not known statically (a launch argument with no value): which program runs is "
        "unknown, not missing; the instance is kept without publishers, subscribers or "
        "other links, as one of unknown interface."),
    "NODE_EXITS": Entry(
        "warning", "{node} exits before it starts a ROS node: {why}",
        "The arguments the launch file gives a program whose command line the tool reads "
        "(ROS 1 controller_manager's spawner) are refused by its own parser, which exits "
        "with an error before the program starts its node: roslaunch starts the process, "
        "nothing of what it would do happens (a spawner with no controller named loads "
        "none). The instance is kept, with no ROS call."),
    "NODE_STANDALONE_NODELET": Entry(
        "info", "node type {node} is no target of its package's CMake files; a command "
                "they call from outside the workspace is given its name with the nodelet "
                "{plugin}: taken as that nodelet run alone",
        "A ROS 1 launch file starts a program that the package's CMake files make through "
        "a function of a package not in the workspace (jsk_topic_tools' jsk_nodelet, which "
        "writes a main() that loads a nodelet class under the node's own name, as "
        "'nodelet standalone' does). The function is not read; its arguments name the "
        "program and one nodelet class the package exports, so the instance takes that "
        "class's interface."),
    "NODELET_PROCESS_HANDLES": Entry(
        "info", "nodelet {nodelet} makes {count} call(s) on node handles its code "
                "(or a tf listener given none) constructs: they are its manager "
                "{manager}'s, named in its namespace, '~' its private namespace, with "
                "{remaps}",
        "A ROS 1 nodelet loaded into a manager (nodelet load pkg/Name manager) gets its "
        "own handles from the nodelet API (getNodeHandle(), getPrivateNodeHandle() and "
        "their MT twins): in the nodelet's namespace, with the remaps it was loaded with. "
        "A handle its code constructs itself (ros::NodeHandle nh; NodeHandle pnh(\"~\")) "
        "is roscpp's handle of the process, the manager's node: its names resolve in the "
        "manager's namespace, '~' is the manager's private namespace, and the remaps that "
        "apply are the manager's; the nodelet's <remap>s do not reach them. So does "
        "a tf2_ros::TransformListener(buffer) or tf::TransformListener() given no "
        "handle: it subscribes /tf and /tf_static on a ros::NodeHandle() it makes (a "
        "remap of /tf on the nodelet does not reach it; given getNodeHandle(), the "
        "listener is the nodelet's). So do roscpp's functions that take no handle, "
        "ros::param::get / has / param / set / del / search and ros::service::call / "
        "createClient, "
        "for a name not global: ros::param::has(\"~x\") asks the manager's ~x. "
        "The graph links those calls so (still as the "
        "nodelet's). Usually a bug of the nodelet (laser_filters' "
        "scan_to_cloud_filter_chain, fixed upstream by passing getNodeHandle()): use "
        "the nodelet's handles."),
    "NODE_NOT_READ": Entry(
        "warning", "node type {node} is {path}, a program this tool does not read (not a "
                   "built target nor a Python program); its interface is unknown",
        "A ROS 1 launch file starts an executable file of the package that is neither "
        "built by its CMakeLists nor a Python program (a shell script, a prebuilt "
        "binary): roslaunch finds it in the package's folder and runs it. A ROS 2 "
        "launch file starts such a program that its package's CMakeLists installs "
        "(install(PROGRAMS ...)) into its lib folder, where ros2 launch finds it. The "
        "instance "
        "is kept without links, of unknown interface; describe it with hints if it "
        "matters."),
    "NODE_PACKAGE_UNKNOWN": Entry(
        "warning", "package {name} of node {node} {why}; {interface}",
        "A launch file starts a node from a package this machine does not have (it may "
        "be installed where the system runs), or one the workspace holds in a folder an "
        "ignore marker (COLCON_IGNORE, CATKIN_IGNORE, AMENT_IGNORE) leaves out of the "
        "build, as colcon and catkin do: the marker file is named. The instance is kept "
        "without links; describe it with hints if it matters. A ros_gz bridge "
        "(parameter_bridge, image_bridge, or their ros_ign names) is the exception: its "
        "topics are its arguments, read as the bridge reads them."),
    # interface models (haros_arch.models)
    "MODEL_DISTRO": Entry(
        "info", "interface models of distribution {distro} ({why})",
        "Nodes of packages without source in the workspace take the interface model of "
        "this ROS distribution: the project file's 'distro', else ROS_DISTRO in the "
        "configuration's environment when it is a distribution of the launch files' ROS "
        "(a ROS 2 one runs no ROS 1 launch file), else noetic for ROS 1 launch files "
        "and, for ROS 2 ones, the distribution the workspace's own files name (its git branch, its "
        "build and CI files, its README's 'ROS 2 <name>'), else jazzy. humble and iron "
        "take jazzy's model of a package they have none of; another distribution of a "
        "known ROS (melodic, foxy, rolling, ...) takes the "
        "nearest release's of its ROS, and the node is then partial: its own release may "
        "read or name what that model's does not."),
    "MODEL_USED": Entry(
        "info", "node {node} ({where}) takes the interface model {model}",
        "The node's package has no source in the workspace; its interface comes from a "
        "model (the project's 'models:' files first, then the shipped ones), generated "
        "by haros-arch from the named repository and commit. Its links have origin "
        "'model'."),
    "MODEL_NODE_MISSING": Entry(
        "warning", "the interface model {model} has no node {node} (it has: {nodes}); "
                   "its interface is unknown",
        "The package's model does not list the executable the launch file starts: a "
        "different distribution or version, or a node the generator did not find."),
    "RVIZ_CONFIG_INVALID": Entry(
        "warning", "rviz display configuration {path} not read: {detail}",
        "rviz is started with this configuration (-d), whose displays and tools say what "
        "it subscribes to and publishes; it could not be read as YAML, so rviz keeps the "
        "interface its model gives."),
    "MODEL_INVALID": Entry(
        "warning", "interface model not used: {detail}",
        "A model file (listed under 'models:' in the project file, or shipped) could not "
        "be read; nodes it would describe stay of unknown interface."),
    # our own bugs, kept to the file that shows them
    "INTERNAL": Entry(
        "error", "internal error while reading {path}: {detail} (at {at}; please report it "
                 "with this file)",
        "An unexpected exception in haros-arch while it read this file. What the file "
        "would have added to the model is missing; the run went on with the other files."),
}


def make(code: str, location: Location = NOWHERE, **params: object) -> Diagnostic:
    """Build a diagnostic from the catalogue entry ``code``, filling its template."""
    entry = CATALOGUE[code]
    return Diagnostic(code, entry.severity, entry.template.format(**params), location)


def per_file(where: Location, path: str, found: list[Diagnostic],
             action: Callable[[], T], default: T) -> T:
    """``action()``, the work of one file; an exception that escapes it (a bug of ours)
    becomes an INTERNAL diagnostic at ``where`` and ``default`` stands for its result, so
    the run goes on with the other files."""
    try:
        return action()
    except Exception as err:  # only around one file's work
        frames = traceback.extract_tb(err.__traceback__)
        at = f"{os.path.basename(frames[-1].filename)}:{frames[-1].lineno}" if frames else "?"
        detail = f"{type(err).__name__}: {str(err)[:200]}"
        found.append(make("INTERNAL", where, path=path, detail=detail, at=at))
        return default
