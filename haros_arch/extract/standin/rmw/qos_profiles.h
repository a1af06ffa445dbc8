// haros_arch stand-in: rmw QoS profiles (declarations only)
#ifndef HAROS_STANDIN_RMW_QOS_PROFILES_H
#define HAROS_STANDIN_RMW_QOS_PROFILES_H
#include <cstddef>
extern "C" {
typedef enum { RMW_QOS_POLICY_HISTORY_SYSTEM_DEFAULT, RMW_QOS_POLICY_HISTORY_KEEP_LAST,
               RMW_QOS_POLICY_HISTORY_KEEP_ALL } rmw_qos_history_policy_t;
typedef enum { RMW_QOS_POLICY_RELIABILITY_SYSTEM_DEFAULT, RMW_QOS_POLICY_RELIABILITY_RELIABLE,
               RMW_QOS_POLICY_RELIABILITY_BEST_EFFORT } rmw_qos_reliability_policy_t;
typedef enum { RMW_QOS_POLICY_DURABILITY_SYSTEM_DEFAULT,
               RMW_QOS_POLICY_DURABILITY_TRANSIENT_LOCAL,
               RMW_QOS_POLICY_DURABILITY_VOLATILE } rmw_qos_durability_policy_t;
typedef enum { RMW_QOS_POLICY_LIVELINESS_SYSTEM_DEFAULT, RMW_QOS_POLICY_LIVELINESS_AUTOMATIC,
               RMW_QOS_POLICY_LIVELINESS_MANUAL_BY_NODE,
               RMW_QOS_POLICY_LIVELINESS_MANUAL_BY_TOPIC,
               RMW_QOS_POLICY_LIVELINESS_UNKNOWN } rmw_qos_liveliness_policy_t;
// rmw/network_flow_endpoint.h: what publisher / subscription options ask of the endpoints
typedef enum { RMW_UNIQUE_NETWORK_FLOW_ENDPOINTS_NOT_REQUIRED = 0,
               RMW_UNIQUE_NETWORK_FLOW_ENDPOINTS_STRICTLY_REQUIRED,
               RMW_UNIQUE_NETWORK_FLOW_ENDPOINTS_OPTIONALLY_REQUIRED,
               RMW_UNIQUE_NETWORK_FLOW_ENDPOINTS_SYSTEM_DEFAULT
} rmw_unique_network_flow_endpoints_requirement_t;
typedef struct rmw_time_t { unsigned long long sec; unsigned long long nsec; } rmw_time_t;
// rmw/types.h: a publisher's global id (rclcpp's ``PublisherBase::get_gid``)
#define RMW_GID_STORAGE_SIZE 16u
typedef struct rmw_gid_t {
  const char* implementation_identifier; unsigned char data[RMW_GID_STORAGE_SIZE];
} rmw_gid_t;
#define RMW_QOS_POLICY_DEPTH_SYSTEM_DEFAULT 0
#define RMW_QOS_DEADLINE_DEFAULT {0, 0}
#define RMW_QOS_LIFESPAN_DEFAULT {0, 0}
#define RMW_QOS_LIVELINESS_LEASE_DURATION_DEFAULT {0, 0}
typedef struct rmw_qos_profile_t {
  rmw_qos_history_policy_t history;
  size_t depth;
  rmw_qos_reliability_policy_t reliability;
  rmw_qos_durability_policy_t durability;
  rmw_time_t deadline;
  rmw_time_t lifespan;
  rmw_qos_liveliness_policy_t liveliness;
  rmw_time_t liveliness_lease_duration;
  bool avoid_ros_namespace_conventions;
} rmw_qos_profile_t;
extern const rmw_qos_profile_t rmw_qos_profile_default;
extern const rmw_qos_profile_t rmw_qos_profile_sensor_data;
extern const rmw_qos_profile_t rmw_qos_profile_services_default;
extern const rmw_qos_profile_t rmw_qos_profile_parameters;
extern const rmw_qos_profile_t rmw_qos_profile_parameter_events;
extern const rmw_qos_profile_t rmw_qos_profile_system_default;
extern const rmw_qos_profile_t rmw_qos_profile_unknown;
extern const rmw_qos_profile_t rmw_qos_profile_rosout_default;
typedef struct rmw_request_id_t { long sequence_number; } rmw_request_id_t;
// rmw/rmw.h (which rclcpp's subscription_base.hpp includes): the middleware's name and
// its serialization format (zed_components' logs ``rmw_get_implementation_identifier()``)
const char* rmw_get_implementation_identifier(void);
const char* rmw_get_serialization_format(void);
}
#endif
