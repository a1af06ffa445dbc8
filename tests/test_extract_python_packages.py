"""A script that imports its package's own module (``import pkg.sub`` from the folder
setup.py's package_dir names) is followed; ``rospy.get_name()`` is the node's own name."""

from __future__ import annotations

from pathlib import Path

from haros_arch.extract.python import extract_python
from haros_arch.workspace import scan


def test_a_script_calling_its_own_package_module(tmp_path: Path) -> None:
    package = tmp_path / "src" / "talk"
    (package / "nodes").mkdir(parents=True)
    (package / "src" / "talk").mkdir(parents=True)
    (package / "package.xml").write_text(
        '<package format="2"><name>talk</name><version>1.0.0</version>'
        '<description>d</description><maintainer email="a@b.c">a</maintainer>'
        '<license>BSD</license></package>\n')
    (package / "setup.py").write_text(
        "from setuptools import setup\nsetup(packages=['talk'], package_dir={'': 'src'})\n")
    (package / "src" / "talk" / "__init__.py").write_text("")
    (package / "src" / "talk" / "speaker.py").write_text(
        "import rospy\nimport actionlib\nfrom std_msgs.msg import String\n"
        "from talk.msg import CountAction\n"
        "class Server(object):\n"
        "    def __init__(self, name):\n"
        "        self._as = actionlib.SimpleActionServer(name, CountAction)\n"
        "def main(argv):\n"
        "    rospy.init_node('speaker')\n"
        "    pub = rospy.Publisher('chatter', String, queue_size=1)\n"
        "    server = Server(rospy.get_name())\n"
        "    client = rospy.ServiceProxy('backup/' + rospy.get_name(), String)\n")
    script = package / "nodes" / "speaker"
    script.write_text("#!/usr/bin/env python\nimport sys\nimport talk.speaker\n\n"
                      "if __name__ == '__main__':\n    talk.speaker.main(sys.argv[1:])\n")
    result = extract_python([str(script)], scan([str(tmp_path)]), package="talk")
    assert sorted((c.kind, c.name) for c in result.calls) == [
        ("action-server", "~"), ("client", "backup/?"), ("publish", "chatter")]
    assert result.rosname == "speaker"


def test_a_tf2_buffer_serves_its_frames_unless_debug_is_off(tmp_path: Path) -> None:
    source = tmp_path / "pointer.py"
    source.write_text(
        "import rospy\nimport tf2_ros\nrospy.init_node('pointer')\n"
        "buffer = tf2_ros.Buffer()\nlistener = tf2_ros.TransformListener(buffer)\n"
        "quiet = tf2_ros.Buffer(rospy.Duration(10), debug=False)\n")
    result = extract_python([str(source)], scan([str(tmp_path)]), package="p")
    assert [(c.kind, c.name, c.type) for c in result.calls] == [
        ("server", "~tf2_frames", "tf2_msgs/FrameGraph"),
        ("subscribe", "/tf", "tf2_msgs/TFMessage"),
        ("subscribe", "/tf_static", "tf2_msgs/TFMessage")]
