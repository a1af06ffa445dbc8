"""``context.environment`` in an OpaqueFunction is the process's environment, read as
``os.environ`` is: the configuration's value, else a value not known (an info), not an
unsupported ``.get()`` warning. depthai-ros' camera.launch.py picks its log level with
``context.environment.get("DEPTHAI_DEBUG") == "1"``."""

from __future__ import annotations

from test_launch_ros2_python import codes, run

BODY = """
def setup(context, *args, **kwargs):
    level = "info"
    if context.environment.get("CAM_DEBUG") == "1":
        level = "debug"
    name = context.environment.get("CAM_NAME", "cam")
    return [Node(package='p', executable='e', name=name + '_' + level)]

def generate_launch_description():
    return LaunchDescription([OpaqueFunction(function=setup)])
"""


def test_the_context_environment_is_the_configurations(write_tree):
    model, _ = run(write_tree, BODY, env={"CAM_DEBUG": "1", "CAM_NAME": "left"})
    assert [n.name for n in model.nodes] == ["/left_debug"]
    assert "LAUNCH_PY_UNSUPPORTED" not in codes(model)


def test_a_variable_the_configuration_does_not_set_is_not_known(write_tree):
    model, _ = run(write_tree, BODY)
    # the level not known (CAM_DEBUG may be set where it runs); the name's default
    assert len(model.nodes) == 1 and model.nodes[0].name.startswith("/cam_"), model.nodes
    assert "LAUNCH_PY_UNSUPPORTED" not in codes(model)
    assert "LAUNCH_UNKNOWN_VALUE" in codes(model)
