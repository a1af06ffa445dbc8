"""rospy.search_param and roscpp's ros::param::search(key, result) ask the master to
search from the node's own name up (rospy's caller id, roscpp's this_node::getName()):
the node's private parameter is found first. A NodeHandle's searchParam starts at the
handle's namespace (NodeHandle::resolveName("")): a public handle's is the node's
namespace, which does not hold the node's private parameters."""

from __future__ import annotations

import os

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.pipeline import analyse
from haros_arch.project import load
from haros_arch.query import run_catalogue
from haros_arch.workspace import scan

BRIDGE = """
#!/usr/bin/env python3
import rospy

rospy.init_node("bridge")
prefix = ""
path = rospy.search_param("tf_prefix")
if path is not None:
    prefix = rospy.get_param(path)
frame = rospy.get_param(rospy.search_param("frame_id"))
rospy.spin()
"""

LAUNCH = """
<launch>
  <param name="frame_id" value="map" />
  <node name="bridge" pkg="pkg" type="bridge.py" ns="robot">
    <param name="tf_prefix" value="robot" />
  </node>
</launch>
"""


def test_rospy_search_param_finds_the_node_s_private_parameter(write_tree) -> None:
    # mobipick (noetic 0210868) robotiq_2f_140_command_bridge.py:121-123 reads the
    # tf_prefix its <node> tag sets so; it was searched from /robot up, not found, and
    # the launch file's parameter was reported as set and never read
    root = write_tree({
        "src/pkg/package.xml": package_xml("pkg"),
        "src/pkg/CMakeLists.txt": "project(pkg)\n",
        "src/pkg/scripts/bridge.py": BRIDGE,
        "src/pkg/launch/a.launch": LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [pkg/launch/a.launch]\n",
    })
    os.chmod(root / "src/pkg/scripts/bridge.py", 0o755)
    project = load(str(root / "project.yaml"))
    model = analyse(project, {"PATH": ""})
    rules = {f.rule for f in run_catalogue(model, project)}
    assert "parameter-set-not-read" not in rules
    config = model.configurations[0]
    assert [r.node.name for r in config.parameter("/robot/bridge/tf_prefix").readers] == [
        "/robot/bridge", "/robot/bridge"]
    # found at the root, as before
    assert [r.node.name for r in config.parameter("/frame_id").readers] == [
        "/robot/bridge", "/robot/bridge"]
    assert config.parameter("/robot/tf_prefix") is None


def test_roscpp_search_without_a_handle_starts_at_the_node_s_name(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("p", "catkin"))
    source = tmp_path / "a.cpp"
    source.write_text(
        "#include <ros/ros.h>\n#include <string>\n"
        "int main(int argc, char** argv) {\n"
        "  ros::init(argc, argv, \"n\");\n"
        "  ros::NodeHandle nh, pnh(\"~\");\n"
        "  std::string a, b, c, d;\n"
        "  nh.searchParam(\"public_key\", a);\n"
        "  pnh.searchParam(\"private_key\", b);\n"
        "  ros::param::search(\"free_key\", c);\n"
        "  ros::param::search(\"/global_key\", d);\n"
        "  return 0;\n}\n")
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    assert [(c.name, c.searched) for c in result.calls] == [
        ("public_key", True), ("~private_key", True), ("~free_key", True),
        ("/global_key", True)]
