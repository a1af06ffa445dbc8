// haros_arch stand-in: interactive_markers' MenuHandler (declarations only; no ROS call of
// its own: it puts menu entries on a server's markers). ROS 2's menu_handler.hpp includes
// its server and then this: the callback type is the server's.
#ifndef HAROS_STANDIN_INTERACTIVE_MARKERS_MENU_HANDLER_H
#define HAROS_STANDIN_INTERACTIVE_MARKERS_MENU_HANDLER_H
#include <string>
#include <interactive_markers/interactive_marker_server.h>

namespace interactive_markers {
class MenuHandler {
 public:
  typedef uint32_t EntryHandle;
  typedef InteractiveMarkerServer::FeedbackCallback FeedbackCallback;
  enum CheckState { NO_CHECKBOX, CHECKED, UNCHECKED };
  MenuHandler();
  EntryHandle insert(const std::string& title, const FeedbackCallback& feedback_cb);
  EntryHandle insert(const std::string& title, const uint8_t command_type = 0,
                     const std::string& command = "");
  EntryHandle insert(EntryHandle parent, const std::string& title,
                     const FeedbackCallback& feedback_cb);
  EntryHandle insert(EntryHandle parent, const std::string& title,
                     const uint8_t command_type = 0, const std::string& command = "");
  bool setVisible(EntryHandle handle, bool visible);
  bool setCheckState(EntryHandle handle, CheckState check_state);
  bool getCheckState(EntryHandle handle, CheckState& check_state) const;
  bool apply(InteractiveMarkerServer& server, const std::string& marker_name);
  bool reApply(InteractiveMarkerServer& server);
  bool getTitle(EntryHandle handle, std::string& title) const;
};
}  // namespace interactive_markers
#endif
