"""<test> nodes: started by rostest only, so a roslaunch configuration leaves them out."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.pipeline import analyse
from haros_arch.project import load

LAUNCH = """
<launch>
  <node pkg="robot" type="driver" name="driver"/>
  <test test-name="driver_test" pkg="robot" type="check">
    <param name="timeout" value="3"/>
  </test>
</launch>
"""


def test_tests_only_in_rostest_configurations(write_tree):
    root = write_tree({
        "src/robot/package.xml": package_xml("robot"),
        "src/robot/launch/robot.launch": LAUNCH,
        "project.yaml": """
            project: p
            configurations:
              run: {launch: [robot/launch/robot.launch]}
              check: {launch: [robot/launch/robot.launch], rostest: true}
        """,
    })
    project = load(str(root / "project.yaml"))
    assert [c.rostest for c in project.configurations] == [None, True]
    run, check = analyse(project, {}).configurations
    assert [(n.name, n.test) for n in run.nodes] == [("/driver", False)]
    left = [d for d in run.diagnostics if d.code == "LAUNCH_TEST_LEFT_OUT"]
    assert [(d.location.file, d.location.line) for d in left] == [
        ("robot/launch/robot.launch", 3)]
    assert [(n.name, n.test) for n in check.nodes] == [
        ("/driver", False), ("/driver_test", True)]
    # roslaunch sets a test's parameters all the same
    assert "/driver_test/timeout" in {p.name for p in run.parameters}
    assert not any(d.code == "LAUNCH_TEST_LEFT_OUT" for d in check.diagnostics)


def test_a_test_file_is_a_rostest_run_unless_said_otherwise(write_tree):
    root = write_tree({
        "src/robot/package.xml": package_xml("robot"),
        "src/robot/test/robot.test": LAUNCH,
        "project.yaml": """
            project: p
            configurations:
              test: [robot/test/robot.test]
              plain: {launch: [robot/test/robot.test], rostest: false}
        """,
    })
    test, plain = analyse(load(str(root / "project.yaml")), {}).configurations
    assert [n.name for n in test.nodes] == ["/driver", "/driver_test"]
    assert [n.name for n in plain.nodes] == ["/driver"]


def test_a_left_out_test_s_parameters_are_no_parameter_set_but_not_read(write_tree):
    # ros_kortex's run_all_examples.launch:62-64: <test test-name="test_all_examples_success">
    # <param name="robot_name"/>, read by the test's ros::param::get("~robot_name")
    from haros_arch.query import run_catalogue

    root = write_tree({
        "src/robot/package.xml": package_xml("robot"),
        "src/robot/launch/robot.launch": """
            <launch>
              <param name="unused" value="1"/>
              <test test-name="driver_test" pkg="robot" type="check">
                <param name="timeout" value="3"/>
              </test>
            </launch>
            """,
        "project.yaml": """
            project: p
            configurations:
              run: {launch: [robot/launch/robot.launch]}
        """,
    })
    model = analyse(load(str(root / "project.yaml")), {})
    (run,) = model.configurations
    timeout = next(p for p in run.parameters if p.name == "/driver_test/timeout")
    assert timeout.set_by_launch and timeout.for_test == "/driver_test"
    unread = [f.message for f in run_catalogue(model) if f.rule == "parameter-set-not-read"]
    assert [m.split()[0] for m in unread] == ["/unused"]
