"""tf2_ros' ROS 1 MessageFilter reports its target frames as text and its queue size
(``getTargetFramesString()``, ``getQueueSize()``, geometry2 noetic-devel
tf2_ros/include/tf2_ros/message_filter.h:259, 436): MoveIt's PointCloudOctomapUpdater
logs the frames in ``start()``, the function that subscribes the point cloud, and the
parse error there made the updater partial."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import Workspace


def test_a_message_filters_frames_text_parses(tmp_path) -> None:
    source = tmp_path / "n.cpp"
    source.write_text(
        "#include <ros/ros.h>\n#include <string>\n#include <sensor_msgs/PointCloud2.h>\n"
        "#include <tf2_ros/buffer.h>\n#include <tf2_ros/message_filter.h>\n"
        "#include <message_filters/subscriber.h>\n"
        "struct Updater {\n"
        "  virtual void start() {\n"
        "    sub_ = new message_filters::Subscriber<sensor_msgs::PointCloud2>(nh_, \"cloud\", 5);\n"
        "    filter_ = new tf2_ros::MessageFilter<sensor_msgs::PointCloud2>(*sub_, buffer_,\n"
        "                                                                   \"map\", 5, nh_);\n"
        "    std::string frames = filter_->getTargetFramesString();\n"
        "    unsigned size = filter_->getQueueSize();\n"
        "    ROS_INFO(\"%s %u\", frames.c_str(), size);\n"
        "  }\n"
        "  ros::NodeHandle nh_;\n"
        "  tf2_ros::Buffer buffer_;\n"
        "  message_filters::Subscriber<sensor_msgs::PointCloud2>* sub_;\n"
        "  tf2_ros::MessageFilter<sensor_msgs::PointCloud2>* filter_;\n"
        "};\n")
    result = extract_cpp([str(source)], Workspace(root=str(tmp_path)), cache_dir=None)
    assert [(c.kind, c.name) for c in result.calls] == [("subscribe", "cloud")]
    assert [d.message for d in result.diagnostics
            if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL")] == []
