"""mavros loads every plugin its deny / allow list lets through; where that list is not
set as far as we see but a parameter file not known statically may set it (mavros' own
``launch/px4_pluginlists.yaml`` from its share, where mavros is not installed here), the
plugins it loads are not known: the mavros node is partial, with that reason, as a host
whose plugin parameter may be set so is (move_base's ``/move_base/?``). Before, the
unknown file was taken for no list: every plugin of the models loaded and the node
whole. A list the configuration gives, or no unknown file, keeps it whole."""

from __future__ import annotations

import os

from conftest import package_xml

from haros_arch import pipeline
from haros_arch.project import ConfigurationSpec, Project

LAUNCH = """from launch import LaunchDescription
from launch.substitutions import PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    share = FindPackageShare('mavros')
    return LaunchDescription([Node(
        package='mavros', executable='mavros_node', namespace='mavros',
        parameters=[{files}{{'fcu_url': 'udp://:14540@'{given}}}])])
"""

SHARE = ("PathJoinSubstitution([share, 'launch', 'px4_pluginlists.yaml']), "
         "PathJoinSubstitution([share, 'launch', 'px4_config.yaml']), ")


def _uas(write_tree, files: str, given: str = ""):
    root = write_tree({
        "dr/package.xml": package_xml("dr", "ament_python").replace(
            "</package>", "<exec_depend>mavros</exec_depend></package>"),
        "dr/setup.py": "from setuptools import setup\nsetup(name='dr', data_files=["
                       "('share/dr/launch', ['launch/a.launch.py'])])\n",
        "dr/launch/a.launch.py": LAUNCH.format(files=files, given=given),
    })
    project = Project("p", os.path.join(str(root), "project.yaml"), workspace=[str(root)],
                      configurations=[ConfigurationSpec("c", ["dr/launch/a.launch.py"], {})])
    model = pipeline.analyse(project, {}, pipeline.Options(cache_dir=None, jobs=1))
    (config,) = model.configurations
    uas = config.node("/mavros/mavros")
    assert uas is not None
    return uas, config


def test_a_plugin_list_an_unknown_file_may_set_leaves_mavros_partial(write_tree):
    uas, config = _uas(write_tree, SHARE)
    assert uas.completeness == "partial"
    assert any("plugin_denylist" in reason and "/mavros/mavros/?" in reason
               for reason in uas.completeness_reasons), uas.completeness_reasons
    assert config.node("/mavros/sys") is not None  # the plugins seen are still there


def test_a_list_given_or_no_unknown_file_keeps_it_whole(write_tree):
    uas, _ = _uas(write_tree, "")
    assert uas.completeness != "partial", uas.completeness_reasons
    uas, config = _uas(write_tree, SHARE, ", 'plugin_denylist': ['vibration'], "
                                          "'plugin_allowlist': []")
    assert uas.completeness != "partial", uas.completeness_reasons
    assert config.node("/mavros/vibration") is None
