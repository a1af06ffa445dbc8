"""smach_ros' ROS states, action server wrapper and introspection server (survey T:
strands_navigation's monitored_nav.py builds ``smach_ros.IntrospectionServer`` and
``ActionServerWrapper``; both were PY_CLASS_UNSEEN and the node PY_NODE_PARTIAL with
neither its action server nor its topics). Their constructors take the name and type
the way actionlib and rospy do (smach_ros noetic-devel): ``SimpleActionState(action_name,
action_spec)`` is an action client, ``ServiceState(service_name, service_spec)`` a
service client, ``MonitorState(topic, msg_type, cond_cb)`` a subscription,
``ActionServerWrapper(server_name, action_spec, container, ...)`` an action server and
``IntrospectionServer(server_name, state, path)`` publishes
``<server>/smach/container_structure`` and ``container_status`` and subscribes
``<server>/smach/container_init``."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.python import extract_python
from haros_arch.workspace import scan

NODE = (
    "#!/usr/bin/env python\n"
    "import rospy\n"
    "import smach\n"
    "import smach_ros\n"
    "from smach_ros import SimpleActionState, ServiceState, MonitorState\n"
    "from move_base_msgs.msg import MoveBaseAction\n"
    "from std_srvs.srv import Empty\n"
    "from std_msgs.msg import Bool\n"
    "\n"
    "rospy.init_node('nav_sm')\n"
    "sm = smach.StateMachine(outcomes=['succeeded', 'aborted', 'preempted'])\n"
    "with sm:\n"
    "    smach.StateMachine.add('GO', SimpleActionState('move_base', MoveBaseAction))\n"
    "    smach.StateMachine.add('CLEAR', ServiceState('clear_costmaps', Empty))\n"
    "    smach.StateMachine.add('WAIT', MonitorState('/bumper', Bool, lambda ud, m: False))\n"
    "sis = smach_ros.IntrospectionServer('nav_sm', sm, '/SM_ROOT')\n"
    "sis.start()\n"
    "wrapper = smach_ros.ActionServerWrapper(rospy.get_name() + '/go', MoveBaseAction, sm,\n"
    "                                        ['succeeded'], ['aborted'], ['preempted'])\n"
)


def test_smach_ros_states_wrapper_and_introspection_are_calls(write_tree) -> None:
    manifest = package_xml("pkg").replace(
        "</package>", "<depend>rospy</depend><depend>smach_ros</depend></package>")
    folder = write_tree({"pkg/package.xml": manifest, "pkg/nodes/nav_sm.py": NODE})
    result = extract_python([str(folder / "pkg" / "nodes" / "nav_sm.py")],
                            scan([str(folder)]), package="pkg")
    assert [d.code for d in result.diagnostics] == []
    assert [(c.kind, c.name, c.type, c.queue_size, c.location.line)
            for c in result.calls] == [
        ("action-client", "move_base", "move_base_msgs/MoveBase", None, 13),
        ("client", "clear_costmaps", "std_srvs/Empty", None, 14),
        ("subscribe", "/bumper", "std_msgs/Bool", None, 15),
        ("subscribe", "nav_sm/smach/container_init", "smach_msgs/SmachContainerInitialStatusCmd",
         None, 16),
        ("publish", "nav_sm/smach/container_structure", "smach_msgs/SmachContainerStructure",
         1, 16),
        ("publish", "nav_sm/smach/container_status", "smach_msgs/SmachContainerStatus", 1, 16),
        ("action-server", "~go", "move_base_msgs/MoveBase", None, 18),
    ]


def test_the_node_own_name_as_server_name_is_its_private_namespace(write_tree) -> None:
    folder = write_tree({"pkg/package.xml": package_xml("pkg"), "pkg/n.py": (
        "import rospy\nimport smach_ros\nimport dynamic_reconfigure.client\n"
        "rospy.init_node('n')\n"
        "smach_ros.IntrospectionServer(rospy.get_name(), None, '/SM_ROOT')\n"
        "dynamic_reconfigure.client.Client(rospy.get_name() + '/cam')\n")})
    result = extract_python([str(folder / "pkg" / "n.py")], scan([str(folder)]), package="pkg")
    assert [c.name for c in result.calls] == [
        "~smach/container_init", "~smach/container_structure", "~smach/container_status",
        "~cam/set_parameters", "~cam/parameter_descriptions", "~cam/parameter_updates"]


def test_the_introspection_command_is_a_tool_input() -> None:
    """smach_viewer publishes ``<server>/smach/container_init``; a state machine that
    nothing in the configuration commands is no subscriber-without-publisher (it was,
    strands_navigation's monitored_nav.py, once the introspection server was read)."""
    from haros_arch.query.functions import is_tool_input
    assert is_tool_input(lambda n: None, "/monitored_navigation_sm/smach/container_init")
    assert not is_tool_input(lambda n: None, "/monitored_navigation_sm/smach/container_status")
