#pragma once
// A baked SH grid saved for a static scene and loaded instead of baking (docs/sh_grid.md,
// "Grid files"). Little-endian binary:
//
//   8 bytes   "LSHGRID1"
//   3 x u32   probe counts x, y, z
//   3 x f32   origin (world position of probe (0, 0, 0))
//   3 x f32   spacing
//   probes x 9 x 3 x f32   irradiance coefficients, probe by probe, rgb per coefficient
#include "gi/sh_grid/sh_grid_settings.h"

#include <filesystem>
#include <glm/glm.hpp>
#include <vector>

namespace lumina::gi {

struct ShGridFile {
    ShGridLayout layout;
    std::vector<glm::vec3> coefficients; // probes x 9, rgb
};

// std::runtime_error naming the path when it cannot be written.
void saveShGrid(const std::filesystem::path& path, const ShGridFile& grid);
// std::runtime_error naming the path and the problem: unreadable, not a grid file, truncated,
// counts out of range or non-finite values.
ShGridFile loadShGrid(const std::filesystem::path& path);
// std::invalid_argument when `file` was baked for another grid than `layout` (counts, or origin
// and spacing beyond 1e-4 of the spacing).
void requireSameGrid(const ShGridLayout& layout, const ShGridLayout& file, const std::filesystem::path& path);

} // namespace lumina::gi
