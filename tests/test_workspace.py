from __future__ import annotations

import os

from conftest import FIXTURES, package_xml

from haros_arch.manifest import condition_holds
from haros_arch.workspace import scan

SCAN = FIXTURES / "workspace_scan" / "src"


def codes(ws):
    return sorted((d.code, d.location.file) for d in ws.diagnostics)


def test_scan_finds_packages_and_honours_ignore_markers():
    ws = scan([str(SCAN)], {"ROS_VERSION": "2"})
    assert sorted(ws.packages) == [
        "legacy_pkg", "modern_pkg", "nav_core", "plain_cmake", "py_pkg"]


def test_build_types_follow_export_and_conditions():
    ros2 = scan([str(SCAN)], {"ROS_VERSION": "2"}).packages
    ros1 = scan([str(SCAN)], {"ROS_VERSION": "1"}).packages
    assert ros2["modern_pkg"].build_type == "ament_cmake"
    assert ros1["modern_pkg"].build_type == "catkin"
    assert ros2["legacy_pkg"].build_type == "catkin"
    assert ros2["py_pkg"].build_type == "ament_python"
    assert ros2["plain_cmake"].build_type == "cmake"


def test_manifest_formats_dependencies_and_plugins():
    packages = scan([str(SCAN)], {}).packages
    legacy = packages["legacy_pkg"]
    assert legacy.format == 1
    assert legacy.version == "1.0.0"
    assert ("roscpp", "run_depend") in [(d.name, d.kind) for d in legacy.dependencies]
    assert [(p.kind, p.file) for p in legacy.plugins] == [
        ("nodelet", "legacy_pkg/nodelet_plugins.xml")]
    modern = packages["modern_pkg"]
    assert modern.format == 3
    conditional = [d for d in modern.dependencies if d.condition]
    assert [(d.name, d.condition) for d in conditional] == [
        ("catkin", "$ROS_VERSION == 1"), ("ament_cmake", "$ROS_VERSION == 2")]
    assert modern.location.file == "modern_pkg/package.xml"


def test_malformed_manifest_and_duplicates_are_diagnostics():
    ws = scan([str(SCAN)], {})
    found = codes(ws)
    assert ("PACKAGE_XML_SYNTAX", "broken_pkg/package.xml") in found
    assert ("PACKAGE_DUPLICATE", "dup_b/nav_core/package.xml") in found
    syntax = next(d for d in ws.diagnostics if d.code == "PACKAGE_XML_SYNTAX")
    assert syntax.location.line == 5


def test_missing_workspace_folder_is_a_diagnostic(tmp_path):
    ws = scan([str(tmp_path / "nope")], {})
    assert [d.code for d in ws.diagnostics] == ["WORKSPACE_MISSING"]


def test_installed_packages_are_found_but_not_analysed(write_tree):
    root = write_tree({
        "ws/src/mine/package.xml": package_xml("mine"),
        "opt/share/installed_pkg/package.xml": package_xml("installed_pkg"),
        "rpp/other_pkg/package.xml": package_xml("other_pkg"),
    })
    env = {"AMENT_PREFIX_PATH": str(root / "opt"), "ROS_PACKAGE_PATH": str(root / "rpp")}
    ws = scan([str(root / "ws" / "src")], env)
    assert list(ws.packages) == ["mine"]
    assert ws.find("installed_pkg") == str(root / "opt" / "share" / "installed_pkg")
    assert ws.find("other_pkg") == str(root / "rpp" / "other_pkg")
    assert ws.find("nowhere") is None


def test_entity_expansion_is_never_performed(write_tree):
    root = write_tree({"src/evil/package.xml": """
        <?xml version="1.0"?>
        <!DOCTYPE package [<!ENTITY x SYSTEM "file:///etc/passwd">]>
        <package format="2"><name>evil&x;</name><version>1</version></package>
        """})
    ws = scan([str(root / "src")], {})
    assert all("root:" not in name for name in ws.packages)


