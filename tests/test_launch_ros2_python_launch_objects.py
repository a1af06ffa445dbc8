"""Launch objects (substitutions, conditions, actions) in plain Python expressions of a
launch file, as Python takes them: launch's classes define no ``__bool__``, ``__len__``
nor ``__eq__``, so such an object is true, ``and`` / ``or`` / ``not`` short-circuit on
that, and ``==`` / ``!=`` / ``is`` compare it by identity, whatever the launch
arguments. ``PythonExpression`` is where launch evaluates the values."""

from __future__ import annotations

from test_launch_ros2_python import run

BODY = """
def generate_launch_description():
    use_sim = LaunchConfiguration('use_sim')
    ns = LaunchConfiguration('ns')
    nodes = []
    if use_sim == 'true':
        nodes.append(Node(package='p', executable='e', name='equal_true'))
    else:
        nodes.append(Node(package='p', executable='e', name='equal_false'))
    if use_sim != 'true':
        nodes.append(Node(package='p', executable='e', name='unequal'))
    if not use_sim:
        nodes.append(Node(package='p', executable='e', name='negated'))
    rviz = Node(package='p', executable='e', name='rviz')
    if rviz is not None:
        nodes.append(rviz)
    chosen = ns or 'fallback'
    second = ns and 'second'
    either = IfCondition(use_sim) and IfCondition(LaunchConfiguration('other'))
    return LaunchDescription([
        DeclareLaunchArgument('use_sim', default_value='true'),
        DeclareLaunchArgument('ns', default_value='robot'),
        DeclareLaunchArgument('other', default_value='false'),
        *nodes,
        Node(package='p', executable='e', name='chosen', namespace=chosen),
        Node(package='p', executable='e', name='second', namespace=second),
        Node(package='p', executable='e', name='both', condition=either),
        Node(package='p', executable='e', name='expr_and',
             condition=IfCondition(PythonExpression(["'", use_sim, "' == 'true' and '",
                                                     LaunchConfiguration('other'),
                                                     "' == 'true'"]))),
        Node(package='p', executable='e', name='expr_or',
             condition=IfCondition(PythonExpression(["'", use_sim, "' == 'true' or '",
                                                     LaunchConfiguration('other'),
                                                     "' == 'true'"]))),
    ])
"""


def test_launch_objects_compare_by_identity_and_are_true(write_tree):
    model, _ = run(write_tree, BODY)
    assert [(n.name, n.conditions) for n in model.nodes] == [
        ("/equal_false", ()), ("/unequal", ()), ("/rviz", ()), ("/robot/chosen", ()),
        ("/second/second", ()), ("/expr_or", ())]
    said = sorted((d.code, d.message.split("'")[1]) for d in model.diagnostics
                  if d.code.startswith("LAUNCH_PY_ALWAYS"))
    # the test of an action against None is a test of the variable: nothing said
    assert said == [("LAUNCH_PY_ALWAYS_FALSE", "not use_sim"),
                    ("LAUNCH_PY_ALWAYS_FALSE", "use_sim == "),
                    ("LAUNCH_PY_ALWAYS_TRUE", "use_sim != ")]
    # an ``or`` / ``and`` that takes a substitution's or a condition's truth is said
    # where it takes it (``ns or 'fallback'`` never falls back)
    assert sorted((d.severity, d.message.split("'")[4]) for d in model.diagnostics
                  if d.code == "LAUNCH_PY_BOOLEAN_OBJECT") == [
        ("warning", "IfCondition(use_sim)"), ("warning", "ns"), ("warning", "ns")]


def test_a_helper_comparing_a_launch_object_once_and_a_string_once(write_tree):
    model, _ = run(write_tree, """
def pick(value, name):
    if value == 'true':
        return [Node(package='p', executable='e', name=name)]
    return []

def generate_launch_description():
    return LaunchDescription(pick(LaunchConfiguration('sim'), 'never') + pick('true', 'kept'))
""")
    assert [n.name for n in model.nodes] == ["/kept"]
    said = [d.message for d in model.diagnostics if d.code.startswith("LAUNCH_PY_ALWAYS")]
    assert len(said) == 1 and "always false" in said[0]


ACTION_AS_NAME = """
def generate_launch_description():
    frame = DeclareLaunchArgument('reference_frame', default_value='')
    params = {'reference_frame': LaunchConfiguration(frame),
              'camera_frame': LaunchConfiguration('camera_frame')}
    return LaunchDescription([
        frame,
        DeclareLaunchArgument('camera_frame', default_value='cam'),
        Node(package='p', executable='e', name='detector', parameters=[params]),
    ])
"""


def test_an_action_where_launch_takes_text_is_an_error(write_tree):
    """``LaunchConfiguration(frame)`` with ``frame`` the DeclareLaunchArgument action, not
    its name (aruco_ros 238489d): launch's normalisation of substitutions raises a
    TypeError, so the launch stops; an error, not a construct we do not read."""
    model, _ = run(write_tree, ACTION_AS_NAME)
    bad = [d for d in model.diagnostics if d.code == "LAUNCH_BAD_VALUE"]
    assert len(bad) == 1 and "DeclareLaunchArgument('reference_frame')" in bad[0].message
    assert bad[0].severity == "error"
    assert not any(d.code == "LAUNCH_UNSUPPORTED" for d in model.diagnostics)
