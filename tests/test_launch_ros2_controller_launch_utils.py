"""controller_manager's ``launch_utils`` (PAL's TIAGo controller launch files return
``generate_load_controller_launch_description(...)``): the launch description it makes,
two launch arguments and a spawner of the controller with its parameter file. Before,
the call was not interpreted and the file's spawner was unseen (LAUNCH_PY_UNSUPPORTED)."""

from __future__ import annotations

from test_launch_ros2_python import run


def spawner(model):
    (node,) = [n for n in model.nodes if n.executable == "spawner"]
    return node


def test_the_load_controller_helper_starts_a_spawner(write_tree) -> None:
    model, _ = run(write_tree, """
from controller_manager.launch_utils import generate_load_controller_launch_description

def generate_launch_description():
    return generate_load_controller_launch_description(
        controller_name='arm_controller',
        controller_type='joint_trajectory_controller/JointTrajectoryController',
        controller_params_file=os.path.join(
            get_package_share_directory('pkg'), 'config', 'arm_controller.yaml'))
""", extra={"src/pkg/config/arm_controller.yaml": "arm_controller: {}\n"})
    node = spawner(model)
    assert node.package == "controller_manager"
    words = node.args.split()
    assert words[:3] == ["arm_controller", "--controller-manager", "controller_manager"]
    assert words[3] == "--param-file" and words[4].endswith("pkg/config/arm_controller.yaml")
    assert len(words) == 5  # unload_on_kill defaults to false: '' is no word (shell=True)
    assert "LAUNCH_PY_UNSUPPORTED" not in [d.code for d in model.diagnostics]


def test_its_arguments_are_declared_and_read(write_tree) -> None:
    model, _ = run(write_tree, """
from controller_manager import launch_utils

def generate_launch_description():
    return launch_utils.generate_controllers_spawner_launch_description(
        ['a', 'b'], extra_spawner_args=['--inactive'])
""", args={"controller_manager_name": "/robot/cm", "unload_on_kill": "true"})
    words = spawner(model).args.split()
    assert words == ["a", "b", "--controller-manager", "/robot/cm", "--unload-on-kill",
                     "--inactive"]
    assert "LAUNCH_ARG_UNSET" not in [d.code for d in model.diagnostics]


def test_the_dict_form_takes_each_controller_s_files(write_tree) -> None:
    model, _ = run(write_tree, """
from controller_manager.launch_utils import (
    generate_controllers_spawner_launch_description_from_dict)

def generate_launch_description():
    return generate_controllers_spawner_launch_description_from_dict(
        {'a': '/x/a.yaml', 'b': None, 'c': ['/x/c1.yaml', '/x/c2.yaml']})
""")
    words = spawner(model).args.split()
    assert words == ["a", "b", "c", "--controller-manager", "controller_manager",
                     "--param-file", "/x/a.yaml", "--param-file", "/x/c1.yaml",
                     "--param-file", "/x/c2.yaml"]
