// haros_arch stand-in: ros::NodeHandle (declarations only)
#ifndef HAROS_STANDIN_ROS_NODE_HANDLE_H
#define HAROS_STANDIN_ROS_NODE_HANDLE_H
#include <ros/forwards.h>
#include <ros/time.h>
#include <ros/publisher.h>
#include <ros/service_server.h>
#include <ros/timer.h>
namespace ros {
// roscpp's callback helpers, which a SubscribeOptions or AdvertiseServiceOptions holds as
// its ``helper`` (a recorder's ShapeShifter subscription, a relay's service whose calls
// it forwards: nimbro_service_transport's ``class CallbackHelper : public
// ros::ServiceCallbackHelper``); no ROS call of their own
class SubscriptionCallbackHelper {
public:
  virtual ~SubscriptionCallbackHelper();
  virtual bool isConst();
  virtual bool hasHeader();
};
typedef boost::shared_ptr<SubscriptionCallbackHelper> SubscriptionCallbackHelperPtr;
// the callback's own parameter type ``P`` (``const M::ConstPtr&``, an event of M)
template<typename P, typename Enabled = void>
class SubscriptionCallbackHelperT : public SubscriptionCallbackHelper {
public:
  typedef boost::function<void(P)> Callback;
  explicit SubscriptionCallbackHelperT(const Callback& callback);
};
struct ServiceCallbackHelperCallParams {
  boost::shared_ptr<M_string> connection_header;
};
class ServiceCallbackHelper {
public:
  virtual ~ServiceCallbackHelper();
  virtual bool call(ServiceCallbackHelperCallParams& params) = 0;
};
typedef boost::shared_ptr<ServiceCallbackHelper> ServiceCallbackHelperPtr;
// what subscribe(ops) / advertise(ops) take; init<M> / create<M> hold the topic
struct SubscribeOptions {
  SubscribeOptions();
  // roscpp's constructor of a topic by its md5sum and datatype, the callback set on the
  // object's ``helper`` after (topic_tools' ShapeShifter subscribers)
  SubscribeOptions(const std::string& topic, uint32_t queue_size, const std::string& md5sum,
                   const std::string& datatype);
  template<class M>
  void init(const std::string& topic, uint32_t queue_size,
            const boost::function<void(const boost::shared_ptr<M const>&)>& callback);
  // the callback's own parameter type: ``const M&``, ``const M::ConstPtr&``, an event
  template<class P>
  void initByFullCallbackType(const std::string& topic, uint32_t queue_size,
                              const boost::function<void(P)>& callback);
  template<class M>
  static SubscribeOptions create(const std::string& topic, uint32_t queue_size,
                                 const boost::function<void(const boost::shared_ptr<M const>&)>& callback,
                                 const VoidConstPtr& tracked_object = VoidConstPtr(),
                                 CallbackQueueInterface* queue = 0);
  std::string topic;
  uint32_t queue_size;
  std::string md5sum;
  std::string datatype;
  CallbackQueueInterface* callback_queue;
  bool allow_concurrent_callbacks;
  SubscriptionCallbackHelperPtr helper;
  VoidConstPtr tracked_object;
  TransportHints transport_hints;
};
struct AdvertiseOptions {
  AdvertiseOptions();
  // roscpp's constructor of a topic by its md5sum, datatype and definition (a relay's
  // publisher of the ShapeShifter type it received: jsk_topic_tools' nodelets)
  AdvertiseOptions(const std::string& topic, uint32_t queue_size, const std::string& md5sum,
                   const std::string& datatype, const std::string& message_definition,
                   const SubscriberStatusCallback& connect_cb = SubscriberStatusCallback(),
                   const SubscriberStatusCallback& disconnect_cb = SubscriberStatusCallback());
  template<class M>
  void init(const std::string& topic, uint32_t queue_size,
            const SubscriberStatusCallback& connect_cb = SubscriberStatusCallback(),
            const SubscriberStatusCallback& disconnect_cb = SubscriberStatusCallback());
  template<class M>
  static AdvertiseOptions create(const std::string& topic, uint32_t queue_size,
                                 const SubscriberStatusCallback& connect_cb,
                                 const SubscriberStatusCallback& disconnect_cb,
                                 const VoidConstPtr& tracked_object,
                                 CallbackQueueInterface* queue);
  std::string topic;
  uint32_t queue_size;
  std::string md5sum;
  std::string datatype;
  std::string message_definition;
  SubscriberStatusCallback connect_cb;
  SubscriberStatusCallback disconnect_cb;
  CallbackQueueInterface* callback_queue;
  VoidConstPtr tracked_object;
  bool latch;
  bool has_header;
};
// what advertiseService(ops) takes; init<Service> / init<MReq, MRes> / create<Service>
// hold the service name and callback
struct AdvertiseServiceOptions {
  AdvertiseServiceOptions();
  template<class MReq, class MRes>
  void init(const std::string& service, const boost::function<bool(MReq&, MRes&)>& callback);
  template<class Service>
  void init(const std::string& service,
            const boost::function<bool(typename Service::Request&,
                                       typename Service::Response&)>& callback);
  template<class Service>
  static AdvertiseServiceOptions create(
      const std::string& service,
      const boost::function<bool(typename Service::Request&,
                                 typename Service::Response&)>& callback,
      const VoidConstPtr& tracked_object, CallbackQueueInterface* queue);
  std::string service;
  std::string md5sum;
  std::string datatype;
  std::string req_datatype;
  std::string res_datatype;
  ServiceCallbackHelperPtr helper;
  CallbackQueueInterface* callback_queue;
  VoidConstPtr tracked_object;
};
class NodeHandle {
public:
  NodeHandle(const std::string& ns = std::string(), const M_string& remappings = M_string());
  NodeHandle(const NodeHandle& parent, const std::string& ns);
  NodeHandle(const NodeHandle& parent, const std::string& ns, const M_string& remappings);
  NodeHandle(const NodeHandle& rhs);
  // a namespace the parse knows only as a permissive value (``"~/" + name_``, name_ a
  // member of a layer's base whose header is missing): the namespace, not a copy of a
  // handle, which the value converts to as well (the construction was ambiguous); only
  // for such a value (anything converts to the permissive class)
  template <class T, class = typename std::enable_if<
    __is_base_of(haros_any, typename std::decay<T>::type)>::type>
  NodeHandle(T&& ns, const M_string& remappings = M_string());
  ~NodeHandle();
  NodeHandle& operator=(const NodeHandle& rhs);

