"""``new P(args)`` in a class template, ``P`` one of its type parameters: the class it
constructs is the one the template is given for ``P``, its default argument where the
specialisation the code names gives none. rosserial_server's socket_node builds a
``TcpServer<>`` (tcp_server.h:44, ``template<typename Session =
Session<tcp::socket>>``), whose ``start_accept`` makes each client's ``new
Session(io_service_)`` (line 65); the session subscribes, publishes and calls services
for its client on its own handle (session.h, topic_handlers.h). Without the
construction, socket_node had the session's subscription (a construction the walk
records without its owner running) but not its publisher nor its service client, which
serial_node, whose SerialSession derives from ``Session<serial_port>``, has."""

from __future__ import annotations

from haros_arch import cmake
from haros_arch.extract import extract_nodes
from haros_arch.workspace import scan
from tests.conftest import package_xml

SOURCE = """
    #include <ros/ros.h>
    #include <std_msgs/String.h>

    class Publisher {
     public:
      Publisher(ros::NodeHandle& nh, const std::string& topic) {
        pub_ = nh.advertise<std_msgs::String>(topic, 1);
      }
      ros::Publisher pub_;
    };
    struct Socket {};
    template<typename S>
    class Session {
     public:
      explicit Session(int& io) : io_(io) {}
      void start() { publisher_ = new Publisher(nh_, "to_client"); }
     private:
      int& io_;
      ros::NodeHandle nh_;
      Publisher* publisher_;
    };
    template<typename SessionT = Session<Socket> >
    class Server {
     public:
      explicit Server(int& io) : io_(io) { accept(); }
     private:
      void accept() {
        SessionT* session = new SessionT(io_);
        session->start();
      }
      int& io_;
    };
    int main(int argc, char** argv) {
      ros::init(argc, argv, "socket_node");
      int io = 0;
      Server<> server(io);
      ros::spin();
    }
    """


def test_a_new_of_a_template_parameter_constructs_its_default(write_tree) -> None:
    root = write_tree({
        "bridge/package.xml": package_xml("bridge", "catkin"),
        "bridge/CMakeLists.txt": """
            cmake_minimum_required(VERSION 3.0.2)
            project(bridge)
            find_package(catkin REQUIRED COMPONENTS roscpp std_msgs)
            catkin_package()
            include_directories(${catkin_INCLUDE_DIRS})
            add_executable(socket_node src/socket_node.cpp)
            target_link_libraries(socket_node ${catkin_LIBRARIES})
            """,
        "bridge/src/socket_node.cpp": SOURCE,
    })
    ws = scan([str(root)])
    package = ws.packages["bridge"]
    package.nodes, _ = cmake.parse_package(package, ws)
    extract_nodes(package.nodes, ws, cache_dir=None, jobs=1)
    node = package.nodes[0]
    found = sorted((c.kind, c.name, c.type, c.location.line) for c in node.calls)
    assert found == [("publish", "to_client", "std_msgs/String", 7)], found
    assert node.completeness == "complete", node.completeness_reasons


def test_the_class_a_specialisation_gives_wins_over_the_default(write_tree) -> None:
    # a server whose sessions are another class (a base ``Server<Logger>``): the
    # sessions the template builds are Loggers, not its default
    source = SOURCE.replace("""    int main(int argc, char** argv) {""", """    class Logger {
     public:
      explicit Logger(int& io) {}
      void start() { pub_ = nh_.advertise<std_msgs::String>("log", 1); }
      ros::NodeHandle nh_;
      ros::Publisher pub_;
    };
    class LogServer : public Server<Logger> {
     public:
      explicit LogServer(int& io) : Server<Logger>(io) {}
    };
    int main(int argc, char** argv) {""").replace("Server<> server(io);",
                                                  "LogServer server(io);")
    root = write_tree({
        "bridge/package.xml": package_xml("bridge", "catkin"),
        "bridge/CMakeLists.txt": """
            cmake_minimum_required(VERSION 3.0.2)
            project(bridge)
            find_package(catkin REQUIRED COMPONENTS roscpp std_msgs)
            catkin_package()
            add_executable(log_node src/log_node.cpp)
            """,
        "bridge/src/log_node.cpp": source,
    })
    ws = scan([str(root)])
    package = ws.packages["bridge"]
    package.nodes, _ = cmake.parse_package(package, ws)
    extract_nodes(package.nodes, ws, cache_dir=None, jobs=1)
    node = package.nodes[0]
    found = sorted((c.kind, c.name, c.type) for c in node.calls)
    assert found == [("publish", "log", "std_msgs/String")], found
