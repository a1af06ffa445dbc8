// haros_arch stand-in: ROS 1 rosbag's Bag, View, queries and message instances
// (declarations only), for a workspace that has rosbag installed, not as sources. A bag
// is a file: reading or writing one makes no ROS call (slam_gmapping's replay mode,
// cartographer_ros' bag tools, amcl's map from a bag).
#ifndef HAROS_STANDIN_ROSBAG_BAG_H
#define HAROS_STANDIN_ROSBAG_BAG_H
#include <string>
#include <vector>
#include <functional>
#include <map>
#include <stdexcept>
#include <boost/shared_ptr.hpp>
#include <ros/time.h>
#include <rosbag/macros.h>
#include <rosbag/stream.h>

namespace rosbag {
namespace bagmode {
enum BagMode { Write = 1, Read = 2, Append = 4 };
}  // namespace bagmode
typedef bagmode::BagMode BagMode;

class BagException : public std::runtime_error {
 public:
  explicit BagException(const std::string& what);
};
class BagIOException : public BagException {
 public:
  explicit BagIOException(const std::string& what);
};

struct ConnectionInfo {
  unsigned int id;
  std::string topic;
  std::string datatype;
  std::string md5sum;
  std::string msg_def;
  boost::shared_ptr<std::map<std::string, std::string>> header;
};

class Bag {
 public:
  Bag();
  explicit Bag(const std::string& filename, unsigned int mode = bagmode::Read);
  ~Bag();
  void open(const std::string& filename, unsigned int mode = bagmode::Read);
  void close();
  bool isOpen() const;
  std::string getFileName() const;
  BagMode getMode() const;
  unsigned long getSize() const;
  void setCompression(CompressionType compression);
  CompressionType getCompression() const;
  void setChunkThreshold(unsigned int chunk_threshold);
  // a message of any type, as a message, a pointer to one or a message instance
  template<class T> void write(const std::string& topic, const ros::Time& time, const T& msg);
  template<class T> void write(const std::string& topic, const ros::Time& time, const T& msg,
                               const boost::shared_ptr<std::map<std::string, std::string>>&
                                   connection_header);
};

class MessageInstance {
 public:
  const std::string& getTopic() const;
  const std::string& getDataType() const;
  const std::string& getMD5Sum() const;
  const std::string& getMessageDefinition() const;
  const std::string& getCallerId() const;
  bool isLatching() const;
  const ros::Time& getTime() const;
  const ConnectionInfo* getConnection() const;
  boost::shared_ptr<std::map<std::string, std::string>> getConnectionHeader() const;
  unsigned int size() const;
  template<class T> bool isType() const;
  template<class T> boost::shared_ptr<T> instantiate() const;
  template<class Stream> void write(Stream& stream) const;
};

class Query {
 public:
  Query(const std::function<bool(const ConnectionInfo*)>& query,
        const ros::Time& start_time = ros::Time(), const ros::Time& end_time = ros::Time());
};
class TopicQuery {
 public:
  explicit TopicQuery(const std::string& topic);
  explicit TopicQuery(const std::vector<std::string>& topics);
  bool operator()(const ConnectionInfo* info) const;
};
class TypeQuery {
 public:
  explicit TypeQuery(const std::string& type);
  explicit TypeQuery(const std::vector<std::string>& types);
  bool operator()(const ConnectionInfo* info) const;
};

class View {
 public:
  class iterator {
   public:
    MessageInstance& operator*() const;
    MessageInstance* operator->() const;
    iterator& operator++();
    iterator operator++(int);
    bool operator==(const iterator& other) const;
    bool operator!=(const iterator& other) const;
  };
  typedef iterator const_iterator;
  explicit View(bool reduce_overlap = false);
  explicit View(const Bag& bag, const ros::Time& start_time = ros::Time(),
                const ros::Time& end_time = ros::Time(), bool reduce_overlap = false);
  template<class Q>
  View(const Bag& bag, const Q& query, const ros::Time& start_time = ros::Time(),
       const ros::Time& end_time = ros::Time(), bool reduce_overlap = false);
  void addQuery(const Bag& bag, const ros::Time& start_time = ros::Time(),
                const ros::Time& end_time = ros::Time());
  template<class Q>
  void addQuery(const Bag& bag, const Q& query, const ros::Time& start_time = ros::Time(),
                const ros::Time& end_time = ros::Time());
  iterator begin();
  iterator end();
  unsigned int size();
  std::vector<const ConnectionInfo*> getConnections();
  ros::Time getBeginTime();
  ros::Time getEndTime();
};
}  // namespace rosbag
#endif
