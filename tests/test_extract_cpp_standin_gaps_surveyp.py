"""Stand-in gaps seen on real ROS 2 code (bench/README, helper surveyP): each left a C++
error in a function of a node, which made the node partial where that function calls the
ROS API."""

from __future__ import annotations

import pytest
from standin_gap_checks import assert_call_found, ros2_main

CASES = {
    # rclcpp's logging macros pass their first argument through rclcpp::get_c_string:
    # a std::string is a format (the Omron AMR's demo_execute_macro.cpp logs
    # ``feedback->feed_msg``)
    "string_format": (
        "#include <string>\n",
        "  const std::string text = \"goal\";\n"
        "  RCLCPP_INFO(node->get_logger(), text);\n"
        "  RCLCPP_WARN_ONCE(node->get_logger(), std::string(\"once\"));\n"
        "  RCLCPP_ERROR(node->get_logger(), rclcpp::get_c_string(text));\n"),
    # the events executor's listeners on subscriptions, services and clients (III-Drone's
    # lifecycle nodes clear them in on_deactivate)
    "event_listeners": (
        "#include <std_srvs/srv/trigger.hpp>\n",
        "  auto sub = node->create_subscription<std_msgs::msg::String>(\"in\", 10,\n"
        "      [](std_msgs::msg::String::SharedPtr) {});\n"
        "  auto srv = node->create_service<std_srvs::srv::Trigger>(\"do\",\n"
        "      [](const std::shared_ptr<std_srvs::srv::Trigger::Request>,\n"
        "         std::shared_ptr<std_srvs::srv::Trigger::Response>) {});\n"
        "  auto cli = node->create_client<std_srvs::srv::Trigger>(\"ask\");\n"
        "  sub->set_on_new_message_callback([](size_t) {});\n"
        "  sub->clear_on_new_message_callback();\n"
        "  srv->set_on_new_request_callback([](size_t) {});\n"
        "  srv->clear_on_new_request_callback();\n"
        "  cli->set_on_new_response_callback([](size_t) {});\n"
        "  cli->clear_on_new_response_callback();\n"),
    # std::shared_lock's members (III-Drone's utils unlock one early)
    "shared_lock": (
        "#include <shared_mutex>\n",
        "  std::shared_mutex mutex;\n"
        "  std::shared_lock<std::shared_mutex> lock(mutex);\n"
        "  if (lock.owns_lock()) { lock.unlock(); }\n"
        "  std::shared_lock<std::shared_mutex> later(mutex, std::defer_lock);\n"
        "  later.lock();\n"),
    # <complex>'s imaginary literals (corgi's gait generators: ``std::exp(1i * a) * v``)
    "complex_literals": (
        "#include <complex>\n#include <cmath>\n",
        "  using namespace std::complex_literals;\n"
        "  const double a = 0.5;\n"
        "  std::complex<double> v(1.0, 0.0);\n"
        "  std::complex<double> turned = std::exp(1i * (a + M_PI)) * v;\n"
        "  double x = turned.real() + (2.0 * (std::exp(1i * a) * v)).imag();\n"),
    # Eigen's partialPivLu() (corgi's leg model solves its Newton step with it)
    "partial_piv_lu": (
        "#include <Eigen/Dense>\n",
        "  Eigen::Matrix2d jac = Eigen::Matrix2d::Identity();\n"
        "  Eigen::Vector2d cost(1.0, 2.0);\n"
        "  Eigen::Vector2d step = jac.partialPivLu().solve(-cost);\n"),
    # Node::get_clock() const and Clock::now() const (hexapod-ros2-control's bridge reads
    # its clock in a const member, ``(get_clock()->now() - boot_).nanoseconds()``)
    "const_clock": (
        "#include <cstdint>\n"
        "struct Ticker {\n"
        "  const rclcpp::Node* node;\n"
        "  rclcpp::Time boot;\n"
        "  std::int64_t since() const {\n"
        "    return (node->get_clock()->now() - boot).nanoseconds();\n"
        "  }\n"
        "};\n",
        "  Ticker ticker{node.get(), node->now()};\n"
        "  rclcpp::Clock::ConstSharedPtr clock = ticker.node->get_clock();\n"
        "  auto elapsed = ticker.since() + clock->now().nanoseconds();\n"),
    # the Linux SPI and GPIO character device interfaces (Husarion Panther's APA102
    # lights, hexapod-ros2-control's SH1122 display): the headers were missing
    "spidev_gpio": (
        "#include <fcntl.h>\n#include <sys/ioctl.h>\n#include <unistd.h>\n"
        "#include <cstring>\n#include <linux/spi/spidev.h>\n#include <linux/gpio.h>\n",
        "  int spi = open(\"/dev/spidev0.0\", O_RDWR);\n"
        "  uint8_t mode = SPI_MODE_3 | SPI_NO_CS;\n"
        "  uint32_t speed = 8000000;\n"
        "  ioctl(spi, SPI_IOC_WR_MODE, &mode);\n"
        "  ioctl(spi, SPI_IOC_WR_MAX_SPEED_HZ, &speed);\n"
        "  uint8_t tx[4] = {0, 0, 0, 0};\n"
        "  struct spi_ioc_transfer transfer;\n"
        "  std::memset(&transfer, 0, sizeof(transfer));\n"
        "  transfer.tx_buf = reinterpret_cast<uint64_t>(tx);\n"
        "  transfer.len = sizeof(tx);\n"
        "  transfer.bits_per_word = 8;\n"
        "  ioctl(spi, SPI_IOC_MESSAGE(1), &transfer);\n"
        "  int chip = open(\"/dev/gpiochip0\", O_RDWR);\n"
        "  gpio_v2_line_request request{};\n"
        "  request.offsets[0] = 24;\n"
        "  request.num_lines = 1;\n"
        "  request.config.flags = GPIO_V2_LINE_FLAG_OUTPUT;\n"
        "  std::strncpy(request.consumer, \"panel\", sizeof(request.consumer) - 1);\n"
        "  ioctl(chip, GPIO_V2_GET_LINE_IOCTL, &request);\n"
        "  gpio_v2_line_values values{};\n"
        "  values.mask = 1ULL;\n"
        "  values.bits = 1ULL;\n"
        "  ioctl(request.fd, GPIO_V2_LINE_SET_VALUES_IOCTL, &values);\n"
        "  gpiohandle_request handle{};\n"
        "  handle.flags = GPIOHANDLE_REQUEST_OUTPUT;\n"
        "  ioctl(chip, GPIO_GET_LINEHANDLE_IOCTL, &handle);\n"
        "  close(spi);\n"),
}


@pytest.mark.parametrize("case", sorted(CASES))
def test_a_call_after_the_library_s_use_is_found(tmp_path, case: str) -> None:
    include, body = CASES[case]
    assert_call_found(tmp_path, ros2_main(include, body), "ament_cmake", "jazzy")
