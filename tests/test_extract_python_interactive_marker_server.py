"""rospy's interactive marker server (``interactive_markers.interactive_marker_server.
InteractiveMarkerServer(topic_ns, server_id="", q_size=100)``, noetic-devel) publishes
``topic_ns + "/update_full"`` (latched) and ``topic_ns + "/update"`` and subscribes to
``topic_ns + "/feedback"``, as roscpp's server does. The class was one of a ROS package
whose code is not read (PY_CLASS_UNSEEN), the node partial: mil's poi_server. Now its
three topics, typed, with their queues (``q_size`` the subscription's)."""

from __future__ import annotations

import json

from conftest import package_xml

from haros_arch.cli import main

NODE = """
    #!/usr/bin/env python
    import interactive_markers.interactive_marker_server as ims
    import rospy
    from interactive_markers.interactive_marker_server import InteractiveMarkerServer


    class PoiServer:
        def __init__(self):
            self.server = InteractiveMarkerServer("points_of_interest")
            self.private = ims.InteractiveMarkerServer(rospy.get_name() + "/markers",
                                                       q_size=5)


    rospy.init_node("poi_server")
    PoiServer()
    rospy.spin()
    """

LAUNCH = """
    <launch>
      <node name="poi_server" pkg="poi" type="poi_server.py" ns="sub"/>
    </launch>
    """


def test_an_interactive_marker_server_makes_its_three_topics(write_tree):
    root = write_tree({
        "src/poi/package.xml": package_xml("poi"),
        "src/poi/CMakeLists.txt": "project(poi)\n",
        "src/poi/scripts/poi_server.py": NODE,
        "src/poi/launch/poi.launch": LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [poi/launch/poi.launch]\n"})
    (root / "src/poi/scripts/poi_server.py").chmod(0o755)
    out = root / "model.json"
    main(["extract", str(root / "project.yaml"), "-o", str(out)])
    config = json.loads(out.read_text())["configurations"][0]
    links = sorted((link["kind"], link["name"], link["type"], link["queue_size"],
                    link["latch"]) for link in config["links"])
    init, update, feedback = ("visualization_msgs/InteractiveMarkerInit",
                              "visualization_msgs/InteractiveMarkerUpdate",
                              "visualization_msgs/InteractiveMarkerFeedback")
    assert links == sorted([
        ("publish", "/sub/points_of_interest/update", update, 100, False),
        ("publish", "/sub/points_of_interest/update_full", init, 100, True),
        ("publish", "/sub/poi_server/markers/update", update, 100, False),
        ("publish", "/sub/poi_server/markers/update_full", init, 100, True),
        ("subscribe", "/sub/points_of_interest/feedback", feedback, 100, False),
        ("subscribe", "/sub/poi_server/markers/feedback", feedback, 5, False)])
    assert [node["completeness"] for node in config["nodes"]] == ["complete"]
    codes = {d["code"] for d in config["diagnostics"]}
    assert "PY_CLASS_UNSEEN" not in codes
