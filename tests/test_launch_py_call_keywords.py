"""A function of the interpreted Python called with a keyword it does not take:
interbotix_ros_manipulators 47c468e's xsarm_dual.launch.py called interbotix_xs_modules'
``declare_interbotix_xsarm_robot_description_launch_arguments`` with
``robot_description_launch_configuration_name=``, a keyword the helper names
``robot_description_launch_config_name``. Python binds no such keyword (the function has
no ``**kwargs``), so the call raises TypeError, its body does not run, and the launch
file does not load: said where the call is (LAUNCH_PY_UNSUPPORTED, the Python error of
the interpreted code), not read as if the call had declared its arguments. A function
that takes ``**kwargs``, and keywords it names, are bound as before; a ``try`` that
catches TypeError takes the error."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.launch import load
from haros_arch.workspace import scan

HELPER = """
from launch.actions import DeclareLaunchArgument
def declare_camera_arguments(name_config_name='name', default_name='camera'):
    return [DeclareLaunchArgument(name_config_name, default_value=default_name)]
def declare_any(**kwargs):
    return [DeclareLaunchArgument(key, default_value=value) for key, value in kwargs.items()]
"""

LAUNCH = """
from launch import LaunchDescription
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node
from pkg_helpers.helpers import declare_camera_arguments, declare_any
def generate_launch_description():
    declared = []
    declared.extend(declare_camera_arguments(KEYWORD='camera_name', default_name='front'))
    declared.extend(declare_any(rate='10'))
    return LaunchDescription(declared + [
        Node(package='pkg', executable='camera', name=LaunchConfiguration('camera_name')),
    ])
"""

CAUGHT = """
from launch import LaunchDescription
from launch_ros.actions import Node
from pkg_helpers.helpers import declare_camera_arguments
def generate_launch_description():
    try:
        declared = declare_camera_arguments(name_configuration_name='camera_name')
    except TypeError:
        declared = []
    return LaunchDescription(declared + [Node(package='pkg', executable='camera', name='cam')])
"""


def _model(write_tree, text: str):
    root = write_tree({
        "src/pkg/package.xml": package_xml("pkg", "ament_python"),
        "src/pkg/launch/main.launch.py": text,
        "src/pkg_helpers/package.xml": package_xml("pkg_helpers", "ament_python"),
        "src/pkg_helpers/setup.py": "from setuptools import setup\n"
                                    "setup(name='pkg_helpers', packages=['pkg_helpers'])\n",
        "src/pkg_helpers/pkg_helpers/__init__.py": "",
        "src/pkg_helpers/pkg_helpers/helpers.py": HELPER,
    })
    ws = scan([str(root / "src")], {})
    return load(str(root / "src/pkg/launch/main.launch.py"), ws, {}, {})


def _type_errors(model) -> list[tuple[int, str]]:
    return [(d.location.line, d.message) for d in model.diagnostics
            if d.code == "LAUNCH_PY_UNSUPPORTED" and "TypeError" in d.message]


def _names(model) -> list[str]:
    return sorted(str(node.name) for node in model.nodes)


def test_a_keyword_the_function_does_not_name_is_the_type_error(write_tree):
    text = LAUNCH.replace("KEYWORD", "name_configuration_name")
    model = _model(write_tree, text)
    said = _type_errors(model)
    call = next(number for number, line in enumerate(text.strip().splitlines(), 1)
                if "declare_camera_arguments(name_configuration_name" in line)
    assert [line for line, _ in said] == [call]
    assert "declare_camera_arguments() got an unexpected keyword argument " \
           "'name_configuration_name'" in said[0][1]
    # the helper's DeclareLaunchArgument did not run: camera_name is not declared here
    assert _names(model) != ["/front"]


def test_the_keyword_it_names_and_kwargs_bind_as_before(write_tree):
    model = _model(write_tree, LAUNCH.replace("KEYWORD", "name_config_name"))
    assert _type_errors(model) == []
    assert _names(model) == ["/front"]


def test_a_try_that_catches_type_error_takes_it(write_tree):
    model = _model(write_tree, CAUGHT)
    assert _type_errors(model) == []
    assert _names(model) == ["/cam"]