def test_rep149_conditions():
    env = {"ROS_VERSION": "2", "ROS_DISTRO": "humble"}
    assert condition_holds("$ROS_VERSION == 2", env) is True
    assert condition_holds("$ROS_VERSION == 1", env) is False
    assert condition_holds("$ROS_VERSION == 2 and $ROS_DISTRO != foxy", env) is True
    assert condition_holds("($ROS_VERSION == 1 or $ROS_DISTRO == humble)", env) is True
    assert condition_holds("$ROS_VERSION >= 2", env) is True
    assert condition_holds("$ROS_VERSION ==", env) is None
    # compared as texts, as catkin_pkg does; a variable not set is empty (tiago_2dnav
    # 0959772's ``<exec_depend condition="$PAL_DISTRO > 0">``: an internal error before)
    assert condition_holds("$PAL_DISTRO > 0", env) is False
    assert condition_holds("$PAL_DISTRO > 0", {"PAL_DISTRO": "alum"}) is True
    assert condition_holds("$ROS_DISTRO >= galactic", env) is True
    assert condition_holds("$V < 9", {"V": "10"}) is True  # "10" < "9" as texts


def test_symlinked_checkouts_are_followed_once_and_cycles_end(write_tree):
    # src/ links to a checkout kept elsewhere (as catkin and colcon allow), and a link
    # inside it points back up: the package is found once and the walk ends
    root = write_tree({
        "elsewhere/robot_nav/package.xml": package_xml("robot_nav"),
        "ws/src/local_pkg/package.xml": package_xml("local_pkg"),
    })
    os.symlink(root / "elsewhere", root / "ws/src/external")
    os.symlink(root / "ws/src", root / "elsewhere/loop")
    os.symlink(root / "elsewhere/robot_nav", root / "ws/src/again")
    ws = scan([str(root / "ws/src")])
    assert sorted(ws.packages) == ["local_pkg", "robot_nav"]
    assert not [d for d in ws.diagnostics if d.code == "PACKAGE_DUPLICATE"]
    assert ws.packages["robot_nav"].root.startswith(str(root / "ws/src"))


def test_readable_covers_linked_packages_and_nothing_else(write_tree):
    root = write_tree({
        "elsewhere/robot_nav/package.xml": package_xml("robot_nav"),
        "elsewhere/robot_nav/config/planner.yaml": "a: 1\n",
        "elsewhere/secret.yaml": "b: 2\n",
        "ws/src/local_pkg/package.xml": package_xml("local_pkg"),
    })
    os.symlink(root / "elsewhere/robot_nav", root / "ws/src/robot_nav")
    ws = scan([str(root / "ws/src")], {})
    assert ws.readable(str(root / "ws/src/robot_nav/config/planner.yaml"))
    assert ws.readable(str(root / "elsewhere/robot_nav/config/planner.yaml"))
    assert not ws.readable(str(root / "elsewhere/secret.yaml"))
    assert not ws.readable(str(root / "ws/src/robot_nav/../secret.yaml"))
    assert not ws.readable("/etc/passwd")


def test_launch_reads_parameter_files_of_a_linked_package(write_tree):
    from haros_arch import launch

    root = write_tree({
        "elsewhere/robot_nav/package.xml": package_xml("robot_nav"),
        "elsewhere/robot_nav/config/planner.yaml": "max_vel: 0.5\n",
        "elsewhere/robot_nav/launch/nav.launch": (
            '<launch><rosparam file="$(find robot_nav)/config/planner.yaml" '
            'command="load" ns="planner"/></launch>\n'),
    })
    os.makedirs(root / "ws/src")
    os.symlink(root / "elsewhere/robot_nav", root / "ws/src/robot_nav")
    ws = scan([str(root / "ws/src")], {})
    loaded = launch.load(str(root / "ws/src/robot_nav/launch/nav.launch"), ws, {}, {})
    assert [(p.name, p.value) for p in loaded.params] == [("/planner/max_vel", 0.5)]
    assert not [d for d in loaded.diagnostics if d.code == "LAUNCH_UNKNOWN_VALUE"]