  const std::string& getNamespace() const;
  const std::string& getUnresolvedNamespace() const;
  std::string resolveName(const std::string& name, bool remap = true) const;
  bool ok() const;
  void shutdown();
  void setCallbackQueue(CallbackQueueInterface* queue);
  CallbackQueueInterface* getCallbackQueue() const;

  // topics
  template<class M>
  Publisher advertise(const std::string& topic, uint32_t queue_size, bool latch = false);
  template<class M>
  Publisher advertise(const std::string& topic, uint32_t queue_size,
                      const SubscriberStatusCallback& connect_cb,
                      const SubscriberStatusCallback& disconnect_cb = SubscriberStatusCallback(),
                      const VoidConstPtr& tracked_object = VoidConstPtr(), bool latch = false);
  template<class M, class T>
  Subscriber subscribe(const std::string& topic, uint32_t queue_size, void (T::*fp)(M),
                       T* obj, const TransportHints& hints = TransportHints());
  template<class M, class T>
  Subscriber subscribe(const std::string& topic, uint32_t queue_size, void (T::*fp)(M) const,
                       T* obj, const TransportHints& hints = TransportHints());
  template<class M, class T>
  Subscriber subscribe(const std::string& topic, uint32_t queue_size, void (T::*fp)(M),
                       const boost::shared_ptr<T>& obj,
                       const TransportHints& hints = TransportHints());
  template<class M, class T>
  Subscriber subscribe(const std::string& topic, uint32_t queue_size,
                       void (T::*fp)(const boost::shared_ptr<M const>&), T* obj,
                       const TransportHints& hints = TransportHints());
  template<class M>
  Subscriber subscribe(const std::string& topic, uint32_t queue_size,
                       void (*fp)(const boost::shared_ptr<M const>&),
                       const TransportHints& hints = TransportHints());
  // a std::shared_ptr message (PCL >= 1.11's pcl::PointCloud<T>::ConstPtr, with pcl_ros)
  template<class M, class T>
  Subscriber subscribe(const std::string& topic, uint32_t queue_size,
                       void (T::*fp)(const std::shared_ptr<M const>&), T* obj,
                       const TransportHints& hints = TransportHints());
  template<class M>
  Subscriber subscribe(const std::string& topic, uint32_t queue_size,
                       void (*fp)(const std::shared_ptr<M const>&),
                       const TransportHints& hints = TransportHints());
  template<class M>
  Subscriber subscribe(const std::string& topic, uint32_t queue_size, void (*fp)(M),
                       const TransportHints& hints = TransportHints());
  template<class M>
  Subscriber subscribe(const std::string& topic, uint32_t queue_size,
                       const boost::function<void(const boost::shared_ptr<M const>&)>& callback,
                       const VoidConstPtr& tracked_object = VoidConstPtr(),
                       const TransportHints& hints = TransportHints());

  Publisher advertise(AdvertiseOptions& ops);
  Subscriber subscribe(SubscribeOptions& ops);

