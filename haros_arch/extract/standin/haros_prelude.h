// haros_arch: the stand-in headers precompiled once per process (a PCH) so that each
// translation unit parses in milliseconds. Headers included again later are skipped by
// their include guards.
#include "std/haros_std.h"
#include <boost/shared_ptr.hpp>
#include <boost/function.hpp>
#include <boost/bind.hpp>
#include <ros/ros.h>
