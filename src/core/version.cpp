#include "raylab/version.h"

namespace raylab {

// Compiled into the library, so that it reports the library's version, not the caller's headers'.
const char* version() { return RAYLAB_VERSION_STRING; }

}  // namespace raylab
