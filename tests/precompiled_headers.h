// The headers every test executable gets precompiled (lumina_test_pch, tests/CMakeLists.txt):
// GoogleTest, GLM and the standard library, which made up about half of a test file's compile
// time. CI builds the tests three times (Linux, the sanitizer build, MinGW for Windows). Only
// headers from outside the project: a change to Lumina's own headers rebuilds what includes them,
// not every test.
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
#include <gtest/gtest.h>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>
