// haros_arch stand-in: ament_index_cpp (declarations only); every ament_index_cpp header
// stands in as this one
#ifndef HAROS_STANDIN_AMENT_INDEX_CPP_HPP
#define HAROS_STANDIN_AMENT_INDEX_CPP_HPP
#include <list>
#include <map>
#include <stdexcept>
#include <string>
namespace ament_index_cpp {
class PackageNotFoundError : public std::out_of_range {
public:
  explicit PackageNotFoundError(const std::string& package_name);
  std::string package_name;
};
std::string get_package_share_directory(const std::string& package_name);
void get_package_share_directory(const std::string& package_name, std::string& result);
std::string get_package_share_path(const std::string& package_name);
std::string get_package_prefix(const std::string& package_name);
void get_package_prefix(const std::string& package_name, std::string& result);
std::map<std::string, std::string> get_packages_with_prefixes();
std::map<std::string, std::string> get_resources(const std::string& resource_type);
bool get_resource(const std::string& resource_type, const std::string& resource_name,
                  std::string& content, std::string* prefix_path = nullptr);
bool has_resource(const std::string& resource_type, const std::string& resource_name,
                  std::string* prefix_path = nullptr);
std::list<std::string> get_search_paths();
}  // namespace ament_index_cpp
#endif
