// haros_arch stand-in: ROS 1 gazebo_plugins' PubQueue.h (noetic-devel), the queue through
// which Gazebo classic plugins publish from their update thread (smb_common's odometry
// source, copies of gazebo_plugins' own sensors: ``pmq.addPub<nav_msgs::Odometry>()``,
// then ``queue->push(msg, pub_)`` with a publisher advertised as usual). Read only when
// the workspace has no such header (headers.FALLBACK). The queue makes no ROS call: the
// publisher it is handed was advertised where the graph sees it.
#ifndef HAROS_STANDIN_GAZEBO_PLUGINS_PUBQUEUE_H
#define HAROS_STANDIN_GAZEBO_PLUGINS_PUBQUEUE_H
#include <deque>
#include <vector>
#include <boost/function.hpp>
#include <boost/shared_ptr.hpp>
#include <boost/thread.hpp>
#include <ros/ros.h>

template <class T>
class PubMessagePair
{
public:
  T msg_;
  ros::Publisher pub_;
  PubMessagePair(T &msg, ros::Publisher &pub);
};

template <class T>
class PubQueue
{
public:
  typedef boost::shared_ptr<std::deque<boost::shared_ptr<PubMessagePair<T> > > > QueuePtr;
  typedef boost::shared_ptr<PubQueue<T> > Ptr;
  PubQueue(QueuePtr queue, boost::shared_ptr<boost::mutex> queue_lock,
           boost::function<void()> notify_func);
  void push(T &msg, ros::Publisher &pub);
  void pop(std::vector<boost::shared_ptr<PubMessagePair<T> > > &els);
};

class PubMultiQueue
{
public:
  PubMultiQueue();
  ~PubMultiQueue();
  template <class T> boost::shared_ptr<PubQueue<T> > addPub();
  void spinOnce();
  void spin();
  void startServiceThread();
  void notifyServiceThread();
};
#endif