def test_rosbuild_packages_are_packages(write_tree):
    root = write_tree({
        "src/stack/old_driver/manifest.xml": """
            <package>
              <description brief="old">A rosbuild package.</description>
              <depend package="roscpp"/>
              <export><nodelet plugin="${prefix}/plugins.xml"/></export>
            </package>""",
        "src/stack/old_driver/launch/driver.launch":
            '<launch><param name="dir" value="$(find old_driver)"/></launch>',
        "src/both/package.xml": package_xml("both_pkg"),
        "src/both/manifest.xml": "<package/>",
        "src/broken/manifest.xml": "<package>",
        "src/web/manifest.xml": "<manifest><icon/></manifest>",  # not ROS: quietly no package
    })
    ws = scan([str(root / "src")], {})
    old = ws.packages["old_driver"]
    assert (old.format, old.build_type, old.path) == (1, "catkin", "stack/old_driver")
    assert [(d.name, d.kind) for d in old.dependencies] == [("roscpp", "depend")]
    assert [(p.kind, p.file) for p in old.plugins] == [
        ("nodelet", "stack/old_driver/plugins.xml")]
    assert "both_pkg" in ws.packages and "both" not in ws.packages  # package.xml wins
    assert [(d.code, d.location.file) for d in ws.diagnostics] == [
        ("PACKAGE_XML_SYNTAX", "broken/manifest.xml")]
    from haros_arch.launch import load
    model = load(str(root / "src/stack/old_driver/launch/driver.launch"), ws, {}, {})
    assert [p.value for p in model.params] == [str(root / "src/stack/old_driver")]


def test_ros_package_path_is_searched_recursively(write_tree):
    root = write_tree({
        "opt/repo/group/deep_pkg/package.xml": package_xml("deep"),
        "opt/repo/group/deep_pkg/inner/package.xml": package_xml("inner"),
        "opt/repo/skipped/CATKIN_IGNORE": "",
        "opt/repo/skipped/ghost/package.xml": package_xml("ghost"),
        "opt/repo/meta/package.xml": package_xml("meta").replace(
            "</package>", "<export><metapackage/></export></package>"),
        "opt/repo/meta/under_meta/package.xml": package_xml("under_meta"),
        "opt/repo/nosub/rospack_nosubdirs": "",
        "opt/repo/nosub/below/package.xml": package_xml("below"),
        "opt/repo/rosbuild_one/manifest.xml": "<package/>",
        "first/deep/package.xml": package_xml("deep"),
        "ws/src/mine/package.xml": package_xml("mine"),
    })
    env = {"ROS_PACKAGE_PATH": f"{root / 'first'}:{root / 'opt'}"}
    ws = scan([str(root / "ws/src")], env)
    assert ws.find("deep") == str(root / "first/deep")  # the earlier entry wins
    assert ws.find("rosbuild_one") == str(root / "opt/repo/rosbuild_one")
    for name in ("inner", "ghost", "meta", "under_meta", "below"):
        assert ws.find(name) is None, name
    assert ws.find("mine") == str(root / "ws/src/mine")


def test_relpath_is_relative_inside_the_root_only(tmp_path, monkeypatch) -> None:
    import pickle

    from haros_arch.workspace import Workspace

    root = tmp_path / "ws"
    root.mkdir()
    ws = Workspace(root=str(root) + "/")
    assert ws.relpath(str(root / "src" / "a.cpp")) == os.path.join("src", "a.cpp")
    assert ws.relpath(str(root)) == "."
    sibling = str(tmp_path / "ws2" / "b.cpp")  # a name that only starts like the root
    assert ws.relpath(sibling) == sibling
    assert ws.relpath(str(root / "x" / ".." / "y.h")) == "y.h"
    monkeypatch.chdir(root)
    assert ws.relpath("z.h") == "z.h"
    monkeypatch.chdir(tmp_path)
    assert ws.relpath("z.h") == str(tmp_path / "z.h")  # relative names follow the cwd
    assert pickle.loads(pickle.dumps(ws)).relpath(str(root / "q")) == "q"
    assert Workspace(root="/").relpath("/etc/hosts") == "etc/hosts"


