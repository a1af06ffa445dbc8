"""A condition as a finding's message writes it: its statement and, when it has one,
its text; a ``try`` block, which has none, is ``try``, not ``try ()`` (the report's
conditional-communication infos of ethzasl_xsens_driver read "exists only under try
(), while (...)")."""

from __future__ import annotations

from haros_arch.model.conditions import Condition


def test_a_condition_without_text_is_its_statement() -> None:
    assert str(Condition("x > 1")) == "if (x > 1)"
    assert str(Condition("not rospy.is_shutdown()", statement="while")) == (
        "while (not rospy.is_shutdown())")
    assert str(Condition("", statement="try")) == "try"


def test_conditional_communication_names_only_what_may_not_hold(write_tree) -> None:
    """The conditional-communication info says the conditions under which the link
    may not exist, not the ``try`` around it nor the ``while not rospy.is_shutdown()``
    loop it is made in (no condition of existing: ``conditions.undecided``)."""
    import os

    from conftest import package_xml

    from haros_arch.pipeline import Options, analyse
    from haros_arch.project import load
    from haros_arch.query.catalogue import run_catalogue

    node = (
        "import os\n"
        "import rospy\n"
        "from std_msgs.msg import String\n"
        "def main():\n"
        "    rospy.init_node('driver')\n"
        "    while not rospy.is_shutdown():\n"
        "        try:\n"
        "            if os.path.exists('/dev/imu'):\n"
        "                rospy.Publisher('data', String, queue_size=10)\n"
        "        except IOError:\n"
        "            pass\n"
        "main()\n")
    root = write_tree({
        "src/pkg/package.xml": package_xml("pkg"),
        "src/pkg/CMakeLists.txt": "cmake_minimum_required(VERSION 3.0)\nproject(pkg)\n"
                                  "find_package(catkin REQUIRED)\ncatkin_package()\n"
                                  "catkin_install_python(PROGRAMS scripts/driver.py\n"
                                  "  DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})\n",
        "src/pkg/scripts/driver.py": node,
        "src/pkg/launch/run.launch": '<launch><node pkg="pkg" type="driver.py" '
                                     'name="driver"/></launch>',
        "project.yaml": "project: p\nconfigurations:\n  c: [pkg/launch/run.launch]\n",
    })
    model = analyse(load(str(root / "project.yaml")),
                    {"PATH": os.environ.get("PATH", "")}, Options(cache_dir=None))
    found = [f for f in run_catalogue(model) if f.rule == "conditional-communication"]
    assert [f.message for f in found] == [
        "/driver: publish /data exists only under if (os.path.exists('/dev/imu'))"]
