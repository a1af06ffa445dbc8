"""A loop over ``numpy.array`` of a list parameter walks the parameter's elements: tauv's
thruster manager keeps ``np.array(rospy.get_param('~thruster_ids'))`` and publishes
``f'vehicle/thrusters/{thruster_id}/target_thrust'`` for each. The array was a value not
known, so the name stayed ``vehicle/thrusters/?/target_thrust`` whatever the
configuration gave. Not so with a ``dtype`` (``dtype=float`` writes ``0.0``)."""

from __future__ import annotations

import json

from conftest import package_xml

from haros_arch.cli import main

NODE = """
    #!/usr/bin/env python
    import numpy as np
    import rospy
    from numpy import asarray
    from std_msgs.msg import Float64


    class ThrusterManager:
        def __init__(self):
            self._load_config()
            for thruster_id in self._thruster_ids:
                rospy.Publisher(f"vehicle/thrusters/{thruster_id}/target_thrust", Float64,
                                queue_size=10)
            for servo in asarray(rospy.get_param("~servo_ids")):
                rospy.Subscriber(f"vehicle/servos/{servo}/target_position", Float64, print)
            for gain in np.array(rospy.get_param("~gain_ids"), dtype=float):
                rospy.Publisher(f"gain/{gain}", Float64, queue_size=1)

        def _load_config(self):
            self._thruster_ids = np.array(rospy.get_param("~thruster_ids"))


    rospy.init_node("thruster_manager")
    ThrusterManager()
    rospy.spin()
    """

LAUNCH = """
    <launch>
      <node name="thruster_manager" pkg="tm" type="thruster_manager.py">
        <rosparam>
          thruster_ids: [0, 1]
          servo_ids: [left, right]
          gain_ids: [3]
        </rosparam>
      </node>
    </launch>
    """


def test_a_numpy_array_of_a_list_parameter_walks_its_elements(write_tree):
    root = write_tree({
        "src/tm/package.xml": package_xml("tm"),
        "src/tm/CMakeLists.txt": "project(tm)\n",
        "src/tm/scripts/thruster_manager.py": NODE,
        "src/tm/launch/tm.launch": LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [tm/launch/tm.launch]\n"})
    (root / "src/tm/scripts/thruster_manager.py").chmod(0o755)
    out = root / "model.json"
    main(["extract", str(root / "project.yaml"), "-o", str(out)])
    config = json.loads(out.read_text())["configurations"][0]
    names = sorted((link["kind"], link["name"]) for link in config["links"]
                   if link["kind"] in ("publish", "subscribe"))
    assert names == [
        ("publish", "/gain/?"),
        ("publish", "/vehicle/thrusters/0/target_thrust"),
        ("publish", "/vehicle/thrusters/1/target_thrust"),
        ("subscribe", "/vehicle/servos/left/target_position"),
        ("subscribe", "/vehicle/servos/right/target_position")]
