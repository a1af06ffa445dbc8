"""A name with an integer parameter's value in it: tauv's actuator client publishes
``f'vehicle/servos/{self._torpedo_servo}/target_position'``, ``_torpedo_servo`` read from
``actuators/torpedo_servo``. Only a text value was put in a name, so the name stayed
``vehicle/servos/?/target_position`` and NAME_PARAM_UNSET said the configuration does not
set the parameter, which it does. An integer goes in in decimal where the name has other
text (as a list's integer elements do); a float or a bool, whose text each language
writes its own way, stays ``?``, and the diagnostic now says the value is set but is no
text."""

from __future__ import annotations

import json

from conftest import package_xml

from haros_arch.cli import main

NODE = """
    #!/usr/bin/env python
    import rospy
    from std_msgs.msg import Float64


    class ActuatorClient:
        def __init__(self):
            self._torpedo_servo = rospy.get_param("actuators/torpedo_servo")
            self._gain = rospy.get_param("actuators/gain")
            rospy.Publisher(f"vehicle/servos/{self._torpedo_servo}/target_position",
                            Float64, queue_size=1)
            rospy.Publisher("gain_%s" % self._gain, Float64, queue_size=1)
            rospy.Publisher(rospy.get_param("actuators/alone"), Float64, queue_size=1)


    rospy.init_node("actuators")
    ActuatorClient()
    rospy.spin()
    """

LAUNCH = """
    <launch>
      <rosparam ns="actuators">
        torpedo_servo: 4
        gain: 0.5
        alone: 7
      </rosparam>
      <node name="actuators" pkg="act" type="actuators.py"/>
    </launch>
    """


def test_an_integer_parameter_value_in_a_name(write_tree):
    root = write_tree({
        "src/act/package.xml": package_xml("act"),
        "src/act/CMakeLists.txt": "project(act)\n",
        "src/act/scripts/actuators.py": NODE,
        "src/act/launch/act.launch": LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [act/launch/act.launch]\n"})
    (root / "src/act/scripts/actuators.py").chmod(0o755)
    out = root / "model.json"
    main(["extract", str(root / "project.yaml"), "-o", str(out)])
    config = json.loads(out.read_text())["configurations"][0]
    names = sorted(link["name"] for link in config["links"] if link["kind"] == "publish")
    assert names == ["/gain_?", "/vehicle/servos/4/target_position", "?"]
    unset = sorted(d["message"] for d in config["diagnostics"]
                   if d["code"] == "NAME_PARAM_UNSET")
    assert len(unset) == 2
    assert all("sets to a value that is not text" in m for m in unset)
    assert not any("torpedo_servo" in m for m in unset)
