"""Qt's ``QPainter::fillRect(x, y, w, h, color)`` and a ``QColor`` made from a ``QRgb``
are declared by the Qt stand-in: turtlesim's TurtleFrame::paintEvent reads the
background parameters and fills the window with ``painter.fillRect(0, 0, width(),
height(), qRgb(r, g, b))``, and its node was partial for "too many arguments"."""

from __future__ import annotations

from haros_arch import cmake
from haros_arch.extract import extract_nodes
from haros_arch.workspace import scan
from tests.conftest import package_xml

CMAKE = """
    cmake_minimum_required(VERSION 3.8)
    project(frame)
    find_package(ament_cmake REQUIRED)
    find_package(rclcpp REQUIRED)
    find_package(Qt5 REQUIRED COMPONENTS Widgets)
    add_executable(frame src/frame.cpp)
    ament_target_dependencies(frame rclcpp)
    target_link_libraries(frame Qt5::Widgets)
    ament_package()
    """

SOURCE = """
    #include <QPainter>
    #include <QWidget>
    #include <QApplication>
    #include <rclcpp/rclcpp.hpp>
    class Frame : public QWidget {
    public:
      explicit Frame(rclcpp::Node::SharedPtr node) : node_(node) {
        node_->declare_parameter("background_r", 69);
      }
    protected:
      void paintEvent(QPaintEvent*) {
        QPainter painter(this);
        int r = 69;
        node_->get_parameter("background_r", r);
        QRgb background = qRgb(r, 86, 255);
        painter.fillRect(0, 0, width(), height(), background);
      }
      rclcpp::Node::SharedPtr node_;
    };
    int main(int argc, char** argv) {
      rclcpp::init(argc, argv);
      QApplication app(argc, argv);
      auto node = std::make_shared<rclcpp::Node>("frame");
      Frame frame(node);
      frame.show();
      return app.exec();
    }
    """


def test_a_window_filled_with_a_colour_of_parameters_parses(write_tree) -> None:
    root = write_tree({"frame/package.xml": package_xml("frame", "ament_cmake"),
                       "frame/CMakeLists.txt": CMAKE, "frame/src/frame.cpp": SOURCE})
    ws = scan([str(root)])
    package = ws.packages["frame"]
    package.nodes, _ = cmake.parse_package(package, ws)
    extract_nodes(package.nodes, ws, cache_dir=None, jobs=1)
    (node,) = package.nodes
    assert ("read", "background_r") in {(c.kind, c.name) for c in node.calls}
    assert node.completeness == "complete", node.completeness_reasons
