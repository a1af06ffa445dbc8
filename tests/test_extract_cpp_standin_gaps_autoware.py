"""Stand-in gaps seen on Autoware (universe 0.43 with autoware_utils 1.3, thirty-third
session): ``std::invoke`` of a lambda (the autonomous emergency braking node's
``checkCollision``, behavior_path_planner's ``publishPathCandidate``), ``std::exchange``
(its planner manager's ``print``), ``PublisherBase::get_gid`` with ``rmw_gid_t`` and
``std::memcmp`` (autoware_utils' ``PublishedTimePublisher``, which most planning nodes
hold), the timer's handle and ``rclcpp::get_logging_directory()`` (the evaluators'
constructors), ``tf2::BufferCore::lookupTransform``, ``tf2::Vector3::setW``, rosidl's
builders (``geometry_msgs::build<Pose>().position(p).orientation(q)``, in 27 Autoware
files: autoware_planning_factor_interface's header among them), ``boost::optional`` with
``boost::none``, OpenCV's ``Mat::setTo`` of a vector and a few more of the standard
library. Each left a C++ error in a function that calls the ROS API, so the call after it
could be missed and the node was partial."""

from __future__ import annotations

import pytest
from standin_gap_checks import assert_call_found

HEAD = ("#include <rclcpp/rclcpp.hpp>\n#include <std_msgs/msg/string.hpp>\n"
        "#include <cstring>\n#include <random>\n#include <sstream>\n")

