// haros_arch stand-in for Boost.Filesystem (declarations only): the names of <filesystem>
// under boost::filesystem (path, exists, is_directory, create_directory, the iterators),
// and its fstream classes, which open a path; every boost/filesystem/... header stands in
// as this one
#include <filesystem>
#include <fstream>
#ifndef HAROS_STANDIN_BOOST_FILESYSTEM_HPP
#define HAROS_STANDIN_BOOST_FILESYSTEM_HPP
namespace boost {
namespace filesystem {
using namespace std::filesystem;
class ifstream : public std::ifstream {
public:
  ifstream();
  explicit ifstream(const path& p, std::ios_base::openmode mode = std::ios_base::in);
  void open(const path& p, std::ios_base::openmode mode = std::ios_base::in);
};
class ofstream : public std::ofstream {
public:
  ofstream();
  explicit ofstream(const path& p, std::ios_base::openmode mode = std::ios_base::out);
  void open(const path& p, std::ios_base::openmode mode = std::ios_base::out);
};
}  // namespace filesystem
}  // namespace boost
#endif
