// haros_arch stand-in: xmlrpcpp (every xmlrpcpp/ header stands in as this one), whose
// XmlRpcValue and XmlRpcException are declared with roscpp's in ros/forwards.h
#include <ros/forwards.h>
