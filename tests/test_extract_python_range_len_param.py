"""A Python counting loop up to the length of a list parameter, ``for i in
range(len(p))``: tauv's thrusters node subscribes ``f'vehicle/thrusters/{thruster_id}/
target_thrust'`` for ``thruster_id in range(len(self._thruster_channels))``, the channels
a YAML file gives. ``range(n)`` of an integer parameter was one call per turn; the length
of a list was not known, so the name stayed ``vehicle/thrusters/?/target_thrust``. Now one
call per element's index (from ``k`` in ``range(k, len(p))``); an empty list makes none,
the code's default list counts when nothing sets the parameter, and a list nobody sets
keeps the ``?`` with NAME_PARAM_UNSET naming the list."""

from __future__ import annotations

import json

from conftest import package_xml

from haros_arch.cli import main

NODE = """
    #!/usr/bin/env python
    import rospy
    from std_msgs.msg import Float64


    class Thrusters:
        def __init__(self):
            self._thruster_channels = rospy.get_param("~thruster_channels")
            for thruster_id in range(len(self._thruster_channels)):
                rospy.Subscriber(f"vehicle/thrusters/{thruster_id}/target_thrust", Float64,
                                 self.handle, callback_args=thruster_id)
            for servo_id in range(len(rospy.get_param("~servo_channels"))):
                rospy.Subscriber(f"vehicle/servos/{servo_id}/target_position", Float64,
                                 self.handle)
            for led in range(1, len(rospy.get_param("~leds", ["a", "b", "c"]))):
                rospy.Publisher("led_%d" % led, Float64, queue_size=1)
            for pump in range(len(rospy.get_param("~pumps"))):
                rospy.Publisher(f"pump/{pump}", Float64, queue_size=1)

        def handle(self, msg, index=0):
            pass


    rospy.init_node("thrusters")
    Thrusters()
    rospy.spin()
    """

LAUNCH = """
    <launch>
      <node name="thrusters" pkg="th" type="thrusters.py">
        <rosparam>
          thruster_channels: [6, 5, 2]
          servo_channels: []
        </rosparam>
      </node>
    </launch>
    """


def test_a_loop_up_to_a_list_parameter_length(write_tree):
    root = write_tree({
        "src/th/package.xml": package_xml("th"),
        "src/th/CMakeLists.txt": "project(th)\n",
        "src/th/scripts/thrusters.py": NODE,
        "src/th/launch/th.launch": LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [th/launch/th.launch]\n"})
    (root / "src/th/scripts/thrusters.py").chmod(0o755)
    out = root / "model.json"
    main(["extract", str(root / "project.yaml"), "-o", str(out)])
    config = json.loads(out.read_text())["configurations"][0]
    names = sorted((link["kind"], link["name"]) for link in config["links"]
                   if link["kind"] in ("publish", "subscribe"))
    assert names == [
        ("publish", "/led_1"), ("publish", "/led_2"), ("publish", "/pump/?"),
        ("subscribe", "/vehicle/thrusters/0/target_thrust"),
        ("subscribe", "/vehicle/thrusters/1/target_thrust"),
        ("subscribe", "/vehicle/thrusters/2/target_thrust")]
    unset = [d["message"] for d in config["diagnostics"] if d["code"] == "NAME_PARAM_UNSET"]
    assert len(unset) == 1
    assert "loop over the elements of the list parameter ~pumps" in unset[0]
