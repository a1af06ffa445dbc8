"""The scalars of a ROS 2 parameter file typed as rcl_yaml_param_parser types them, not as
YAML 1.1 does: a plain scalar is a bool word, else an integer strtol reads whole (base
0), else a double strtod reads whole, else a string. bitbots_robot_filter's params.yaml
sets ``robot_storage_time: 10e9``, which the node declares as a double: the safe
loader (YAML 1.1: a float needs a dot, and an exponent a sign) read a string, and
parameter-type-mismatch said "set as str (10e9) but read as double", a false warning.
Values given as text in a launch file stay launch_ros' (PyYAML's) reading."""

from __future__ import annotations

from test_launch_ros2_python import run

from haros_arch.launch.ros2.naming import load_param_file

BODY = """
def generate_launch_description():
    params = os.path.join(get_package_share_directory('pkg'), 'config', 'p.yaml')
    return LaunchDescription([
        Node(package='p', executable='e', name='filter',
             parameters=[params, {'inline': '1e3'}]),
    ])
"""

PARAMS = """filter:
  ros__parameters:
    storage_time: 10e9
    tolerance: 1e-3
    scale: 1.0e5
    quoted: "1e3"
    grouped: 1_000
    clock: 1:30
    hexadecimal: 0x1A
    octal: 010
    leading_zero: 08
    fraction: .5
    infinite: -.inf
    count: 3
    flag: true
"""


def test_parameter_file_scalars_are_typed_as_rcl_types_them(write_tree):
    model, _ = run(write_tree, BODY, extra={"src/pkg/config/p.yaml": PARAMS})
    values = {p.name.rsplit("/", 1)[-1]: p.value for p in model.params}
    assert values["storage_time"] == 10e9 and isinstance(values["storage_time"], float)
    assert values["tolerance"] == 1e-3 and values["scale"] == 1.0e5
    assert values["quoted"] == "1e3" and values["grouped"] == "1_000"
    assert values["clock"] == "1:30"
    assert (values["hexadecimal"], values["octal"]) == (26, 8)
    assert values["leading_zero"] == 8.0 and isinstance(values["leading_zero"], float)
    assert values["fraction"] == 0.5 and values["infinite"] == float("-inf")
    assert values["count"] == 3 and values["flag"] is True
    assert values["inline"] == "1e3"  # launch_ros reads a text with PyYAML


def test_the_yaml_1_1_reading_elsewhere_is_unchanged():
    import yaml

    assert yaml.safe_load("a: 1e3") == {"a": "1e3"}
    assert load_param_file("a: 1e3") == {"a": 1000.0}
