"""A call named by each element of a list parameter of integers: tauv's thruster manager
publishes ``f'vehicle/thrusters/{thruster_id}/target_thrust'`` for each of
``~thruster_ids`` (``[0, 1, 2, ...]`` in its YAML file). The element was taken only when
it is a string, so the name stayed ``vehicle/thrusters/?/target_thrust`` with a
NAME_PARAM_UNSET that said the configuration does not set the list. An integer is written
in decimal by ``str``, an f-string, ``%d`` and C++'s ``std::to_string`` alike; a float or
a bool is not (each language writes them its own way), and an integer alone is no legal
name: those stay unknown."""

from __future__ import annotations

import json

from conftest import package_xml

from haros_arch.cli import main

NODE = """
    #!/usr/bin/env python
    import rospy
    from std_msgs.msg import Float64


    def main():
        rospy.init_node("thruster_manager")
        for thruster_id in rospy.get_param("~thruster_ids"):
            rospy.Publisher(f"vehicle/thrusters/{thruster_id}/target_thrust", Float64,
                            queue_size=10)
        for servo in rospy.get_param("~servos"):
            rospy.Subscriber("servo_%d/position" % servo["id"], Float64, print)
        for gain in rospy.get_param("~gains"):
            rospy.Publisher("gain/" + str(gain), Float64, queue_size=1)
        for alone in rospy.get_param("~alone"):
            rospy.Publisher(alone, Float64, queue_size=1)
        rospy.spin()


    main()
    """

PARAMS = """
    thruster_ids: [0, 1, 2]
    servos:
      - {id: 4}
      - {id: 5}
    gains: [1.5, true]
    alone: [7]
    """

LAUNCH = """
    <launch>
      <node name="thruster_manager" pkg="tm" type="thruster_manager.py">
        <rosparam command="load" file="$(find tm)/config/tm.yaml"/>
      </node>
    </launch>
    """


def test_integer_elements_name_the_calls(write_tree):
    root = write_tree({
        "src/tm/package.xml": package_xml("tm"),
        "src/tm/CMakeLists.txt": "project(tm)\n",
        "src/tm/scripts/thruster_manager.py": NODE,
        "src/tm/config/tm.yaml": PARAMS,
        "src/tm/launch/tm.launch": LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [tm/launch/tm.launch]\n"})
    (root / "src/tm/scripts/thruster_manager.py").chmod(0o755)
    out = root / "model.json"
    main(["extract", str(root / "project.yaml"), "-o", str(out)])
    config = json.loads(out.read_text())["configurations"][0]
    links = {(link["kind"], link["name"]) for link in config["links"]
             if link["kind"] in ("publish", "subscribe")}
    assert {name for kind, name in links if name.startswith("/vehicle")} == {
        "/vehicle/thrusters/0/target_thrust", "/vehicle/thrusters/1/target_thrust",
        "/vehicle/thrusters/2/target_thrust"}
    assert {name for kind, name in links if name.startswith("/servo")} == {
        "/servo_4/position", "/servo_5/position"}
    # a float and a bool are written differently by each language; an integer alone is
    # no legal name: unknown, as before
    assert {name for kind, name in links if name.startswith("/gain")} == {"/gain/?"}
    assert ("publish", "?") in links
    unset = [d["message"] for d in config["diagnostics"] if d["code"] == "NAME_PARAM_UNSET"]
    assert not any("thruster_ids" in m or "servos" in m for m in unset)
