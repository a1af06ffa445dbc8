// haros_arch stand-in
#include <diagnostic_updater/diagnostic_updater.h>
