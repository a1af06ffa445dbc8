"""Python launch files: math's constants and functions of numbers known statically
(webots_ros2_epuck's waypoints: ``orientation=-pi/2``), and a helper class of the file
said not interpreted once where it is built, not again at each of its method calls."""

from __future__ import annotations

from test_launch_ros2_python import codes, run


def test_math_constants_and_functions(write_tree):
    model, _ = run(write_tree, """
import math
from math import pi, cos as c

def generate_launch_description():
    return LaunchDescription([Node(
        package='p', executable='e', name='n',
        parameters=[{'yaw': -pi / 2, 'tau': math.tau, 'x': c(0.0), 's': math.sqrt(4)}])])
""")
    assert "LAUNCH_PY_UNSUPPORTED" not in codes(model)
    params = {p.name: p.value for p in model.params}
    assert params == {"/n/yaw": -1.5707963267948966, "/n/tau": 6.283185307179586,
                      "/n/x": 1.0, "/n/s": 2.0}


def test_a_math_error_is_said(write_tree):
    model, _ = run(write_tree, """
import math

def generate_launch_description():
    return LaunchDescription([Node(package='p', executable='e', name='n',
                                   parameters=[{'r': math.sqrt(-1)}])])
""")
    assert model.diagnostics


def test_methods_of_an_object_said_not_interpreted_are_not_said_again(write_tree):
    model, _ = run(write_tree, """
class Collection(list):  # of a base not interpreted
    def add(self, x):
        pass

def generate_launch_description():
    c = Collection()
    c.add(1)
    c.add(2)
    c.add(3)
    return LaunchDescription([Node(package='p', executable='e', name='n')])
""")
    said = [d for d in model.diagnostics if d.code == "LAUNCH_PY_UNSUPPORTED"]
    assert len(said) == 1 and "Collection" in said[0].message
    assert [n.name for n in model.nodes] == ["/n"]
