"""``new C(args)`` in a class template, ``C`` a class of the workspace (no template),
where an argument depends on the template's parameters: clang keeps no call of ``C``'s
constructor, only the argument list. rosserial_server's ``Session<Socket>`` makes ``new
Subscriber(nh_, topic_info, boost::bind(&Session::write_message, this, _1))``
(session.h:433), whose constructor subscribes on the handle it is given
(topic_handlers.h:96): the list is a site of that constructor, as a call would be, so
the subscription is read on ``nh_``; the ``new Publisher(nh_, topic_info)`` beside it,
whose arguments depend on nothing, was always read."""

from __future__ import annotations

from haros_arch import cmake
from haros_arch.extract import extract_nodes
from haros_arch.workspace import scan
from tests.conftest import package_xml

SOURCE = """
    #include <ros/ros.h>
    #include <std_msgs/String.h>
    #include <boost/bind.hpp>
    #include <boost/function.hpp>
    #include <map>
    class Publisher {
     public:
      Publisher(ros::NodeHandle& nh, const std::string& topic) {
        pub_ = nh.advertise<std_msgs::String>(topic, 1);
      }
      ros::Publisher pub_;
    };
    class Subscriber {
     public:
      Subscriber(ros::NodeHandle& nh, const std::string& topic,
                 boost::function<void(int)> write_fn) : write_fn_(write_fn) {
        sub_ = nh.subscribe(topic, 1, &Subscriber::handle, this);
      }
     private:
      void handle(const std_msgs::String::ConstPtr& msg) { write_fn_(1); }
      ros::Subscriber sub_;
      boost::function<void(int)> write_fn_;
    };
    template<typename Socket>
    class Session {
     public:
      explicit Session(Socket& socket) : socket_(socket) {
        callbacks_[0] = boost::bind(&Session::setup_publisher, this, _1);
        callbacks_[1] = boost::bind(&Session::setup_subscriber, this, _1);
      }
      void setup_publisher(int id) {
        publishers_[id] = new Publisher(nh_, "to_serial");
      }
      void setup_subscriber(int id) {
        subscribers_[id] = new Subscriber(nh_, "from_serial",
                                          boost::bind(&Session::write_message, this, _1));
      }
      void write_message(int id) {}
     private:
      Socket& socket_;
      ros::NodeHandle nh_;
      std::map<int, boost::function<void(int)> > callbacks_;
      std::map<int, Publisher*> publishers_;
      std::map<int, Subscriber*> subscribers_;
    };
    struct Port {};
    class SerialSession : public Session<Port> {
     public:
      explicit SerialSession(Port& port) : Session<Port>(port) {}
    };
    int main(int argc, char** argv) {
      ros::init(argc, argv, "serial_node");
      Port port;
      SerialSession session(port);
      ros::spin();
    }
    """


def test_a_dependent_new_of_a_class_constructs_it_with_its_arguments(write_tree) -> None:
    root = write_tree({
        "bridge/package.xml": package_xml("bridge", "catkin"),
        "bridge/CMakeLists.txt": """
            cmake_minimum_required(VERSION 3.0.2)
            project(bridge)
            find_package(catkin REQUIRED COMPONENTS roscpp std_msgs)
            catkin_package()
            include_directories(${catkin_INCLUDE_DIRS})
            add_executable(serial_node src/serial_node.cpp)
            target_link_libraries(serial_node ${catkin_LIBRARIES})
            """,
        "bridge/src/serial_node.cpp": SOURCE,
    })
    ws = scan([str(root)])
    package = ws.packages["bridge"]
    package.nodes, _ = cmake.parse_package(package, ws)
    extract_nodes(package.nodes, ws, cache_dir=None, jobs=1)
    node = package.nodes[0]
    found = sorted((c.kind, c.name, c.type, c.location.line) for c in node.calls)
    assert found == [("publish", "to_serial", "std_msgs/String", 9),
                     ("subscribe", "from_serial", "std_msgs/String", 17)]
    assert node.completeness == "complete"
