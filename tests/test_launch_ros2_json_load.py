"""``json.load`` / ``json.loads`` in a ROS 2 Python launch file (DOBOT's
dobot_bringup_ros2.launch.py reads its robot's node name and number from
``config/param.json`` with ``json.load(file)`` and names its node and parameters by
them): Python's JSON reader, run on a workspace file opened for reading, gives the data;
not LAUNCH_PY_UNSUPPORTED and a node named ``/?``. A file that is not JSON is an error
the launch file stops at; keyword arguments (callables) are not run."""

from __future__ import annotations

from test_launch_ros2_python import codes, run

BODY = """
import json

def generate_launch_description():
    path = os.path.join(get_package_share_directory('pkg'), 'config', 'param.json')
    with open(path, 'r') as f:
        data = json.load(f)
    info = data['node_info'][data['current'] - 1]
    inline = json.loads('{"rate": 5}')
    return LaunchDescription([
        Node(package='p', executable='e', name=info['robot_node_name'],
             parameters=[{'robot_number': data['robot_number'],
                          'rate': inline['rate']}]),
    ])
"""

PARAM = """{
  "robot_number": 1, "current": 2,
  "node_info": [{"robot_node_name": "first"}, {"robot_node_name": "second"}]
}
"""


def test_json_load_reads_a_workspace_file(write_tree):
    model, _ = run(write_tree, BODY, extra={"src/pkg/config/param.json": PARAM})
    assert "LAUNCH_PY_UNSUPPORTED" not in codes(model), [
        d.message for d in model.diagnostics]
    assert [n.name for n in model.nodes] == ["/second"]
    values = {p.name: p.value for p in model.params}
    assert values.get("/second/robot_number") == 1
    assert values.get("/second/rate") == 5


def test_json_that_is_not_json_is_said(write_tree):
    model, _ = run(write_tree, BODY, extra={"src/pkg/config/param.json": "{robot: 1"})
    assert [n.name for n in model.nodes] != ["/second"]
    assert any("JSON cannot be read" in d.message for d in model.diagnostics), [
        d.message for d in model.diagnostics]


def test_json_load_with_a_hook_is_not_run(write_tree):
    body = BODY.replace("json.load(f)", "json.load(f, object_hook=dict)")
    model, _ = run(write_tree, body, extra={"src/pkg/config/param.json": PARAM})
    assert "LAUNCH_PY_UNSUPPORTED" in codes(model)
