"""Stand-in gaps seen on real ROS 1 code (bench/README, helper surveyO), each a C++ error
in a function that calls the ROS API, so the call after it could be missed and the node
was partial. roscpp's option structs hold a ``helper`` (AIS-Bonn's humanoid_op_ros:
nimbro_service_transport's service relays set ``ops.helper`` to their own subclass of
``ros::ServiceCallbackHelper``; its fork of rosbag's recorder sets a
``ros::SubscriptionCallbackHelperT`` on a SubscribeOptions), and rosbag's export macro
and compression types (``rosbag/macros.h``, ``rosbag/stream.h``, fallback headers: the
fork declares ``class ROSBAG_DECL Recorder`` holding a
``rosbag::compression::CompressionType``, so the whole class was an error); and small
gaps of the same robot's nodes: a directory entry's ``status()`` and the queries over a
status (config_server's backups, Boost.Filesystem as ``<filesystem>``),
``std::string::insert(iterator, char)`` (rrlogger), ``std::map::insert(hint, value)``
(the rosbag fork's player), ``ServiceClient::call(req, res, md5sum)`` (the UDP service
server's relay of serialized messages)."""

from __future__ import annotations

import pytest
from standin_gap_checks import assert_call_found, ros1_main

CASES = {
    "service_callback_helper": (
        "class Relay : public ros::ServiceCallbackHelper {\n"
        " public:\n"
        "  explicit Relay(const std::string &name) : name_(name) {}\n"
        "  virtual bool call(ros::ServiceCallbackHelperCallParams &params) { return true; }\n"
        "  std::string name_;\n"
        "};\n",
        "  ros::AdvertiseServiceOptions ops;\n"
        "  ops.callback_queue = 0;\n"
        "  ops.datatype = \"std_srvs/Empty\";\n"
        "  ops.helper = boost::make_shared<Relay>(\"relay\");\n"
        "  ops.service = \"relay\";\n"
        "  ros::ServiceServer server = nh.advertiseService(ops);\n"),
    "subscription_callback_helper": (
        "static void queue(const std_msgs::String::ConstPtr &msg) {}\n",
        "  ros::SubscribeOptions ops;\n"
        "  ops.topic = \"in\";\n"
        "  ops.queue_size = 100;\n"
        "  ops.helper = boost::make_shared<ros::SubscriptionCallbackHelperT<\n"
        "      const std_msgs::String::ConstPtr &> >(boost::bind(&queue, _1));\n"
        "  ros::Subscriber sub = nh.subscribe(ops);\n"),
    "rosbag_macros_and_stream": (
        "#include <rosbag/bag.h>\n#include <rosbag/stream.h>\n#include <rosbag/macros.h>\n"
        "namespace rosbag {\n"
        "struct ROSBAG_DECL RecorderOptions {\n"
        "  RecorderOptions() : compression(compression::Uncompressed) {}\n"
        "  CompressionType compression;\n"
        "};\n"
        "class ROSBAG_DECL Recorder {\n"
        " public:\n"
        "  explicit Recorder(const RecorderOptions &options) : options_(options) {}\n"
        "  RecorderOptions options_;\n"
        "};\n"
        "}\n",
        "  rosbag::RecorderOptions options;\n"
        "  options.compression = rosbag::compression::LZ4;\n"
        "  rosbag::Recorder recorder(options);\n"),
    "directory_entry_status": (
        "#include <boost/filesystem.hpp>\n"
        "namespace fs = boost::filesystem;\n",
        "  fs::directory_iterator end;\n"
        "  for (fs::directory_iterator file(\"/tmp\"); file != end; ++file) {\n"
        "    if (!fs::is_directory(file->status())) continue;\n"
        "  }\n"),
    "string_insert_char": (
        "",
        "  std::string topic = \"chatter\";\n"
        "  if (topic[0] != '/') topic.insert(topic.begin(), '/');\n"),
    "map_insert_hint": (
        "#include <map>\n",
        "  std::map<std::string, ros::Publisher> publishers;\n"
        "  publishers.insert(publishers.begin(),\n"
        "                    std::pair<std::string, ros::Publisher>(\"a\", ros::Publisher()));\n"),
    "service_call_md5sum": (
        "#include <std_srvs/Empty.h>\n",
        "  ros::ServiceClient client = nh.serviceClient<std_srvs::Empty>(\"relay\");\n"
        "  std_srvs::Empty::Request request;\n"
        "  std_srvs::Empty::Response response;\n"
        "  bool ok = client.call(request, response, std::string(\"*\"));\n"),
}


@pytest.mark.parametrize("case", sorted(CASES))
def test_a_call_after_the_library_s_use_is_found(tmp_path, case: str) -> None:
    include, body = CASES[case]
    assert_call_found(tmp_path, ros1_main(include, body))
