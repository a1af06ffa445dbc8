"""What a ROS 1 connection compares: the definition (md5sum), not the type's name."""

from haros_arch.extract.cpp.interfaces import wire_key


def test_two_ros1_names_of_one_definition_have_one_key() -> None:
    assert wire_key("tf/tfMessage") == wire_key("tf2_msgs/TFMessage")
    assert wire_key("tf/tfMessage", ).startswith("ros1:")


def test_different_definitions_and_unknown_ones_keep_apart() -> None:
    assert wire_key("std_msgs/String") != wire_key("std_msgs/Bool")
    # a definition we do not know is no claim: the name stays the key
    assert wire_key("acme_msgs/Thing") == "acme_msgs/Thing"
    assert wire_key("std_msgs/Int32") != wire_key("acme_msgs/Thing")


def test_ros2_names_match_by_name() -> None:
    assert wire_key("tf2_msgs/msg/TFMessage") == "tf2_msgs/msg/TFMessage"
    assert wire_key("tf2_msgs/msg/TFMessage") != wire_key("tf/msg/tfMessage")
    assert wire_key(None) is None
