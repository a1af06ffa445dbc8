// haros_arch stand-in: filters (see filter_chain.h)
#include <filters/filter_chain.h>