def test_plugin_exports_follow_their_conditions(write_tree):
    # foxglove_bridge's package.xml: one tree for ROS 1 and ROS 2, its nodelets exported
    # for ROS 1 only; a ROS 2 build has no nodelet library, so no nodelet node
    root = write_tree({"src/bridge/package.xml": """<?xml version="1.0"?>
        <package format="3">
          <name>bridge</name><version>0.1.0</version>
          <description>d</description><maintainer email="a@b.c">m</maintainer>
          <license>MIT</license>
          <export>
            <build_type condition="$ROS_VERSION == 1">catkin</build_type>
            <build_type condition="$ROS_VERSION == 2">ament_cmake</build_type>
            <nodelet condition="$ROS_VERSION == 1" plugin="${prefix}/nodelets.xml"/>
            <rviz plugin="${prefix}/rviz.xml"/>
          </export>
        </package>"""})
    ros2 = scan([str(root / "src")], {"ROS_VERSION": "2"}).packages["bridge"]
    ros1 = scan([str(root / "src")], {"ROS_VERSION": "1"}).packages["bridge"]
    assert [(p.kind, p.file) for p in ros2.plugins] == [("rviz", "bridge/rviz.xml")]
    assert [(p.kind, p.file) for p in ros1.plugins] == [
        ("nodelet", "bridge/nodelets.xml"), ("rviz", "bridge/rviz.xml")]


def test_ros_version_reads_the_dependencies_whose_conditions_hold(write_tree):
    # foxglove_bridge: catkin for ROS 1 listed before ament_cmake for ROS 2; its ROS 2
    # sources were parsed as ROS 1 code (roscpp's prelude, boost's placeholders beside
    # std's: every ``std::bind(..., _1)`` of the node ambiguous)
    from haros_arch.manifest import ros_version
    from haros_arch.model.load import _package
    from haros_arch.model.serialise import to_data

    root = write_tree({"src/bridge/package.xml": """<?xml version="1.0"?>
        <package format="3">
          <name>bridge</name><version>0.1.0</version>
          <description>d</description><maintainer email="a@b.c">m</maintainer>
          <license>MIT</license>
          <buildtool_depend condition="$ROS_VERSION == 1">catkin</buildtool_depend>
          <buildtool_depend condition="$ROS_VERSION == 2">ament_cmake</buildtool_depend>
          <depend condition="$ROS_VERSION == 1">roscpp</depend>
          <depend condition="$ROS_VERSION == 2">rclcpp</depend>
        </package>"""})
    ros2 = scan([str(root / "src")], {"ROS_VERSION": "2"}).packages["bridge"]
    ros1 = scan([str(root / "src")], {"ROS_VERSION": "1"}).packages["bridge"]
    assert (ros_version(ros2), ros_version(ros1)) == (2, 1)
    assert sorted(d.name for d in ros2.dependencies if not d.active) == ["catkin", "roscpp"]
    # kept through the JSON model, and left out of it where it holds
    data = to_data(ros2)
    assert [d.get("active", True) for d in data["dependencies"]] == [False, True, False, True]
    assert ros_version(_package(data)) == 2


def test_an_xml_declaration_expat_reads_is_read(write_tree):
    """pyrobot 03af552: five package.xml files begin ``<?xml version="0.1"?>``, which
    catkin_pkg's and roslaunch's parser (expat) reads and libxml2 refuses ("Unsupported
    version"): the packages were left out, each with an error. A launch file so
    declared is read too; one not well-formed stays an error."""
    root = write_tree({
        "src/locobot_control/package.xml":
            package_xml("locobot_control").replace('"1.0"', '"0.1"'),
        "src/locobot_control/launch/main.launch":
            "<?xml version='2.0'?>\n<launch><node pkg='locobot_control' type='ctl' "
            "name='ctl'/></launch>\n",
        "src/broken/package.xml": '<?xml version="0.1"?>\n<package><name>broken</name>',
    })
    ws = scan([str(root / "src")], {})
    assert "locobot_control" in ws.packages
    assert codes(ws) == [("PACKAGE_XML_SYNTAX", "broken/package.xml")]
    from haros_arch.launch import load
    loaded = load(str(root / "src/locobot_control/launch/main.launch"), ws, {}, {})
    assert [d.code for d in loaded.diagnostics if d.code == "LAUNCH_XML_SYNTAX"] == []
    assert len(loaded.nodes) == 1
