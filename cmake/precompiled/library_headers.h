// The headers every library and executable of Lumina's own code gets precompiled
// (cmake/LuminaPrecompiledHeaders.cmake): GLM and the standard library, about a third of a source
// file's compile time. CI builds the code three times (Linux, the sanitizer build, MinGW for
// Windows). Only headers from outside the project, none that reads a macro a source file could
// set first: a change to Lumina's own headers rebuilds what includes them, not everything.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>
