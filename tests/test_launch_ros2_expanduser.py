"""``os.path.expanduser(path)`` (and ``Path.expanduser()``) in a Python launch file: a
path that does not start with ``~`` is itself; ``~`` / ``~/...`` is the home folder,
which Python takes from HOME, as ``os.getenv('HOME')`` reads it here (the
configuration's environment); without HOME, or for ``~user``, that part is not known
and said so (LAUNCH_UNKNOWN_VALUE), the rest of the path kept. It was a call not
interpreted: Nautilus-One's dashboard launcher (the working folder of its processes)
and perseus-v2's mapping launch files (fast_lio's map path) said LAUNCH_PY_UNSUPPORTED."""

from __future__ import annotations

from pathlib import PurePosixPath

from test_launch_ros2_python import run

BODY = """
from pathlib import Path

def generate_launch_description():
    return LaunchDescription([Node(package='p', executable='e', name='n', parameters=[{
        'home': os.path.expanduser('~/maps/site.map'),
        'plain': os.path.expanduser('/opt/maps/site.map'),
        'tilde': os.path.expanduser('~'),
        'other': os.path.expanduser('~robot/maps'),
        'path': str(Path('~/bags').expanduser())}])])
"""


def _params(model) -> dict[str, object]:
    return {p.name.rsplit("/", 1)[-1]: p.value for p in model.params}


def test_expanduser_takes_home_from_the_environment(write_tree):
    model, _ = run(write_tree, BODY, env={"HOME": "/home/robot/"})
    params = _params(model)
    assert params["home"] == "/home/robot/maps/site.map"
    assert params["plain"] == "/opt/maps/site.map"
    assert params["tilde"] == "/home/robot"
    assert params["path"] == str(PurePosixPath("/home/robot/bags"))
    assert not any(d.code == "LAUNCH_PY_UNSUPPORTED" for d in model.diagnostics), [
        d.message for d in model.diagnostics]
    unknown = [d.message for d in model.diagnostics if d.code == "LAUNCH_UNKNOWN_VALUE"]
    assert len(unknown) == 1 and "robot" in unknown[0], unknown


def test_expanduser_without_home_is_said_unknown(write_tree):
    model, _ = run(write_tree, BODY, env={})
    params = _params(model)
    assert params["plain"] == "/opt/maps/site.map"
    assert not isinstance(params["home"], str) or "?" in params["home"], params["home"]
    assert not any(d.code in ("LAUNCH_PY_UNSUPPORTED", "LAUNCH_UNSUPPORTED")
                   for d in model.diagnostics), [
        d.message for d in model.diagnostics]
    unknown = [d.message for d in model.diagnostics if d.code == "LAUNCH_UNKNOWN_VALUE"]
    assert any("HOME" in m for m in unknown), unknown
