"""A node named by a string literal that reaches ``rclcpp::Node`` through a virtual
method: the code calls the interface's method, which the class it constructs overrides.
rviz_common's ``VisualizerApp::init`` calls ``ros_client_abstraction_->init(argc, argv,
"rviz", false)`` on a ``RosClientAbstractionIface``; ``RosClientAbstraction::init``
(another file) makes ``RosNodeAbstraction(final_name)`` (a third), whose member
initialiser makes ``rclcpp::Node::make_shared(node_name)``: the node was named ``?``.
A member passed that way stays unknown (a later method may change it)."""

from __future__ import annotations

import pytest

from haros_arch.extract.cpp import CppBatch, extract_cpp_nodes
from haros_arch.workspace import scan
from tests.conftest import package_xml

HEADER = """#pragma once
#include <memory>
#include <string>
#include <rclcpp/rclcpp.hpp>
class Holder {
 public:
  explicit Holder(const std::string & node_name);
 private:
  rclcpp::Node::SharedPtr node_;
};
class Starter {
 public:
  virtual ~Starter() = default;
  virtual std::shared_ptr<Holder> start(int argc, char ** argv, const std::string & name,
                                        bool hidden) = 0;
};
class RclStarter : public Starter {
 public:
  std::shared_ptr<Holder> start(int argc, char ** argv, const std::string & name,
                                bool hidden) override;
};
class Viewer {
 public:
  explicit Viewer(std::unique_ptr<Starter> starter);
  bool init(int argc, char ** argv);
 private:
  std::unique_ptr<Starter> starter_;
  std::shared_ptr<Holder> holder_;
  std::string title_;
};
"""

HOLDER = """#include "viewer/parts.hpp"
Holder::Holder(const std::string & node_name)
: node_(rclcpp::Node::make_shared(node_name))
{}
"""

STARTER = """#include "viewer/parts.hpp"
std::shared_ptr<Holder> RclStarter::start(int argc, char ** argv, const std::string & name,
                                          bool hidden)
{
  std::string chosen = name;
  if (hidden) {
    throw std::runtime_error("not supported");
  }
  rclcpp::init(argc, argv);
  return std::make_shared<Holder>(chosen);
}
"""

VIEWER = """#include "viewer/parts.hpp"
Viewer::Viewer(std::unique_ptr<Starter> starter)
: starter_(std::move(starter)), title_("viewer_title") {}
bool Viewer::init(int argc, char ** argv)
{
  holder_ = starter_->start(argc, argv, %s, false);
  return true;
}
"""

MAIN = """#include "viewer/parts.hpp"
int main(int argc, char ** argv)
{
  Viewer viewer(std::make_unique<RclStarter>());
  return viewer.init(argc, argv) ? 0 : 1;
}
"""


@pytest.fixture(scope="module")
def batch(tmp_path_factory: pytest.TempPathFactory) -> CppBatch:
    root = tmp_path_factory.mktemp("ws")
    package = root / "src" / "viewer"
    (package / "src").mkdir(parents=True)
    (package / "include" / "viewer").mkdir(parents=True)
    (package / "package.xml").write_text(package_xml("viewer", "ament_cmake"))
    (package / "include" / "viewer" / "parts.hpp").write_text(HEADER)
    src = package / "src"
    files = {"holder.cpp": HOLDER, "starter.cpp": STARTER, "main.cpp": MAIN,
             "viewer.cpp": VIEWER % '"viewer"', "member.cpp": VIEWER % "title_",
             "mixed.cpp": VIEWER % '"viewer", false);\n  starter_->start(argc, argv, title_',
             "alone.cpp": "\n".join([HOLDER, STARTER, VIEWER % '"viewer"', MAIN])}
    for name, text in files.items():
        (src / name).write_text(text)
    nodes = [[str(src / n) for n in ("main.cpp", "viewer.cpp", "starter.cpp", "holder.cpp")],
             [str(src / "alone.cpp")],
             [str(src / n) for n in ("main.cpp", "member.cpp", "starter.cpp", "holder.cpp")],
             [str(src / n) for n in ("main.cpp", "mixed.cpp", "starter.cpp", "holder.cpp")]]
    return extract_cpp_nodes(nodes, scan([str(root)]), cache_dir=None, jobs=1)


def test_a_literal_given_to_a_virtual_method_names_the_node_across_files(
        batch: CppBatch) -> None:
    assert batch.results[0].rosname == "viewer"


def test_a_literal_given_to_a_virtual_method_names_the_node_in_one_file(
        batch: CppBatch) -> None:
    assert batch.results[1].rosname == "viewer"


def test_a_member_given_to_a_virtual_method_stays_unknown(batch: CppBatch) -> None:
    assert batch.results[2].rosname == "?"
    # a literal at one call and a member at another: not the literal alone
    assert batch.results[3].rosname == "?"