CASES = {
    "invoke_lambda": (
        "",
        "    const auto closest = std::invoke([&]() -> std::optional<double> {\n"
        "      return std::nullopt; });\n"
        "    const double half = std::invoke([](double a, double b) { return a / b; }, 1.0, 2.0);\n"
        "    if (closest && half > 0.0) {}\n"),
    "invoke_member": (
        "",
        "    std::string name = \"a\";\n"
        "    const size_t size = std::invoke(&std::string::size, name);\n"
        "    if (size > 0) {}\n"),
    "exchange": (
        "",
        "    std::string delimiter = \"\";\n"
        "    std::stringstream text;\n"
        "    text << std::exchange(delimiter, \" ==> \") << \"[[\";\n"),
    "gid": (
        "",
        "    auto base = create_publisher<std_msgs::msg::String>(\"base\", 1);\n"
        "    const rclcpp::PublisherBase::ConstSharedPtr publisher = base;\n"
        "    const auto & gid = publisher->get_gid();\n"
        "    rmw_gid_t other = gid;\n"
        "    if (std::memcmp(gid.data, other.data, RMW_GID_STORAGE_SIZE) < 0) {}\n"),
    "timer_and_log_folder": (
        "",
        "    auto timer = create_wall_timer(std::chrono::seconds(1), []() {});\n"
        "    if (timer->get_timer_handle() && timer->time_until_trigger().count() > 0) {}\n"
        "    const std::string folder = rclcpp::get_logging_directory().string() + \"/m\";\n"),
    "buffer_core": (
        "#include <tf2_ros/buffer.h>\n",
        "    tf2::BufferCore core;\n"
        "    auto t = core.lookupTransform(\"map\", \"base_link\", tf2::TimePointZero);\n"
        "    tf2::Vector3 v(1.0, 2.0, 3.0);\n"
        "    v.setW(t.transform.translation.x);\n"
        "    tf2::Vector3 w = tf2::lerp(v, v, 0.5);\n"
        "    tf2::Quaternion q;\n"
        "    double yaw, pitch, roll;\n"
        "    tf2::getEulerYPR(q, yaw, pitch, roll);\n"),
    "rosidl_builder": (
        "#include <geometry_msgs/msg/pose.hpp>\n#include <std_srvs/srv/set_bool.hpp>\n",
        "    geometry_msgs::msg::Point p;\n"
        "    const auto pose = geometry_msgs::build<geometry_msgs::msg::Pose>()\n"
        "      .position(p).orientation(geometry_msgs::build<geometry_msgs::msg::Quaternion>()\n"
        "        .x(0.0).y(0.0).z(0.0).w(1.0));\n"
        "    const auto request = std_srvs::build<std_srvs::srv::SetBool_Request>()"
        ".data(true);\n"
        "    if (pose.position.x > 0.0 && request.data) {}\n"),
    "boost_optional": (
        "#include <boost/optional.hpp>\n",
        "    boost::optional<rclcpp::Time> last;\n"
        "    last = boost::none;\n"
        "    last = now();\n"
        "    boost::optional<double> gap = boost::make_optional(true, 1.0);\n"
        "    if (!last || last == boost::none || gap.get_value_or(0.0) > *gap) last.reset();\n"),
    "streams_variants_pointers": (
        "#include <regex>\n#include <variant>\n",
        "    const std::array<double, 3> offsets{0.0, 1.0, 2.0};\n"
        "    const double first = offsets.at(0);\n"
        "    auto a = std::make_shared<const std_msgs::msg::String>();\n"
        "    std_msgs::msg::String::ConstSharedPtr b = a;\n"
        "    bool active{};\n"
        "    std::istringstream(\"true\") >> std::boolalpha >> active;\n"
        "    try { std::regex r(\"[\"); } catch (const std::regex_error & e) { e.code(); }\n"
        "    std::variant<std_msgs::msg::String, int> value;\n"
        "    std::visit([&](auto & v) { (void)v; }, value);\n"
        "    if (a != b && first > 0.0 && active) {}\n"),
    "opencv_set_to": (
        "#include <opencv2/core.hpp>\n",
        "    cv::Mat merged(cv::Size(4, 4), CV_8UC3, cv::Scalar(0, 0, 0));\n"
        "    cv::Mat mask(cv::Size(4, 4), CV_8UC1, cv::Scalar(0));\n"
        "    merged.setTo(cv::Vec3b(0, 0, 255), mask);\n"),
    "standard_library": (
        "",
        "    std::vector<int> values{1, 2};\n"
        "    auto first = std::cbegin(values);\n"
        "    auto last = std::cend(values);\n"
        "    std::vector<int> moved(std::make_move_iterator(values.begin()),\n"
        "                           std::make_move_iterator(values.end()));\n"
        "    std::remove_extent_t<int[3]> element = 0;\n"
        "    std::independent_bits_engine<std::mt19937, 8, unsigned short> bits;\n"
        "    std::istringstream in(\"a b\");\n"
        "    char c;\n"
        "    in >> std::noskipws >> c;\n"
        "    if (std::signbit(-1.0) && first != last && element == 0 && bits() > 0) {}\n"),
    # the thirty-fourth session: the emergency braking node's closest object
    "algorithms_with_a_comparison": (
        "",
        "    std::vector<double> values{1.0, 2.0};\n"
        "    const auto closest = std::min_element(values.begin(), values.end(),\n"
        "      [](const auto & a, const auto & b) { return a < b; });\n"
        "    const auto farthest = std::max_element(values.begin(), values.end(),\n"
        "      [](double a, double b) { return a < b; });\n"
        "    auto end = std::unique(values.begin(), values.end(),\n"
        "      [](double a, double b) { return a == b; });\n"
        "    if (closest != farthest && end != values.end()) {}\n"),
}


@pytest.mark.parametrize("case", sorted(CASES))
def test_a_call_after_the_library_s_use_is_found(tmp_path, case: str) -> None:
    include, body = CASES[case]
    assert_call_found(tmp_path, (
        HEAD + include + "class Node : public rclcpp::Node {\npublic:\n"
        "  Node() : rclcpp::Node(\"node\") {\n" + body +
        "    pub_ = create_publisher<std_msgs::msg::String>(\"out\", 1);\n  }\n"
        "  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;\n};\n"),
        "ament_cmake", "jazzy")
