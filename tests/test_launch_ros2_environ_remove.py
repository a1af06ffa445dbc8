"""``del os.environ[key]`` and ``os.environ.pop(key[, default])`` in a Python launch file
remove the variable from the launch process's environment: a later read of it in the same
file finds it not set. cabrillo_rov_2023's rviz.launch.py (78bccc9) pops GTK_PATH under a
test on it; both the ``pop`` and the ``del`` were said not interpreted, and a read after
the ``del`` took the value the file had set before it."""

from __future__ import annotations

from test_launch_ros2_python import run

BODY = """
import os

def generate_launch_description():
    os.environ['ROBOT_NAME'] = 'rover'
    del os.environ['ROBOT_NAME']
    after_del = os.environ.get('ROBOT_NAME', 'gone')
    os.environ['SIDE'] = 'left'
    popped = os.environ.pop('SIDE')
    after_pop = os.getenv('SIDE', 'none') + '_' + str('SIDE' in os.environ)
    os.environ.pop('NEVER_SET', None)
    return LaunchDescription([Node(package='p', executable='e', name=after_del),
                              Node(package='p', executable='e', name=popped),
                              Node(package='p', executable='e', name=after_pop)])
"""


def test_a_variable_the_file_removes_is_not_set_after(write_tree):
    model, _ = run(write_tree, BODY, env={"OTHER": "1"})
    assert [n.name for n in model.nodes] == ["/gone", "/left", "/none_False"]
    said = [(d.code, d.message) for d in model.diagnostics
            if d.code in ("LAUNCH_UNKNOWN_VALUE", "LAUNCH_PY_UNSUPPORTED")]
    assert said == [], said


GUARDED = """
import os

def generate_launch_description():
    if 'GTK_PATH' in os.environ and 'snap' in os.environ['GTK_PATH']:
        os.environ.pop('GTK_PATH')
    if os.environ.get('UNSET_FOR_TEST'):
        del os.environ['HOME_NAME']
    name = os.environ.get('HOME_NAME', 'default')
    return LaunchDescription([Node(package='p', executable='e', name=name)])
"""


def test_a_removal_under_a_test_not_known_leaves_reads_after_not_known(write_tree):
    model, _ = run(write_tree, GUARDED, env={"HOME_NAME": "base"})
    # HOME_NAME is 'base' or not set ('default'): not known, said
    assert "?" in model.nodes[0].name, model.nodes[0].name
    codes = [d.code for d in model.diagnostics]
    assert "LAUNCH_PY_UNSUPPORTED" not in codes, [
        (d.code, d.message) for d in model.diagnostics]
    assert any(d.code == "LAUNCH_UNKNOWN_VALUE" and "HOME_NAME" in d.message
               for d in model.diagnostics)


def test_del_of_a_dict_item_removes_it(write_tree):
    body = """
def generate_launch_description():
    names = {'a': 'first', 'b': 'second'}
    del names['a']
    return LaunchDescription([Node(package='p', executable='e', name=n)
                              for n in names.values()])
"""
    model, _ = run(write_tree, body)
    assert [n.name for n in model.nodes] == ["/second"]



def test_del_of_a_key_a_known_dict_lacks_is_python_s_key_error(write_tree):
    body = """
def generate_launch_description():
    names = {'a': 'first'}
    try:
        del names['b']
        name = 'deleted'
    except KeyError:
        name = 'caught'
    del names['c']
    return LaunchDescription([Node(package='p', executable='e', name=name)])
"""
    model, _ = run(write_tree, body)
    assert [n.name for n in model.nodes] == ["/caught"]
    said = [d.message for d in model.diagnostics if d.code == "LAUNCH_PY_UNSUPPORTED"]
    assert len(said) == 1 and "no such key" in said[0], said
