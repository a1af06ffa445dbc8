"""A name that is the value of a parameter whose own name holds a command-line argument.
underwater_simulation's dynamics.py takes its vehicle from ``sys.argv[1]``, reads
``self.vehicle_name + "/dynamics/external_force_topic"`` and subscribes to that value;
its launch file gives ``g500`` and sets ``/g500/dynamics/external_force_topic``. The read
was resolved from the argument, the subscription looked the parameter up as
``?/dynamics/external_force_topic``: unset (NAME_PARAM_UNSET), the topic ``?``."""

from __future__ import annotations

import json

from conftest import package_xml

from haros_arch.cli import main

NODE = """
    #!/usr/bin/env python
    import sys
    import rospy
    from geometry_msgs.msg import WrenchStamped


    class Dynamics:
        def __init__(self):
            self.vehicle_name = sys.argv[1]
            self.force_topic = rospy.get_param(self.vehicle_name + "/dynamics/force_topic")
            rospy.init_node("dynamics_" + self.vehicle_name)
            rospy.Subscriber(self.force_topic, WrenchStamped, self.update, queue_size=1)

        def update(self, msg):
            pass


    Dynamics()
    rospy.spin()
    """

LAUNCH = """
    <launch>
      <rosparam param="/g500/dynamics/force_topic">g500/ForceSensor</rosparam>
      <node name="dynamics_g500" pkg="dyn" type="dynamics.py" args="g500"/>
    </launch>
    """


def test_the_parameter_is_named_by_the_argument(write_tree):
    root = write_tree({
        "src/dyn/package.xml": package_xml("dyn"),
        "src/dyn/CMakeLists.txt": "project(dyn)\n",
        "src/dyn/scripts/dynamics.py": NODE,
        "src/dyn/launch/sim.launch": LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [dyn/launch/sim.launch]\n"})
    (root / "src/dyn/scripts/dynamics.py").chmod(0o755)
    out = root / "model.json"
    main(["extract", str(root / "project.yaml"), "-o", str(out)])
    config = json.loads(out.read_text())["configurations"][0]
    assert sorted((link["kind"], link["name"]) for link in config["links"]) == [
        ("read", "/g500/dynamics/force_topic"), ("subscribe", "/g500/ForceSensor")]
    assert "NAME_PARAM_UNSET" not in {d["code"] for d in config["diagnostics"]}
