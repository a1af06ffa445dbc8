"""rosparam's Python API (``import rosparam``) reads and writes the parameter server as
rospy's functions do: cob_voltage_control's time_volt.py reads its three parameters with
``rosparam.get_param("/csv_proc/file_name")``."""

from __future__ import annotations

from haros_arch.extract.python import extract_python
from haros_arch.workspace import Workspace

NODE = (
    "import rospy\n"
    "import rosparam\n"
    "from rosparam import get_param as fetch\n"
    "rospy.init_node('csv_proc')\n"
    "filename = rosparam.get_param('/csv_proc/file_name')\n"
    "mode = fetch('mode')\n"
    "rosparam.set_param_raw('/csv_proc/done', True)\n"
    "rosparam.set_param('/csv_proc/text', '[1, 2]')\n"
    "rosparam.delete_param('/csv_proc/old')\n"
    "rosparam.load_file('params.yaml')\n"
)


def test_rosparam_functions_are_parameter_calls(tmp_path) -> None:
    source = tmp_path / "time_volt.py"
    source.write_text(NODE)
    result = extract_python([str(source)], Workspace(root=str(tmp_path)), package="p")
    calls = sorted((c.kind, c.name, c.location.line, c.deletes) for c in result.calls)
    assert calls == [
        ("read", "/csv_proc/file_name", 5, False),
        ("read", "mode", 6, False),
        ("write", "/csv_proc/done", 7, False),
        ("write", "/csv_proc/old", 9, True),
        ("write", "/csv_proc/text", 8, False),
    ]
    done = next(c for c in result.calls if c.name == "/csv_proc/done")
    assert done.type == "bool"
    # a YAML text the function parses: no value taken from it
    text = next(c for c in result.calls if c.name == "/csv_proc/text")
    assert text.type is None
