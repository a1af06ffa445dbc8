// haros_arch stand-in: image_geometry (see pinhole_camera_model.h)
#include <image_geometry/pinhole_camera_model.h>
