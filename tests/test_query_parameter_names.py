"""parameter-name-illegal: a YAML comment that lost its '#' loads as a key no node can read."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.model.load import from_data
from haros_arch.pipeline import analyse
from haros_arch.project import load
from haros_arch.query.catalogue import load_catalogue, run_rule

(RULE,) = [r for r in load_catalogue() if r.id == "parameter-name-illegal"]

# kobuki_node's base.yaml before b213df3: the second line of a comment lost its '#'
BASE_YAML = """use_imu_heading: true

# Causes node to publish TF for odom_frame to base_frame. Disable only if you plan to
(see use_imu_heading description) (bool, default: true)
publish_tf: true
"""


def test_a_comment_line_loaded_as_a_key_is_found(write_tree):
    root = write_tree({
        "src/base/package.xml": package_xml("base"),
        "src/base/CMakeLists.txt": "project(base)\n",
        "src/base/param/base.yaml": BASE_YAML,
        "src/base/launch/base.launch": '<launch>\n  <node pkg="base" type="base_node" '
                                       'name="mobile_base">\n    <rosparam file="$(find '
                                       'base)/param/base.yaml" command="load"/>\n  '
                                       "</node>\n</launch>\n",
        "project.yaml": "project: p\nconfigurations:\n  c: [base/launch/base.launch]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {"PATH": ""})
    (finding,) = run_rule(RULE, model)
    assert finding.entities == (
        "parameter:/mobile_base/(see use_imu_heading description) (bool, default",)
    # where the key is written in the file (it was the <rosparam> that loads it)
    assert (finding.location.file, finding.location.line) == ("base/param/base.yaml", 4)


def test_ros2_parameter_names_may_hold_dots_and_dashes():
    # joy_teleop's piloting.axis_mappings.angular-z (create_bringup): read by prefix
    model = from_data({"configurations": [{"name": "c", "nodes": [
        {"name": "/joy_teleop", "ros_version": 2}], "parameters": [
        {"name": "/joy_teleop/piloting.axis_mappings.angular-z.axis", "type": "int",
         "value": 0, "writers": ["<launch>"]}]}]})
    assert run_rule(RULE, model) == []


# pmb2_2dnav's amcl.yaml before c82f6a1: rosparam's !degrees tag beside a misspelt key
AMCL_YAML = """odom_alpha1    : 0.2
update_min_a     : !degrees 10.0
lobal_frame_id : map
"""


def test_a_key_of_a_file_with_rosparam_tags_is_pointed_at(write_tree):
    (rule,) = [r for r in load_catalogue() if r.id == "parameter-set-not-read"]
    root = write_tree({
        "src/loc/package.xml": package_xml("loc"),
        "src/loc/CMakeLists.txt": "project(loc)\nfind_package(catkin REQUIRED roscpp)\n"
                                  "add_executable(loc_node src/main.cpp)\n",
        "src/loc/config/amcl.yaml": AMCL_YAML,
        "src/loc/launch/amcl.launch": '<launch>\n  <node pkg="loc" type="loc_node" '
                                      'name="amcl">\n    <rosparam file="$(find '
                                      'loc)/config/amcl.yaml" command="load"/>\n  '
                                      "</node>\n</launch>\n",
        "src/loc/src/main.cpp": '#include <ros/ros.h>\nint main(int argc, char **argv) {\n'
                                '  ros::init(argc, argv, "amcl");\n'
                                '  ros::NodeHandle p("~");\n  std::string f;\n  double a;\n'
                                '  p.param("odom_alpha1", a, 0.2);\n'
                                '  p.param("update_min_a", a, 0.5);\n'
                                '  p.param("global_frame_id", f, std::string("map"));\n}\n',
        "project.yaml": "project: p\nconfigurations:\n  c: [loc/launch/amcl.launch]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {"PATH": ""})
    (finding,) = run_rule(rule, model)
    assert finding.entities == ("parameter:/amcl/lobal_frame_id",)
    # the key's line in the file, not the <rosparam> (the !degrees tag is rosparam's)
    assert (finding.location.file, finding.location.line) == ("loc/config/amcl.yaml", 3)
