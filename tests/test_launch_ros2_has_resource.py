"""ament_index_python's ``has_resource('packages', name)`` in a Python launch file
(camera_ros' camera.launch.py adds image_view's viewer only when image_view is
installed): True when the workspace has the package; else not known here (an info,
LAUNCH_UNKNOWN_VALUE, not an unsupported call), and the ``if`` takes both branches."""

from __future__ import annotations

from test_launch_ros2_python import codes, run

from tests.conftest import package_xml

BODY = """
from ament_index_python.resources import has_resource

def generate_launch_description():
    nodes = [Node(package='pkg', executable='cam', name='cam')]
    if has_resource('packages', '{viewer}'):
        nodes.append(Node(package='{viewer}', executable='view', name='view'))
    else:
        nodes.append(Node(package='pkg', executable='cam', name='fallback'))
    return LaunchDescription(nodes)
"""


def test_a_package_the_workspace_has_is_there(write_tree):
    model, _ = run(write_tree, BODY.replace("{viewer}", "viewer"), extra={
        "src/viewer/package.xml": package_xml("viewer", "ament_python")})
    assert [n.name for n in model.nodes] == ["/cam", "/view"]
    assert "LAUNCH_PY_UNSUPPORTED" not in codes(model)
    assert "LAUNCH_UNKNOWN_VALUE" not in codes(model)


def test_a_package_not_here_may_be_installed_where_it_runs(write_tree):
    model, _ = run(write_tree, BODY.replace("{viewer}", "image_viewer"))
    assert [n.name for n in model.nodes] == ["/cam", "/view", "/fallback"]
    assert "LAUNCH_PY_UNSUPPORTED" not in codes(model)
    assert "LAUNCH_UNKNOWN_VALUE" in codes(model)


def test_another_resource_type_is_still_unsupported(write_tree):
    model, _ = run(write_tree, BODY.replace("'packages'", "'rviz_plugins'").replace(
        "{viewer}", "viewer"))
    assert "LAUNCH_PY_UNSUPPORTED" in codes(model)


PREFIXES = """
from ament_index_python.packages import get_packages_with_prefixes

def generate_launch_description():
    nodes = [Node(package='pkg', executable='cam', name='cam')]
    if '{viewer}' in get_packages_with_prefixes():
        nodes.append(Node(package='{viewer}', executable='view', name='view'))
    if '{viewer}' not in get_packages_with_prefixes():
        nodes.append(Node(package='pkg', executable='cam', name='fallback'))
    return LaunchDescription(nodes)
"""


def test_a_name_in_the_packages_with_prefixes_asks_as_has_resource(write_tree):
    # webots_ros2's robot launch files: ``if 'nav2_bringup' in
    # get_packages_with_prefixes():`` was a call not interpreted and a test not known
    model, _ = run(write_tree, PREFIXES.replace("{viewer}", "viewer"), extra={
        "src/viewer/package.xml": package_xml("viewer", "ament_python")})
    assert [n.name for n in model.nodes] == ["/cam", "/view"]
    assert "LAUNCH_PY_UNSUPPORTED" not in codes(model)
    model, _ = run(write_tree, PREFIXES.replace("{viewer}", "image_viewer"))
    assert [n.name for n in model.nodes] == ["/cam", "/view", "/fallback"]
    assert "LAUNCH_PY_UNSUPPORTED" not in codes(model)
    assert "LAUNCH_UNKNOWN_VALUE" in codes(model)
