"""Python packages a ROS package keeps where its setup.py's ``package_dir`` says
(duckietown's dt-core and dt-ros-commons: ``setup(**generate_distutils_setup(packages=[..],
package_dir={'': 'include'}))``): a node's imports of them, from its own package or from
another one of the workspace, are read, so the calls their classes make (a base class
that offers services, a parameter class that reads the parameter it is given) are the
node's."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.python import extract_python
from haros_arch.pysetup import python_folders
from haros_arch.workspace import scan

CATKIN_SETUP = (
    "from distutils.core import setup\n"
    "from catkin_pkg.python_setup import generate_distutils_setup\n"
    "setup_args = generate_distutils_setup(\n"
    "    packages=['{name}'],\n"
    "    package_dir={{'': 'include'}},\n"
    ")\n"
    "setup(**setup_args)\n")

TREE = {
    "src/commons/package.xml": package_xml("commons"),
    "src/commons/setup.py": CATKIN_SETUP.format(name="dtlib"),
    "src/commons/include/dtlib/__init__.py": "from .base import Base, Param\n",
    "src/commons/include/dtlib/base.py": (
        "import rospy\n"
        "from std_srvs.srv import SetBool\n"
        "class Base(object):\n"
        "    def __init__(self, node_name):\n"
        "        rospy.init_node(node_name)\n"
        "        self.srv = rospy.Service('~switch', SetBool, self.switch)\n"
        "    def switch(self, req):\n"
        "        return None\n"
        "class Param(object):\n"
        "    def __init__(self, name):\n"
        "        self.value = rospy.get_param(name)\n"),
    "src/lane/package.xml": package_xml("lane"),
    # the same idiom, written in one call
    "src/lane/setup.py": (
        "from distutils.core import setup\n"
        "from catkin_pkg.python_setup import generate_distutils_setup\n"
        "setup(**generate_distutils_setup(packages=['lane_tools'],"
        " package_dir={'': 'include'}))\n"),
    "src/lane/include/lane_tools/__init__.py": "",
    "src/lane/include/lane_tools/control.py": (
        "import rospy\n"
        "from std_msgs.msg import Float32\n"
        "class Controller(object):\n"
        "    def __init__(self):\n"
        "        self.pub = rospy.Publisher('~error', Float32, queue_size=1)\n"),
    "src/lane/src/lane_node.py": (
        "import rospy\n"
        "from dtlib import Base, Param\n"
        "from lane_tools.control import Controller\n"
        "class LaneNode(Base):\n"
        "    def __init__(self):\n"
        "        super(LaneNode, self).__init__(node_name='lane_node')\n"
        "        self.k = Param('~k_d')\n"
        "        self.controller = Controller()\n"
        "if __name__ == '__main__':\n"
        "    LaneNode()\n"
        "    rospy.spin()\n"),
}


def test_modules_in_the_folder_setup_py_names_are_read(write_tree) -> None:
    root = write_tree(TREE)
    ws = scan([str(root / "src")], {})
    node = root / "src" / "lane" / "src" / "lane_node.py"
    result = extract_python([str(node)], ws, package="lane")
    got = sorted((c.kind, c.name, c.location.file) for c in result.calls)
    assert got == [
        ("publish", "~error", "lane/include/lane_tools/control.py"),
        ("read", "~k_d", "commons/include/dtlib/base.py"),
        ("server", "~switch", "commons/include/dtlib/base.py"),
    ]
    assert result.rosname == "lane_node"


def test_python_folders_of_setup_py(write_tree) -> None:
    root = write_tree({
        **TREE,
        # setup() itself with package_dir; a named package in a folder of its name
        "src/named/setup.py": (
            "from setuptools import setup\n"
            "setup(name='named', packages=['tool'], package_dir={'tool': 'lib/tool'})\n"),
        "src/named/lib/tool/__init__.py": "",
        # outside the package, or not there: no folder
        "src/outside/setup.py": (
            "from setuptools import setup\n"
            "setup(package_dir={'': '../elsewhere', 'x': 'missing/x'})\n"),
    })
    src = root / "src"
    assert python_folders(str(src / "commons")) == (str(src / "commons" / "include"),)
    assert python_folders(str(src / "lane")) == (str(src / "lane" / "include"),)
    assert python_folders(str(src / "named")) == (str(src / "named" / "lib"),)
    assert python_folders(str(src / "outside")) == ()
    assert python_folders(str(src / "nothing")) == ()


def test_items_set_on_the_setup_dict_after_the_call(write_tree) -> None:
    """object_recognition_ros' setup.py: ``d = generate_distutils_setup()``, then
    ``d['packages'] = [...]`` and ``d['package_dir'] = {'': 'python'}``, then
    ``setup(**d)``: setup() gets the dict as changed, so the module its ``server``
    script imports its RecognitionServer from is in ``python/``; not read, the server
    (an action server and a subscriber) was a complete node of no call. A key set again
    replaces the call's keyword."""
    root = write_tree({
        "src/ork/package.xml": package_xml("ork"),
        "src/ork/setup.py": (
            "from distutils.core import setup\n"
            "from catkin_pkg.python_setup import generate_distutils_setup\n"
            "d = generate_distutils_setup(package_dir={'': 'lib'})\n"
            "d['packages'] = ['ork_ros']\n"
            "d['package_dir'] = {'': 'python'}\n"
            "setup(**d)\n"),
        "src/ork/python/ork_ros/__init__.py": "",
        "src/ork/python/ork_ros/server.py": (
            "import actionlib\n"
            "import rospy\n"
            "from std_msgs.msg import String\n"
            "class RecognitionServer(object):\n"
            "    def __init__(self):\n"
            "        rospy.Subscriber('recognized_object_array', String, self.done)\n"
            "        self.server = actionlib.SimpleActionServer('recognize_objects', Action,"
            " self.execute, False)\n"
            "    def done(self, msg):\n"
            "        pass\n"
            "    def execute(self, goal):\n"
            "        pass\n"),
        "src/ork/apps/server.py": (
            "import rospy\n"
            "from ork_ros.server import RecognitionServer\n"
            "if __name__ == '__main__':\n"
            "    rospy.init_node('recognize_objects_server')\n"
            "    server = RecognitionServer()\n"
            "    rospy.spin()\n"),
    })
    src = root / "src"
    assert python_folders(str(src / "ork")) == (str(src / "ork" / "python"),)
    ws = scan([str(src)], {})
    result = extract_python([str(src / "ork" / "apps" / "server.py")], ws, package="ork")
    assert sorted((c.kind, c.name) for c in result.calls) == [
        ("action-server", "recognize_objects"), ("subscribe", "recognized_object_array")]
