"""The parameter and condition queries follow the parameter server and real semantics."""

from __future__ import annotations

import os

from conftest import package_xml

from haros_arch.pipeline import analyse
from haros_arch.project import load
from haros_arch.query import run_catalogue

NODE = """
#!/usr/bin/env python3
import rospy
from std_msgs.msg import String

def main():
    rospy.init_node("talker")
    gains = rospy.get_param("gains")           # the whole namespace
    rate = rospy.get_param("~rate", 10)        # has a default: fine if unset
    port = rospy.get_param("~port")            # no default and never set
    found = rospy.search_param("robot_model")  # set at the root
    rospy.delete_param("~scratch")             # a delete does not set it ...
    scratch = rospy.get_param("~scratch")      # ... so this read fails
    rospy.delete_param("/legacy")              # nor does a search find a deleted one
    legacy = rospy.search_param("legacy")      # (a search only looks: it cannot fail)
    if rospy.has_param("~optional"):           # checked before it is read
        optional = rospy.get_param("~optional")
    if rospy.has_param("~optional"):           # checks another name: this read fails
        other = rospy.get_param("~optional_b")
    pub = rospy.Publisher("chatter", String, queue_size=10)
    if rospy.get_time() > rate:               # not decided statically
        fast = rospy.Publisher("fast", String, queue_size=10)

try:
    main()
except rospy.ROSInterruptException:
    pass
"""

LAUNCH = """
<launch>
  <param name="robot_model" value="small" />
  <group ns="foo">
    <group ns="gains"><param name="P" value="1.0" /><param name="I" value="2.0" /></group>
    <node name="talker" pkg="pkg" type="talker.py" />
  </group>
</launch>
"""


def test_catalogue_on_parameter_server_semantics(write_tree):
    root = write_tree({
        "src/pkg/package.xml": package_xml("pkg"),
        "src/pkg/CMakeLists.txt": "project(pkg)\n",
        "src/pkg/scripts/talker.py": NODE,
        "src/pkg/launch/a.launch": LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [pkg/launch/a.launch]\n",
    })
    os.chmod(root / "src/pkg/scripts/talker.py", 0o755)
    project = load(str(root / "project.yaml"))
    model = analyse(project, {"PATH": ""})
    findings = run_catalogue(model, project)
    by_rule: dict[str, list[str]] = {}
    for finding in findings:
        by_rule.setdefault(finding.rule, []).append(finding.message)
    # ~port and ~scratch are read without a default or a check and never set (~scratch
    # is only deleted); ~optional_b too, but only under has_param("~optional"), which
    # the graph decides false (nothing sets ~optional, nor may anything unseen): the
    # read does not happen here, and the configuration says so
    assert sorted(m.split()[0] for m in by_rule["parameter-read-not-set"]) == [
        "/foo/talker/port", "/foo/talker/scratch"]
    assert "parameter-read-not-set-undecided" not in by_rule
    config = model.configurations[0]
    assert [d.message for d in config.diagnostics if d.code == "CONDITION_FALSE"
            and "/foo/talker/optional_b" in d.message] == [
        '/foo/talker: no read /foo/talker/optional_b in this configuration: the code makes '
        'it under if (rospy.has_param("~optional")) (pkg/scripts/talker.py:17), which does '
        'not hold here']
    # the search for legacy does not stop at /legacy, which is only deleted; it stays
    # where rospy's search starts, the node's own namespace
    assert [r.node.name for r in config.parameter("/foo/talker/legacy").readers] == [
        "/foo/talker"]
    assert config.parameter("/legacy").readers == []
    # gains/P and gains/I are read as the gains namespace; robot_model is found by search
    assert "parameter-set-not-read" not in by_rule
    # the publisher under `if` is conditional; the one in the try body is not
    (conditional,) = by_rule["conditional-communication"]
    assert "/foo/fast" in conditional
