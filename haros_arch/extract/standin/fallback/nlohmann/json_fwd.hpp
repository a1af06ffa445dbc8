// haros_arch stand-in: nlohmann/json_fwd.hpp, the library's forward declarations: the
// whole stand-in
#include <nlohmann/json.hpp>
