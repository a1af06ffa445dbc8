"""Two ROS 1 nodes whose names read alike with ``?`` in them each read the parameters of
their own <node> element. robosub-ros' sensors.launch includes pink_bins_detector.launch
twice, ``camera`` front and bottom, and that file starts ``$(anon pink_bins_detector)``
with ``<param name="camera" value="$(arg camera)"/>``: two names, both
``/pink_bins_detector_?`` here. The graph took one parameter by name for both, so both
published ``/cv/front/...``: four false multiple-publishers, and nothing on
``/cv/bottom/...``, which the task runner subscribes."""

from __future__ import annotations

import json

from conftest import package_xml

from haros_arch.cli import main

DETECTOR = """
    #!/usr/bin/env python
    import rospy
    from sensor_msgs.msg import Image
    rospy.init_node("detector", anonymous=True)
    camera = rospy.get_param("~camera")
    pub = rospy.Publisher(f"/cv/{camera}/detections", Image, queue_size=10)
    rospy.spin()
    """

PART = """
    <launch>
      <arg name="camera" default="front"/>
      <node name="$(anon detector)" pkg="cv" type="detector.py">
        <param name="camera" value="$(arg camera)"/>
      </node>
    </launch>
    """

ROBOT = """
    <launch>
      <include file="$(find cv)/launch/part.launch"><arg name="camera" value="front"/></include>
      <include file="$(find cv)/launch/part.launch"><arg name="camera" value="bottom"/></include>
    </launch>
    """


def test_anon_nodes_of_two_includes_read_their_own_parameters(write_tree):
    root = write_tree({
        "src/cv/package.xml": package_xml("cv"),
        "src/cv/CMakeLists.txt": "project(cv)\n",
        "src/cv/scripts/detector.py": DETECTOR,
        "src/cv/launch/part.launch": PART,
        "src/cv/launch/robot.launch": ROBOT,
        "project.yaml": "project: p\nconfigurations:\n  c: [cv/launch/robot.launch]\n"})
    (root / "src/cv/scripts/detector.py").chmod(0o755)
    model = root / "model.json"
    main(["extract", str(root / "project.yaml"), "-o", str(model)])
    config = json.loads(model.read_text())["configurations"][0]
    published = sorted((link["node"], link["name"]) for link in config["links"]
                       if link["kind"] == "publish")
    assert published == [("/detector_?", "/cv/bottom/detections"),
                         ("/detector_?", "/cv/front/detections")]
    out = root / "check.json"
    main(["check", str(root / "project.yaml"), "--format", "json", "-o", str(out),
          "--fail-on", "never"])
    rules = {f["rule"] for f in json.loads(out.read_text())["findings"]}
    assert "multiple-publishers" not in rules
