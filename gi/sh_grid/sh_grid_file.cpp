#include "gi/sh_grid/sh_grid_file.h"

#include "shaders/sh_grid/sh_grid_shared.h"

#include <cmath>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>

namespace lumina::gi {

namespace {

constexpr char kMagic[8] = {'L', 'S', 'H', 'G', 'R', 'I', 'D', '1'};
constexpr uint32_t kMaxCount = 1024;

template <typename T>
void put(std::ofstream& out, const T& value) {
    out.write(reinterpret_cast<const char*>(&value), sizeof(T));
}

template <typename T>
bool get(std::ifstream& in, T& value) {
    return bool(in.read(reinterpret_cast<char*>(&value), sizeof(T)));
}

bool finite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

} // namespace

void saveShGrid(const std::filesystem::path& path, const ShGridFile& grid) {
    std::ofstream out(path, std::ios::binary);
    if (!out) {
        throw std::runtime_error("sh-grid: cannot write '" + path.string() + "'");
    }
    out.write(kMagic, sizeof(kMagic));
    for (int a = 0; a < 3; ++a) {
        put(out, grid.layout.counts[a]);
    }
    for (int a = 0; a < 3; ++a) {
        put(out, grid.layout.origin[a]);
    }
    for (int a = 0; a < 3; ++a) {
        put(out, grid.layout.spacing[a]);
    }
    out.write(reinterpret_cast<const char*>(grid.coefficients.data()),
              std::streamsize(grid.coefficients.size() * sizeof(glm::vec3)));
    if (!out) {
        throw std::runtime_error("sh-grid: writing '" + path.string() + "' failed");
    }
}

ShGridFile loadShGrid(const std::filesystem::path& path) {
    const std::string name = "sh-grid file '" + path.string() + "'";
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        throw std::runtime_error(name + ": cannot be read");
    }
    char magic[sizeof(kMagic)] = {};
    if (!in.read(magic, sizeof(magic)) || std::memcmp(magic, kMagic, sizeof(kMagic)) != 0) {
        throw std::runtime_error(name + ": not an SH grid (no LSHGRID1 header)");
    }
    ShGridFile grid;
    bool ok = true;
    for (int a = 0; a < 3; ++a) {
        ok = ok && get(in, grid.layout.counts[a]);
    }
    for (int a = 0; a < 3; ++a) {
        ok = ok && get(in, grid.layout.origin[a]);
    }
    for (int a = 0; a < 3; ++a) {
        ok = ok && get(in, grid.layout.spacing[a]);
    }
    if (!ok) {
        throw std::runtime_error(name + ": truncated header");
    }
    if (glm::any(glm::lessThan(grid.layout.counts, glm::uvec3(2))) ||
        glm::any(glm::greaterThan(grid.layout.counts, glm::uvec3(kMaxCount)))) {
        throw std::runtime_error(name + ": probe counts out of range (2 to " + std::to_string(kMaxCount) +
                                 ")");
    }
    if (!finite(grid.layout.origin) || !finite(grid.layout.spacing) ||
        glm::any(glm::lessThanEqual(grid.layout.spacing, glm::vec3(0.0f)))) {
        throw std::runtime_error(name + ": origin or spacing not finite (or a spacing not positive)");
    }
    grid.coefficients.resize(size_t(grid.layout.probes()) * LUMINA_SH_GRID_COEFFICIENTS);
    if (!in.read(reinterpret_cast<char*>(grid.coefficients.data()),
                 std::streamsize(grid.coefficients.size() * sizeof(glm::vec3)))) {
        throw std::runtime_error(name + ": truncated (expected " + std::to_string(grid.layout.probes()) +
                                 " probes of coefficients)");
    }
    for (const glm::vec3& c : grid.coefficients) {
        if (!finite(c)) {
            throw std::runtime_error(name + ": a coefficient is not finite");
        }
    }
    if (in.peek() != std::char_traits<char>::eof()) {
        throw std::runtime_error(name + ": trailing bytes after the coefficients");
    }
    return grid;
}

void requireSameGrid(const ShGridLayout& layout, const ShGridLayout& file,
                     const std::filesystem::path& path) {
    const float tolerance = 1e-4f * glm::length(layout.spacing);
    const bool same = layout.counts == file.counts && glm::length(layout.origin - file.origin) <= tolerance &&
                      glm::length(layout.spacing - file.spacing) <= tolerance;
    if (!same) {
        throw std::invalid_argument("sh-grid file '" + path.string() +
                                    "' was baked for another grid (other scene, preset or probe counts)");
    }
}

} // namespace lumina::gi
