"""A value said not known where it was made stays said: what Python computes from it is
as unknown and says no more. III-Drone-Core's launch files read a YAML file from
``~/.config`` (outside the workspace: said once, where it is read), then subscript the
dict, join paths of its items, expand ``~``, open and read the path so made, subscript
the second dict at each use, and loop over ``os.popen(cmd).read().split()``: each of
these said again, 60 warnings for two causes."""

from __future__ import annotations

from test_launch_ros2_python import run

BODY = """
import yaml

def generate_launch_description():
    config = os.path.join(os.getenv('CONFIG_BASE_DIR', default='/etc/robot'), 'robot')
    index = yaml.safe_load(open(os.path.join(config, 'index.yaml'), 'r').read())
    folder = os.path.join(config, index['/**']['ros__parameters']['folder'])
    path = os.path.join(folder, index['/**']['ros__parameters']['file'])
    if path[0] == '~':
        path = '/home/' + os.getenv('USER', 'robot') + path[1:]
    path = os.path.expanduser(path)
    params = yaml.safe_load(open(path, 'r').read())
    running = os.popen('ros2 node list').read().split('\\n')
    nodes = [Node(package='p', executable='e', name='n',
                  parameters=[{'frame': params['tf']['frame']['value']}])]
    for node in running:
        if 'server' in node:
            nodes.append(Node(package='p', executable='s', name='server'))
    return LaunchDescription(nodes)
"""


def test_a_value_said_not_known_is_said_once(write_tree):
    model, root = run(write_tree, BODY)
    lines = (root / "src/pkg/launch/main.launch.py").read_text().splitlines()
    read = next(i + 1 for i, line in enumerate(lines) if "index.yaml" in line)
    popen = next(i + 1 for i, line in enumerate(lines) if "os.popen" in line)
    said = sorted((d.location.line, d.code) for d in model.diagnostics
                  if d.severity in ("warning", "error") or d.code.startswith("LAUNCH_PY"))
    assert said == [(read, "LAUNCH_PY_FILE_UNKNOWN"), (popen, "LAUNCH_PY_UNSUPPORTED")], [
        (d.location.line, d.code, d.message) for d in model.diagnostics]
    assert sorted(n.name for n in model.nodes) == ["/n", "/server"]
