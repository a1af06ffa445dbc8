"""A Python class statement runs its body once, where the class is defined: mbzirc2020
(e474cee)'s parser_c2 reads its two file names in the body of its class,
``ugv_file = rospy.get_param('~UGV_data')``, and its launch file sets them; the body was
not walked, so no read was seen and both parameters were false parameter-set-not-read
findings. The functions the body defines are walked as methods, not as the body; a
class it defines runs its own body in turn."""

from __future__ import annotations

from haros_arch.extract.python import extract_python
from haros_arch.workspace import Workspace

PARSER = (
    "#!/usr/bin/env python\n"
    "import rospy\n"
    "from std_msgs.msg import String\n"
    "class parser:\n"
    "    '''Reads the brick order.'''\n"
    "    rospy.init_node('parser', anonymous=True)\n"
    "    ugv_file = rospy.get_param('~UGV_data')\n"
    "    if rospy.has_param('~UAV_data'):\n"
    "        uav_file = rospy.get_param('~UAV_data')\n"
    "    status = rospy.Publisher('status', String, queue_size=1)\n"
    "    def read(self):\n"
    "        return open(self.ugv_file).read()\n"
    "    class Inner:\n"
    "        rate = rospy.get_param('~rate', 10)\n"
    "if __name__ == '__main__':\n"
    "    parser().read()\n")


def test_a_class_body_runs_where_the_class_is_defined(tmp_path) -> None:
    source = tmp_path / "parser.py"
    source.write_text(PARSER)
    result = extract_python([str(source)], Workspace(root=str(tmp_path)), package="p")
    got = [(c.kind, c.name, c.location.line, bool(c.conditions)) for c in result.calls]
    assert got == [("read", "~UGV_data", 7, False), ("read", "~UAV_data", 8, False),
                   ("read", "~UAV_data", 9, True), ("publish", "status", 10, False),
                   ("read", "~rate", 14, False)]
