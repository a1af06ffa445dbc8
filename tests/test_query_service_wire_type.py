"""ROS 1 connects a service client to a server of another service type when the two
types are defined alike: roscpp and rospy compare the md5sum of the request and response
definitions, not the type's name. godel's process_path_generator calls ``offset_polygon``
as ``godel_msgs/OffsetBoundary``, which polygon_offset_node serves as
``godel_polygon_offset/OffsetPolygon``, the same fields (comments aside): it was a
service-type-mismatch error. The workspace's own definitions are read for it (the
catalogue has only the standard packages'); a different field still mismatches."""

from __future__ import annotations

import json

from conftest import package_xml

from haros_arch.model.load import from_data
from haros_arch.model.serialise import model_to_data
from haros_arch.pipeline import analyse
from haros_arch.project import load
from haros_arch.query.catalogue import load_catalogue, run_rule

SERVER = """\
#!/usr/bin/env python
import rospy
from offset.srv import OffsetPolygon, Other


def serve(req):
    return None


rospy.init_node('offset_server')
rospy.Service('offset_polygon', OffsetPolygon, serve)
rospy.Service('other', Other, serve)
rospy.spin()
"""

CLIENT = """\
#!/usr/bin/env python
import rospy
from planner_msgs.srv import OffsetBoundary, Different


rospy.init_node('planner')
offset = rospy.ServiceProxy('offset_polygon', OffsetBoundary)
other = rospy.ServiceProxy('other', Different)
rospy.spin()
"""

# one definition, written with other comments and spacing
BOUNDARY = ("geometry_msgs/Polygon[] polygons    # boundary, CCW external\n"
            "float64 offset_distance\n---\n"
            "geometry_msgs/Polygon[] offset_polygons  # ordered\nfloat64[] offsets\n")
POLYGON = ("# offset a polygon\ngeometry_msgs/Polygon[] polygons\nfloat64  offset_distance\n"
           "---\ngeometry_msgs/Polygon[] offset_polygons\nfloat64[] offsets\n")

LAUNCH = """<launch>
  <node pkg="offset" type="server.py" name="offset_server"/>
  <node pkg="planner" type="client.py" name="planner"/>
</launch>
"""

CMAKE = ("cmake_minimum_required(VERSION 3.0.2)\nproject({0})\nfind_package(catkin REQUIRED)\n"
         "catkin_package()\ncatkin_install_python(PROGRAMS scripts/{1} "
         "DESTINATION ${{CATKIN_PACKAGE_BIN_DESTINATION}})\n")


def test_ros1_service_types_defined_alike_connect(write_tree) -> None:
    root = write_tree({
        "src/offset/package.xml": package_xml("offset"),
        "src/offset/CMakeLists.txt": CMAKE.format("offset", "server.py"),
        "src/offset/scripts/server.py": SERVER,
        "src/offset/srv/OffsetPolygon.srv": POLYGON,
        "src/offset/srv/Other.srv": "string name\n---\nbool ok\n",
        "src/offset/launch/robot.launch": LAUNCH,
        "src/planner/package.xml": package_xml("planner"),
        "src/planner/CMakeLists.txt": CMAKE.format("planner", "client.py"),
        "src/planner/scripts/client.py": CLIENT,
        "src/planner_msgs/package.xml": package_xml("planner_msgs"),
        "src/planner_msgs/CMakeLists.txt": "project(planner_msgs)\n",
        "src/planner_msgs/srv/OffsetBoundary.srv": BOUNDARY,
        "src/planner_msgs/srv/Different.srv": "string name\n---\nint32 ok\n",
        "project.yaml": "project: p\nconfigurations:\n  c: [offset/launch/robot.launch]\n",
    })
    for script in ("offset/scripts/server.py", "planner/scripts/client.py"):
        (root / "src" / script).chmod(0o755)
    model = analyse(load(str(root / "project.yaml")), {"PATH": ""})
    (rule,) = [r for r in load_catalogue() if r.id == "service-type-mismatch"]

    def mismatches(model: object) -> list[str]:
        return sorted(f.message for f in run_rule(rule, model) if f.rule == rule.id)

    assert mismatches(model) == [
        "/planner calls /other as planner_msgs/Different but /offset_server serves it as "
        "offset/Other"]
    # a model read back from JSON has no folders: the workspace's definitions are not
    # known, and the names are compared, as before
    reloaded = from_data(json.loads(json.dumps(model_to_data(model))))
    assert len(mismatches(reloaded)) == 2


def test_a_service_key_is_its_two_sections(tmp_path) -> None:
    from haros_arch.extract.cpp.interfaces import use_workspace, wire_key

    folder = tmp_path / "pkg"
    (folder / "srv").mkdir(parents=True)
    (folder / "msg").mkdir()
    (folder / "srv" / "A.srv").write_text("int32 x\n---\nint32 y\n")
    (folder / "srv" / "B.srv").write_text("int32 x\nint32 y\n---\n")  # moved across
    (folder / "msg" / "A.msg").write_text("int32 x\nint32 y\n")
    try:
        use_workspace({"pkg": str(folder)})
        assert wire_key("pkg/A", kind="srv") != wire_key("pkg/B", kind="srv")
        assert wire_key("pkg/A", kind="srv").startswith("ros1:")
        assert wire_key("pkg/A") != wire_key("pkg/A", kind="srv")  # the message of A
        assert wire_key("pkg/Missing", kind="srv") == "pkg/Missing"
    finally:
        use_workspace({})