  // services
  template<class MReq, class MRes>
  ServiceServer advertiseService(const std::string& service, bool (*srv_func)(MReq&, MRes&));
  template<class T, class MReq, class MRes>
  ServiceServer advertiseService(const std::string& service, bool (T::*srv_func)(MReq&, MRes&),
                                 T* obj);
  template<class T, class MReq, class MRes>
  ServiceServer advertiseService(const std::string& service, bool (T::*srv_func)(MReq&, MRes&),
                                 const boost::shared_ptr<T>& obj);
  template<class MReq, class MRes>
  ServiceServer advertiseService(const std::string& service,
                                 const boost::function<bool(MReq&, MRes&)>& callback,
                                 const VoidConstPtr& tracked_object = VoidConstPtr());
  ServiceServer advertiseService(AdvertiseServiceOptions& ops);
  template<class Service>
  ServiceClient serviceClient(const std::string& service_name, bool persistent = false,
                              const M_string& header_values = M_string());
  template<class MReq, class MRes>
  ServiceClient serviceClient(const std::string& service_name, bool persistent = false,
                              const M_string& header_values = M_string());

  // timers
  Timer createTimer(Duration period, const TimerCallback& callback, bool oneshot = false,
                    bool autostart = true) const;
  template<class T>
  Timer createTimer(Duration period, void (T::*callback)(const TimerEvent&), T* obj,
                    bool oneshot = false, bool autostart = true) const;
  template<class T>
  Timer createTimer(Duration period, void (T::*callback)(const TimerEvent&) const, T* obj,
                    bool oneshot = false, bool autostart = true) const;
  template<class T>
  Timer createTimer(Duration period, void (T::*callback)(const TimerEvent&),
                    const boost::shared_ptr<T>& obj, bool oneshot = false,
                    bool autostart = true) const;
  // at a rate: a member function and its object
  template<class Handler, class Obj>
  Timer createTimer(Rate r, Handler h, Obj o, bool oneshot = false,
                    bool autostart = true) const;
  Timer createTimer(TimerOptions& ops) const;
  Timer createWallTimer(Duration period, const TimerCallback& callback, bool oneshot = false,
                        bool autostart = true) const;
  template<class T>
  Timer createWallTimer(Duration period, void (T::*callback)(const TimerEvent&), T* obj,
                        bool oneshot = false, bool autostart = true) const;
  // roscpp 1.13.1 on (ROS_VERSION_MINIMUM): a timer on the monotonic clock
  Timer createSteadyTimer(Duration period, const TimerCallback& callback,
                          bool oneshot = false, bool autostart = true) const;
  template<class T>
  Timer createSteadyTimer(Duration period, void (T::*callback)(const TimerEvent&), T* obj,
                          bool oneshot = false, bool autostart = true) const;

  // parameters
  void setParam(const std::string& key, const XmlRpc::XmlRpcValue& v) const;
  void setParam(const std::string& key, const std::string& s) const;
  void setParam(const std::string& key, const char* s) const;
  void setParam(const std::string& key, double d) const;
  void setParam(const std::string& key, int i) const;
  void setParam(const std::string& key, bool b) const;
  template<class T> void setParam(const std::string& key, const std::vector<T>& vec) const;
  template<class T>
  void setParam(const std::string& key, const std::map<std::string, T>& map) const;
  bool getParam(const std::string& key, std::string& s) const;
  bool getParam(const std::string& key, double& d) const;
  bool getParam(const std::string& key, float& f) const;
  bool getParam(const std::string& key, int& i) const;
  bool getParam(const std::string& key, bool& b) const;
  bool getParam(const std::string& key, XmlRpc::XmlRpcValue& v) const;
  template<class T> bool getParam(const std::string& key, std::vector<T>& vec) const;
  template<class T>
  bool getParam(const std::string& key, std::map<std::string, T>& map) const;
  bool getParamCached(const std::string& key, std::string& s) const;
  bool getParamCached(const std::string& key, double& d) const;
  bool getParamCached(const std::string& key, float& f) const;
  bool getParamCached(const std::string& key, int& i) const;
  bool getParamCached(const std::string& key, bool& b) const;
  bool getParamCached(const std::string& key, XmlRpc::XmlRpcValue& v) const;
  template<class T> bool getParamCached(const std::string& key, std::vector<T>& vec) const;
  bool hasParam(const std::string& key) const;
  bool searchParam(const std::string& key, std::string& result) const;
  bool deleteParam(const std::string& key) const;
  bool getParamNames(std::vector<std::string>& keys) const;
  template<typename T>
  bool param(const std::string& param_name, T& param_val, const T& default_val) const;
  // a value of a type whose header is missing (declared permissively: elevation_mapping's
  // ``param("track_point_x", parameters.trackPoint_.x(), 0.0)``, a kindr position) read
  // with a default of a real type: roscpp deduces T from both, which here differ
  template<typename T, typename D>
  bool param(const std::string& param_name, T& param_val, const D& default_val) const;
  template<typename T> T param(const std::string& param_name, const T& default_val) const;
};
}  // namespace ros
#endif
