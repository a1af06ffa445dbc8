"""``$(anon x)`` in a ROS 1 launch file is one name within that file and a new one in
each include of it: roslaunch swaps in a fresh substitution dictionary for an included
file, so its anonymous names are made again. cob_robots' pc_monitor.launch, included
once per computer of the robot, starts ``$(anon cpu_monitor)`` in each: six nodes of six
names, which all read ``/cpu_monitor_?`` here and were three LAUNCH_NODE_DUPLICATE
errors. Two nodes of one ``$(anon x)`` in one file stay roslaunch's refusal."""

from __future__ import annotations

import json

from conftest import package_xml

from haros_arch.cli import main

ROS1_NODE = """
    #!/usr/bin/env python
    import rospy
    rospy.init_node("monitor")
    """

MONITOR = """
    <launch>
      <arg name="pc" default="localhost"/>
      <node pkg="mon" type="monitor" name="$(anon cpu_monitor)" args="$(arg pc)"/>
    </launch>
    """


def duplicates(write_tree, launch: dict[str, str]) -> list[tuple[str, str, int]]:
    files = {"src/mon/package.xml": package_xml("mon"),
             "src/mon/CMakeLists.txt": "project(mon)\n",
             "src/mon/scripts/monitor": ROS1_NODE,
             "project.yaml": "project: p\nconfigurations:\n  c: [mon/launch/robot.launch]\n"}
    files.update({f"src/mon/launch/{name}": text for name, text in launch.items()})
    root = write_tree(files)
    (root / "src/mon/scripts/monitor").chmod(0o755)
    out = root / "check.json"
    main(["check", str(root / "project.yaml"), "--format", "json", "-o", str(out),
          "--fail-on", "never"])
    report = json.loads(out.read_text())
    found = [(d["code"], d["location"]["file"], d["location"]["line"])
             for d in report["diagnostics"] if "DUPLICATE" in d["code"]]
    return found + [(f["rule"], f["location"]["file"], f["location"]["line"])
                    for f in report["findings"] if "duplicate" in f["rule"]]


def test_anon_names_of_two_includes_of_one_file_are_two_names(write_tree):
    assert duplicates(write_tree, {"monitor.launch": MONITOR, "robot.launch": """
        <launch>
          <group>
            <include file="$(find mon)/launch/monitor.launch"><arg name="pc" value="b1"/></include>
          </group>
          <group>
            <include file="$(find mon)/launch/monitor.launch"><arg name="pc" value="t1"/></include>
          </group>
          <include file="$(find mon)/launch/monitor.launch"><arg name="pc" value="h1"/></include>
        </launch>
        """}) == []


def test_one_anon_name_twice_in_one_file_is_still_refused(write_tree):
    # within one file (and the groups in it) every $(anon x) is the same name
    assert duplicates(write_tree, {"robot.launch": """
        <launch>
          <node pkg="mon" type="monitor" name="$(anon cpu_monitor)"/>
          <group>
            <node pkg="mon" type="monitor" name="$(anon cpu_monitor)"/>
          </group>
        </launch>
        """}) == [("LAUNCH_NODE_DUPLICATE", "mon/launch/robot.launch", 4)]


def test_an_anon_name_of_the_including_file_is_not_the_included_files(write_tree):
    # the included file makes its own: no clash with the includer's $(anon x)
    assert duplicates(write_tree, {"monitor.launch": MONITOR, "robot.launch": """
        <launch>
          <node pkg="mon" type="monitor" name="$(anon cpu_monitor)"/>
          <include file="$(find mon)/launch/monitor.launch"/>
        </launch>
        """}) == []
