#pragma once
// Reading glTF accessors with every bound checked: the accessor, its bufferView and buffer,
// the stride, sparse substitutions and the element count against the loader's limits.
#include "gi/scene/gltf_internal.h"

#include <cstdint>
#include <string>
#include <vector>

namespace lumina::scene::gltf {

// Accessor `index` as `components` floats per element (type VEC2 is 2, VEC3 is 3), with
// integer components converted per glTF's `normalized` rule. `what` names the use in errors
// ("mesh 0 'Box' primitive 1 POSITION").
std::vector<float> readFloatAccessor(const Context& context, int index, int components,
                                     const std::string& what);

// An index accessor: SCALAR of unsigned byte, short or int.
std::vector<uint32_t> readIndexAccessor(const Context& context, int index, const std::string& what);

} // namespace lumina::scene::gltf
