"""A Python node that builds a class of a module named after a ROS package of the
workspace (another package, or its own) that the loader cannot find in that package's
sources (object_recognition_ros' server: its setup.py moved the module with
``package_dir`` where the reader did not look) was 'complete' with the class's calls
silently missing. Its code is not read: PY_CLASS_UNSEEN, so the node is partial. A class
of a module the workspace holds is read as before, and one of a Python library (numpy)
or of a package the workspace does not name is no workspace module."""

from __future__ import annotations

from haros_arch.extract.python import extract_python
from haros_arch.workspace import scan


def _manifest(name: str, *depends: str) -> str:
    tags = "".join(f"<exec_depend>{d}</exec_depend>" for d in depends)
    return (
        '<?xml version="1.0"?><package format="2">'
        f"<name>{name}</name><version>0.0.1</version><description>d</description>"
        '<maintainer email="a@b.c">a</maintainer><license>MIT</license>'
        f"<buildtool_depend>catkin</buildtool_depend>{tags}</package>\n")


def _package(src, name: str, *depends: str):
    package = src / name
    (package / "scripts").mkdir(parents=True)
    (package / "package.xml").write_text(_manifest(name, "rospy", *depends))
    (package / "CMakeLists.txt").write_text(
        f"project({name})\nfind_package(catkin REQUIRED)\ncatkin_python_setup()\n")
    return package


def _run(tmp_path, imported: str, *, found: bool = False):
    src = tmp_path / "src"
    node = _package(src, "p", "q")
    other = _package(src, "q")
    # q's Python code lives in a folder no reader looks in (a setup.py's own layout),
    # or in src/, where catkin_python_setup's usual setup.py has it
    hidden = other / ("src" if found else "odd_layout") / "q"
    hidden.mkdir(parents=True)
    (hidden / "__init__.py").write_text("")
    (hidden / "server.py").write_text(
        "import rospy\nclass Server(object):\n"
        "    def __init__(self):\n"
        "        self.pub = rospy.Publisher('hidden', rospy.AnyMsg, queue_size=1)\n")
    source = node / "scripts" / "n.py"
    module, cls = imported.rsplit(".", 1)
    source.write_text(
        "import rospy\n"
        f"from {module} import {cls}\n"
        "rospy.init_node('n')\n"
        f"s = {cls}()\n"
        "pub = rospy.Publisher('out', rospy.AnyMsg, queue_size=1)\n"
        "rospy.spin()\n")
    return extract_python([str(source)], scan([str(src)]), package="p")


def _unseen(result) -> list[str]:
    return [d.message for d in result.diagnostics if d.code == "PY_CLASS_UNSEEN"]


def test_a_class_of_a_workspace_package_module_not_found_is_said(tmp_path):
    said = _unseen(_run(tmp_path, "q.server.Server"))
    assert len(said) == 1 and "q.server.Server" in said[0] and "package q" in said[0]


def test_a_class_of_the_own_package_module_not_found_is_said(tmp_path):
    said = _unseen(_run(tmp_path, "p.server.Server"))
    assert len(said) == 1 and "p.server.Server" in said[0] and "package p" in said[0]


def test_a_workspace_module_found_is_read_not_said(tmp_path):
    result = _run(tmp_path, "q.server.Server", found=True)
    assert _unseen(result) == []
    assert "hidden" in {c.name for c in result.calls}


def test_a_library_or_a_package_not_named_is_no_workspace_module(tmp_path):
    assert _unseen(_run(tmp_path, "numpy.random.Generator")) == []
    assert _unseen(_run(tmp_path / "b", "somelib.thing.Widget")) == []
