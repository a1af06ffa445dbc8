"""Classes a launch file (or a module it imports) derives from a launch action and gives
only a constructor, as Interbotix's ``DeclareInterbotixXSArmRobotDescriptionLaunchArgument
(DeclareLaunchArgument)`` does (xs_launch.py): calling one builds the base action with
what the constructor hands to ``super().__init__``. A class that adds another method (one
launch may call: ``execute``) stays not interpreted, and says so where it is used."""

from __future__ import annotations

from test_launch_ros2_python import codes, run

CLASSES = """
from typing import Optional
from launch.frontend import expose_action
from launch.substitutions import PathJoinSubstitution


class DeclareArmDescription(DeclareLaunchArgument):
    \"\"\"The arm's URDF as an argument.\"\"\"

    def __init__(self, *, description_name='robot_description',
                 model_name='robot_model', default_value=None, **kwargs):
        if default_value is None:
            # a tuple of one substitution (the comma), as xs_launch.py:72 writes it
            default_value = PathJoinSubstitution(['urdf', LaunchConfiguration(model_name)]),
        super().__init__(name=description_name, default_value=default_value,
                         description='URDF', **kwargs)


@expose_action('named_driver')
class NamedDriver(Node):
    def __init__(self, side, **kwargs):
        self.side = side
        Node.__init__(self, package='drive', executable='driver',
                      name=self.side + '_driver', **kwargs)


class LeftDriver(NamedDriver):
    def __init__(self):
        super(LeftDriver, self).__init__('left', namespace='arm')


class SpareDriver(NamedDriver):
    def __init__(self):
        NamedDriver.__init__(self, 'spare')


class Watched(Node):
    def execute(self, context):
        return super().execute(context)


class Forgetful(DeclareLaunchArgument):
    def __init__(self, name):
        self.kept = name
"""


def test_a_class_on_a_launch_action_builds_it(write_tree):
    model, _ = run(write_tree, CLASSES + """
def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('robot_model', default_value='wx250'),
        DeclareArmDescription(),
        Node(package='robot_state_publisher', executable='robot_state_publisher', name='rsp',
             parameters=[{'robot_description': LaunchConfiguration('robot_description')}]),
        NamedDriver('right'),
        LeftDriver(),
        SpareDriver(),
    ])
""")
    assert model.args["robot_description"] == "urdf/wx250"
    params = {p.name: p.value for p in model.params}
    assert params["/rsp/robot_description"] == "urdf/wx250"
    assert [n.name for n in model.nodes] == [
        "/rsp", "/right_driver", "/arm/left_driver", "/spare_driver"]
    assert "LAUNCH_PY_UNSUPPORTED" not in codes(model)


def test_a_class_that_adds_a_method_or_builds_nothing_is_said(write_tree):
    model, _ = run(write_tree, CLASSES + """
def generate_launch_description():
    return LaunchDescription([Watched(package='p', executable='e'), Forgetful('x')])
""")
    said = sorted(d.message for d in model.diagnostics if d.code == "LAUNCH_PY_UNSUPPORTED")
    assert len(said) == 2
    assert said[0].endswith("call to class Watched (not interpreted)")
    assert said[1].endswith(
        "class Forgetful: its constructor does not build the action it derives from")
    assert model.nodes == []
